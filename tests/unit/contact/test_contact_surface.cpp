// SPDX-License-Identifier: MIT
// ContactSurface topology, facet geometry and the bucket search (against brute force).
#include "contact_test_utils.hpp"

#include <chrono>
#include <gtest/gtest.h>

using namespace trifem;
using namespace trifem::contact;

TEST(ContactSurface, NodesAndAdjacency) {
  const auto g = test::grid_surface(
      3, 2, 1.0, [](Real, Real) { return 0.0; }, 0.0, 1);
  const ContactSurface s(g.surface);
  EXPECT_EQ(s.num_facets(), 6);
  EXPECT_EQ(s.num_nodes(), 12);
  EXPECT_EQ(s.local_node(5), 5);
  EXPECT_EQ(s.local_node(99), -1);
  // Interior node (1, 1) = mesh node 5 touches facets 0, 1, 3, 4.
  const auto nf = s.node_facets(s.local_node(5));
  EXPECT_EQ(std::vector<Index>(nf.begin(), nf.end()), (std::vector<Index>{0, 1, 3, 4}));
  // Facet 0 (nodes 0, 1, 5, 4): edge 0 (η = -1) free, edge 1 (ξ = +1) -> 1, edge 2 -> 3.
  EXPECT_EQ(s.edge_neighbour(0, 0), -1);
  EXPECT_EQ(s.edge_neighbour(0, 1), 1);
  EXPECT_EQ(s.edge_neighbour(0, 2), 3);
  EXPECT_EQ(s.edge_neighbour(0, 3), -1);
  EXPECT_EQ(s.edge_neighbour(4, 3), 3);
  EXPECT_TRUE(s.on_free_boundary(0, 0, -1));  // on edge 0
  EXPECT_FALSE(s.on_free_boundary(0, 1, -1)); // on edge 1
  EXPECT_FALSE(s.on_free_boundary(4, 0, 0));  // at corner 0 (edges 3 and 0)
  EXPECT_TRUE(s.on_free_boundary(0, 0, 1));   // at corner 1 (edges 0 and 1)
}

TEST(ContactSurface, PositionsFromArrayOrCallable) {
  const auto g = test::grid_surface(
      2, 2, 0.5, [](Real x, Real) { return x * x; }, 0.1, 2);
  const ContactSurface s(g.surface);
  const NodePositions from_array(g.x);
  const NodePositions from_fn([&g](Index i) { return Vec3(g.x[i] + Vec3(1, 2, 3)); });
  for (Index f = 0; f < s.num_facets(); ++f) {
    const FacetNodePositions diff = s.coords(f, from_fn).x - s.coords(f, from_array).x;
    ASSERT_EQ(diff.rows(), 4);
    for (int a = 0; a < 4; ++a)
      EXPECT_LE((diff.row(a).transpose() - Vec3(1, 2, 3)).norm(), 1e-14);
  }
}

/// Tangents, second derivatives and normal of random facets of `type` against differences.
void expect_geometry_matches_differences(mesh::FacetType type, const Vec2& xi) {
  std::mt19937 rng(3);
  for (int k = 0; k < 10; ++k) {
    const FacetCoords X =
        type == mesh::FacetType::Quad4 ? test::warped_quad(rng) : test::random_facet(type, rng);
    const FacetPoint p = evaluate_facet(X, xi);
    const Real h = 1e-5;
    for (int a = 0; a < 2; ++a) {
      const Vec2 e = h * Vec2::Unit(a);
      const Vec3 fd = (evaluate_facet(X, xi + e).x - evaluate_facet(X, xi - e).x) / (2 * h);
      EXPECT_LE((fd - p.t[a]).norm(), 1e-9);
      for (int b = 0; b < 2; ++b) {
        const Vec3 fd2 =
            (evaluate_facet(X, xi + e).t[b] - evaluate_facet(X, xi - e).t[b]) / (2 * h);
        EXPECT_LE((fd2 - p.second(a, b)).norm(), 1e-8) << mesh::name(type) << " " << a << b;
      }
    }
    EXPECT_NEAR(p.normal.norm(), 1.0, 1e-14);
    EXPECT_NEAR(p.normal.dot(p.t[0]), 0.0, 1e-14);
    EXPECT_NEAR(p.normal.dot(p.t[1]), 0.0, 1e-14);
  }
}

TEST(FacetGeometry, TangentsSecondDerivativesAndNormalMatchDifferences) {
  expect_geometry_matches_differences(mesh::FacetType::Quad4, Vec2(0.3, -0.6));
  expect_geometry_matches_differences(mesh::FacetType::Quad8, Vec2(0.3, -0.6));
  expect_geometry_matches_differences(mesh::FacetType::Tri3, Vec2(0.2, 0.5));
  expect_geometry_matches_differences(mesh::FacetType::Tri6, Vec2(0.2, 0.5));
}

TEST(FacetGeometry, FlatFacetsHaveTheirNormalAndArea) {
  // Counter-clockwise flat square: outward normal +z.
  FacetNodePositions sq(4, 3);
  sq << 0, 0, 0, 2, 0, 0, 2, 2, 0, 0, 2, 0;
  const FacetCoords S(mesh::FacetType::Quad4, sq);
  EXPECT_LE((evaluate_facet(S, Vec2(0.1, 0.2)).normal - Vec3::UnitZ()).norm(), 1e-15);
  EXPECT_NEAR(evaluate_facet(S, Vec2::Zero()).jacobian, 1.0, 1e-15);
}

TEST(BucketSearch, CandidatesContainEveryFacetWithinRadius) {
  const auto g = test::grid_surface(
      20, 20, 0.1, [](Real x, Real y) { return 0.2 * std::sin(6 * x) * std::cos(5 * y); }, 0.2, 4);
  const ContactSurface s(g.surface);
  const Real radius = 0.07;
  const BucketSearch search(s, g.x, radius);
  std::mt19937 rng(5);
  std::uniform_real_distribution<Real> u(-0.1, 2.1), v(-0.4, 0.4);
  std::vector<Index> cand;
  for (int q = 0; q < 500; ++q) {
    const Vec3 p(u(rng), u(rng), v(rng));
    search.candidates(p, cand);
    EXPECT_TRUE(std::is_sorted(cand.begin(), cand.end()));
    for (Index f = 0; f < s.num_facets(); ++f) {
      const auto pr = project_onto_facet(p, s.coords(f, g.x));
      ASSERT_TRUE(pr);
      if (std::abs(pr->gap) <= radius) {
        EXPECT_TRUE(std::binary_search(cand.begin(), cand.end(), f)) << "facet " << f;
      }
    }
  }
}

TEST(BucketSearch, SameClosestFacetAsBruteForceOn10kFacets) {
  const auto g = test::grid_surface(
      100, 100, 0.05,
      [](Real x, Real y) { return 0.3 * std::sin(2 * x) * std::cos(3 * y) + 0.05 * x; }, 0.25, 6);
  const ContactSurface s(g.surface);
  ASSERT_EQ(s.num_facets(), 10000);
  const Real radius = 0.05;
  const auto t0 = std::chrono::steady_clock::now();
  const BucketSearch search(s, g.x, radius);
  const auto t1 = std::chrono::steady_clock::now();
  ProjectionOptions opt;
  opt.search_distance = radius;
  std::mt19937 rng(7);
  std::uniform_real_distribution<Real> u(-0.1, 5.1), v(-0.06, 0.06);
  int projected = 0, boundary = 0;
  Real t_search = 0, t_brute = 0;
  for (int q = 0; q < 400; ++q) {
    const Vec2 xy(u(rng), u(rng));
    // Points near the surface: above the nearest node plus a random normal offset.
    Vec3 p(xy[0], xy[1], 0);
    p[2] = 0.3 * std::sin(2 * p[0]) * std::cos(3 * p[1]) + 0.05 * p[0] + v(rng);
    const auto a0 = std::chrono::steady_clock::now();
    const auto fast = project(p, s, g.x, search, opt);
    const auto a1 = std::chrono::steady_clock::now();
    const auto slow = project(p, s, g.x, opt);
    const auto a2 = std::chrono::steady_clock::now();
    t_search += std::chrono::duration<Real>(a1 - a0).count();
    t_brute += std::chrono::duration<Real>(a2 - a1).count();
    ASSERT_EQ(fast.has_value(), slow.has_value()) << "query " << q;
    if (!slow)
      continue;
    ++projected;
    boundary += slow->on_boundary;
    EXPECT_EQ(fast->facet, slow->facet) << "query " << q;
    EXPECT_EQ(fast->gap, slow->gap);
    if (q < 40) { // fully independent of the pruning in project(): every facet, no shortcuts
      Real d_min = std::numeric_limits<Real>::infinity();
      for (Index f = 0; f < s.num_facets(); ++f)
        d_min = std::min(d_min, std::abs(project_onto_facet(p, s.coords(f, g.x))->gap));
      EXPECT_EQ(std::abs(slow->gap), d_min) << "query " << q;
    }
  }
  EXPECT_GT(projected, 300);
  std::printf("[ search ] 10k facets: build %.2f ms, %zu entries, bucket %.3g; per query: "
              "search %.1f us, brute force %.1f us; %d projected (%d on boundary)\n",
              1e3 * std::chrono::duration<Real>(t1 - t0).count(), search.num_entries(),
              search.bucket_size(), 1e6 * t_search / 400, 1e6 * t_brute / 400, projected, boundary);
  EXPECT_LT(search.num_entries(), 20u * 10000u); // O(n) storage
}

TEST(BucketSearch, EmptySurfaceAndFarPoints) {
  const ContactSurface empty{mesh::Surface{}};
  const std::vector<Vec3> none;
  const BucketSearch search(empty, none, 1.0);
  EXPECT_TRUE(search.candidates(Vec3::Zero()).empty());
  const auto g = test::grid_surface(
      4, 4, 1.0, [](Real, Real) { return 0.0; }, 0.0, 8);
  const ContactSurface s(g.surface);
  const BucketSearch s2(s, g.x, 0.5);
  EXPECT_TRUE(s2.candidates(Vec3(2, 2, 0.6)).empty());
  EXPECT_FALSE(s2.candidates(Vec3(2, 2, 0.4)).empty());
  EXPECT_FALSE(project(Vec3(2, 2, 0.6), s, g.x, s2));
}
