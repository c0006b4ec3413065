// SPDX-License-Identifier: MIT
#include "trifem/contact/projection_derivatives.hpp"

namespace trifem::contact {
namespace {

using Row = StencilRows<1>;
using Block = StencilRows<3>;

/// Variation of d = p - x(ξ) at fixed ξ: [I, -N_0 I, ..., -N_(n-1) I].
Block d_distance(const FacetPoint& fp) {
  const auto n = fp.N.size();
  Block D = Block::Zero(3, 3 * (1 + n));
  D.block<3, 3>(0, 0).setIdentity();
  for (Index a = 0; a < n; ++a)
    D.block<3, 3>(0, 3 + 3 * a) = -fp.N[a] * Mat3::Identity();
  return D;
}

/// Variation of the tangent t_v = t_α v^α along the reference direction v at fixed ξ:
/// [0, N_{0,v} I, ..., N_{n-1,v} I].
Block d_tangent(const FacetPoint& fp, const Vec2& v) {
  const auto n = fp.N.size();
  Block D = Block::Zero(3, 3 * (1 + n));
  for (Index a = 0; a < n; ++a)
    D.block<3, 3>(0, 3 + 3 * a) = fp.dN.row(a).dot(v) * Mat3::Identity();
  return D;
}

/// Right-hand side of the projection linearisation along the reference direction v:
/// t_v·(Δx_s - Σ N_a Δx_a) + g n·Σ N_{a,v} Δx_a.
Row projection_rhs(const FacetPoint& fp, const Projection& pr, const Block& Dd, const Vec2& v) {
  const Vec3 t = fp.t[0] * v[0] + fp.t[1] * v[1];
  return t.transpose() * Dd + pr.gap * pr.normal.transpose() * d_tangent(fp, v);
}

void interior(const FacetPoint& fp, const Projection& pr, const Block& Dd,
              ProjectionDerivatives& out) {
  const Mat2 a = fp.metric();
  const Mat2 b = fp.curvature();
  const Mat2 M = a - pr.gap * b;
  StencilRows<2> rhs(2, Dd.cols());
  rhs.row(0) = projection_rhs(fp, pr, Dd, Vec2::UnitX());
  rhs.row(1) = projection_rhs(fp, pr, Dd, Vec2::UnitY());
  out.dxi = M.inverse() * rhs;
  // n·Δt̂_β = n·Σ_a N_{a,β} Δx_a + b_βγ Δξ^γ
  StencilRows<2> n_dt(2, Dd.cols());
  n_dt.row(0) = pr.normal.transpose() * d_tangent(fp, Vec2::UnitX());
  n_dt.row(1) = pr.normal.transpose() * d_tangent(fp, Vec2::UnitY());
  n_dt += b * out.dxi;
  const Mat2 a_inv = a.inverse();
  out.dnormal = Block::Zero(3, Dd.cols());
  for (int alpha = 0; alpha < 2; ++alpha)
    for (int beta = 0; beta < 2; ++beta)
      out.dnormal -= a_inv(alpha, beta) * fp.t[alpha] * n_dt.row(beta);
}

void boundary(const FacetPoint& fp, const Projection& pr, const Block& Dd, Real h,
              mesh::FacetType type, ProjectionDerivatives& out) {
  out.dxi = StencilRows<2>::Zero(2, Dd.cols());
  Block Dd_total = Dd; // Δ(p - x(ξ)) including the sliding along the edge
  if (pr.corner < 0) {
    const Vec2 v = edge_direction(type, pr.edge);
    const Vec3 xu = fp.t[0] * v[0] + fp.t[1] * v[1];
    Vec3 xuu = Vec3::Zero();
    for (int alpha = 0; alpha < 2; ++alpha)
      for (int beta = 0; beta < 2; ++beta)
        xuu += v[alpha] * v[beta] * fp.second(alpha, beta);
    const Row du = projection_rhs(fp, pr, Dd, v) / (xu.squaredNorm() - pr.gap * pr.normal.dot(xuu));
    out.dxi = v * du;
    Dd_total -= xu * du;
  }
  if (std::abs(pr.gap) <= 1e-10 * h) { // same threshold as the projection's fallback
    out.dnormal = Block::Zero(3, Dd.cols());
    return;
  }
  const Mat3 P = Mat3::Identity() - pr.normal * pr.normal.transpose();
  out.dnormal = P * Dd_total / pr.gap;
}

} // namespace

ProjectionDerivatives projection_derivatives(const Projection& pr, const FacetCoords& X) {
  const FacetPoint fp = evaluate_facet(X, pr.xi);
  const Block Dd = d_distance(fp);
  ProjectionDerivatives out;
  out.dgap = pr.normal.transpose() * Dd;
  if (pr.on_boundary)
    boundary(fp, pr, Dd, facet_size(X), X.type(), out);
  else
    interior(fp, pr, Dd, out);
  return out;
}

} // namespace trifem::contact
