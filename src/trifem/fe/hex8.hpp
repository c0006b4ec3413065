// SPDX-License-Identifier: MIT
// Trilinear hex8 and bilinear quad4 shape functions and the reference-configuration geometry
// of a hex8 cell at its 2x2x2 Gauss points.
#pragma once

#include "trifem/fe/quadrature.hpp"
#include "trifem/mesh/mesh.hpp"

#include <array>
#include <optional>

namespace trifem::fe {

using HexShape = Eigen::Matrix<Real, 8, 1>;
using HexShapeGrad = Eigen::Matrix<Real, 8, 3>; ///< row a = dN_a/d(xi, eta, zeta) or d/dX
using HexCoords = Eigen::Matrix<Real, 8, 3>;    ///< row a = coordinates of node a
using QuadShape = Eigen::Matrix<Real, 4, 1>;
using QuadShapeGrad = Eigen::Matrix<Real, 4, 2>;
using QuadCoords = Eigen::Matrix<Real, 4, 3>;

/// N_a(xi) = (1 + xi xi_a)(1 + eta eta_a)(1 + zeta zeta_a)/8.
HexShape hex8_shape(const Vec3& xi);
/// dN_a/dxi.
HexShapeGrad hex8_shape_grad(const Vec3& xi);
/// N_a(xi) = (1 + xi xi_a)(1 + eta eta_a)/4 with nodes counter-clockwise from (-1,-1).
QuadShape quad4_shape(const Vec2& xi);
/// dN_a/dxi.
QuadShapeGrad quad4_shape_grad(const Vec2& xi);

/// Reference-configuration values of a hex8 cell at its 8 Gauss points (total Lagrangian).
struct HexGeometry {
  std::array<HexShapeGrad, 8> dN_dX; ///< gradients with respect to reference coordinates
  std::array<Real, 8> dV;            ///< det(dX/dxi) * weight
};

/// The reference coordinates of the nodes of cell `c` of `mesh`.
HexCoords cell_coordinates(const mesh::Mesh& mesh, Index c);

/// Geometry of the cell with nodal coordinates X; empty if det(dX/dxi) <= 0 at a Gauss point
/// (inverted or degenerate cell).
std::optional<HexGeometry> hex8_geometry(const HexCoords& X);

/// A corner of a hex8 cell whose volume map has turned over: `ratio` = det(dx/dxi) / det(dX/dxi)
/// at the node `corner` (0-7), negative.
struct ReversedCorner {
  int corner = -1;
  Real ratio = 0.0;
};

/// The corner of a hex8 cell (reference coordinates `X`, current `x`) whose volume map has
/// turned over the most, if any has by more than `tolerance` of its reference measure
/// (det(dx/dxi) < -tolerance det(dX/dxi) at the node). A cell turned inside out or everted (a
/// body pushed through its own support) has such corners even where det(dx/dxi) > 0 at every
/// Gauss point; a coarse cell under strong compression may fold a corner slightly (a few
/// percent) and unfold it again, which a tolerance of the order of 1 lets pass.
std::optional<ReversedCorner> hex8_reversed_corner(const HexCoords& X, const HexCoords& x,
                                                   Real tolerance);

} // namespace trifem::fe
