// SPDX-License-Identifier: MIT
#include "trifem/material/ogden.hpp"

#include "trifem/core/error.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace trifem::material {
namespace {

constexpr int kMaxTerms = 3;

using Eigensystem = Eigen::SelfAdjointEigenSolver<Mat3>;

std::string term_key(const char* name, int i) {
  return name + std::to_string(i + 1);
}

} // namespace

const std::vector<ParameterSchema>& Ogden::schema() {
  static const std::vector<ParameterSchema> s = {
      {"c1", "MPa", "coefficient of term 1 (c1 + c2 + c3 > 0)", Range{}, std::nullopt},
      {"m1", "", "exponent of term 1 (nonzero)", Range{}, std::nullopt},
      {"c2", "MPa", "coefficient of term 2 (0: no term 2)", Range{}, 0.0},
      {"m2", "", "exponent of term 2 (nonzero if c2 != 0)", Range{}, 1.0},
      {"c3", "MPa", "coefficient of term 3 (0: no term 3)", Range{}, 0.0},
      {"m3", "", "exponent of term 3 (nonzero if c3 != 0)", Range{}, 1.0},
      {"k", "MPa", "bulk modulus", Range::positive(), std::nullopt},
  };
  return s;
}

void Ogden::check(const ParameterValues& p, const std::string& context) {
  Real sum = 0.0;
  for (int i = 0; i < kMaxTerms; ++i) {
    const Real c = p.at(term_key("c", i)), m = p.at(term_key("m", i));
    TRIFEM_CHECK(c == 0.0 || m != 0.0, "{0}.m{1} = 0: must be nonzero when {0}.c{1} = {2} != 0",
                 context, i + 1, c);
    sum += c;
  }
  TRIFEM_CHECK(
      sum > 0.0,
      "{0}.c1 + {0}.c2 + {0}.c3 = {1}: must be > 0 (the shear modulus is (c1 + c2 + c3)/2)",
      context, sum);
}

Ogden::Ogden(const ParameterValues& p) : k_(p.at("k")) {
  check(p, "ogden");
  for (int i = 0; i < kMaxTerms; ++i)
    if (p.at(term_key("c", i)) != 0.0)
      terms_.push_back({p.at(term_key("c", i)), p.at(term_key("m", i))});
}

Real Ogden::shear_modulus() const {
  Real sum = 0.0;
  for (const Term& t : terms_)
    sum += t.c;
  return 0.5 * sum;
}

uncoupled::ScalarFunction Ogden::strain_energy(const Mat3& C, bool with_hessian) const {
  const Eigensystem eig(C);
  uncoupled::ScalarFunction W;
  for (const Term& t : terms_) {
    const Real weight = t.c / (t.m * t.m);
    W.value -= 3.0 * weight;
    uncoupled::accumulate(
        W, weight,
        uncoupled::isochoric(
            uncoupled::power_trace(eig.eigenvalues(), eig.eigenvectors(), 0.5 * t.m, with_hessian),
            -t.m / 6.0, C, with_hessian));
  }
  uncoupled::accumulate(W, k_, uncoupled::log_volumetric(C, with_hessian));
  return W;
}

} // namespace trifem::material
