// SPDX-License-Identifier: MIT
#include "trifem/material/saint_venant_kirchhoff.hpp"

namespace trifem::material {

const std::vector<ParameterSchema>& SaintVenantKirchhoff::schema() {
  static const std::vector<ParameterSchema> s = {
      {"E", "MPa", "Young's modulus", Range::positive(), std::nullopt},
      {"nu", "", "Poisson's ratio", Range::open(-1.0, 0.5), 0.0},
  };
  return s;
}

SaintVenantKirchhoff::SaintVenantKirchhoff(const ParameterValues& p)
    : lame_(lame_from_young(p.at("E"), p.at("nu"))) {}

Real SaintVenantKirchhoff::energy(const Mat3& C) const {
  const Mat3 E = 0.5 * (C - Mat3::Identity());
  const Real trE = E.trace();
  return 0.5 * lame_.lambda * trE * trE + lame_.mu * (E.array() * E.array()).sum();
}

Mat3 SaintVenantKirchhoff::stress(const Mat3& C) const {
  const Mat3 E = 0.5 * (C - Mat3::Identity());
  return lame_.lambda * E.trace() * Mat3::Identity() + 2.0 * lame_.mu * E;
}

StressTangent SaintVenantKirchhoff::stress_tangent(const Mat3& C) const {
  StressTangent st{stress(C), Mat6::Zero()};
  st.D.topLeftCorner<3, 3>().setConstant(lame_.lambda);
  for (int k = 0; k < 3; ++k) {
    st.D(k, k) += 2.0 * lame_.mu;
    st.D(k + 3, k + 3) = lame_.mu;
  }
  return st;
}

} // namespace trifem::material
