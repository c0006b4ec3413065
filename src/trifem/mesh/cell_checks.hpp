// SPDX-License-Identifier: MIT
// Shape checks of the cells a reader reads (Gmsh, FEBio): inverted, degenerate or folded cells.
#pragma once

#include "trifem/mesh/mesh.hpp"

#include <span>
#include <string>

namespace trifem::mesh {

/// What is wrong with a cell of `type` whose nodes are `cell` (in the order of cell_type.hpp),
/// as the end of a sentence naming the cell ("has negative volume (inverted node order;
/// expected ...)", "is degenerate (zero volume)", "is too distorted: ...", "has its mid-edge
/// node ... off the edge ..."), or empty. The corners are checked: their order, a zero volume,
/// and for a hex8 or hex20 the fold of the trilinear corner map at one of the 2x2x2 Gauss
/// points; and each mid-edge node of a tet10 or hex20 lies within a quarter of its edge's
/// length of the edge's midpoint. (A curved quadratic cell folding inside is found where the
/// cells are integrated.)
std::string cell_shape_problem(const Mesh& mesh, CellType type, std::span<const Index> cell);

} // namespace trifem::mesh
