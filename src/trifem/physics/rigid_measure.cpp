// SPDX-License-Identifier: MIT
#include "trifem/physics/rigid_measure.hpp"

#include "trifem/tensor/rotation.hpp"

#include <cmath>

namespace trifem::physics::rigid {
namespace {

/// ∂²(m·y)/∂q² of attachment `a`: only its body's rotation block is not zero.
void add_second_derivative(const AttachmentValue& a, const Vec3& m, Real weight, PairMatrix& H) {
  if (a.body < 0 || weight == 0.0)
    return;
  const Mat3 T = rotation::tangent(a.theta);
  const Mat3 block = rotation::tangent_derivative(a.theta, a.arm.cross(m)) +
                     T.transpose() * rotation::skew(m) * rotation::skew(a.arm) * T;
  const int r = 6 * a.body + 3;
  H.block<3, 3>(r, r) += weight * block;
}

/// Q = Σ w y_i·y_j with its derivatives.
void evaluate_sum(std::span<const Dot> dots, std::span<const AttachmentValue> y, bool derivatives,
                  MeasureValue& out) {
  out = MeasureValue{};
  for (const Dot& d : dots) {
    const AttachmentValue &a = y[d.i], &b = y[d.j];
    out.value += d.weight * a.y.dot(b.y);
    if (!derivatives)
      continue;
    out.gradient += d.weight * (a.jacobian.transpose() * b.y + b.jacobian.transpose() * a.y);
    const PairMatrix JaJb = a.jacobian.transpose() * b.jacobian;
    out.hessian += d.weight * (JaJb + JaJb.transpose());
    add_second_derivative(a, b.y, d.weight, out.hessian);
    add_second_derivative(b, a.y, d.weight, out.hessian);
  }
}

/// ℓ = √Q: ℓ' = Q'/(2ℓ), ℓ'' = Q''/(2ℓ) − Q'Q'ᵀ/(4ℓ³).
bool length_of(MeasureValue& q, bool derivatives) {
  if (!(q.value > 0.0))
    return false;
  const Real l = std::sqrt(q.value);
  if (derivatives) {
    q.hessian = q.hessian / (2.0 * l) - q.gradient * q.gradient.transpose() / (4.0 * l * l * l);
    q.gradient /= 2.0 * l;
  }
  q.value = l;
  return true;
}

/// φ = atan2(S, C) with its derivatives by the chain rule through (S, C).
bool angle_of(const MeasureValue& S, const MeasureValue& C, bool derivatives, MeasureValue& out) {
  const Real r2 = S.value * S.value + C.value * C.value;
  if (!(r2 > 0.0))
    return false;
  out.value = std::atan2(S.value, C.value);
  if (!derivatives)
    return true;
  const Real fs = C.value / r2, fc = -S.value / r2;
  const Real fss = -2.0 * S.value * C.value / (r2 * r2), fcc = -fss;
  const Real fsc = (S.value * S.value - C.value * C.value) / (r2 * r2);
  out.gradient = fs * S.gradient + fc * C.gradient;
  const PairMatrix sc = S.gradient * C.gradient.transpose();
  out.hessian = fs * S.hessian + fc * C.hessian + fss * S.gradient * S.gradient.transpose() +
                fcc * C.gradient * C.gradient.transpose() + fsc * (sc + sc.transpose());
  return true;
}

} // namespace

std::vector<AttachmentValue> evaluate(std::span<const Attachment> attachments,
                                      const PairState& state) {
  std::vector<AttachmentValue> out(attachments.size());
  for (std::size_t i = 0; i < attachments.size(); ++i) {
    const Attachment& a = attachments[i];
    AttachmentValue& v = out[i];
    if (a.body < 0 || !state.moving[a.body]) {
      v.y = a.reference;
      continue;
    }
    const int k = a.body;
    v.body = k;
    v.theta = state.theta[k];
    const Mat3 R = rotation::matrix(v.theta);
    v.arm = R * (a.point ? Vec3(a.reference - state.centre[k]) : a.reference);
    v.y = a.point ? Vec3(state.centre[k] + state.u[k] + v.arm) : v.arm;
    if (a.point)
      v.jacobian.block<3, 3>(0, 6 * k).setIdentity();
    v.jacobian.block<3, 3>(0, 6 * k + 3) = -rotation::skew(v.arm) * rotation::tangent(v.theta);
  }
  return out;
}

bool evaluate(const Measure& measure, std::span<const AttachmentValue> y, bool derivatives,
              MeasureValue& out) {
  evaluate_sum(measure.first, y, derivatives, out);
  switch (measure.kind) {
  case MeasureKind::Sum:
    return true;
  case MeasureKind::Length:
    return length_of(out, derivatives);
  case MeasureKind::Angle: {
    MeasureValue S = std::move(out), C;
    evaluate_sum(measure.second, y, derivatives, C);
    return angle_of(S, C, derivatives, out);
  }
  }
  return false;
}

} // namespace trifem::physics::rigid
