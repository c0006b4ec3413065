// SPDX-License-Identifier: MIT
// Small generated meshes of the explicit-dynamics tests and examples: a thick spherical shell
// octant (three mapped blocks of a cubed sphere) and Cook's membrane (a mapped box).
#pragma once

#include "trifem/core/error.hpp"
#include "trifem/mesh/box.hpp"
#include "trifem/mesh/mesh.hpp"

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <string>

namespace trifem::test {

/// Octant 0 ≤ x, y, z of the thick spherical shell A ≤ |X| ≤ B.
struct ShellOctantSpec {
  std::string name = "shell";
  Real inner = 1.0;   ///< A [mm]
  Real outer = 2.0;   ///< B [mm]
  int divisions = 4;  ///< cells along each edge of the three cube-face patches (3 n² per layer)
  int layers = 4;     ///< cells through the thickness
  Real grading = 1.0; ///< ratio of the outermost to the innermost layer thickness
};

/// Cook's membrane: the tapered panel (0,0), (48,44), (48,60), (0,44) [mm], extruded by
/// `thickness` in z.
struct CookSpec {
  std::string name = "cook";
  int nx = 8;           ///< cells along the length (x)
  int ny = 8;           ///< cells across the height (y)
  int nz = 1;           ///< cells through the thickness
  Real thickness = 1.0; ///< [mm]
};

/// A copy of `mesh` with every node moved to map(X) (cells, node sets, surfaces and cell blocks
/// kept). The map must preserve orientation (positive Jacobian) so facets stay outward.
inline mesh::Mesh transform_nodes(const mesh::Mesh& in,
                                  const std::function<Vec3(const Vec3&)>& map) {
  mesh::Mesh out;
  for (const Vec3& X : in.nodes())
    out.add_node(map(X));
  for (Index c = 0; c < in.num_cells(); ++c)
    out.add_cell(in.cell_type(c), in.cell_nodes(c));
  for (const auto& [name, nodes] : in.node_sets())
    if (!in.has_surface(name))
      out.add_node_set(name, nodes);
  for (const auto& [name, surface] : in.surfaces())
    out.add_surface(name, surface);
  for (const auto& [name, cells] : in.cell_blocks())
    out.add_cell_block(name, cells);
  return out;
}

namespace detail {

/// Lattice point (i, j, k) with max = n on the cube-face octant; unique id per point.
using Lattice = std::array<int, 3>;

/// Unit direction of a lattice point: equiangular map tan(π/4 · i/n), then normalised.
inline Vec3 direction(const Lattice& p, int n) {
  Vec3 d;
  for (int k = 0; k < 3; ++k)
    d[k] = std::tan(0.25 * std::numbers::pi * p[k] / n);
  return d.normalized();
}

/// The quads of the three patches, each ordered so that its normal points outward (+r).
inline std::vector<std::array<Lattice, 4>> patch_quads(int n) {
  std::vector<std::array<Lattice, 4>> quads;
  for (int s = 0; s < n; ++s)
    for (int t = 0; t < n; ++t) {
      quads.push_back({{{n, s, t}, {n, s + 1, t}, {n, s + 1, t + 1}, {n, s, t + 1}}});
      quads.push_back({{{t, n, s}, {t, n, s + 1}, {t + 1, n, s + 1}, {t + 1, n, s}}});
      quads.push_back({{{s, t, n}, {s + 1, t, n}, {s + 1, t + 1, n}, {s, t + 1, n}}});
    }
  return quads;
}

inline std::vector<Real> layer_radii(const ShellOctantSpec& spec) {
  const std::vector<Real> x =
      mesh::graded_coordinates(spec.outer - spec.inner, spec.layers, spec.grading);
  std::vector<Real> r(x.size());
  for (std::size_t i = 0; i < x.size(); ++i)
    r[i] = spec.inner + x[i];
  return r;
}

/// Node sets `<name>.x0/.y0/.z0` (lattice coordinate k = 0 on every layer), `<name>.all` and
/// the cell block `<name>`.
inline void add_plane_and_block_sets(const ShellOctantSpec& spec,
                                     const std::map<Lattice, Index>& surface_id, mesh::Mesh& m) {
  const Index ns = static_cast<Index>(surface_id.size());
  for (int k = 0; k < 3; ++k) {
    std::vector<Index> plane;
    for (const auto& [p, id] : surface_id)
      if (p[k] == 0)
        for (int layer = 0; layer <= spec.layers; ++layer)
          plane.push_back(layer * ns + id);
    m.add_node_set(spec.name + "." + "xyz"[k] + "0", plane);
  }
  std::vector<Index> all(m.num_nodes()), cells(m.num_cells());
  for (Index i = 0; i < m.num_nodes(); ++i)
    all[i] = i;
  for (Index c = 0; c < m.num_cells(); ++c)
    cells[c] = c;
  m.add_node_set(spec.name + ".all", all);
  m.add_cell_block(spec.name, cells);
}

} // namespace detail

/// Cubed-sphere octant: the three faces x = 1, y = 1, z = 1 of the unit cube are divided into
/// n x n squares with equiangular spacing (tan(π/4 · i/n)), projected radially on the sphere and
/// extruded through the thickness, so every symmetry face lies exactly in a coordinate plane.
/// Named sets: surfaces `<name>.inner`, `<name>.outer`; node sets `<name>.x0`, `<name>.y0`,
/// `<name>.z0` (nodes on the symmetry planes), `<name>.all`; cell block `<name>`.
inline mesh::Mesh make_shell_octant(const ShellOctantSpec& spec) {
  using namespace detail;
  TRIFEM_CHECK(spec.inner > 0.0 && spec.outer > spec.inner,
               "shell octant: need 0 < inner < outer (got {}, {})", spec.inner, spec.outer);
  TRIFEM_CHECK(spec.divisions >= 1 && spec.layers >= 1,
               "shell octant: divisions and layers must be >= 1");
  const int n = spec.divisions;
  const auto quads = patch_quads(n);
  std::map<Lattice, Index> surface_id; // lattice point → index on one spherical layer
  for (const auto& q : quads)
    for (const Lattice& p : q)
      surface_id.try_emplace(p, static_cast<Index>(surface_id.size()));
  const Index ns = static_cast<Index>(surface_id.size());
  std::vector<Vec3> dirs(ns);
  for (const auto& [p, id] : surface_id)
    dirs[id] = direction(p, n);
  const std::vector<Real> radii = layer_radii(spec);
  mesh::Mesh m;
  for (Real r : radii)
    for (const Vec3& d : dirs)
      m.add_node(r * d);
  std::vector<std::array<Index, 4>> inner, outer;
  for (int layer = 0; layer < spec.layers; ++layer)
    for (const auto& q : quads) {
      mesh::Hex8 h;
      for (int a = 0; a < 4; ++a) {
        h[a] = layer * ns + surface_id.at(q[a]);
        h[a + 4] = h[a] + ns;
      }
      m.add_cell(h);
      if (layer == 0)
        inner.push_back({h[0], h[1], h[2], h[3]});
      if (layer == spec.layers - 1)
        outer.push_back({h[4], h[5], h[6], h[7]});
    }
  m.add_surface(spec.name + ".inner", {m.find_facets(inner)});
  m.add_surface(spec.name + ".outer", {m.find_facets(outer)});
  add_plane_and_block_sets(spec, surface_id, m);
  return m;
}

/// A box [0,1]² x [0,t] mapped by (ξ, η, z) → (48 ξ, 44 ξ + η (44 − 28 ξ), z); the box's sets
/// `<name>.xmin` (clamped edge, x = 0), `<name>.xmax` (loaded edge, x = 48), ..., `<name>.all`.
inline mesh::Mesh make_cook_membrane(const CookSpec& spec) {
  TRIFEM_CHECK(spec.thickness > 0.0, "Cook membrane: thickness must be > 0");
  mesh::BoxSpec box;
  box.name = spec.name;
  box.size = Vec3(1.0, 1.0, spec.thickness);
  box.divisions = {spec.nx, spec.ny, spec.nz};
  return transform_nodes(mesh::make_box(box), [](const Vec3& X) {
    return Vec3(48.0 * X[0], 44.0 * X[0] + X[1] * (44.0 - 28.0 * X[0]), X[2]);
  });
}

} // namespace trifem::test
