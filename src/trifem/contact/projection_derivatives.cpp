// SPDX-License-Identifier: MIT
#include "trifem/contact/projection_derivatives.hpp"

namespace trifem::contact {
namespace {

using Row = Eigen::Matrix<Real, 1, kStencil>;
using Block = Eigen::Matrix<Real, 3, kStencil>;

/// Variation of d = p - x(ξ) at fixed ξ: [I, -N_0 I, -N_1 I, -N_2 I, -N_3 I].
Block d_distance(const FacetPoint& fp) {
  Block D = Block::Zero();
  D.block<3, 3>(0, 0).setIdentity();
  for (int a = 0; a < 4; ++a)
    D.block<3, 3>(0, 3 + 3 * a) = -fp.N[a] * Mat3::Identity();
  return D;
}

/// Variation of t_α at fixed ξ: [0, N_{0,α} I, ..., N_{3,α} I].
Block d_tangent(const FacetPoint& fp, int alpha) {
  Block D = Block::Zero();
  for (int a = 0; a < 4; ++a)
    D.block<3, 3>(0, 3 + 3 * a) = fp.dN(a, alpha) * Mat3::Identity();
  return D;
}

/// Right-hand side of the projection linearisation for direction α:
/// t_α·(Δx_s - Σ N_a Δx_a) + g n·Σ N_{a,α} Δx_a.
Row projection_rhs(const FacetPoint& fp, const Projection& pr, const Block& Dd, int alpha) {
  return fp.t[alpha].transpose() * Dd + pr.gap * pr.normal.transpose() * d_tangent(fp, alpha);
}

void interior(const FacetPoint& fp, const Projection& pr, const Block& Dd,
              ProjectionDerivatives& out) {
  const Mat2 a = fp.metric();
  const Mat2 M = a - pr.gap * fp.curvature();
  Eigen::Matrix<Real, 2, kStencil> rhs;
  rhs.row(0) = projection_rhs(fp, pr, Dd, 0);
  rhs.row(1) = projection_rhs(fp, pr, Dd, 1);
  out.dxi = M.inverse() * rhs;
  // n·Δt̂_β with Δt̂_1 = ΣN_{a,1}Δx_a + x_{,12} Δξ^2 and Δt̂_2 = ΣN_{a,2}Δx_a + x_{,12} Δξ^1.
  const Real nx12 = pr.normal.dot(fp.x12);
  Eigen::Matrix<Real, 2, kStencil> n_dt;
  n_dt.row(0) = pr.normal.transpose() * d_tangent(fp, 0) + nx12 * out.dxi.row(1);
  n_dt.row(1) = pr.normal.transpose() * d_tangent(fp, 1) + nx12 * out.dxi.row(0);
  const Mat2 a_inv = a.inverse();
  out.dnormal.setZero();
  for (int alpha = 0; alpha < 2; ++alpha)
    for (int beta = 0; beta < 2; ++beta)
      out.dnormal -= a_inv(alpha, beta) * fp.t[alpha] * n_dt.row(beta);
}

void boundary(const FacetPoint& fp, const Projection& pr, const Block& Dd, Real h,
              ProjectionDerivatives& out) {
  out.dxi.setZero();
  Block Dd_total = Dd; // Δ(p - x(ξ)) including the sliding along the edge
  for (int beta = 0; beta < 2; ++beta) {
    if (pr.fixed[beta])
      continue;
    out.dxi.row(beta) = projection_rhs(fp, pr, Dd, beta) / fp.t[beta].squaredNorm();
    Dd_total -= fp.t[beta] * out.dxi.row(beta);
  }
  if (std::abs(pr.gap) <= 1e-10 * h) { // same threshold as the projection's fallback
    out.dnormal.setZero();
    return;
  }
  const Mat3 P = Mat3::Identity() - pr.normal * pr.normal.transpose();
  out.dnormal = P * Dd_total / pr.gap;
}

} // namespace

ProjectionDerivatives projection_derivatives(const Projection& pr, const fe::QuadCoords& X) {
  const FacetPoint fp = evaluate_facet(X, pr.xi);
  const Block Dd = d_distance(fp);
  ProjectionDerivatives out;
  out.dgap = pr.normal.transpose() * Dd;
  if (pr.on_boundary)
    boundary(fp, pr, Dd, facet_size(X), out);
  else
    interior(fp, pr, Dd, out);
  return out;
}

} // namespace trifem::contact
