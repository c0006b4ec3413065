// SPDX-License-Identifier: MIT
#include "trifem/mesh/cell_checks.hpp"

#include "trifem/mesh/hex_faces.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <utility>

namespace trifem::mesh {
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

/// The problem of a hex whose Jacobian determinant at the centre is negative or zero (inverted
/// or degenerate), or at one of the 2x2x2 Gauss points where the elements integrate
/// (distorted).
std::string hex_problem(const Mesh& mesh, const Hex8& cell) {
  const Mat3 centre = hex_jacobian(mesh, cell, Vec3::Zero());
  const Real det = centre.determinant();
  const Real scale = centre.col(0).norm() * centre.col(1).norm() * centre.col(2).norm();
  if (det < 0.0)
    return "has negative volume (inverted node order; expected nodes 0-3 counter-clockwise "
           "seen from nodes 4-7)";
  if (!(det > 1e-12 * scale))
    return "is degenerate (zero volume)";
  const Real g = 1.0 / std::sqrt(3.0);
  for (int a = 0; a < 8; ++a) {
    const Vec3 xi(g * kHexNodeCoords[a][0], g * kHexNodeCoords[a][1], g * kHexNodeCoords[a][2]);
    if (!(hex_jacobian(mesh, cell, xi).determinant() > 1e-12 * scale))
      return fmt::format("is too distorted: its volume map folds near its local node {} (the "
                         "Jacobian determinant is not positive at the Gauss point next to it; "
                         "move the node or split the element)",
                         a + 1);
  }
  return {};
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

/// The problem of a tet or wedge whose corners are in the inverted order or degenerate.
std::string corner_problem(const Mesh& mesh, CellType type, std::span<const Index> cell) {
  const auto [det, scale] = corner_jacobian(mesh, type, cell);
  if (det < 0.0)
    return fmt::format("has negative volume (inverted node order; expected {})",
                       type == CellType::Penta6 ? "nodes 0-2 counter-clockwise seen from nodes 3-5"
                                                : "nodes 0-2 counter-clockwise seen from node 3");
  if (!(det > 1e-12 * scale))
    return "is degenerate (zero volume)";
  return {};
}

/// The problem of a quadratic cell whose mid-edge node is off its edge: farther from the edge's
/// midpoint than a quarter of the edge (a curved edge bends less; a node of another edge, as
/// in a node list of another program's order, is farther).
std::string mid_edge_problem(const Mesh& mesh, CellType type, std::span<const Index> cell) {
  const std::span<const Edge> mids = mid_edges(type);
  for (std::size_t m = 0; m < mids.size(); ++m) {
    const Vec3& a = mesh.node(cell[static_cast<std::size_t>(mids[m][0])]);
    const Vec3& b = mesh.node(cell[static_cast<std::size_t>(mids[m][1])]);
    const std::size_t local = static_cast<std::size_t>(num_corners(type)) + m;
    if ((mesh.node(cell[local]) - 0.5 * (a + b)).norm() > 0.25 * (b - a).norm())
      return fmt::format("has its mid-edge node {} off the edge of its nodes {} and {} (farther "
                         "from the edge's midpoint than a quarter of the edge): the node order "
                         "is not that of a {}",
                         local + 1, mids[m][0] + 1, mids[m][1] + 1, name(type));
  }
  return {};
}

} // namespace

std::string cell_shape_problem(const Mesh& mesh, CellType type, std::span<const Index> cell) {
  std::string problem;
  if (type != CellType::Hex8 && type != CellType::Hex20) {
    problem = corner_problem(mesh, type, cell);
  } else {
    Hex8 corners;
    std::copy_n(cell.begin(), 8, corners.begin());
    problem = hex_problem(mesh, corners);
  }
  return problem.empty() ? mid_edge_problem(mesh, type, cell) : problem;
}

} // namespace trifem::mesh
