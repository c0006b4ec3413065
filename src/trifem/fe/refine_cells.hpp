// SPDX-License-Identifier: MIT
// Uniform refinement of meshes of any cell family (tet4, tet10, penta6, hex8, hex20, mixed), for
// mesh-convergence studies: mesh::refine_uniformly's rules for every family.
#pragma once

#include "trifem/mesh/mesh.hpp"

namespace trifem::fe {

/// The mesh with every cell split into eight of its own type: a hex into the eight of its
/// 3 x 3 x 3 grid, a tet by Bey's rule (its four corner tets and the octahedron of its edge
/// midpoints cut along the diagonal between the midpoints of edges (0, 2) and (1, 3)), a wedge
/// into its triangle's four (cut by the edge midpoints) times two halves in z. Every node is
/// placed by the parent's own map (quadratic on tet10 and hex20: curved cells stay curved), and
/// a node on a shared edge or face is shared. The nodes of `mesh` keep their indices; cell c
/// becomes cells 8c, ..., 8c + 7; cell blocks, cell data, surfaces (each facet into the
/// children's faces on it) and node sets (a new node joins a set holding every corner it is
/// built from) are carried over as by mesh::refine_uniformly, whose hex8 meshes this leaves to
/// it (the same mesh, bit for bit). Throws InputError for a surface mesh that bounds no cell.
mesh::Mesh refine_uniformly(const mesh::Mesh& mesh);

/// `mesh` refined `levels` times (levels >= 0).
mesh::Mesh refine_uniformly(const mesh::Mesh& mesh, int levels);

} // namespace trifem::fe
