// SPDX-License-Identifier: MIT
#include "trifem/material/ellipsoidal_fibre_distribution.hpp"

#include "trifem/core/error.hpp"
#include "trifem/material/sphere_rule.hpp"

#include <cmath>
#include <numbers>
#include <numeric>

namespace trifem::material {
namespace {

/// (n1^2/a1^2 + n2^2/a2^2 + n3^2/a3^2)^(-1/2), a component with n_i = 0 left out and one with
/// a_i = 0 (and n_i != 0) making it 0.
Real ellipsoid(const Vec3& n, const Vec3& a) {
  Real sum = 0.0;
  for (int i = 0; i < 3; ++i) {
    if (n[i] == 0.0)
      continue;
    if (a[i] == 0.0)
      return 0.0;
    sum += (n[i] / a[i]) * (n[i] / a[i]);
  }
  return 1.0 / std::sqrt(sum);
}

} // namespace

const std::vector<ParameterSchema>& EllipsoidalFibreDistribution::schema() {
  static const std::vector<ParameterSchema> s = {
      {"ksi", "MPa", "fibre moduli along x, y, z (semi-axes of the modulus ellipsoid)",
       Range::non_negative(), std::nullopt, ParameterKind::Vector},
      {"beta", "", "powers of (I_n - 1) along x, y, z (semi-axes of the power ellipsoid)",
       Range{2.0, 1e300, false, false}, std::nullopt, ParameterKind::Vector},
      {"resolution", "",
       "Gauss points along each edge of a cube face of the rule on the sphere (an integer; "
       "3 resolution^2 directions)",
       Range::closed(kMinSphereResolution, kMaxSphereResolution), 12.0},
  };
  return s;
}

void EllipsoidalFibreDistribution::check(const ParameterValues& p, const std::string& context) {
  const Real r = p.at("resolution");
  TRIFEM_CHECK(r == std::floor(r), "{}.resolution = {}: must be an integer", context, r);
}

EllipsoidalFibreDistribution::EllipsoidalFibreDistribution(const ParameterValues& p) {
  check(p, "ellipsoidal-fibre-distribution");
  const Vec3 ksi = vector_value(p, "ksi"), beta = vector_value(p, "beta");
  const Real r = p.at("resolution");
  TRIFEM_CHECK((ksi.array() >= 0.0).all() && (beta.array() >= 2.0).all() && ksi.allFinite() &&
                   beta.allFinite() && r >= kMinSphereResolution && r <= kMaxSphereResolution,
               "ellipsoidal-fibre-distribution: ksi = [{}, {}, {}], beta = [{}, {}, {}], "
               "resolution = {}: need ksi >= 0, beta >= 2, resolution in [{}, {}]",
               ksi.x(), ksi.y(), ksi.z(), beta.x(), beta.y(), beta.z(), r, kMinSphereResolution,
               kMaxSphereResolution);
  const SphereRule rule = sphere_rule(static_cast<int>(r));
  // the rule's weights on the half sphere, scaled to the area 4 pi of the whole sphere (each
  // direction stands for n and -n)
  const Real total = std::accumulate(rule.weights.begin(), rule.weights.end(), 0.0);
  for (std::size_t i = 0; i < rule.directions.size(); ++i) {
    const Vec3& n = rule.directions[i];
    directions_.push_back({voigt::stress(n * n.transpose()),
                           4.0 * std::numbers::pi * rule.weights[i] / total * ellipsoid(n, ksi),
                           ellipsoid(n, beta)});
  }
}

Vec6 EllipsoidalFibreDistribution::sum(const Mat3& C, Mat6* D) const {
  // I_n - 1 = (n (x) n) : (C - I), exactly 0 at C = I
  const Vec6 strain = voigt::strain(C - Mat3::Identity());
  Vec6 S = Vec6::Zero();
  if (D)
    D->setZero();
  for (const Direction& d : directions_) {
    const Real x = d.N.dot(strain);
    if (!(x > 0.0) || d.weight == 0.0)
      continue;
    const Real x2 = std::pow(x, d.beta - 2.0); // (I_n - 1)^(beta - 2)
    S += (2.0 * d.weight * d.beta * x2 * x) * d.N;
    if (D)
      D->noalias() += (4.0 * d.weight * d.beta * (d.beta - 1.0) * x2) * d.N * d.N.transpose();
  }
  return S;
}

Real EllipsoidalFibreDistribution::energy(const Mat3& C) const {
  const Vec6 strain = voigt::strain(C - Mat3::Identity());
  Real W = 0.0;
  for (const Direction& d : directions_) {
    const Real x = d.N.dot(strain);
    if (x > 0.0)
      W += d.weight * std::pow(x, d.beta);
  }
  return W;
}

Mat3 EllipsoidalFibreDistribution::stress(const Mat3& C) const {
  return voigt::from_stress(sum(C, nullptr));
}

StressTangent EllipsoidalFibreDistribution::stress_tangent(const Mat3& C) const {
  StressTangent st;
  st.S = voigt::from_stress(sum(C, &st.D));
  return st;
}

} // namespace trifem::material
