// SPDX-License-Identifier: MIT
// Current-configuration geometry of a bilinear quad4 contact facet at one point of the reference
// square: position, tangents, twist and unit normal (docs/theory/contact.md §2.1).
#pragma once

#include "trifem/fe/hex8.hpp"

#include <array>

namespace trifem::contact {

/// Geometry of the bilinear facet x(ξ) = Σ_a N_a(ξ) x_a at one point ξ = (ξ^1, ξ^2) of the
/// reference square [-1,1]² (nodes counter-clockwise from (-1,-1), right-hand rule = outward).
struct FacetPoint {
  fe::QuadShape N;       ///< N_a(ξ)
  fe::QuadShapeGrad dN;  ///< N_{a,α}(ξ) (row a, column α)
  Vec3 x;                ///< x(ξ)
  std::array<Vec3, 2> t; ///< covariant tangents t_α = ∂x/∂ξ^α
  Vec3 x12;              ///< twist x_{,12} = Σ_a x_a ξ_a η_a / 4; x_{,11} = x_{,22} = 0
  Vec3 normal;           ///< n = t_1 × t_2 / |t_1 × t_2| (zero if the facet is degenerate)
  Real jacobian = 0;     ///< |t_1 × t_2| (area scale: da = jacobian dξ^1 dξ^2)

  /// Metric a_αβ = t_α · t_β.
  Mat2 metric() const;
  /// Curvature b_αβ = n · x_{,αβ}: b_11 = b_22 = 0, b_12 = b_21 = n · x_{,12}.
  Mat2 curvature() const;
};

/// Evaluates the facet with current nodal coordinates X (row a = x_a) at ξ. ξ may lie outside
/// [-1,1]² (the bilinear extension is used).
FacetPoint evaluate_facet(const fe::QuadCoords& X, const Vec2& xi);

/// Reference coordinates of facet corner a (a = 0..3): (-1,-1), (1,-1), (1,1), (-1,1).
Vec2 facet_corner(int a);

/// Diameter of the facet: the longest of its four edges and two diagonals (length unit of X).
Real facet_size(const fe::QuadCoords& X);

} // namespace trifem::contact
