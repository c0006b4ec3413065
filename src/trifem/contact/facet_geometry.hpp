// SPDX-License-Identifier: MIT
// Current-configuration geometry of a contact facet of any family (tri3, tri6, quad4, quad8) at
// one point of its reference facet: position, tangents, second derivatives and unit normal
// (docs/theory/contact.md §2.1), and the reference domain's centre, corners and edges.
#pragma once

#include "trifem/fe/reference_element.hpp"

#include <array>

namespace trifem::contact {

/// Current coordinates of a facet's nodes (row a = x_a, corners then mid-edge nodes).
using FacetNodePositions = Eigen::Matrix<Real, Eigen::Dynamic, 3, 0, fe::kMaxFacetNodes, 3>;
/// Values of a field at a facet's nodes (row a), K components.
template <int K>
using FacetNodeValues = Eigen::Matrix<Real, Eigen::Dynamic, K, 0, fe::kMaxFacetNodes, K>;

/// A facet in a configuration: its reference facet (shape functions, rule) and the current
/// coordinates of its nodes.
struct FacetCoords {
  const fe::ReferenceFacet* reference = nullptr;
  FacetNodePositions x;

  FacetCoords(mesh::FacetType type, FacetNodePositions positions)
      : reference(&fe::reference_facet(type)), x(std::move(positions)) {}
  mesh::FacetType type() const { return reference->type(); }
  int num_nodes() const { return static_cast<int>(x.rows()); }
  int num_corners() const { return mesh::num_corners(type()); }
  Vec3 node(int a) const { return x.row(a).transpose(); }
};

/// Geometry of the facet x(ξ) = Σ_a N_a(ξ) x_a at one point ξ = (ξ^1, ξ^2) of its reference
/// facet (the square [-1,1]² or the triangle ξ^1, ξ^2 ≥ 0, ξ^1 + ξ^2 ≤ 1; nodes counter-clockwise
/// seen from outside: t_1 × t_2 points out of the body).
struct FacetPoint {
  fe::FacetShapeValues N;     ///< N_a(ξ)
  fe::FacetShapeGrads dN;     ///< N_{a,α}(ξ) (row a, column α)
  fe::FacetShapeHessians d2N; ///< (N_{a,11}, N_{a,22}, N_{a,12}) (row a)
  Vec3 x;                     ///< x(ξ)
  std::array<Vec3, 2> t;      ///< covariant tangents t_α = ∂x/∂ξ^α
  std::array<Vec3, 3> x2;     ///< second derivatives x_{,11}, x_{,22}, x_{,12}
  Vec3 normal;                ///< n = t_1 × t_2 / |t_1 × t_2| (zero if the facet is degenerate)
  Real jacobian = 0;          ///< |t_1 × t_2| (area scale: da = jacobian dξ^1 dξ^2)

  /// Metric a_αβ = t_α · t_β.
  Mat2 metric() const;
  /// x_{,αβ} as a function of the indices.
  const Vec3& second(int alpha, int beta) const { return alpha == beta ? x2[alpha] : x2[2]; }
  /// Curvature b_αβ = n · x_{,αβ} (only b_12 = b_21 for a bilinear facet, zero for tri3).
  Mat2 curvature() const;
};

/// Evaluates the facet at ξ. ξ may lie outside the reference facet (the polynomial extension is
/// used).
FacetPoint evaluate_facet(const FacetCoords& X, const Vec2& xi);

/// True for tri3 and tri6 facets.
inline bool is_triangle(mesh::FacetType type) {
  return mesh::num_corners(type) == 3;
}

/// Centre of the reference facet: (0, 0) for quads, (1/3, 1/3) for triangles.
Vec2 facet_centre(mesh::FacetType type);

/// Reference coordinates of facet corner a.
Vec2 facet_corner(mesh::FacetType type, int a);

/// True if ξ lies in the reference facet enlarged by `tolerance` (in reference units).
bool inside_facet(mesh::FacetType type, const Vec2& xi, Real tolerance);

/// How far ξ lies outside the reference facet, in reference units (0 inside).
Real outside_distance(mesh::FacetType type, const Vec2& xi);

/// Edge e of a facet runs from corner e to corner (e + 1) mod corners: ξ(u) = c_e + u d_e,
/// u ∈ [0, 1], d_e = c_(e+1) - c_e (its mid-edge node, if any, at u = ½).
Vec2 edge_direction(mesh::FacetType type, int e);

/// The linear facet type of a facet's corners: tri3 for tri6, quad4 for quad8 (else itself).
mesh::FacetType corner_facet_type(mesh::FacetType type);

/// The corners' linear shape functions of a facet of `type` at ξ, as a vector over all its
/// nodes (zero at the mid-edge nodes): how a field interpolated linearly from the corners (the
/// fluxes of tet10 and hex20 cells) varies over a quadratic facet. The facet's own N_a on
/// linear facets.
fe::FacetShapeValues corner_shape(mesh::FacetType type, const Vec2& xi);

/// Their gradients (row a = dL_a/dξ, zero rows at the mid-edge nodes).
fe::FacetShapeGrads corner_shape_grad(mesh::FacetType type, const Vec2& xi);

/// Diameter of the facet's corners: the longest distance between two of them (length unit).
Real facet_size(const FacetCoords& X);

/// Largest distance of a mid-edge node from the midpoint of its edge's corners (0 for linear
/// facets): the patch lies within the box of its corners grown by twice this.
Real facet_bulge(const FacetCoords& X);

} // namespace trifem::contact
