// SPDX-License-Identifier: MIT
#include "trifem/material/porous_neo_hookean.hpp"

#include <cmath>
#include <limits>

namespace trifem::material {

const std::vector<ParameterSchema>& PorousNeoHookean::schema() {
  static const std::vector<ParameterSchema> s = {
      {"E", "MPa", "Young's modulus at small strain", Range::positive(), std::nullopt},
      {"phi0", "",
       "solid volume fraction in the reference configuration (the pores close at J = phi0)",
       Range::half_open(0.0, 1.0), std::nullopt},
  };
  return s;
}

PorousNeoHookean::PorousNeoHookean(const ParameterValues& p)
    : phi_s_(p.at("phi0")), phi_w_(1.0 - p.at("phi0")),
      mu_(p.at("E") / 3.0 * (1.0 + 0.5 * phi_w_ * phi_w_)),
      bulk_(2.0 * mu_ / (3.0 * phi_w_ * phi_w_)) {}

Real PorousNeoHookean::energy(const Mat3& C) const {
  const Real J = std::sqrt(C.determinant());
  if (!(J > phi_s_))
    return std::numeric_limits<Real>::infinity();
  const Real Jp = (J - phi_s_) / phi_w_; // J~
  return mu_ * (0.5 * (C.trace() * std::cbrt(Jp * Jp / (J * J)) - 3.0) - std::log(Jp));
}

Mat3 PorousNeoHookean::stress(const Mat3& C) const {
  return stress_tangent(C).S;
}

StressTangent PorousNeoHookean::stress_tangent(const Mat3& C) const {
  const Real J = std::sqrt(C.determinant());
  const Real I1 = C.trace();
  const Real Jp = (J - phi_s_) / phi_w_;
  const Real g = std::cbrt(Jp * Jp / (J * J)); // (J~/J)^(2/3)
  const Real d = J - phi_s_;
  // g' = dg/dJ = 2/3 g phi_s/(J d); q = mu I1 g phi_s/(3 d) - mu J/d
  const Real dg = 2.0 / 3.0 * g * phi_s_ / (J * d);
  const Real q = mu_ * I1 * g * phi_s_ / (3.0 * d) - mu_ * J / d;
  const Real q_I1 = mu_ * g * phi_s_ / (3.0 * d);
  const Real q_J = mu_ * I1 * phi_s_ / 3.0 * (dg / d - g / (d * d)) + mu_ * phi_s_ / (d * d);
  const Mat3 Ci = C.inverse();
  StressTangent st{mu_ * g * Mat3::Identity() + q * Ci, Mat6()};
  // D = 2 dS/dC = mu g' J (I x Ci) + 2 q_I1 (Ci x I) + q_J J (Ci x Ci) - 2 q (Ci . Ci), with
  // mu g' J = 2 q_I1 (D has the major symmetry) and (Ci . Ci)_IJKL = (Ci_IK Ci_JL + Ci_IL Ci_JK)/2
  const Real a = mu_ * dg * J;
  for (int r = 0; r < 6; ++r) {
    const int I = voigt::kI[r], J2 = voigt::kJ[r];
    const Real delta_r = I == J2 ? 1.0 : 0.0;
    for (int c = 0; c < 6; ++c) {
      const int K = voigt::kI[c], L = voigt::kJ[c];
      const Real delta_c = K == L ? 1.0 : 0.0;
      st.D(r, c) = a * delta_r * Ci(K, L) + 2.0 * q_I1 * Ci(I, J2) * delta_c +
                   q_J * J * Ci(I, J2) * Ci(K, L) -
                   q * (Ci(I, K) * Ci(J2, L) + Ci(I, L) * Ci(J2, K));
    }
  }
  return st;
}

} // namespace trifem::material
