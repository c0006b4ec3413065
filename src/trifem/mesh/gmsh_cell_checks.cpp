// SPDX-License-Identifier: MIT
#include "trifem/mesh/gmsh_cell_checks.hpp"

#include "trifem/mesh/hex_faces.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace trifem::mesh::detail {
namespace {

/// dx/dxi of the hex `cell` at the natural coordinates `xi` (column k: d/dxi_k).
Mat3 hex_jacobian(const Mesh& mesh, const Hex8& cell, const Vec3& xi) {
  Mat3 jac = Mat3::Zero();
  for (int a = 0; a < 8; ++a)
    for (int k = 0; k < 3; ++k) {
      Real dN = kHexNodeCoords[a][k] / 8.0; // dN_a/dxi_k
      for (int j = 0; j < 3; ++j)
        if (j != k)
          dN *= 1.0 + kHexNodeCoords[a][j] * xi[j];
      jac.col(k) += dN * mesh.node(cell[a]);
    }
  return jac;
}

/// Rejects a hex whose Jacobian determinant at the centre is negative or zero (inverted or
/// degenerate), or at one of the 2x2x2 Gauss points where the elements integrate (distorted).
void check_hex_orientation(const LineReader& in, const Mesh& mesh, std::int64_t tag,
                           const Hex8& cell, CellType type) {
  const Mat3 centre = hex_jacobian(mesh, cell, Vec3::Zero());
  const Real det = centre.determinant();
  const Real scale = centre.col(0).norm() * centre.col(1).norm() * centre.col(2).norm();
  TRIFEM_CHECK(det >= 0.0,
               "{}: {} element {} has negative volume (inverted node order; expected nodes "
               "0-3 counter-clockwise seen from nodes 4-7)",
               in.location(), name(type), tag);
  TRIFEM_CHECK(det > 1e-12 * scale, "{}: {} element {} is degenerate (zero volume)", in.location(),
               name(type), tag);
  const Real g = 1.0 / std::sqrt(3.0);
  for (int a = 0; a < 8; ++a) {
    const Vec3 xi(g * kHexNodeCoords[a][0], g * kHexNodeCoords[a][1], g * kHexNodeCoords[a][2]);
    TRIFEM_CHECK(
        hex_jacobian(mesh, cell, xi).determinant() > 1e-12 * scale,
        "{}: {} element {} is too distorted: its volume map folds near its local node {} (the "
        "Jacobian determinant is not positive at the Gauss point next to it; move the "
        "node or split the element)",
        in.location(), name(type), tag, a + 1);
  }
}

/// The Jacobian determinant of the map from the corners of a tet or a wedge at its centroid
/// and its scale (the product of the columns' lengths).
std::pair<Real, Real> corner_jacobian(const Mesh& mesh, CellType type,
                                      std::span<const Index> cell) {
  auto x = [&](int a) { return mesh.node(cell[static_cast<std::size_t>(a)]); };
  Mat3 jac;
  if (type == CellType::Penta6) { // triangle (0,1,2) x [-1,1] at (1/3, 1/3, 0)
    jac.col(0) = 0.5 * (x(1) - x(0) + x(4) - x(3));
    jac.col(1) = 0.5 * (x(2) - x(0) + x(5) - x(3));
    jac.col(2) = (x(3) + x(4) + x(5) - x(0) - x(1) - x(2)) / 6.0;
  } else {
    jac << x(1) - x(0), x(2) - x(0), x(3) - x(0);
  }
  return {jac.determinant(), jac.col(0).norm() * jac.col(1).norm() * jac.col(2).norm()};
}

/// Rejects a tet or wedge whose corners are in the inverted order or degenerate.
void check_corner_orientation(const LineReader& in, const Mesh& mesh, std::int64_t tag,
                              CellType type, std::span<const Index> cell) {
  const auto [det, scale] = corner_jacobian(mesh, type, cell);
  TRIFEM_CHECK(det >= 0.0,
               "{}: {} element {} has negative volume (inverted node order; expected Gmsh's: {})",
               in.location(), name(type), tag,
               type == CellType::Penta6 ? "nodes 0-2 counter-clockwise seen from nodes 3-5"
                                        : "nodes 0-2 counter-clockwise seen from node 3");
  TRIFEM_CHECK(det > 1e-12 * scale, "{}: {} element {} is degenerate (zero volume)", in.location(),
               name(type), tag);
}

} // namespace

void check_cell_orientation(const LineReader& in, const Mesh& mesh, std::int64_t tag, CellType type,
                            std::span<const Index> cell) {
  if (type != CellType::Hex8 && type != CellType::Hex20)
    return check_corner_orientation(in, mesh, tag, type, cell);
  Hex8 corners;
  std::copy_n(cell.begin(), 8, corners.begin());
  check_hex_orientation(in, mesh, tag, corners, type);
}

} // namespace trifem::mesh::detail
