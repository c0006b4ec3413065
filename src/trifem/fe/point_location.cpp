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

/// Snaps the natural coordinates of a cell other than a hex8 to 0, 1/2, 1 and −1.
Real snap_any(Real xi) {
  for (Real v : {-1.0, 0.0, 0.5, 1.0})
    if (std::abs(xi - v) <= kSnap)
      return v;
  return xi;
}

/// True if xi lies in the reference domain of `type`, widened by kInside.
bool inside(mesh::CellType type, const Vec3& xi) {
  switch (type) {
  case mesh::CellType::Tet4:
  case mesh::CellType::Tet10:
    return xi.minCoeff() >= -kInside && xi.sum() <= 1.0 + kInside;
  case mesh::CellType::Penta6:
    return xi[0] >= -kInside && xi[1] >= -kInside && xi[0] + xi[1] <= 1.0 + kInside &&
           std::abs(xi[2]) <= 1.0 + kInside;
  default:
    return xi.cwiseAbs().maxCoeff() <= 1.0 + kInside;
  }
}

/// The cell point of X in cell c of a type other than hex8, or nothing if it is outside.
std::optional<CellPoint> locate_in_cell(const mesh::Mesh& mesh, Index c, const Vec3& X) {
  const ReferenceCell& reference = reference_cell(mesh.cell_type(c));
  const std::span<const Index> nodes = mesh.cell_nodes(c);
  CellNodeCoords coords(static_cast<Index>(nodes.size()), 3);
  for (std::size_t a = 0; a < nodes.size(); ++a)
    coords.row(static_cast<Index>(a)) = mesh.node(nodes[a]).transpose();
  const Vec3 lo = coords.colwise().minCoeff().transpose(), hi = coords.colwise().maxCoeff();
  const Real margin = kInside * (hi - lo).norm();
  if ((X.array() < lo.array() - margin).any() || (X.array() > hi.array() + margin).any())
    return std::nullopt;
  const std::optional<Vec3> xi = natural_coordinates(reference, coords, X);
  if (!xi || !inside(mesh.cell_type(c), *xi))
    return std::nullopt;
  CellPoint p{c, *xi};
  for (int k = 0; k < 3; ++k)
    p.xi[k] = snap_any(p.xi[k]);
  return p;
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

std::optional<Vec3> natural_coordinates(const ReferenceCell& reference, const CellNodeCoords& nodes,
                                        const Vec3& X) {
  Vec3 xi = reference.nodes().colwise().mean().transpose(); // the reference centroid
  for (int it = 0; it < 50; ++it) {
    const Vec3 residual = nodes.transpose() * reference.shape(xi) - X;
    const Mat3 jacobian = nodes.transpose() * reference.shape_grad(xi);
    if (!(std::abs(jacobian.determinant()) > 0.0))
      return std::nullopt;
    const Vec3 step = jacobian.lu().solve(residual);
    xi -= step;
    if (!xi.allFinite() || xi.cwiseAbs().maxCoeff() > 10.0)
      return std::nullopt;
    if (step.norm() <= 1e-14)
      return xi;
  }
  return std::nullopt;
}

std::optional<CellPoint> locate_point(const mesh::Mesh& mesh, const Vec3& X) {
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    if (mesh.cell_type(c) != mesh::CellType::Hex8) {
      if (const std::optional<CellPoint> p = locate_in_cell(mesh, c, X))
        return p;
      continue;
    }
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
