// SPDX-License-Identifier: MIT
// Orientation checks of the cells the Gmsh reader reads (internal to the mesh library).
#pragma once

#include "trifem/mesh/gmsh_line_reader.hpp"
#include "trifem/mesh/mesh.hpp"

#include <cstdint>
#include <span>

namespace trifem::mesh::detail {

/// Rejects, naming the reader's location, the element tag and the family, a cell of `type`
/// whose corners are in the inverted order or degenerate; a hex8 or hex20 also if its
/// trilinear corner map folds at one of the 2x2x2 Gauss points (distorted). (A curved
/// quadratic cell folding inside is found where the cells are integrated.)
void check_cell_orientation(const LineReader& in, const Mesh& mesh, std::int64_t tag, CellType type,
                            std::span<const Index> cell);

} // namespace trifem::mesh::detail
