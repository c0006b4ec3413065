// SPDX-License-Identifier: MIT
#include "trifem/material/sphere_rule.hpp"

#include "trifem/core/error.hpp"

#include <cmath>
#include <numbers>
#include <utility>

namespace trifem::material {
namespace {

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

SphereRule sphere_rule(int resolution) {
  // The cubed sphere: the faces x = 1, y = 1, z = 1 of the cube (the half sphere; the faces
  // -1 hold the directions -n, which give the same terms) in equiangular coordinates
  // (a, b) in [-pi/4, pi/4]^2, n = (1, tan a, tan b)/|.| on the face x = 1 (cyclically on the
  // others), with the k-point Gauss-Legendre rule in a and b and the area element
  // dS = (1 + A^2)(1 + B^2)/(1 + A^2 + B^2)^(3/2) da db, A = tan a, B = tan b.
  const int k = resolution;
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
  SphereRule rule;
  rule.directions = std::move(n);
  for (std::size_t i = 0; i < w.size(); ++i)
    rule.weights.push_back(w[i] * (1.0 + eps * g[i]));
  return rule;
}

ParameterSchema resolution_schema() {
  return {"resolution", "",
          "Gauss points along each edge of a cube face of the rule on the sphere (an integer; "
          "3 resolution^2 directions)",
          Range::closed(kMinSphereResolution, kMaxSphereResolution), 12.0};
}

void check_resolution(const ParameterValues& p, const std::string& context) {
  const Real r = p.at("resolution");
  TRIFEM_CHECK(r == std::floor(r), "{}.resolution = {}: must be an integer", context, r);
}

} // namespace trifem::material
