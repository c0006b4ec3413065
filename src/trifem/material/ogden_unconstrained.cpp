// SPDX-License-Identifier: MIT
#include "trifem/material/ogden_unconstrained.hpp"

#include "trifem/core/error.hpp"
#include "trifem/material/uncoupled.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace trifem::material {
namespace {

constexpr int kUnconstrainedTerms = 6;

std::string unconstrained_key(const char* name, int i) {
  return name + std::to_string(i + 1);
}

} // namespace

const std::vector<ParameterSchema>& OgdenUnconstrained::schema() {
  static const std::vector<ParameterSchema> s = [] {
    std::vector<ParameterSchema> keys;
    for (int i = 0; i < kUnconstrainedTerms; ++i) {
      keys.push_back({unconstrained_key("c", i), "MPa",
                      "coefficient of term " + std::to_string(i + 1) + " (c1 + ... + c6 > 0)",
                      Range{}, 0.0});
      keys.push_back({unconstrained_key("m", i), "",
                      "exponent of term " + std::to_string(i + 1) + " (nonzero)", Range{}, 1.0});
    }
    keys.push_back({"cp", "MPa", "volumetric coefficient (Lame's lambda)", Range::non_negative(),
                    std::nullopt});
    return keys;
  }();
  return s;
}

void OgdenUnconstrained::check(const ParameterValues& p, const std::string& context) {
  Real sum = 0.0;
  for (int i = 0; i < kUnconstrainedTerms; ++i) {
    const Real c = p.at(unconstrained_key("c", i));
    TRIFEM_CHECK(c == 0.0 || p.at(unconstrained_key("m", i)) != 0.0,
                 "{}.m{} = 0: the exponent of a term with c{} != 0 must be nonzero", context, i + 1,
                 i + 1);
    sum += c;
  }
  TRIFEM_CHECK(sum > 0.0,
               "{0}.c1 + ... + {0}.c6 = {1}: must be > 0 (the shear modulus is half "
               "of it)",
               context, sum);
}

OgdenUnconstrained::OgdenUnconstrained(const ParameterValues& p) : cp_(p.at("cp")) {
  check(p, "ogden-unconstrained");
  for (int i = 0; i < kUnconstrainedTerms; ++i)
    if (const Real c = p.at(unconstrained_key("c", i)); c != 0.0)
      terms_.push_back({c, p.at(unconstrained_key("m", i))});
}

Real OgdenUnconstrained::shear_modulus() const {
  Real sum = 0.0;
  for (const Term& t : terms_)
    sum += t.c;
  return 0.5 * sum;
}

void OgdenUnconstrained::evaluate(const Mat3& C, bool with_hessian, Real& W, Mat3& dW,
                                  Mat6* d2W) const {
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(C);
  const Mat3 Ci = C.inverse();
  const Real I3 = C.determinant(), J = std::sqrt(I3), lnI3 = std::log(I3);
  W = 0.5 * cp_ * (J - 1.0) * (J - 1.0);
  const Mat3 dJ = 0.5 * J * Ci;
  dW = cp_ * (J - 1.0) * dJ;
  Mat6 Ci_Ci, Ci_sym;
  if (with_hessian) {
    Ci_Ci = voigt::outer(Ci, Ci);
    Ci_sym = voigt::symmetric_product(Ci);
    *d2W = cp_ * (voigt::outer(dJ, dJ) + (J - 1.0) * (0.25 * J * Ci_Ci - 0.5 * J * Ci_sym));
  }
  for (const Term& t : terms_) {
    const Real w = t.c / (t.m * t.m);
    const uncoupled::ScalarFunction f =
        uncoupled::power_trace(eig.eigenvalues(), eig.eigenvectors(), 0.5 * t.m, with_hessian);
    W += w * (f.value - 3.0 - 0.5 * t.m * lnI3);
    dW += w * (f.gradient - 0.5 * t.m * Ci);
    if (with_hessian)
      *d2W += w * (f.hessian + 0.5 * t.m * Ci_sym);
  }
}

Real OgdenUnconstrained::energy(const Mat3& C) const {
  Real W;
  Mat3 dW;
  evaluate(C, false, W, dW, nullptr);
  return W;
}

Mat3 OgdenUnconstrained::stress(const Mat3& C) const {
  Real W;
  Mat3 dW;
  evaluate(C, false, W, dW, nullptr);
  return 2.0 * dW;
}

StressTangent OgdenUnconstrained::stress_tangent(const Mat3& C) const {
  Real W;
  Mat3 dW;
  Mat6 d2W;
  evaluate(C, true, W, dW, &d2W);
  return {2.0 * dW, 4.0 * d2W};
}

} // namespace trifem::material
