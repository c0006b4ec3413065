// SPDX-License-Identifier: MIT
// Structured box generator (hex8 cells, or cells of another family made from them).
#pragma once

#include "trifem/mesh/mesh.hpp"

#include <array>
#include <string>

namespace trifem::mesh {

/// Parameters of a structured box.
struct BoxSpec {
  std::string name = "box";   ///< block name; surfaces are "<name>.xmin" ... "<name>.zmax"
  Vec3 origin = Vec3::Zero(); ///< corner with the smallest coordinates [length]
  Vec3 size = Vec3::Ones();   ///< edge lengths [length], all > 0
  std::array<int, 3> divisions{1, 1, 1}; ///< cells per direction, all >= 1
  /// Geometric grading per direction: ratio of the last to the first cell length (> 0; 1 =
  /// uniform).
  Vec3 grading = Vec3::Ones();
  /// The cells: hex8, or those each hex8 becomes (convert_cells.hpp).
  CellType cell = CellType::Hex8;
};

/// Builds the box: one cell block `name`, six outward-oriented surfaces
/// `name.xmin, name.xmax, name.ymin, name.ymax, name.zmin, name.zmax` (each also a node set),
/// and the node set `name.all` (with cells other than hex8: their facets on the faces,
/// convert_cells). Throws InputError on invalid parameters.
Mesh make_box(const BoxSpec& spec);

/// The 1-D node coordinates of a graded division of [0, length] into n cells.
std::vector<Real> graded_coordinates(Real length, int n, Real grading);

} // namespace trifem::mesh
