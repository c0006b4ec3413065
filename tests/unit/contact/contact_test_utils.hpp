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
inline FacetCoords warped_quad(std::mt19937& rng, Real warp = 0.2) {
  std::uniform_real_distribution<Real> u(-1, 1);
  FacetNodePositions X(4, 3);
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
  return {mesh::FacetType::Quad4, X};
}

/// A facet of `type` of about unit size (normal about +z before the rotation): the reference
/// facet (quads scaled to [-0.5, 0.5]²) with random in-plane distortion of every node (±0.1)
/// and out-of-plane offsets (±warp; on quadratic facets the mid-edge nodes move by up to
/// `warp` as well: curved edges), rotated and translated at random.
inline FacetCoords random_facet(mesh::FacetType type, std::mt19937& rng, Real warp = 0.2) {
  std::uniform_real_distribution<Real> u(-1, 1);
  const fe::ReferenceFacet& ref = fe::reference_facet(type);
  const Real scale = is_triangle(type) ? 1.0 : 0.5;
  FacetNodePositions X(ref.num_nodes(), 3);
  for (int a = 0; a < ref.num_nodes(); ++a)
    X.row(a) << scale * ref.nodes()(a, 0) + 0.1 * u(rng), scale * ref.nodes()(a, 1) + 0.1 * u(rng),
        warp * u(rng);
  const Mat3 R = random_rotation(rng);
  const Vec3 shift(u(rng), u(rng), u(rng));
  for (int a = 0; a < ref.num_nodes(); ++a)
    X.row(a) = (R * X.row(a).transpose() + shift).transpose();
  return {type, X};
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

/// The point of the reference facet of `type` nearest to ξ (a clamp).
inline Vec2 clamp_to_facet(mesh::FacetType type, Vec2 xi) {
  if (!is_triangle(type))
    return xi.cwiseMax(-1.0).cwiseMin(1.0);
  xi = xi.cwiseMax(0.0);
  const Real excess = xi.sum() - 1;
  if (excess > 0) { // project onto the hypotenuse, then clamp its ends
    xi.array() -= 0.5 * excess;
    xi = xi.cwiseMax(0.0).cwiseMin(1.0);
  }
  return xi;
}

/// Reference distance from p to the patch X by sampling: a 21 × 21 grid over the square box of
/// the reference facet (points clamped into it), then four zooms (factor 10) around the best
/// sample; resolution ~1e-5 in ξ. Independent of the Newton projection (no derivatives, no
/// edge logic).
inline Real sampled_distance(const Vec3& p, const FacetCoords& X) {
  const bool triangle = is_triangle(X.type());
  Vec2 centre = triangle ? Vec2(0.5, 0.5) : Vec2::Zero();
  Real half = triangle ? 0.5 : 1, best_d = std::numeric_limits<Real>::infinity();
  for (int level = 0; level < 5; ++level) {
    Vec2 best = centre;
    for (int i = 0; i <= 20; ++i)
      for (int j = 0; j <= 20; ++j) {
        const Vec2 xi = clamp_to_facet(X.type(), centre + half * Vec2(-1 + 0.1 * i, -1 + 0.1 * j));
        const Real d = (p - X.x.transpose() * X.reference->shape(xi)).norm();
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
/// other facets are provably farther than `cutoff` (a linear or bilinear patch lies in the box
/// of its nodes) and get +infinity.
inline std::vector<Real> sampled_distances(const Vec3& p, const ContactSurface& s,
                                           const NodePositions& x, Real cutoff) {
  std::vector<Real> d(s.num_facets(), std::numeric_limits<Real>::infinity());
  for (Index f = 0; f < s.num_facets(); ++f) {
    const FacetCoords X = s.coords(f, x);
    const Vec3 lo = X.x.colwise().minCoeff().transpose().array() - 2 * facet_bulge(X);
    const Vec3 hi = X.x.colwise().maxCoeff().transpose().array() + 2 * facet_bulge(X);
    if ((p - p.cwiseMax(lo).cwiseMin(hi)).norm() <= cutoff)
      d[f] = sampled_distance(p, X);
  }
  return d;
}

} // namespace trifem::contact::test
