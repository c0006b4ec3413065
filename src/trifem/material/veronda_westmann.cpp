// SPDX-License-Identifier: MIT
#include "trifem/material/veronda_westmann.hpp"

#include <cmath>

namespace trifem::material {

const std::vector<ParameterSchema>& VerondaWestmann::schema() {
  static const std::vector<ParameterSchema> s = {
      {"c1", "MPa", "scale of the exponential", Range::positive(), std::nullopt},
      {"c2", "", "rate of the exponential in I1~ - 3", Range::positive(), std::nullopt},
      {"k", "MPa", "bulk modulus", Range::positive(), std::nullopt},
  };
  return s;
}

VerondaWestmann::VerondaWestmann(const ParameterValues& p)
    : c1_(p.at("c1")), c2_(p.at("c2")), k_(p.at("k")) {}

uncoupled::ScalarFunction VerondaWestmann::strain_energy(const Mat3& C, bool with_hessian) const {
  const Mat3 I = Mat3::Identity();
  const uncoupled::ScalarFunction I1 =
      uncoupled::isochoric({C.trace(), I, Mat6::Zero()}, -1.0 / 3.0, C, with_hessian);
  const Real tr = C.trace();
  uncoupled::ScalarFunction i2{0.5 * (tr * tr - (C * C).trace()), tr * I - C, Mat6::Zero()};
  if (with_hessian)
    i2.hessian = voigt::outer(I, I) - voigt::symmetric_product(I);
  const uncoupled::ScalarFunction I2 = uncoupled::isochoric(i2, -2.0 / 3.0, C, with_hessian);
  const Real e = std::exp(c2_ * (I1.value - 3.0));
  uncoupled::ScalarFunction W{c1_ * (e - 1.0) - 0.5 * c1_ * c2_ * (I2.value - 3.0),
                              c1_ * c2_ * e * I1.gradient - 0.5 * c1_ * c2_ * I2.gradient,
                              Mat6::Zero()};
  if (with_hessian)
    W.hessian = c1_ * c2_ * e * (c2_ * voigt::outer(I1.gradient, I1.gradient) + I1.hessian) -
                0.5 * c1_ * c2_ * I2.hessian;
  uncoupled::accumulate(W, k_, uncoupled::log_volumetric(C, with_hessian));
  return W;
}

} // namespace trifem::material
