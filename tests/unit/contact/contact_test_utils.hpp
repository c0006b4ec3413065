// SPDX-License-Identifier: MIT
// Geometry generators shared by the contact tests: warped (non-planar, twisted) quads, wavy
// structured surfaces and dense-sampling reference solutions.
#pragma once

#include "trifem/contact/projection.hpp"

#include <cmath>
#include <functional>
#include <random>

namespace trifem::contact::test {

/// Random rotation (unit quaternion).
inline Mat3 random_rotation(std::mt19937& rng) {
  std::normal_distribution<Real> g;
  Eigen::Quaterniond q(g(rng), g(rng), g(rng), g(rng));
  return q.normalized().toRotationMatrix();
}

/// A unit square (counter-clockwise, normal +z) with random in-plane distortion (±0.15),
/// out-of-plane warp (±warp: a non-zero twist x_,12), rotated and translated at random.
inline fe::QuadCoords warped_quad(std::mt19937& rng, Real warp = 0.2) {
  std::uniform_real_distribution<Real> u(-1, 1);
  fe::QuadCoords X;
  const Real base[4][2] = {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
  for (int a = 0; a < 4; ++a)
    X.row(a) << base[a][0] + 0.15 * u(rng), base[a][1] + 0.15 * u(rng), warp * u(rng);
  // Make sure the warp is a real twist: push nodes 0, 2 up and 1, 3 down.
  X(0, 2) += 0.5 * warp;
  X(2, 2) += 0.5 * warp;
  X(1, 2) -= 0.5 * warp;
  X(3, 2) -= 0.5 * warp;
  const Mat3 R = random_rotation(rng);
  const Vec3 shift(u(rng), u(rng), u(rng));
  for (int a = 0; a < 4; ++a)
    X.row(a) = (R * X.row(a).transpose() + shift).transpose();
  return X;
}

/// A structured nx × ny grid surface with node (i, j) at (i h + jitter, j h + jitter,
/// z(x, y) + jitter) and facets counter-clockwise in (x, y) (normal towards +z).
struct GridSurface {
  mesh::Surface surface;
  std::vector<Vec3> x;
};

inline GridSurface grid_surface(int nx, int ny, Real h, const std::function<Real(Real, Real)>& z,
                                Real jitter, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> u(-1, 1);
  GridSurface g;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const Real px = i * h + jitter * h * u(rng), py = j * h + jitter * h * u(rng);
      g.x.emplace_back(px, py, z(px, py) + jitter * h * u(rng));
    }
  const auto id = [nx](int i, int j) { return static_cast<Index>(j * (nx + 1) + i); };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      mesh::Facet f;
      f.nodes = {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)};
      g.surface.facets.push_back(f);
    }
  return g;
}

/// Reference distance from p to the bilinear patch X (ξ ∈ [-1,1]²) by sampling: a 21 × 21 grid,
/// then four zooms (factor 10) around the best sample; resolution ~1e-5 in ξ. Independent of the
/// Newton projection (no derivatives, no clamping logic).
inline Real sampled_distance(const Vec3& p, const fe::QuadCoords& X) {
  Vec2 centre = Vec2::Zero();
  Real half = 1, best_d = std::numeric_limits<Real>::infinity();
  for (int level = 0; level < 5; ++level) {
    Vec2 best = centre;
    for (int i = 0; i <= 20; ++i)
      for (int j = 0; j <= 20; ++j) {
        Vec2 xi = centre + half * Vec2(-1 + 0.1 * i, -1 + 0.1 * j);
        xi = xi.cwiseMax(-1.0).cwiseMin(1.0);
        const Real d = (p - X.transpose() * fe::quad4_shape(xi)).norm();
        if (d < best_d) {
          best_d = d;
          best = xi;
        }
      }
    centre = best;
    half *= 0.1;
  }
  return best_d;
}

/// Sampled distance of p to every facet of s whose node box lies within `cutoff` of p; the
/// other facets are provably farther than `cutoff` (the patch lies in the box of its nodes)
/// and get +infinity.
inline std::vector<Real> sampled_distances(const Vec3& p, const ContactSurface& s,
                                           const NodePositions& x, Real cutoff) {
  std::vector<Real> d(s.num_facets(), std::numeric_limits<Real>::infinity());
  for (Index f = 0; f < s.num_facets(); ++f) {
    const fe::QuadCoords X = s.coords(f, x);
    const Vec3 lo = X.colwise().minCoeff().transpose(), hi = X.colwise().maxCoeff().transpose();
    if ((p - p.cwiseMax(lo).cwiseMin(hi)).norm() <= cutoff)
      d[f] = sampled_distance(p, X);
  }
  return d;
}

} // namespace trifem::contact::test
