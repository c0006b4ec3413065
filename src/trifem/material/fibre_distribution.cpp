// SPDX-License-Identifier: MIT
#include "trifem/material/fibre_distribution.hpp"

#include "trifem/core/error.hpp"
#include "trifem/material/sphere_rule.hpp"

#include <cmath>

namespace trifem::material {
const std::vector<ParameterSchema>& FibreDistribution::schema() {
  static const std::vector<ParameterSchema> s = {
      {"ksi", "MPa", "fibre modulus", Range::non_negative(), std::nullopt},
      {"alpha", "", "coefficient of (I_n - 1)^beta in the exponential", Range::non_negative(),
       std::nullopt},
      {"beta", "", "power of (I_n - 1)", Range{2.0, 1e300, false, false}, std::nullopt},
      {"semi_axes", "",
       "semi-axes of the ellipsoidal fibre density along x, y, z (equal: spherical)",
       Range::positive(), std::nullopt, ParameterKind::Vector},
      resolution_schema(),
  };
  return s;
}

void FibreDistribution::check(const ParameterValues& p, const std::string& context) {
  check_resolution(p, context);
}

FibreDistribution::FibreDistribution(const ParameterValues& p)
    : ksi_(p.at("ksi")), alpha_(p.at("alpha")), beta_(p.at("beta")) {
  check(p, "fibre-distribution");
  const Vec3 a = vector_value(p, "semi_axes");
  const Real r = p.at("resolution");
  TRIFEM_CHECK(ksi_ >= 0.0 && alpha_ >= 0.0 && beta_ >= 2.0 && (a.array() > 0.0).all() &&
                   a.allFinite() && r >= kMinSphereResolution && r <= kMaxSphereResolution,
               "fibre-distribution: ksi = {}, alpha = {}, beta = {}, semi_axes = [{}, {}, {}], "
               "resolution = {}: need ksi >= 0, alpha >= 0, beta >= 2, semi_axes > 0, "
               "resolution in [{}, {}]",
               ksi_, alpha_, beta_, a.x(), a.y(), a.z(), r, kMinSphereResolution,
               kMaxSphereResolution);
  const SphereRule rule = sphere_rule(static_cast<int>(r));
  const std::vector<Vec3>& n = rule.directions;
  const Vec3 inverse_square = a.array().square().inverse().matrix();
  Real total = 0.0;
  for (std::size_t i = 0; i < n.size(); ++i) {
    const Real weight =
        rule.weights[i] / std::sqrt(n[i].cwiseProduct(n[i]).dot(inverse_square)); // times R(n)
    directions_.push_back({voigt::stress(n[i] * n[i].transpose()), weight});
    total += weight;
  }
  for (Direction& d : directions_)
    d.weight /= total;
}

Vec6 FibreDistribution::sum(const Mat3& C, Mat6* D) const {
  // I_n - 1 = n.(C - I) n = (n (x) n) : (C - I), exactly 0 at C = I
  const Vec6 strain = voigt::strain(C - Mat3::Identity());
  Vec6 S = Vec6::Zero();
  if (D)
    D->setZero();
  for (const Direction& d : directions_) {
    const Real x = d.N.dot(strain);
    if (!(x > 0.0))
      continue;
    // W_f' = ksi x^(beta-1) e^(alpha x^beta), W_f'' = ksi x^(beta-2) [beta (alpha x^beta + 1)
    // - 1] e^(alpha x^beta), as FibreExpPow
    const Real x2 = std::pow(x, beta_ - 2.0), xb = x2 * x * x;
    const Real e = ksi_ * d.weight * std::exp(alpha_ * xb);
    S += (2.0 * x2 * x * e) * d.N;
    if (D)
      D->noalias() += (4.0 * x2 * (beta_ * (alpha_ * xb + 1.0) - 1.0) * e) * d.N * d.N.transpose();
  }
  return S;
}

Real FibreDistribution::energy(const Mat3& C) const {
  const Vec6 strain = voigt::strain(C - Mat3::Identity());
  Real W = 0.0;
  for (const Direction& d : directions_) {
    const Real x = d.N.dot(strain);
    if (!(x > 0.0))
      continue;
    const Real xb = std::pow(x, beta_);
    // alpha = 0: the limit ksi/beta x^beta; expm1 is exact as alpha -> 0
    W += d.weight * (alpha_ == 0.0 ? xb / beta_ : std::expm1(alpha_ * xb) / (alpha_ * beta_));
  }
  return ksi_ * W;
}

Mat3 FibreDistribution::stress(const Mat3& C) const {
  return voigt::from_stress(sum(C, nullptr)); // as in stress_tangent, to the last bit
}

StressTangent FibreDistribution::stress_tangent(const Mat3& C) const {
  StressTangent st;
  st.S = voigt::from_stress(sum(C, &st.D));
  return st;
}

} // namespace trifem::material
