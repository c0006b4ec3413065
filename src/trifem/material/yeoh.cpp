// SPDX-License-Identifier: MIT
#include "trifem/material/yeoh.hpp"

#include <cmath>

namespace trifem::material {

const std::vector<ParameterSchema>& Yeoh::schema() {
  static const std::vector<ParameterSchema> s = {
      {"c1", "MPa", "coefficient of (I1~ - 3) (half the shear modulus)", Range::positive(),
       std::nullopt},
      {"c2", "MPa", "coefficient of (I1~ - 3)^2", Range{}, 0.0},
      {"c3", "MPa", "coefficient of (I1~ - 3)^3", Range{}, 0.0},
      {"c4", "MPa", "coefficient of (I1~ - 3)^4", Range{}, 0.0},
      {"c5", "MPa", "coefficient of (I1~ - 3)^5", Range{}, 0.0},
      {"c6", "MPa", "coefficient of (I1~ - 3)^6", Range{}, 0.0},
      {"k", "MPa", "bulk modulus", Range::positive(), std::nullopt},
  };
  return s;
}

Yeoh::Yeoh(const ParameterValues& p) : k_(p.at("k")) {
  for (int i = 0; i < 6; ++i)
    c_[i] = p.at("c" + std::to_string(i + 1));
}

uncoupled::ScalarFunction Yeoh::strain_energy(const Mat3& C, bool with_hessian) const {
  const uncoupled::ScalarFunction I1 = uncoupled::isochoric(
      {C.trace(), Mat3::Identity(), Mat6::Zero()}, -1.0 / 3.0, C, with_hessian);
  const Real x = I1.value - 3.0;
  std::array<Real, 7> power{}; // x^0 .. x^6
  power[0] = 1.0;
  for (int i = 1; i <= 6; ++i)
    power[i] = power[i - 1] * x;
  Real w = 0.0, dw = 0.0, d2w = 0.0; // W(x), W'(x), W''(x)
  for (int i = 1; i <= 6; ++i) {
    const Real c = c_[i - 1], n = static_cast<Real>(i);
    w += c * power[i];
    dw += n * c * power[i - 1];
    if (i >= 2)
      d2w += n * (n - 1.0) * c * power[i - 2];
  }
  uncoupled::ScalarFunction W{w, dw * I1.gradient, Mat6::Zero()};
  if (with_hessian)
    W.hessian = d2w * voigt::outer(I1.gradient, I1.gradient) + dw * I1.hessian;
  uncoupled::accumulate(W, k_, uncoupled::log_volumetric(C, with_hessian));
  return W;
}

Real Yeoh::energy(const Mat3& C) const {
  return strain_energy(C, false).value;
}

Mat3 Yeoh::stress(const Mat3& C) const {
  return 2.0 * strain_energy(C, false).gradient;
}

StressTangent Yeoh::stress_tangent(const Mat3& C) const {
  const uncoupled::ScalarFunction W = strain_energy(C, true);
  return {2.0 * W.gradient, 4.0 * W.hessian};
}

} // namespace trifem::material
