// SPDX-License-Identifier: MIT
// Small generated meshes of the explicit-dynamics benchmarks: a thick spherical shell octant
// (three mapped blocks of a cubed sphere) and Cook's membrane (a mapped box).
#pragma once

#include "trifem/mesh/mesh.hpp"

#include <functional>
#include <string>

namespace trifem::explicit_dynamics {

/// A copy of `mesh` with every node moved to map(X) (cells, node sets, surfaces and cell blocks
/// kept). The map must preserve orientation (positive Jacobian) so facets stay outward.
mesh::Mesh transform_nodes(const mesh::Mesh& mesh, const std::function<Vec3(const Vec3&)>& map);

/// Octant 0 ≤ x, y, z of the thick spherical shell A ≤ |X| ≤ B.
struct ShellOctantSpec {
  std::string name = "shell";
  Real inner = 1.0;   ///< A [mm]
  Real outer = 2.0;   ///< B [mm]
  int divisions = 4;  ///< cells along each edge of the three cube-face patches (3 n² per layer)
  int layers = 4;     ///< cells through the thickness
  Real grading = 1.0; ///< ratio of the outermost to the innermost layer thickness
};

/// Cubed-sphere octant: the three faces x = 1, y = 1, z = 1 of the unit cube are divided into
/// n x n squares with equiangular spacing (tan(π/4 · i/n)), projected radially on the sphere and
/// extruded through the thickness, so every symmetry face lies exactly in a coordinate plane.
/// Named sets: surfaces `<name>.inner`, `<name>.outer`; node sets `<name>.x0`, `<name>.y0`,
/// `<name>.z0` (nodes on the symmetry planes), `<name>.all`; cell block `<name>`.
mesh::Mesh make_shell_octant(const ShellOctantSpec& spec);

/// Cook's membrane: the tapered panel (0,0), (48,44), (48,60), (0,44) [mm], extruded by
/// `thickness` in z.
struct CookSpec {
  std::string name = "cook";
  int nx = 8;           ///< cells along the length (x)
  int ny = 8;           ///< cells across the height (y)
  int nz = 1;           ///< cells through the thickness
  Real thickness = 1.0; ///< [mm]
};

/// A box [0,1]² x [0,t] mapped by (ξ, η, z) → (48 ξ, 44 ξ + η (44 − 28 ξ), z); the box's sets
/// `<name>.xmin` (clamped edge, x = 0), `<name>.xmax` (loaded edge, x = 48), ..., `<name>.all`.
mesh::Mesh make_cook_membrane(const CookSpec& spec);

} // namespace trifem::explicit_dynamics
