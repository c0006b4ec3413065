// SPDX-License-Identifier: MIT
// Closest-point projection: exactness on warped quads, independent dense-sampling reference,
// shared edges, convex kinks and corners, search distance, and a point sliding over 24 facets.
#include "contact_test_utils.hpp"

#include "trifem/mesh/box.hpp"

#include <gtest/gtest.h>
#include <set>

using namespace trifem;
using namespace trifem::contact;

TEST(Projection, RecoversXiAndGapOnWarpedQuads) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<Real> u(-0.9, 0.9), g(0.005, 0.2);
  Real err_xi = 0, err_gap = 0, err_normal = 0, residual = 0;
  for (int q = 0; q < 50; ++q) {
    const FacetCoords X = test::warped_quad(rng);
    ASSERT_GT(evaluate_facet(X, Vec2::Zero()).x2[2].norm(), 0.02); // really twisted
    for (int k = 0; k < 40; ++k) {
      const Vec2 xi0(u(rng), u(rng));
      const Real g0 = (k % 2 ? 1 : -1) * g(rng);
      const FacetPoint fp = evaluate_facet(X, xi0);
      const Vec3 p = fp.x + g0 * fp.normal;
      const auto pr = project_onto_facet(p, X);
      ASSERT_TRUE(pr);
      ASSERT_FALSE(pr->on_boundary);
      const FacetPoint at = evaluate_facet(X, pr->xi);
      err_xi = std::max(err_xi, (pr->xi - xi0).lpNorm<Eigen::Infinity>());
      err_gap = std::max(err_gap, std::abs(pr->gap - g0));
      err_normal = std::max(err_normal, (pr->normal - fp.normal).norm());
      const Vec3 d = p - at.x;
      residual = std::max({residual, std::abs(d.dot(at.t[0])), std::abs(d.dot(at.t[1]))});
    }
  }
  std::printf("[ projection ] 2000 points on 50 warped quads: max |xi - xi0| %.2e, max |g - g0| "
              "%.2e, max |n - n0| %.2e, max |r_alpha| %.2e\n",
              err_xi, err_gap, err_normal, residual);
  EXPECT_LE(err_xi, 1e-12);
  EXPECT_LE(err_gap, 1e-12);
  EXPECT_LE(err_normal, 1e-12);
  EXPECT_LE(residual, 1e-13);
}

TEST(Projection, RecoversXiAndGapOnCurvedFacetsOfEveryType) {
  for (const auto type : {mesh::FacetType::Tri3, mesh::FacetType::Tri6, mesh::FacetType::Quad8}) {
    std::mt19937 rng(17);
    std::uniform_real_distribution<Real> u(0.05, 0.9), g(0.005, 0.1);
    Real err_xi = 0, err_gap = 0, residual = 0;
    for (int q = 0; q < 30; ++q) {
      const FacetCoords X = test::random_facet(type, rng);
      for (int k = 0; k < 20; ++k) {
        Vec2 xi0(u(rng), u(rng));
        if (is_triangle(type) && xi0.sum() > 0.95)
          xi0 *= 0.9 / xi0.sum();
        if (!is_triangle(type))
          xi0 = 2 * xi0 - Vec2::Ones();
        const Real g0 = (k % 2 ? 1 : -1) * g(rng);
        const FacetPoint fp = evaluate_facet(X, xi0);
        const auto pr = project_onto_facet(fp.x + g0 * fp.normal, X);
        ASSERT_TRUE(pr);
        ASSERT_FALSE(pr->on_boundary) << mesh::name(type);
        const FacetPoint at = evaluate_facet(X, pr->xi);
        err_xi = std::max(err_xi, (pr->xi - xi0).lpNorm<Eigen::Infinity>());
        err_gap = std::max(err_gap, std::abs(pr->gap - g0));
        const Vec3 d = fp.x + g0 * fp.normal - at.x;
        residual = std::max({residual, std::abs(d.dot(at.t[0])), std::abs(d.dot(at.t[1]))});
      }
    }
    std::printf("[ projection ] %s: max |xi - xi0| %.2e, max |g - g0| %.2e, max |r| %.2e\n",
                std::string(mesh::name(type)).c_str(), err_xi, err_gap, residual);
    EXPECT_LE(err_xi, 1e-11) << mesh::name(type);
    EXPECT_LE(err_gap, 1e-12) << mesh::name(type);
    EXPECT_LE(residual, 1e-13) << mesh::name(type);
  }
}

/// Projections onto random facets of `type` from points all around them (most beyond its
/// edges): never farther than a dense sampling of the facet, and on it.
void expect_never_farther_than_sampling(mesh::FacetType type) {
  std::mt19937 rng(12);
  std::uniform_real_distribution<Real> u(-1.2, 1.2);
  int boundary = 0;
  for (int q = 0; q < 40; ++q) {
    const FacetCoords X = type == mesh::FacetType::Quad4
                              ? test::warped_quad(rng, q % 2 ? 0.4 : 0.2)
                              : test::random_facet(type, rng, q % 2 ? 0.3 : 0.15);
    const Vec3 c = evaluate_facet(X, facet_centre(type)).x;
    for (int k = 0; k < 25; ++k) {
      const Vec3 p = c + Vec3(u(rng), u(rng), u(rng));
      const auto pr = project_onto_facet(p, X);
      ASSERT_TRUE(pr);
      boundary += pr->on_boundary;
      const Real ref = test::sampled_distance(p, X);
      EXPECT_LE(std::abs(pr->gap), ref + 1e-12);
      EXPECT_GE(std::abs(pr->gap), ref - 1e-6);
      EXPECT_LE((p - pr->point - pr->gap * pr->normal).norm(), 1e-12);
      EXPECT_TRUE(inside_facet(type, pr->xi, 1e-6));
    }
  }
  EXPECT_GT(boundary, 200) << mesh::name(type); // most points lie outside the normal prism
}

TEST(Projection, NeverFartherThanDenseSamplingIncludingOutsidePoints) {
  for (const auto type : {mesh::FacetType::Quad4, mesh::FacetType::Tri3, mesh::FacetType::Tri6,
                          mesh::FacetType::Quad8}) {
    SCOPED_TRACE(mesh::name(type));
    expect_never_farther_than_sampling(type);
  }
}

namespace {

/// Two unit facets sharing the edge x = 0 (y ∈ [-0.5, 0.5]); the right one is tilted by
/// `angle` about the y axis: angle < 0 folds it down (convex kink), > 0 up (concave kink).
test::GridSurface kinked_pair(Real angle) {
  test::GridSurface g;
  const Real c = std::cos(angle), s = std::sin(angle);
  for (Real y : {-0.5, 0.5}) {
    g.x.emplace_back(-1, y, 0);
    g.x.emplace_back(0, y, 0);
    g.x.emplace_back(c, y, s);
  }
  g.surface.facets.resize(2);
  g.surface.facets[0].nodes = {0, 1, 4, 3};
  g.surface.facets[1].nodes = {1, 2, 5, 4};
  return g;
}

} // namespace

TEST(Projection, PointSlidingOverSharedEdgeHasNoGapJump) {
  for (Real angle : {0.0, -0.4, 0.4}) {
    const auto g = kinked_pair(angle);
    const ContactSurface s(g.surface);
    const BucketSearch search(s, g.x, 0.5);
    int switches = 0, boundary = 0;
    std::optional<Projection> prev;
    Vec3 p_prev = Vec3::Zero();
    for (int k = 0; k <= 400; ++k) {
      const Real px = -0.5 + k / 400.0; // follows the fold to stay outside
      const Vec3 p(px, 0.1, 0.1 + std::max(px, 0.0) * std::tan(angle));
      const auto pr = project(p, s, g.x, search);
      const auto brute = project(p, s, g.x);
      ASSERT_TRUE(pr && brute);
      EXPECT_EQ(pr->facet, brute->facet);
      EXPECT_GT(pr->gap, 0);
      boundary += pr->on_boundary;
      EXPECT_FALSE(pr->on_free_boundary);
      if (prev) {
        // The distance to a surface is 1-Lipschitz in p: no jump across the edge.
        EXPECT_LE(std::abs(pr->gap - prev->gap), (p - p_prev).norm() + 1e-12) << "k " << k;
        if (angle <= 0) { // the closest point jumps across a concave kink (the gap does not)
          EXPECT_LE((pr->point - prev->point).norm(), 0.02) << "k " << k;
        }
        switches += pr->facet != prev->facet;
      }
      prev = pr;
      p_prev = p;
    }
    EXPECT_EQ(switches, 1) << "angle " << angle;
    EXPECT_EQ(boundary > 0, angle < 0) << "angle " << angle; // only the convex kink clamps
    // Exactly over the edge (flat case): deterministic, the lower facet index at ξ = +1.
    const auto edge = project(Vec3(0, 0.1, 0.1), s, g.x);
    if (angle == 0.0) {
      EXPECT_EQ(edge->facet, 0);
      EXPECT_NEAR(edge->xi[0], 1.0, 1e-12);
      EXPECT_NEAR(edge->gap, 0.1, 1e-14);
    }
  }
}

TEST(Projection, ConvexKinkClampsToTheEdgeWithContinuousNormal) {
  const auto g = kinked_pair(-0.5);
  const ContactSurface s(g.surface);
  // Above the kink, inside the wedge between the two facet normals: the nearest point is the
  // edge point (0, 0.2, 0); the normal points from it to p.
  const Vec3 p(0.02, 0.2, 0.3);
  const auto pr = project(p, s, g.x);
  ASSERT_TRUE(pr);
  EXPECT_TRUE(pr->on_boundary);
  EXPECT_LE((pr->point - Vec3(0, 0.2, 0)).norm(), 1e-14);
  EXPECT_NEAR(pr->gap, (p - Vec3(0, 0.2, 0)).norm(), 1e-14);
  EXPECT_LE((pr->normal - (p - pr->point).normalized()).norm(), 1e-14);
  EXPECT_FALSE(pr->on_free_boundary);
}

TEST(Projection, ConvexCornerOfABoxGivesTheCornerNode) {
  mesh::BoxSpec spec;
  spec.divisions = {2, 2, 2};
  const mesh::Mesh box = mesh::make_box(spec);
  mesh::Surface corner;
  for (const char* name : {"box.xmax", "box.ymax", "box.zmax"})
    for (const mesh::Facet& f : box.surface(name).facets)
      corner.facets.push_back(f);
  const ContactSurface s(corner);
  const NodePositions x(box.nodes());
  const BucketSearch search(s, x, 0.5);
  // Beyond the vertex (1, 1, 1).
  const Vec3 p(1.1, 1.2, 1.3);
  const auto pr = project(p, s, x, search);
  ASSERT_TRUE(pr);
  EXPECT_TRUE(pr->on_boundary);
  EXPECT_GE(pr->corner, 0);
  EXPECT_FALSE(pr->on_free_boundary);
  EXPECT_LE((pr->point - Vec3::Ones()).norm(), 1e-15);
  EXPECT_NEAR(pr->gap, std::sqrt(0.01 + 0.04 + 0.09), 1e-15);
  EXPECT_LE((pr->normal - Vec3(0.1, 0.2, 0.3).normalized()).norm(), 1e-15);
  // Beyond the convex edge x = y = 1.
  const auto edge = project(Vec3(1.1, 1.2, 0.7), s, x, search);
  EXPECT_TRUE(edge->on_boundary && !edge->on_free_boundary);
  EXPECT_LE((edge->point - Vec3(1, 1, 0.7)).norm(), 1e-15);
  EXPECT_NEAR(edge->gap, std::sqrt(0.05), 1e-15);
  // Beyond the free edge z = 0 of the face x = 1: outside the surface's coverage.
  const auto free = project(Vec3(1.1, 0.3, -0.2), s, x, search);
  EXPECT_TRUE(free->on_boundary && free->on_free_boundary);
  // Penetrating near the corner: interior projection onto the nearest face, negative gap.
  const auto inside = project(Vec3(0.9, 0.95, 0.8), s, x, search);
  EXPECT_FALSE(inside->on_boundary);
  EXPECT_NEAR(inside->gap, -0.05, 1e-14);
  EXPECT_LE((inside->normal - Vec3::UnitY()).norm(), 1e-14);
}

TEST(Projection, SearchDistanceAndProjectNodes) {
  const auto g = test::grid_surface(
      4, 4, 1.0, [](Real, Real) { return 0.0; }, 0.1, 13);
  const ContactSurface s(g.surface);
  ProjectionOptions opt;
  opt.search_distance = 0.3;
  EXPECT_TRUE(project(Vec3(2, 2, 0.25), s, g.x, opt));
  EXPECT_FALSE(project(Vec3(2, 2, 0.45), s, g.x, opt));
  std::vector<Vec3> x = g.x;
  x.emplace_back(2.1, 1.9, 0.2);
  x.emplace_back(2.1, 1.9, 5.0);
  const BucketSearch search(s, x, 0.3);
  const auto res = project_nodes({25, 26}, s, x, search, opt);
  ASSERT_EQ(res.size(), 2u);
  ASSERT_TRUE(res[0]);
  EXPECT_EQ(res[0]->facet, project(x[25], s, x, opt)->facet);
  EXPECT_FALSE(res[1]);
}

TEST(Projection, SlidingPointAlwaysFindsTheClosestFacet) {
  // Wavy, jittered 24 x 3 strip (convex and concave kinks, twisted facets); the point slides
  // along the middle row at a fixed offset above and below the surface.
  const auto z = [](Real x, Real y) { return 0.15 * std::sin(2.5 * x) + 0.05 * y * x; };
  const auto g = test::grid_surface(24, 3, 0.25, z, 0.1, 14);
  const ContactSurface s(g.surface);
  const BucketSearch search(s, g.x, 0.2);
  int mismatches = 0;
  Real worst_excess = -1;
  for (Real offset : {0.06, -0.04}) {
    std::set<Index> visited;
    std::optional<Projection> prev;
    Vec3 p_prev = Vec3::Zero();
    for (int k = 0; k <= 480; ++k) {
      const Real px = 0.02 + 5.96 * k / 480.0, py = 0.37;
      const Vec3 p(px, py, z(px, py) + offset);
      const auto pr = project(p, s, g.x, search);
      ASSERT_TRUE(pr) << "k " << k;
      visited.insert(pr->facet);
      EXPECT_EQ(pr->gap > 0, offset > 0);
      const std::vector<Real> ref = test::sampled_distances(p, s, g.x, std::abs(pr->gap) + 1e-9);
      const auto best = std::min_element(ref.begin(), ref.end());
      // Nothing on any facet is closer than the projection, and the chosen facet is the one
      // containing the closest point (up to sampling resolution where two facets tie).
      worst_excess = std::max(worst_excess, std::abs(pr->gap) - *best);
      EXPECT_LE(std::abs(pr->gap), *best + 1e-12) << "k " << k;
      const Index ref_facet = static_cast<Index>(best - ref.begin());
      if (pr->facet != ref_facet) {
        ++mismatches;
        EXPECT_LE(ref[pr->facet] - *best, 1e-8) << "k " << k;
      }
      if (prev) {
        EXPECT_LE(std::abs(pr->gap - prev->gap), (p - p_prev).norm() + 1e-12);
      }
      prev = pr;
      p_prev = p;
    }
    EXPECT_GE(visited.size(), 20u);
  }
  std::printf("[ sliding ] max (|g| - sampled distance) %.2e, facet ties %d\n", worst_excess,
              mismatches);
}
