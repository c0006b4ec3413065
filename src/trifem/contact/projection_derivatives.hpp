// SPDX-License-Identifier: MIT
// Linearisation of the closest-point projection (docs/theory/contact.md §2.4, paper Appendix A):
// derivatives of ξ, of the gap g and of the normal n with respect to the coordinates
// (x_s, x_0, ..., x_(n-1)) of the projected point and of the n facet nodes.
#pragma once

#include "trifem/contact/projection.hpp"

namespace trifem::contact {

/// Most points of a projection's stencil: the projected point and the nodes of a facet.
inline constexpr int kMaxStencilPoints = 1 + fe::kMaxFacetNodes;
/// Most coordinates a projection depends on (three per stencil point).
inline constexpr int kMaxStencil = 3 * kMaxStencilPoints;

/// A row (or rows) over the stencil coordinates (dynamic width 3 (1 + n), fixed capacity).
template <int Rows>
using StencilRows = Eigen::Matrix<Real, Rows, Eigen::Dynamic, Eigen::RowMajor, Rows, kMaxStencil>;

/// Derivatives of a projection with respect to the stencil coordinates, ordered
/// (x_s, x_0, ..., x_(n-1)), three Cartesian components each: column 3 k + i belongs to
/// component i of stencil point k (k = 0: the projected point x_s; k = 1 + a: facet node a).
struct ProjectionDerivatives {
  StencilRows<2> dxi;     ///< ∂ξ^α/∂(coords)
  StencilRows<1> dgap;    ///< ∂g/∂(coords)
  StencilRows<3> dnormal; ///< ∂n/∂(coords)
  /// Number of stencil points (1 + facet nodes).
  int points() const { return static_cast<int>(dgap.cols() / 3); }
};

/// Derivatives at the projection `pr` of x_s onto the facet with current coordinates X (the
/// facet pr.facet; rows a = x_a). With d = p - x(ξ) = g n and N_a, N_{a,α} at ξ:
///
/// Interior projection (exact derivatives):
///   (a_αβ - g b_αβ) Δξ^β = t_α·(Δx_s - Σ_a N_a Δx_a) + g n·Σ_a N_{a,α} Δx_a
///   Δg = n·(Δx_s - Σ_a N_a Δx_a)            (the ξ- and n-variations drop out)
///   Δn = -a^{αβ} (n·Δt̂_β) t_α,   n·Δt̂_β = n·Σ_a N_{a,β} Δx_a + b_βγ Δξ^γ
/// with a_αβ = t_α·t_β, b_αβ = n·x_{,αβ}.
///
/// Boundary projection (exact derivatives of the clamped projection of Projection, for a fixed
/// edge or corner; n = d/g): on edge e with direction d_e, ξ = c_e + u d_e, the edge curve has
/// x_u = t_α d^α and x_uu = x_{,αβ} d^α d^β, and
///   (x_u·x_u - g n·x_uu) Δu = x_u·(Δx_s - Σ N_a Δx_a) + g n·Σ N_{a,u} Δx_a,   Δξ = d_e Δu;
///   at a corner:  Δξ = 0;
///   both:  Δg = n·(Δx_s - Σ N_a Δx_a),  Δn = (I - n⊗n)(Δx_s - Σ N_a Δx_a - x_u Δu) / g.
/// When p lies on the edge itself (|g| ≤ 1e-10 h, normal = facet normal) the normal is not
/// differentiable: dnormal is returned as zero and dgap as above.
ProjectionDerivatives projection_derivatives(const Projection& pr, const FacetCoords& X);

/// Same, with the facet coordinates taken from `surface` (facet pr.facet) in configuration x.
inline ProjectionDerivatives projection_derivatives(const Projection& pr,
                                                    const ContactSurface& surface,
                                                    const NodePositions& x) {
  return projection_derivatives(pr, surface.coords(pr.facet, x));
}

/// Mesh nodes of a projection's stencil in column order: the projected point's node, then the
/// nodes of the facet (ContactSurface::facet_nodes).
struct StencilNodes {
  std::array<Index, kMaxStencilPoints> nodes{};
  int size = 0;

  Index operator[](int j) const { return nodes[static_cast<std::size_t>(j)]; }
};

/// Mesh nodes of the stencil in column order: (point_node, nodes of facet `facet`).
inline StencilNodes stencil_nodes(Index point_node, const ContactSurface& surface, Index facet) {
  StencilNodes s;
  s.nodes[0] = point_node;
  s.size = 1;
  for (Index n : surface.facet_nodes(facet))
    s.nodes[static_cast<std::size_t>(s.size++)] = n;
  return s;
}

/// Interpolated nodal field on the facet, f(ξ) = Σ_a N_a(ξ) f_a (row a of `f` = f_a).
template <int K>
Eigen::Matrix<Real, K, 1> interpolate(const fe::ReferenceFacet& facet, const FacetNodeValues<K>& f,
                                      const Vec2& xi) {
  return f.transpose() * facet.shape(xi);
}

/// Derivative of f(ξ) = Σ_a N_a(ξ) f_a with respect to the stencil coordinates *through ξ*
/// (nodal values f_a held fixed): ∂f/∂(coords) = (Σ_a f_a N_{a,α}(ξ)) ∂ξ^α/∂(coords).
/// Their own contribution (∂f/∂f_a = N_a) is added by the caller. Example, the flux row
/// G_w = (w^m(ξ) - w_s)·n:  ΔG_w|coords = n·(this with f = w_a) + (w^m - w_s)·dnormal.
template <int K>
StencilRows<K> interpolation_derivative(const fe::ReferenceFacet& facet,
                                        const FacetNodeValues<K>& f, const Vec2& xi,
                                        const ProjectionDerivatives& d) {
  return f.transpose() * facet.shape_grad(xi) * d.dxi;
}

} // namespace trifem::contact
