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
  const uncoupled::ScalarFunction I1 = uncoupled::isochoric_first_invariant(C, with_hessian);
  const Real x = I1.value - 3.0, e = std::exp(beta_ * x);
  // W(x) = mu/(2 beta) (e^(beta x) - 1) (expm1: the limit mu/2 x as beta -> 0), W' = mu/2 e^(beta
  // x), W'' = beta W'
  const Real w = beta_ == 0.0 ? 0.5 * mu_ * x : 0.5 * mu_ * std::expm1(beta_ * x) / beta_;
  const Real dw = 0.5 * mu_ * e, d2w = beta_ * dw;
  uncoupled::ScalarFunction W = uncoupled::compose(I1, w, dw, d2w, with_hessian);
  uncoupled::accumulate(W, k_, uncoupled::log_volumetric(C, with_hessian));
  return W;
}

} // namespace trifem::material
