// SPDX-License-Identifier: MIT
#include "trifem/material/fibre_distribution.hpp"

#include "trifem/core/error.hpp"

#include <cmath>
#include <numbers>

namespace trifem::material {
namespace {

constexpr Real kMinResolution = 3.0, kMaxResolution = 64.0;

/// The k-point Gauss-Legendre rule on [-1, 1]: nodes and weights, by Newton's method on P_k
/// from the usual initial guesses.
std::vector<std::pair<Real, Real>> gauss_legendre(int k) {
  std::vector<std::pair<Real, Real>> rule;
  for (int i = 0; i < k; ++i) {
    Real x = std::cos(std::numbers::pi * (i + 0.75) / (k + 0.5));
    Real dp = 1.0;
    for (int it = 0; it < 100; ++it) {
      Real p0 = 1.0, p1 = x; // P_0, P_1; after the loop p1 = P_k, p0 = P_(k-1)
      for (int j = 2; j <= k; ++j) {
        const Real p2 = ((2 * j - 1) * x * p1 - (j - 1) * p0) / j;
        p0 = p1;
        p1 = p2;
      }
      dp = k * (x * p1 - p0) / (x * x - 1.0);
      const Real step = p1 / dp;
      x -= step;
      if (std::abs(step) <= 1e-16)
        break;
    }
    rule.emplace_back(x, 2.0 / ((1.0 - x * x) * dp * dp));
  }
  return rule;
}

} // namespace

const std::vector<ParameterSchema>& FibreDistribution::schema() {
  static const std::vector<ParameterSchema> s = {
      {"ksi", "MPa", "fibre modulus", Range::non_negative(), std::nullopt},
      {"alpha", "", "coefficient of (I_n - 1)^beta in the exponential", Range::non_negative(),
       std::nullopt},
      {"beta", "", "power of (I_n - 1)", Range{2.0, 1e300, false, false}, std::nullopt},
      {"semi_axes", "",
       "semi-axes of the ellipsoidal fibre density along x, y, z (equal: spherical)",
       Range::positive(), std::nullopt, ParameterKind::Vector},
      {"resolution", "",
       "Gauss points along each edge of a cube face of the rule on the sphere (an integer; "
       "3 resolution^2 directions)",
       Range::closed(kMinResolution, kMaxResolution), 12.0},
  };
  return s;
}

void FibreDistribution::check(const ParameterValues& p, const std::string& context) {
  const Real r = p.at("resolution");
  TRIFEM_CHECK(r == std::floor(r), "{}.resolution = {}: must be an integer", context, r);
}

FibreDistribution::FibreDistribution(const ParameterValues& p)
    : ksi_(p.at("ksi")), alpha_(p.at("alpha")), beta_(p.at("beta")) {
  check(p, "fibre-distribution");
  const Vec3 a = vector_value(p, "semi_axes");
  const Real r = p.at("resolution");
  TRIFEM_CHECK(ksi_ >= 0.0 && alpha_ >= 0.0 && beta_ >= 2.0 && (a.array() > 0.0).all() &&
                   a.allFinite() && r >= kMinResolution && r <= kMaxResolution,
               "fibre-distribution: ksi = {}, alpha = {}, beta = {}, semi_axes = [{}, {}, {}], "
               "resolution = {}: need ksi >= 0, alpha >= 0, beta >= 2, semi_axes > 0, "
               "resolution in [{}, {}]",
               ksi_, alpha_, beta_, a.x(), a.y(), a.z(), r, kMinResolution, kMaxResolution);
  // The cubed sphere: the faces x = 1, y = 1, z = 1 of the cube (the half sphere; the faces
  // -1 hold the directions -n, which give the same terms) in equiangular coordinates
  // (a, b) in [-pi/4, pi/4]^2, n = (1, tan a, tan b)/|.| on the face x = 1 (cyclically on the
  // others), with the k-point Gauss-Legendre rule in a and b and the area element
  // dS = (1 + A^2)(1 + B^2)/(1 + A^2 + B^2)^(3/2) da db, A = tan a, B = tan b.
  const int k = static_cast<int>(r);
  const auto gauss = gauss_legendre(k);
  std::vector<Vec3> n;
  std::vector<Real> w;
  for (int face = 0; face < 3; ++face)
    for (const auto& [xa, wa] : gauss)
      for (const auto& [xb, wb] : gauss) {
        const Real A = std::tan(0.25 * std::numbers::pi * xa);
        const Real B = std::tan(0.25 * std::numbers::pi * xb);
        const Real r2 = 1.0 + A * A + B * B;
        Vec3 v;
        v[face] = 1.0;
        v[(face + 1) % 3] = A;
        v[(face + 2) % 3] = B;
        n.push_back(v / std::sqrt(r2));
        w.push_back(wa * wb * (1.0 + A * A) * (1.0 + B * B) / (r2 * std::sqrt(r2)));
      }
  // The rule has the symmetries of the cube, so it integrates n (x) n exactly (I/3 once the
  // weights sum to 1), and n (x) n (x) n (x) n exactly iff <n1^4 + n2^4 + n3^4> = 3/5. One
  // correction of the weights, w (1 + eps g) with g = n1^4 + n2^4 + n3^4 - 3/5 (a function with
  // the same symmetries), makes that exact at every resolution: it changes the weights by at
  // most 8% at k = 3, 0.4% at k = 4, 2e-9 at k = 8 and round-off from k = 12 on.
  Real wg = 0.0, wgg = 0.0;
  std::vector<Real> g(n.size());
  for (std::size_t i = 0; i < n.size(); ++i) {
    g[i] = n[i].array().pow(4).sum() - 0.6;
    wg += w[i] * g[i];
    wgg += w[i] * g[i] * g[i];
  }
  const Real eps = -wg / wgg;
  const Vec3 inverse_square = a.array().square().inverse().matrix();
  Real total = 0.0;
  for (std::size_t i = 0; i < n.size(); ++i) {
    const Real weight = w[i] * (1.0 + eps * g[i]) /
                        std::sqrt(n[i].cwiseProduct(n[i]).dot(inverse_square)); // times R(n)
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
