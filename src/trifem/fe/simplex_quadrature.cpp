// SPDX-License-Identifier: MIT
#include "trifem/fe/simplex_quadrature.hpp"

#include "trifem/core/error.hpp"

#include <array>
#include <cmath>

namespace trifem::fe {
namespace {

// Points and weights of the simplex rules, to 20 significant digits: the roots of their moment
// equations (solved with 40-digit arithmetic; every monomial of the rule's degree is then
// integrated to 1e-39).

// triangle, degree 4: two orbits of the barycentric coordinates (1 - 2a, a, a), one near the
// midpoints of the edges, one near the corners
constexpr Real kTriangle4EdgeOrbitA = 0.44594849091596488632;
constexpr Real kTriangle4EdgeOrbitWeight = 0.11169079483900573285;
constexpr Real kTriangle4CornerOrbitA = 0.091576213509770743460;
constexpr Real kTriangle4CornerOrbitWeight = 0.054975871827660933819;

// tetrahedron, degree 2: the four permutations of (1 - 3a, a, a, a), a = (5 - sqrt(5))/20
constexpr Real kTet2A = 0.13819660112501051518;

// tetrahedron, degree 5: two orbits of (1 - 3a, a, a, a), near the corners and near the face
// centres, and one of (1/2 - b, 1/2 - b, b, b) near the midpoints of the edges
constexpr Real kTet5CornerOrbitA = 0.092735250310891226402;
constexpr Real kTet5CornerOrbitWeight = 0.012248840519393658257;
constexpr Real kTet5FaceOrbitA = 0.31088591926330060980;
constexpr Real kTet5FaceOrbitWeight = 0.018781320953002641800;
constexpr Real kTet5EdgeOrbitB = 0.045503704125649649492;
constexpr Real kTet5EdgeOrbitWeight = 0.0070910034628469110730;

struct LinePoint {
  Real x;
  Real weight;
};

std::vector<LinePoint> gauss_legendre(int n) {
  TRIFEM_VERIFY(n >= 1 && n <= 3, "no {}-point Gauss-Legendre rule", n);
  if (n == 1)
    return {{0.0, 2.0}};
  if (n == 2) {
    const Real g = 1.0 / std::sqrt(3.0); // as hex_gauss_2x2x2()
    return {{-g, 1.0}, {g, 1.0}};
  }
  const Real g = 0.77459666924148337704; // sqrt(3/5)
  return {{-g, 5.0 / 9.0}, {0.0, 8.0 / 9.0}, {g, 5.0 / 9.0}};
}

/// The points of the orbit of barycentric coordinates (1 - 2a, a, a) with weight w.
void add_triangle_orbit(FacetRule& rule, Real a, Real w) {
  const Real b = 1.0 - 2.0 * a;
  for (const Vec2& xi : {Vec2(a, a), Vec2(b, a), Vec2(a, b)})
    rule.points.push_back({xi, w});
}

/// The points of the orbit of barycentric coordinates (1 - 3a, a, a, a) with weight w.
void add_tet_vertex_orbit(CellRule& rule, Real a, Real w) {
  const Real b = 1.0 - 3.0 * a;
  for (const Vec3& xi : {Vec3(a, a, a), Vec3(b, a, a), Vec3(a, b, a), Vec3(a, a, b)})
    rule.points.push_back({xi, w});
}

/// The points of the orbit of barycentric coordinates (1/2 - b, 1/2 - b, b, b) with weight w.
void add_tet_edge_orbit(CellRule& rule, Real b, Real w) {
  const Real c = 0.5 - b;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      std::array<Real, 4> L{c, c, c, c}; // L[0] = 1 - x - y - z
      L[i] = L[j] = b;
      rule.points.push_back({Vec3(L[1], L[2], L[3]), w});
    }
}

} // namespace

CellRule hex_gauss_rule(int points_per_direction) {
  const auto line = gauss_legendre(points_per_direction);
  CellRule rule{{}, 2 * points_per_direction - 1};
  for (const auto& z : line)
    for (const auto& y : line)
      for (const auto& x : line)
        rule.points.push_back({Vec3(x.x, y.x, z.x), x.weight * y.weight * z.weight});
  return rule;
}

FacetRule quad_gauss_rule(int points_per_direction) {
  const auto line = gauss_legendre(points_per_direction);
  FacetRule rule{{}, 2 * points_per_direction - 1};
  for (const auto& y : line)
    for (const auto& x : line)
      rule.points.push_back({Vec2(x.x, y.x), x.weight * y.weight});
  return rule;
}

FacetRule triangle_rule_degree2() {
  FacetRule rule{{}, 2};
  add_triangle_orbit(rule, 1.0 / 6.0, 1.0 / 6.0);
  return rule;
}

FacetRule triangle_rule_degree4() {
  FacetRule rule{{}, 4};
  add_triangle_orbit(rule, kTriangle4EdgeOrbitA, kTriangle4EdgeOrbitWeight);
  add_triangle_orbit(rule, kTriangle4CornerOrbitA, kTriangle4CornerOrbitWeight);
  return rule;
}

CellRule tet_rule_degree2() {
  CellRule rule{{}, 2};
  add_tet_vertex_orbit(rule, kTet2A, 1.0 / 24.0);
  return rule;
}

CellRule tet_rule_degree5() {
  CellRule rule{{}, 5};
  add_tet_vertex_orbit(rule, kTet5CornerOrbitA, kTet5CornerOrbitWeight);
  add_tet_vertex_orbit(rule, kTet5FaceOrbitA, kTet5FaceOrbitWeight);
  add_tet_edge_orbit(rule, kTet5EdgeOrbitB, kTet5EdgeOrbitWeight);
  return rule;
}

CellRule wedge_rule_degree2() {
  const FacetRule triangle = triangle_rule_degree2();
  CellRule rule{{}, 2};
  for (const auto& z : gauss_legendre(2))
    for (const auto& p : triangle.points)
      rule.points.push_back({Vec3(p.xi[0], p.xi[1], z.x), p.weight * z.weight});
  return rule;
}

} // namespace trifem::fe
