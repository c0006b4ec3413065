// SPDX-License-Identifier: MIT
#include "trifem/contact/frictional_law.hpp"

#include "trifem/core/error.hpp"

namespace trifem::contact {
namespace {

/// The tangential traction t = (λ_1, λ_2, λ_3) of a node.
Vec3 traction_of(const SlaveNodeRows& node) {
  return {node.multiplier[1], node.multiplier[2], node.multiplier[3]};
}

/// The augmented contact pressure p = max(0, -(λ_n + c_N g)) that bounds the friction: at a
/// converged active node (g = 0) the contact pressure -λ_n, and positive exactly where the
/// normal indicator keeps the node in contact, so the friction bound and the normal state agree
/// along the iterations.
Real pressure_of(const SlaveNodeRows& node) {
  const Real gap = node.projection ? node.projection->gap : 0.0;
  return std::max(0.0, -(node.multiplier[0] + node.scale * gap));
}

} // namespace

Slip slip_of(const SlaveNodeRows& node) {
  TRIFEM_VERIFY(node.projection != nullptr, "the slip of a node needs its projection");
  const fe::ReferenceFacet& facet = fe::reference_facet(node.facet_type);
  const Vec2& xi = node.projection->xi;
  const fe::FacetShapeValues N = facet.shape(xi);
  Slip s;
  s.normal = node.projection->normal;
  Vec3 master_old = Vec3::Zero();
  for (Index a = 0; a < N.size(); ++a)
    master_old += N[a] * node.x_old[static_cast<std::size_t>(a + 1)];
  s.w = master_old - node.x_old[0];
  const Mat3 P = Mat3::Identity() - s.normal * s.normal.transpose();
  s.v = P * s.w;
  if (!node.derivatives)
    return s;
  const ProjectionDerivatives& d = *node.derivatives;
  const fe::FacetShapeGrads G = facet.shape_grad(xi);
  Eigen::Matrix<Real, 3, 2> tangents_old = Eigen::Matrix<Real, 3, 2>::Zero();
  for (Index a = 0; a < N.size(); ++a)
    tangents_old += node.x_old[static_cast<std::size_t>(a + 1)] * G.row(a);
  s.dv = P * tangents_old * d.dxi;
  s.dv -= s.normal.dot(s.w) * d.dnormal;
  s.dv -= s.normal * (s.w.transpose() * d.dnormal);
  return s;
}

FrictionalLaw::FrictionalLaw(dofs::FieldId displacement, Real friction_coefficient)
    : u_(displacement), mu_(friction_coefficient) {
  TRIFEM_CHECK(friction_coefficient >= 0.0 && std::isfinite(friction_coefficient),
               "contact: the friction coefficient {} must be finite and >= 0",
               friction_coefficient);
}

Real FrictionalLaw::indicator(const SlaveNodeRows& node) const {
  if (!node.projection)
    return std::numeric_limits<Real>::infinity();
  return node.multiplier[0] + node.scale * node.projection->gap;
}

Real FrictionalLaw::slip_indicator(const SlaveNodeRows& node) const {
  const Slip slip = slip_of(node);
  Vec3 t = traction_of(node);
  for (int i = 0; i < 3; ++i)
    if (node.held[static_cast<std::size_t>(i)])
      t[i] = 0.0;
  const Vec3 q = t - slip.normal * slip.normal.dot(t) - node.scale * slip.v;
  const Real excess = q.norm() - mu_ * pressure_of(node);
  const Real band = kSlipBand * mu_ * pressure_of(node);
  return excess > band ? excess - band : excess < -band ? excess + band : 0.0;
}

void FrictionalLaw::inactive_rows(const SlaveNodeRows& node, LocalSystem& out) const {
  const Real w = node.weight / node.scale;
  for (int c = 0; c < 4; ++c) {
    const Index row = node.lambda_at + c;
    out.r()[row] += w * node.multiplier[c];
    if (out.with_jacobian())
      out.K()(row, row) += w;
  }
}

void FrictionalLaw::active_rows(const SlaveNodeRows& node, LocalSystem& out) const {
  TRIFEM_VERIFY(node.projection && node.derivatives, "an active slave node needs a projection");
  const Index row = node.lambda_at;
  out.r()[row] += node.weight * node.projection->gap;
  if (out.with_jacobian())
    for (int j = 0; j < node.nodes.size; ++j)
      for (int i = 0; i < 3; ++i)
        out.K()(row, node.x_at[j] + i) += node.weight * node.derivatives->dgap(3 * j + i);
  const Slip slip = slip_of(node);
  if (node.slipping)
    slipping_rows(node, slip, out);
  else
    sticking_rows(node, slip, out);
  hold_rows(node, out);
}

void FrictionalLaw::hold_rows(const SlaveNodeRows& node, LocalSystem& out) const {
  const Real w = node.weight / node.scale;
  for (int i = 0; i < 3; ++i) {
    if (!node.held[static_cast<std::size_t>(i)])
      continue;
    const Index row = node.lambda_at + 1 + i;
    out.r()[row] = w * node.multiplier[1 + i];
    if (!out.with_jacobian())
      continue;
    out.K().row(row).setZero();
    out.K()(row, row) = w;
  }
}

void FrictionalLaw::sticking_rows(const SlaveNodeRows& node, const Slip& slip,
                                  LocalSystem& out) const {
  const Real A = node.weight, c = node.scale;
  const Vec3& n = slip.normal;
  const Vec3 t = traction_of(node);
  const Index rows = node.lambda_at + 1;
  out.r().segment<3>(rows) += A * (slip.v + n * (n.dot(t) / c));
  if (!out.with_jacobian())
    return;
  out.K().block<3, 3>(rows, rows) += (A / c) * n * n.transpose();
  const ProjectionDerivatives& d = *node.derivatives;
  const StencilRows<3> dG =
      A * (slip.dv + (n.dot(t) * d.dnormal + n * (t.transpose() * d.dnormal)) / c);
  for (int j = 0; j < node.nodes.size; ++j)
    out.K().block<3, 3>(rows, node.x_at[j]) += dG.middleCols<3>(3 * j);
}

void FrictionalLaw::slipping_rows(const SlaveNodeRows& node, const Slip& slip,
                                  LocalSystem& out) const {
  const Real A = node.weight, c = node.scale, p = pressure_of(node);
  const Vec3& n = slip.normal;
  const Vec3 t = traction_of(node);
  const Mat3 P = Mat3::Identity() - n * n.transpose();
  const Vec3 q = P * t - c * slip.v;
  const Real q_norm = q.norm();
  if (q_norm <= 1e-14 * (mu_ * p + t.norm() + c * slip.v.norm()) || q_norm == 0.0) {
    sticking_rows(node, slip, out); // no direction to slip in: held
    return;
  }
  const Vec3 u = q / q_norm;
  const Index rows = node.lambda_at + 1;
  out.r().segment<3>(rows) += (A / c) * (t - mu_ * p * u);
  if (!out.with_jacobian())
    return;
  const Mat3 du_dq = (Mat3::Identity() - u * u.transpose()) / q_norm;
  out.K().block<3, 3>(rows, rows) += (A / c) * (Mat3::Identity() - mu_ * p * du_dq * P);
  const ProjectionDerivatives& d = *node.derivatives;
  const StencilRows<3> dq = -n.dot(t) * d.dnormal - n * (t.transpose() * d.dnormal) - c * slip.dv;
  StencilRows<3> dG = -(A / c) * mu_ * p * du_dq * dq;
  if (p > 0.0) { // ∂p/∂λ_n = -1, ∂p/∂x = -c ∂g/∂x
    out.K().block<3, 1>(rows, node.lambda_at) += (A / c) * mu_ * u;
    dG += A * mu_ * u * d.dgap;
  }
  for (int j = 0; j < node.nodes.size; ++j)
    out.K().block<3, 3>(rows, node.x_at[j]) += dG.middleCols<3>(3 * j);
}

} // namespace trifem::contact
