// SPDX-License-Identifier: MIT
#include "trifem/material/neo_hookean.hpp"

#include <cmath>

namespace trifem::material {

const std::vector<ParameterSchema>& NeoHookean::schema() {
  static const std::vector<ParameterSchema> s = {
      {"E", "MPa", "Young's modulus", Range::positive(), std::nullopt},
      {"nu", "", "Poisson's ratio", Range::open(-1.0, 0.5), 0.0},
  };
  return s;
}

NeoHookean::NeoHookean(const ParameterValues& p) : lame_(lame_from_young(p.at("E"), p.at("nu"))) {}

Real NeoHookean::energy(const Mat3& C) const {
  const Real lnJ = 0.5 * std::log(C.determinant());
  return 0.5 * lame_.mu * (C.trace() - 3.0) - lame_.mu * lnJ + 0.5 * lame_.lambda * lnJ * lnJ;
}

Mat3 NeoHookean::stress(const Mat3& C) const {
  const Real lnJ = 0.5 * std::log(C.determinant());
  const Mat3 Ci = C.inverse();
  return lame_.mu * (Mat3::Identity() - Ci) + lame_.lambda * lnJ * Ci;
}

StressTangent NeoHookean::stress_tangent(const Mat3& C) const {
  const Real lnJ = 0.5 * std::log(C.determinant());
  const Mat3 Ci = C.inverse();
  StressTangent st{lame_.mu * (Mat3::Identity() - Ci) + lame_.lambda * lnJ * Ci, Mat6()};
  const Real a = 2.0 * (lame_.mu - lame_.lambda * lnJ);
  for (int r = 0; r < 6; ++r) {
    const int I = voigt::kI[r], J = voigt::kJ[r];
    for (int c = 0; c < 6; ++c) {
      const int K = voigt::kI[c], L = voigt::kJ[c];
      st.D(r, c) = lame_.lambda * Ci(I, J) * Ci(K, L) +
                   a * 0.5 * (Ci(I, K) * Ci(J, L) + Ci(I, L) * Ci(J, K));
    }
  }
  return st;
}

} // namespace trifem::material
