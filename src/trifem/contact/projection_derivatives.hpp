// SPDX-License-Identifier: MIT
// Linearisation of the closest-point projection (docs/theory/contact.md §2.4, paper Appendix A):
// derivatives of ξ, of the gap g and of the normal n with respect to the 15 coordinates
// (x_s, x_0, x_1, x_2, x_3) of the projected point and of the facet nodes.
#pragma once

#include "trifem/contact/projection.hpp"

namespace trifem::contact {

/// Number of coordinates a projection depends on: the point (3) and four facet nodes (4 x 3).
inline constexpr int kStencil = 15;

/// Derivatives of a projection with respect to the stencil coordinates, ordered
/// (x_s, x_0, x_1, x_2, x_3), three Cartesian components each: column 3 k + i belongs to
/// component i of stencil point k (k = 0: the projected point x_s; k = 1 + a: facet node a).
struct ProjectionDerivatives {
  Eigen::Matrix<Real, 2, kStencil> dxi;     ///< ∂ξ^α/∂(coords)
  Eigen::Matrix<Real, 1, kStencil> dgap;    ///< ∂g/∂(coords)
  Eigen::Matrix<Real, 3, kStencil> dnormal; ///< ∂n/∂(coords)
};

/// Derivatives at the projection `pr` of x_s onto the facet with current coordinates X (the
/// facet pr.facet; rows a = x_a). With d = p - x(ξ) = g n and N_a, N_{a,α} at ξ:
///
/// Interior projection (exact derivatives):
///   (a_αβ - g b_αβ) Δξ^β = t_α·(Δx_s - Σ_a N_a Δx_a) + g n·Σ_a N_{a,α} Δx_a
///   Δg = n·(Δx_s - Σ_a N_a Δx_a)            (the ξ- and n-variations drop out)
///   Δn = -a^{αβ} (n·Δt̂_β) t_α,   Δt̂_β = Σ_a N_{a,β} Δx_a + x_{,βγ} Δξ^γ
/// with a_αβ = t_α·t_β, b_αβ = n·x_{,αβ} (only b_12 = b_21 ≠ 0 for a bilinear facet).
///
/// Boundary projection (exact derivatives of the clamped projection of Projection, for a fixed
/// clamping pattern `fixed`; n = d/g):
///   on an edge with free direction β:  a_ββ Δξ^β = t_β·(Δx_s - Σ N_a Δx_a) + g n·Σ N_{a,β} Δx_a,
///                                      the fixed component has Δξ = 0;
///   at a corner:                       Δξ = 0;
///   both:  Δg = n·(Δx_s - Σ N_a Δx_a),  Δn = (I - n⊗n)(Δx_s - Σ N_a Δx_a - t_β Δξ^β) / g.
/// When p lies on the edge itself (|g| ≤ 1e-10 h, normal = facet normal) the normal is not
/// differentiable: dnormal is returned as zero and dgap as above.
ProjectionDerivatives projection_derivatives(const Projection& pr, const fe::QuadCoords& X);

/// Same, with the facet coordinates taken from `surface` (facet pr.facet) in configuration x.
inline ProjectionDerivatives projection_derivatives(const Projection& pr,
                                                    const ContactSurface& surface,
                                                    const NodePositions& x) {
  return projection_derivatives(pr, surface.coords(pr.facet, x));
}

/// Mesh nodes of the stencil in column order: (point_node, nodes of facet `facet`).
inline std::array<Index, 5> stencil_nodes(Index point_node, const ContactSurface& surface,
                                          Index facet) {
  const auto& n = surface.facet(facet).nodes;
  return {point_node, n[0], n[1], n[2], n[3]};
}

/// Interpolated nodal field on the facet, f(ξ) = Σ_a N_a(ξ) f_a (row a of `f` = f_a).
template <int K>
Eigen::Matrix<Real, K, 1> interpolate(const Eigen::Matrix<Real, 4, K>& f, const Vec2& xi) {
  return f.transpose() * fe::quad4_shape(xi);
}

/// Derivative of f(ξ) = Σ_a N_a(ξ) f_a with respect to the 15 stencil coordinates *through ξ*
/// (nodal values f_a held fixed): ∂f/∂(coords) = (Σ_a f_a N_{a,α}(ξ)) ∂ξ^α/∂(coords).
/// Their own contribution (∂f/∂f_a = N_a) is added by the caller. Example, the flux row
/// G_w = (w^m(ξ) - w_s)·n:  ΔG_w|coords = n·(this with f = w_a) + (w^m - w_s)·dnormal.
template <int K>
Eigen::Matrix<Real, K, kStencil> interpolation_derivative(const Eigen::Matrix<Real, 4, K>& f,
                                                          const Vec2& xi,
                                                          const ProjectionDerivatives& d) {
  return f.transpose() * fe::quad4_shape_grad(xi) * d.dxi;
}

} // namespace trifem::contact
