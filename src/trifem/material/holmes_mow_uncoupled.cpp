// SPDX-License-Identifier: MIT
#include "trifem/material/holmes_mow_uncoupled.hpp"

#include <cmath>

namespace trifem::material {

const std::vector<ParameterSchema>& HolmesMowUncoupled::schema() {
  static const std::vector<ParameterSchema> s = {
      {"mu", "MPa", "shear modulus", Range::positive(), std::nullopt},
      {"beta", "", "exponential stiffening coefficient", Range::non_negative(), std::nullopt},
      {"k", "MPa", "bulk modulus", Range::positive(), std::nullopt},
  };
  return s;
}

HolmesMowUncoupled::HolmesMowUncoupled(const ParameterValues& p)
    : mu_(p.at("mu")), beta_(p.at("beta")), k_(p.at("k")) {}

uncoupled::ScalarFunction HolmesMowUncoupled::strain_energy(const Mat3& C,
                                                            bool with_hessian) const {
  const uncoupled::ScalarFunction I1 = uncoupled::isochoric(
      {C.trace(), Mat3::Identity(), Mat6::Zero()}, -1.0 / 3.0, C, with_hessian);
  const Real x = I1.value - 3.0, e = std::exp(beta_ * x);
  // W(x) = mu/(2 beta) (e^(beta x) - 1) (expm1: the limit mu/2 x as beta -> 0), W' = mu/2 e^(beta
  // x), W'' = beta W'
  const Real w = beta_ == 0.0 ? 0.5 * mu_ * x : 0.5 * mu_ * std::expm1(beta_ * x) / beta_;
  const Real dw = 0.5 * mu_ * e, d2w = beta_ * dw;
  uncoupled::ScalarFunction W{w, dw * I1.gradient, Mat6::Zero()};
  if (with_hessian)
    W.hessian = d2w * voigt::outer(I1.gradient, I1.gradient) + dw * I1.hessian;
  uncoupled::accumulate(W, k_, uncoupled::log_volumetric(C, with_hessian));
  return W;
}

Real HolmesMowUncoupled::energy(const Mat3& C) const {
  return strain_energy(C, false).value;
}

Mat3 HolmesMowUncoupled::stress(const Mat3& C) const {
  return 2.0 * strain_energy(C, false).gradient;
}

StressTangent HolmesMowUncoupled::stress_tangent(const Mat3& C) const {
  const uncoupled::ScalarFunction W = strain_energy(C, true);
  return {2.0 * W.gradient, 4.0 * W.hessian};
}

} // namespace trifem::material
