// SPDX-License-Identifier: MIT
#include "trifem/material/mooney_rivlin.hpp"

#include "trifem/core/error.hpp"

#include <cmath>

namespace trifem::material {
namespace {

/// I1 = tr C with its derivatives (d2I1/dC2 = 0).
uncoupled::ScalarFunction first_invariant(const Mat3& C) {
  return {C.trace(), Mat3::Identity(), Mat6::Zero()};
}

/// I2 = ((tr C)^2 - tr C^2)/2 with its derivatives.
uncoupled::ScalarFunction second_invariant(const Mat3& C, bool with_hessian) {
  const Real I1 = C.trace();
  const Mat3 I = Mat3::Identity();
  uncoupled::ScalarFunction f{0.5 * (I1 * I1 - (C * C).trace()), I1 * I - C, Mat6::Zero()};
  if (with_hessian)
    f.hessian = voigt::outer(I, I) - voigt::symmetric_product(I);
  return f;
}

} // namespace

const std::vector<ParameterSchema>& MooneyRivlin::schema() {
  static const std::vector<ParameterSchema> s = {
      {"c1", "MPa", "coefficient of I1~ - 3 (c1 + c2 > 0)", Range{}, std::nullopt},
      {"c2", "MPa", "coefficient of I2~ - 3 (c1 + c2 > 0)", Range{}, 0.0},
      {"k", "MPa", "bulk modulus", Range::positive(), std::nullopt},
  };
  return s;
}

void MooneyRivlin::check(const ParameterValues& p, const std::string& context) {
  const Real c1 = p.at("c1"), c2 = p.at("c2");
  TRIFEM_CHECK(c1 + c2 > 0.0,
               "{0}.c1 + {0}.c2 = {1} + {2}: must be > 0 (the shear modulus is 2 (c1 + c2))",
               context, c1, c2);
}

MooneyRivlin::MooneyRivlin(const ParameterValues& p)
    : c1_(p.at("c1")), c2_(p.at("c2")), k_(p.at("k")) {
  check(p, "mooney-rivlin");
}

uncoupled::ScalarFunction MooneyRivlin::strain_energy(const Mat3& C, bool with_hessian) const {
  uncoupled::ScalarFunction W;
  W.value = -3.0 * (c1_ + c2_);
  uncoupled::accumulate(W, c1_,
                        uncoupled::isochoric(first_invariant(C), -1.0 / 3.0, C, with_hessian));
  uncoupled::accumulate(
      W, c2_, uncoupled::isochoric(second_invariant(C, with_hessian), -2.0 / 3.0, C, with_hessian));
  uncoupled::accumulate(W, k_, uncoupled::log_volumetric(C, with_hessian));
  return W;
}

} // namespace trifem::material
