// SPDX-License-Identifier: MIT
#include "trifem/material/fibre_exp_pow.hpp"

#include "trifem/core/error.hpp"

#include <cmath>

namespace trifem::material {

const std::vector<ParameterSchema>& FibreExpPow::schema() {
  static const std::vector<ParameterSchema> s = {
      {"ksi", "MPa", "fibre modulus", Range::non_negative(), std::nullopt},
      {"alpha", "", "coefficient of (I_n - 1)^beta in the exponential", Range::non_negative(),
       std::nullopt},
      {"beta", "", "power of (I_n - 1)", Range{2.0, 1e300, false, false}, std::nullopt},
      {"fibre", "", "fibre direction in the reference configuration (normalised)", Range{},
       std::nullopt, ParameterKind::Vector},
  };
  return s;
}

void FibreExpPow::check(const ParameterValues& p, const std::string& context) {
  (void)fibre_direction(p, context);
}

FibreExpPow::FibreExpPow(const ParameterValues& p)
    : ksi_(p.at("ksi")), alpha_(p.at("alpha")), beta_(p.at("beta")), a0_(vector_value(p, "fibre")) {
  check(p, "fibre-exp-pow");
  TRIFEM_CHECK(ksi_ >= 0.0 && alpha_ >= 0.0 && beta_ >= 2.0,
               "fibre-exp-pow: ksi = {}, alpha = {}, beta = {}: need ksi >= 0, alpha >= 0, "
               "beta >= 2",
               ksi_, alpha_, beta_);
  a0_.normalize();
}

std::pair<Real, Real> FibreExpPow::derivatives(Real x) const {
  const Real xb = std::pow(x, beta_); // x^beta
  const Real e = std::exp(alpha_ * xb);
  const Real x2 = std::pow(x, beta_ - 2.0); // 1 at beta = 2
  return {ksi_ * x2 * x * e, ksi_ * x2 * (beta_ * (alpha_ * xb + 1.0) - 1.0) * e};
}

Real FibreExpPow::energy(const Mat3& C) const {
  const Real x = a0_.dot(C * a0_) - 1.0;
  if (!(x > 0.0))
    return 0.0;
  const Real xb = std::pow(x, beta_);
  if (alpha_ == 0.0)
    return ksi_ / beta_ * xb;
  return ksi_ / (alpha_ * beta_) * std::expm1(alpha_ * xb); // expm1: exact as alpha -> 0
}

Mat3 FibreExpPow::stress(const Mat3& C) const {
  const Real x = a0_.dot(C * a0_) - 1.0;
  if (!(x > 0.0))
    return Mat3::Zero();
  const Mat3 A = a0_ * a0_.transpose();
  return 2.0 * derivatives(x).first * A; // as in stress_tangent, to the last bit
}

StressTangent FibreExpPow::stress_tangent(const Mat3& C) const {
  const Real x = a0_.dot(C * a0_) - 1.0;
  if (!(x > 0.0))
    return {Mat3::Zero(), Mat6::Zero()};
  const auto [dW, d2W] = derivatives(x);
  const Mat3 A = a0_ * a0_.transpose();
  return {2.0 * dW * A, 4.0 * d2W * voigt::outer(A, A)};
}

} // namespace trifem::material
