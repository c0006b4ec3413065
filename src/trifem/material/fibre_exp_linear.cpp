// SPDX-License-Identifier: MIT
#include "trifem/material/fibre_exp_linear.hpp"

#include "trifem/core/error.hpp"
#include "trifem/material/uncoupled.hpp"

#include <cmath>

namespace trifem::material {

const std::vector<ParameterSchema>& FibreExpLinear::schema() {
  static const std::vector<ParameterSchema> s = {
      {"c3", "MPa", "scale of the exponential part (0: the value that makes dF/dl continuous)",
       Range::non_negative(), std::nullopt},
      {"c4", "", "rate of the exponential part", Range::non_negative(), std::nullopt},
      {"c5", "MPa", "modulus of the linear part", Range::non_negative(), std::nullopt},
      {"lam_max", "", "fibre stretch where the linear part begins", Range{1.0, 1e300, false, false},
       std::nullopt},
      {"fibre", "", "fibre direction in the reference configuration (normalised)", Range{},
       std::nullopt, ParameterKind::Vector},
  };
  return s;
}

void FibreExpLinear::check(const ParameterValues& p, const std::string& context) {
  (void)fibre_direction(p, context);
  TRIFEM_CHECK(p.at("c3") > 0.0 || p.at("c5") == 0.0 || p.at("c4") > 0.0,
               "{}.c4 = 0 with {}.c3 = 0: c3 is then c5/c4 exp(-c4 (lam_max - 1)), which needs "
               "c4 > 0",
               context, context);
}

FibreExpLinear::FibreExpLinear(const ParameterValues& p, bool coupled)
    : c3_(p.at("c3")), c4_(p.at("c4")), c5_(p.at("c5")), lam_max_(p.at("lam_max")),
      a0_(vector_value(p, "fibre")), coupled_(coupled) {
  check(p, "fibre-exp-linear");
  a0_.normalize();
  if (c3_ == 0.0 && c5_ > 0.0)
    c3_ = c5_ / c4_ * std::exp(-c4_ * (lam_max_ - 1.0));
  c6_ = c3_ * std::expm1(c4_ * (lam_max_ - 1.0)) - c5_ * lam_max_;
}

Real FibreExpLinear::exponential_energy(Real l) const {
  if (c4_ == 0.0 || c3_ == 0.0)
    return 0.0;
  return c3_ * (std::exp(-c4_) * (std::expint(c4_ * l) - std::expint(c4_)) - std::log(l));
}

void FibreExpLinear::fibre(Real l, Real& W, Real& F, Real& dF) const {
  if (l < lam_max_) {
    W = exponential_energy(l);
    F = c3_ * std::expm1(c4_ * (l - 1.0));
    dF = c3_ * c4_ * std::exp(c4_ * (l - 1.0));
    return;
  }
  W = exponential_energy(lam_max_) + c5_ * (l - lam_max_) + c6_ * std::log(l / lam_max_);
  F = c5_ * l + c6_;
  dF = c5_;
}

void FibreExpLinear::evaluate(const Mat3& C, Real& W, Mat3& dW, Mat6* d2W) const {
  W = 0.0;
  dW.setZero();
  if (d2W)
    d2W->setZero();
  const uncoupled::ScalarFunction whole = {a0_.dot(C * a0_), a0_ * a0_.transpose(), Mat6::Zero()};
  const uncoupled::ScalarFunction I4 =
      coupled_ ? whole : uncoupled::isochoric(whole, -1.0 / 3.0, C, d2W != nullptr);
  if (I4.value <= 1.0) // tension only
    return;
  const Real l = std::sqrt(I4.value);
  Real F, dF;
  fibre(l, W, F, dF);
  const Real W_I = F / (2.0 * I4.value);
  dW = W_I * I4.gradient;
  if (d2W) {
    const Real W_II = (l * dF - 2.0 * F) / (4.0 * I4.value * I4.value);
    *d2W = W_II * voigt::outer(I4.gradient, I4.gradient) + W_I * I4.hessian;
  }
}

Real FibreExpLinear::energy(const Mat3& C) const {
  Real W;
  Mat3 dW;
  evaluate(C, W, dW, nullptr);
  return W;
}

Mat3 FibreExpLinear::stress(const Mat3& C) const {
  Real W;
  Mat3 dW;
  evaluate(C, W, dW, nullptr);
  return 2.0 * dW;
}

StressTangent FibreExpLinear::stress_tangent(const Mat3& C) const {
  Real W;
  Mat3 dW;
  Mat6 d2W;
  evaluate(C, W, dW, &d2W);
  return {2.0 * dW, 4.0 * d2W};
}

} // namespace trifem::material
