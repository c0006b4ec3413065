// SPDX-License-Identifier: MIT
#include "trifem/fe/point_location.hpp"

#include "trifem/fe/hex8.hpp"

#include <cmath>

namespace trifem::fe {
namespace {

/// A point is inside if every |xi| <= 1 + kInside (a relative distance to the faces).
constexpr Real kInside = 1e-8;
/// Natural coordinates this close to -1, 0 or 1 are snapped.
constexpr Real kSnap = 1e-10;

Real snap(Real xi) {
  for (Real v : {-1.0, 0.0, 1.0})
    if (std::abs(xi - v) <= kSnap)
      return v;
  return xi;
}

/// True if X lies in the bounding box of the cell, widened by kInside of its size.
bool in_bounding_box(const HexCoords& nodes, const Vec3& X) {
  const Vec3 lo = nodes.colwise().minCoeff().transpose(), hi = nodes.colwise().maxCoeff();
  const Real margin = kInside * (hi - lo).norm();
  return (X.array() >= lo.array() - margin).all() && (X.array() <= hi.array() + margin).all();
}

} // namespace

std::optional<Vec3> natural_coordinates(const HexCoords& nodes, const Vec3& X) {
  Vec3 xi = Vec3::Zero();
  for (int it = 0; it < 50; ++it) {
    const Vec3 residual = nodes.transpose() * hex8_shape(xi) - X;
    const Mat3 jacobian = nodes.transpose() * hex8_shape_grad(xi);
    if (!(std::abs(jacobian.determinant()) > 0.0))
      return std::nullopt;
    const Vec3 step = jacobian.lu().solve(residual);
    xi -= step;
    if (!xi.allFinite() || xi.cwiseAbs().maxCoeff() > 10.0)
      return std::nullopt;    // far outside: the trilinear map is not invertible there
    if (step.norm() <= 1e-14) // natural coordinates are of order 1
      return xi;
  }
  return std::nullopt;
}

std::optional<CellPoint> locate_point(const mesh::Mesh& mesh, const Vec3& X) {
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const HexCoords nodes = cell_coordinates(mesh, c);
    if (!in_bounding_box(nodes, X))
      continue;
    const std::optional<Vec3> xi = natural_coordinates(nodes, X);
    if (!xi || xi->cwiseAbs().maxCoeff() > 1.0 + kInside)
      continue;
    CellPoint p{c, xi->cwiseMax(-1.0).cwiseMin(1.0)};
    for (int k = 0; k < 3; ++k)
      p.xi[k] = snap(p.xi[k]);
    return p;
  }
  return std::nullopt;
}

} // namespace trifem::fe
