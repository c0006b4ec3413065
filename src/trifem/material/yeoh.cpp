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
  const uncoupled::ScalarFunction I1 = uncoupled::isochoric_first_invariant(C, with_hessian);
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
  uncoupled::ScalarFunction W = uncoupled::compose(I1, w, dw, d2w, with_hessian);
  uncoupled::accumulate(W, k_, uncoupled::log_volumetric(C, with_hessian));
  return W;
}

} // namespace trifem::material
