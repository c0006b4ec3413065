// SPDX-License-Identifier: MIT
#include "trifem/mesh/box.hpp"

#include "trifem/core/error.hpp"
#include "trifem/mesh/convert_cells.hpp"
#include "trifem/mesh/hex_faces.hpp"

#include <cmath>

namespace trifem::mesh {
namespace {

void validate(const BoxSpec& spec) {
  for (int d = 0; d < 3; ++d) {
    TRIFEM_CHECK(spec.size[d] > 0.0 && std::isfinite(spec.size[d]),
                 "box '{}': size[{}] = {} must be a positive length", spec.name, d, spec.size[d]);
    TRIFEM_CHECK(spec.divisions[d] >= 1, "box '{}': divisions[{}] = {} must be >= 1", spec.name, d,
                 spec.divisions[d]);
    TRIFEM_CHECK(spec.grading[d] > 0.0 && std::isfinite(spec.grading[d]),
                 "box '{}': grading[{}] = {} must be > 0", spec.name, d, spec.grading[d]);
  }
}

/// Surface name suffixes in the order (direction, side).
constexpr const char* kSideNames[3][2] = {{"xmin", "xmax"}, {"ymin", "ymax"}, {"zmin", "zmax"}};
/// Local face of a hex8 whose outward normal is -e_d (side 0) or +e_d (side 1).
constexpr int kSideFace[3][2] = {{5, 3}, {2, 4}, {0, 1}};

} // namespace

std::vector<Real> graded_coordinates(Real length, int n, Real grading) {
  std::vector<Real> x(n + 1, 0.0);
  // cell lengths h_i = h_0 r^i with r^(n-1) = grading
  const Real r = n > 1 ? std::pow(grading, 1.0 / (n - 1)) : 1.0;
  Real sum = 0.0, h = 1.0;
  for (int i = 0; i < n; ++i, h *= r)
    sum += h;
  h = length / sum;
  for (int i = 0; i < n; ++i, h *= r)
    x[i + 1] = x[i] + h;
  x[n] = length;
  return x;
}

Mesh make_box(const BoxSpec& spec) {
  validate(spec);
  const int nx = spec.divisions[0], ny = spec.divisions[1], nz = spec.divisions[2];
  std::array<std::vector<Real>, 3> coords;
  for (int d = 0; d < 3; ++d)
    coords[d] = graded_coordinates(spec.size[d], spec.divisions[d], spec.grading[d]);

  Mesh mesh;
  auto node_id = [&](int i, int j, int k) { return (k * (ny + 1) + j) * (nx + 1) + i; };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        mesh.add_node(spec.origin + Vec3(coords[0][i], coords[1][j], coords[2][k]));

  std::array<Surface, 6> sides;
  std::vector<Index> block;
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        Hex8 cell;
        for (int a = 0; a < 8; ++a) {
          const auto& r = kHexNodeCoords[a];
          cell[a] = node_id(i + (r[0] > 0), j + (r[1] > 0), k + (r[2] > 0));
        }
        const Index c = mesh.add_cell(cell);
        block.push_back(c);
        const std::array<int, 3> ijk{i, j, k};
        for (int d = 0; d < 3; ++d) {
          for (int side = 0; side < 2; ++side) {
            if (ijk[d] != (side == 0 ? 0 : spec.divisions[d] - 1))
              continue;
            Facet f{.cell = c, .local_face = kSideFace[d][side]};
            for (int a = 0; a < 4; ++a)
              f.nodes[a] = cell[kHexFaces[f.local_face][a]];
            sides[2 * d + side].facets.push_back(f);
          }
        }
      }
    }
  }
  mesh.add_cell_block(spec.name, std::move(block));
  for (int d = 0; d < 3; ++d)
    for (int side = 0; side < 2; ++side)
      mesh.add_surface(spec.name + "." + kSideNames[d][side], std::move(sides[2 * d + side]));
  std::vector<Index> all(mesh.num_nodes());
  for (Index n = 0; n < mesh.num_nodes(); ++n)
    all[n] = n;
  mesh.add_node_set(spec.name + ".all", std::move(all));
  return spec.cell == CellType::Hex8 ? mesh : convert_cells(mesh, spec.cell);
}

} // namespace trifem::mesh
