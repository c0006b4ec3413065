// SPDX-License-Identifier: MIT
#include "trifem/material/ellipsoidal_fibre_distribution.hpp"

#include "trifem/core/error.hpp"
#include "trifem/material/sphere_rule.hpp"
#include "trifem/material/uncoupled.hpp"

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
      resolution_schema(),
  };
  return s;
}

void EllipsoidalFibreDistribution::check(const ParameterValues& p, const std::string& context) {
  check_resolution(p, context);
}

EllipsoidalFibreDistribution::EllipsoidalFibreDistribution(const ParameterValues& p, bool uncoupled)
    : uncoupled_(uncoupled) {
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

Mat3 EllipsoidalFibreDistribution::deviatoric_sum(const Mat3& C, Mat6* D, Real* W) const {
  // I_n~ = s I_n with s = I3^(-1/3); with a = dW_n/dI_n~ and c = d2W_n/dI_n~2 of each direction,
  // dW/dC = sum a dI_n~/dC and d2W/dC2 = sum c dI_n~/dC (x) dI_n~/dC + sum a d2I_n~/dC2, where
  // the sums of a dI_n~/dC and a d2I_n~/dC2 are the isochoric scaling of sum a {I_n, n (x) n, 0}
  // (linear in it: uncoupled::isochoric once)
  const Real s = std::pow(C.determinant(), -1.0 / 3.0);
  const Vec6 c_voigt = voigt::strain(C);
  const Mat3 Ci = C.inverse();
  uncoupled::ScalarFunction weighted;
  Mat6 outer = Mat6::Zero();
  if (W)
    *W = 0.0;
  for (const Direction& d : directions_) {
    const Real In = d.N.dot(c_voigt);
    const Real x = s * In - 1.0;
    if (!(x > 0.0) || d.weight == 0.0)
      continue;
    const Real x2 = std::pow(x, d.beta - 2.0);
    const Real a = d.weight * d.beta * x2 * x;
    const Mat3 N = voigt::from_stress(d.N);
    weighted.value += a * In;
    weighted.gradient += a * N;
    if (W)
      *W += d.weight * x2 * x * x;
    if (D) {
      const Mat3 g = s * (N - In / 3.0 * Ci); // dI_n~/dC
      outer.noalias() += (d.weight * d.beta * (d.beta - 1.0) * x2) * voigt::outer(g, g);
    }
  }
  const uncoupled::ScalarFunction iso = uncoupled::isochoric(weighted, -1.0 / 3.0, C, D != nullptr);
  if (D)
    *D = 4.0 * (outer + iso.hessian);
  return 2.0 * iso.gradient;
}

Real EllipsoidalFibreDistribution::energy(const Mat3& C) const {
  if (uncoupled_) {
    Real W = 0.0;
    (void)deviatoric_sum(C, nullptr, &W);
    return W;
  }
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
  if (uncoupled_)
    return deviatoric_sum(C, nullptr, nullptr);
  return voigt::from_stress(sum(C, nullptr));
}

StressTangent EllipsoidalFibreDistribution::stress_tangent(const Mat3& C) const {
  StressTangent st;
  st.S = uncoupled_ ? deviatoric_sum(C, &st.D, nullptr) : voigt::from_stress(sum(C, &st.D));
  return st;
}

} // namespace trifem::material
