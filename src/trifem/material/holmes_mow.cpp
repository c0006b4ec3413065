// SPDX-License-Identifier: MIT
#include "trifem/material/holmes_mow.hpp"

#include <cmath>

namespace trifem::material {
using voigt::outer;
using voigt::symmetric_product;

const std::vector<ParameterSchema>& HolmesMow::schema() {
  static const std::vector<ParameterSchema> s = {
      {"E", "MPa", "Young's modulus", Range::positive(), std::nullopt},
      {"nu", "", "Poisson's ratio", Range::half_open(0.0, 0.5), 0.0},
      {"beta", "", "exponential stiffening coefficient", Range::non_negative(), 0.0},
  };
  return s;
}

HolmesMow::HolmesMow(const ParameterValues& p)
    : lame_(lame_from_young(p.at("E"), p.at("nu"))), beta_(p.at("beta")) {}

Real HolmesMow::exponent_base(const Mat3& C) const {
  const auto [lambda, mu] = lame_;
  const Real I1 = C.trace();
  const Real I2 = 0.5 * (I1 * I1 - (C * C).trace());
  return (2.0 * mu - lambda) * (I1 - 3.0) + lambda * (I2 - 3.0) -
         (lambda + 2.0 * mu) * std::log(C.determinant());
}

Mat3 HolmesMow::exponent_base_gradient(const Mat3& C) const {
  const auto [lambda, mu] = lame_;
  return (2.0 * mu - lambda + lambda * C.trace()) * Mat3::Identity() - lambda * C -
         (lambda + 2.0 * mu) * C.inverse();
}

Real HolmesMow::energy(const Mat3& C) const {
  const Real P = exponent_base(C);
  if (beta_ == 0.0)
    return 0.25 * P;
  const Real Ha = p_wave_modulus();
  return Ha / (4.0 * beta_) * std::expm1(beta_ * P / Ha); // expm1: exact as beta -> 0
}

Mat3 HolmesMow::stress(const Mat3& C) const {
  const Real eQ = std::exp(beta_ * exponent_base(C) / p_wave_modulus());
  return 0.5 * eQ * exponent_base_gradient(C);
}

StressTangent HolmesMow::stress_tangent(const Mat3& C) const {
  const Real Ha = p_wave_modulus();
  const Real eQ = std::exp(beta_ * exponent_base(C) / Ha);
  const Mat3 dP = exponent_base_gradient(C);
  const Mat3 I = Mat3::Identity();
  const Mat6 d2P =
      lame_.lambda * (outer(I, I) - symmetric_product(I)) + Ha * symmetric_product(C.inverse());
  return {0.5 * eQ * dP, eQ * (beta_ / Ha * outer(dP, dP) + d2P)};
}

} // namespace trifem::material
