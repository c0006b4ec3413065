// SPDX-License-Identifier: MIT
// Uniform refinement of a hex8 mesh (each cell into eight), for mesh-convergence studies.
#pragma once

#include "trifem/mesh/mesh.hpp"

namespace trifem::mesh {

/// The mesh with every hex8 split into eight by its edge midpoints, face centres and centre,
/// placed by the cell's trilinear map: the refined mesh covers exactly the same region, and a
/// node shared by neighbouring cells stays shared. The nodes of `mesh` keep their indices; cell
/// c becomes cells 8c, ..., 8c + 7. Named sets are carried over:
/// - cell blocks and cell data: a child inherits its parent's membership and values;
/// - surfaces: each facet becomes the four facets of the children on its face;
/// - other node sets: a new node belongs to a set when every corner it is built from (the two
///   of its edge, the four of its face, the eight of its cell) belongs to it, so a set of the
///   nodes of a face, an edge or a block gains the new nodes on it.
/// Throws InputError if the refined mesh would have more nodes or cells than an Index holds.
Mesh refine_uniformly(const Mesh& mesh);

/// `mesh` refined `levels` times (levels >= 0; each level multiplies the cells by eight).
Mesh refine_uniformly(const Mesh& mesh, int levels);

} // namespace trifem::mesh
