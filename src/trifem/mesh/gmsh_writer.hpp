// SPDX-License-Identifier: MIT
// Writer for Gmsh MSH 4.1 ASCII files that read_gmsh reads back into the same Mesh.
#pragma once

#include "trifem/mesh/mesh.hpp"

#include <filesystem>
#include <ostream>

namespace trifem::mesh {

/// Writes `mesh` as a Gmsh MSH 4.1 ASCII file that read_gmsh() reads back into the same mesh:
///
/// - nodes (tags 1..n) and cells (hex8, tet4, tet10, penta6, hex20 as Gmsh's elements 5, 4,
///   11, 6, 17, whose node orders are trifem's) in mesh order, coordinates in the shortest form
///   that reads back bitwise;
/// - every cell block as a physical volume: consecutive cells of one type in the same blocks
///   form one volume entity carrying those physical tags, so a cell may be in several blocks;
/// - every surface as a physical surface of the facets' types (tri3, tri6, quad4, quad8; a block
///   per type, in facet order within it), each written with the nodes of its facet (oriented
///   out of its cell);
/// - every node set that read_gmsh would not re-create by itself (the node set of a surface, or
///   of a cell block's nodes under the block's name) as a physical point group of one point
///   element per node.
///
/// read_gmsh also adds, for each cell block without a node set of its name, the node set of its
/// cells' nodes: the mesh read back is `mesh` plus these sets. Per-cell data is not written.
/// Throws InputError for what MSH cannot carry: a cell in no cell block (it would be read into
/// block "unassigned"), an empty node set, surface or cell block, or a name that is empty, has
/// surrounding blanks or a line break.
void write_gmsh(const Mesh& mesh, std::ostream& out);

/// write_gmsh() into `file` (created or overwritten); InputError if it cannot be written.
void write_gmsh(const Mesh& mesh, const std::filesystem::path& file);

} // namespace trifem::mesh
