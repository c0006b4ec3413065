// SPDX-License-Identifier: MIT
// Central-difference checks of the projection linearisation (docs/theory/contact.md §2.4): dξ,
// dg and dn with respect to all 15 coordinates (x_s, x_0..x_3) on warped, twisted facets, at
// interior projections, near a facet edge (|ξ| = 0.95), and for edge/corner (clamped)
// projections.
#include "contact_test_utils.hpp"

#include "trifem/contact/projection_derivatives.hpp"

#include <gtest/gtest.h>

using namespace trifem;
using namespace trifem::contact;

namespace {

using Coords = Eigen::Matrix<Real, kStencil, 1>;

Coords stack(const Vec3& p, const fe::QuadCoords& X) {
  Coords c;
  c.head<3>() = p;
  for (int a = 0; a < 4; ++a)
    c.segment<3>(3 + 3 * a) = X.row(a).transpose();
  return c;
}

Projection project_coords(const Coords& c) {
  fe::QuadCoords X;
  for (int a = 0; a < 4; ++a)
    X.row(a) = c.segment<3>(3 + 3 * a).transpose();
  return *project_onto_facet(c.head<3>(), X);
}

/// max |A - B| / max |A| (B: finite differences).
template <class M>
Real relative_error(const M& A, const M& B) {
  return (A - B).cwiseAbs().maxCoeff() / std::max(A.cwiseAbs().maxCoeff(), 1e-300);
}

struct Errors {
  Real xi = 0, gap = 0, normal = 0;
  void update(const Errors& e) {
    xi = std::max(xi, e.xi);
    gap = std::max(gap, e.gap);
    normal = std::max(normal, e.normal);
  }
};

/// Compares projection_derivatives at p on X with central differences (step 1e-6).
Errors check_derivatives(const Vec3& p, const fe::QuadCoords& X) {
  const Projection pr = *project_onto_facet(p, X);
  const ProjectionDerivatives d = projection_derivatives(pr, X);
  ProjectionDerivatives fd;
  const Coords c = stack(p, X);
  const Real h = 1e-6;
  for (int j = 0; j < kStencil; ++j) {
    Coords cp = c, cm = c;
    cp[j] += h;
    cm[j] -= h;
    const Projection a = project_coords(cp), b = project_coords(cm);
    EXPECT_EQ(a.on_boundary, pr.on_boundary);
    EXPECT_EQ(b.fixed, pr.fixed);
    fd.dxi.col(j) = (a.xi - b.xi) / (2 * h);
    fd.dgap(j) = (a.gap - b.gap) / (2 * h);
    fd.dnormal.col(j) = (a.normal - b.normal) / (2 * h);
  }
  Errors e;
  e.xi = d.dxi.isZero(0) && fd.dxi.norm() < 1e-9 ? 0 : relative_error(d.dxi, fd.dxi);
  e.gap = relative_error(d.dgap, fd.dgap);
  e.normal = relative_error(d.dnormal, fd.dnormal);
  return e;
}

void report(const char* what, const Errors& e) {
  std::printf("[ tangent ] %-28s worst relative FD error: dxi %.2e, dgap %.2e, dnormal %.2e\n",
              what, e.xi, e.gap, e.normal);
  EXPECT_LE(e.xi, 1e-6) << what;
  EXPECT_LE(e.gap, 1e-6) << what;
  EXPECT_LE(e.normal, 1e-6) << what;
}

Vec3 offset_point(const fe::QuadCoords& X, const Vec2& xi, Real g) {
  const FacetPoint fp = evaluate_facet(X, xi);
  return fp.x + g * fp.normal;
}

} // namespace

TEST(ProjectionDerivatives, InteriorMatchFiniteDifferences) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<Real> u(-0.9, 0.9), g(0.01, 0.2);
  Errors worst;
  for (int q = 0; q < 20; ++q) {
    const fe::QuadCoords X = test::warped_quad(rng);
    for (int k = 0; k < 10; ++k) {
      const Vec3 p = offset_point(X, Vec2(u(rng), u(rng)), (k % 2 ? 1 : -1) * g(rng));
      ASSERT_FALSE(project_onto_facet(p, X)->on_boundary);
      worst.update(check_derivatives(p, X));
    }
  }
  report("interior (200 points)", worst);
}

TEST(ProjectionDerivatives, NearFacetEdgeMatchFiniteDifferences) {
  std::mt19937 rng(22);
  std::uniform_real_distribution<Real> u(-0.9, 0.9), g(0.01, 0.2);
  Errors worst;
  for (int q = 0; q < 20; ++q) {
    const fe::QuadCoords X = test::warped_quad(rng);
    const Real s = q % 2 ? 0.95 : -0.95;
    for (const Vec2& xi : {Vec2(s, u(rng)), Vec2(u(rng), s), Vec2(s, -s), Vec2(s, s)}) {
      const Vec3 p = offset_point(X, xi, (q % 3 ? 1 : -1) * g(rng));
      const Projection pr = *project_onto_facet(p, X);
      ASSERT_FALSE(pr.on_boundary);
      EXPECT_LE((pr.xi - xi).norm(), 1e-12);
      worst.update(check_derivatives(p, X));
    }
  }
  report("near edge |xi| = 0.95 (80)", worst);
}

TEST(ProjectionDerivatives, EdgeAndCornerProjectionsMatchFiniteDifferences) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<Real> u(-0.8, 0.8), g(0.05, 0.3);
  Errors edge_worst, corner_worst;
  for (int q = 0; q < 20; ++q) {
    const fe::QuadCoords X = test::warped_quad(rng);
    // Beyond edge 1 (ξ = +1): step outwards along t_1 and off the surface.
    const FacetPoint fe_ = evaluate_facet(X, Vec2(1, u(rng)));
    const Vec3 p_edge = fe_.x + 0.2 * fe_.t[0].normalized() + g(rng) * fe_.normal;
    const Projection pe = *project_onto_facet(p_edge, X);
    ASSERT_TRUE(pe.on_boundary);
    ASSERT_TRUE(pe.fixed[0] && !pe.fixed[1]);
    edge_worst.update(check_derivatives(p_edge, X));
    // Beyond corner 2 (ξ = η = +1).
    const FacetPoint fc = evaluate_facet(X, Vec2(1, 1));
    const Vec3 p_corner = fc.x + 0.2 * (fc.t[0].normalized() + fc.t[1].normalized()) +
                          (q % 2 ? 1 : -1) * g(rng) * fc.normal;
    const Projection pc = *project_onto_facet(p_corner, X);
    ASSERT_TRUE(pc.on_boundary);
    ASSERT_TRUE(pc.fixed[0] && pc.fixed[1]);
    corner_worst.update(check_derivatives(p_corner, X));
  }
  report("clamped to an edge (20)", edge_worst);
  report("clamped to a corner (20)", corner_worst);
}

TEST(ProjectionDerivatives, InterpolatedMasterFieldThroughXi) {
  // q = (w^m(ξ) - w_s)·n with fixed nodal w_a: Δq = n·(Σ w_a N_a,α) Δξ^α + (w^m - w_s)·Δn.
  std::mt19937 rng(24);
  std::uniform_real_distribution<Real> u(-0.9, 0.9), g(0.01, 0.2);
  Real worst = 0;
  for (int q = 0; q < 20; ++q) {
    const fe::QuadCoords X = test::warped_quad(rng);
    const Eigen::Matrix<Real, 4, 3> w = Eigen::Matrix<Real, 4, 3>::Random();
    const Vec3 w_s = Vec3::Random();
    const Vec3 p = offset_point(X, Vec2(u(rng), u(rng)), g(rng));
    const auto value = [&](const Coords& c) {
      const Projection pr = project_coords(c);
      return (interpolate(w, pr.xi) - w_s).dot(pr.normal);
    };
    const Projection pr = *project_onto_facet(p, X);
    const ProjectionDerivatives d = projection_derivatives(pr, X);
    const Eigen::Matrix<Real, 1, kStencil> dq =
        pr.normal.transpose() * interpolation_derivative(w, pr.xi, d) +
        (interpolate(w, pr.xi) - w_s).transpose() * d.dnormal;
    Eigen::Matrix<Real, 1, kStencil> fd;
    const Coords c = stack(p, X);
    for (int j = 0; j < kStencil; ++j) {
      Coords cp = c, cm = c;
      cp[j] += 1e-6;
      cm[j] -= 1e-6;
      fd(j) = (value(cp) - value(cm)) / 2e-6;
    }
    worst = std::max(worst, relative_error(dq, fd));
  }
  std::printf("[ tangent ] (w^m(xi) - w_s).n through xi and n: worst relative FD error %.2e\n",
              worst);
  EXPECT_LE(worst, 1e-6);
}

TEST(ProjectionDerivatives, GapVariationIsExactAtClosestPoint) {
  // Δg = n·(Δx_s - Σ N_a Δx_a): equals the full chain rule of g = (x_s - x(ξ))·n(ξ).
  std::mt19937 rng(25);
  const fe::QuadCoords X = test::warped_quad(rng);
  const Vec3 p = offset_point(X, Vec2(0.3, -0.4), 0.15);
  const Projection pr = *project_onto_facet(p, X);
  const ProjectionDerivatives d = projection_derivatives(pr, X);
  const FacetPoint fp = evaluate_facet(X, pr.xi);
  // Full chain rule: Δg = Δd·n + d·Δn with Δd = Δx_s - ΣN_aΔx_a - t_α Δξ^α.
  Eigen::Matrix<Real, 3, kStencil> Dd = Eigen::Matrix<Real, 3, kStencil>::Zero();
  Dd.block<3, 3>(0, 0).setIdentity();
  for (int a = 0; a < 4; ++a)
    Dd.block<3, 3>(0, 3 + 3 * a) = -fp.N[a] * Mat3::Identity();
  Dd -= fp.t[0] * d.dxi.row(0) + fp.t[1] * d.dxi.row(1);
  const Eigen::Matrix<Real, 1, kStencil> chain =
      pr.normal.transpose() * Dd + pr.gap * pr.normal.transpose() * d.dnormal;
  EXPECT_LE((chain - d.dgap).norm(), 1e-13 * d.dgap.norm());
}

TEST(ProjectionDerivatives, StencilOfASlaveNodeOnAMeshSurface) {
  // Assembly-style use: project a slave mesh node onto a warped grid surface through the
  // search, then check the derivatives w.r.t. the mesh coordinates of stencil_nodes().
  const auto z = [](Real x, Real y) { return 0.2 * std::sin(3 * x) * std::cos(2 * y); };
  auto g = test::grid_surface(6, 6, 0.2, z, 0.15, 26);
  const ContactSurface s(g.surface);
  const Index slave = static_cast<Index>(g.x.size());
  g.x.emplace_back(0.53, 0.61, z(0.53, 0.61) + 0.03);
  const auto project_slave = [&](const std::vector<Vec3>& x) {
    const BucketSearch search(s, x, 0.1);
    return *project(x[slave], s, x, search);
  };
  const Projection pr = project_slave(g.x);
  ASSERT_FALSE(pr.on_boundary);
  const ProjectionDerivatives d = projection_derivatives(pr, s, g.x);
  const std::array<Index, 5> nodes = stencil_nodes(slave, s, pr.facet);
  Errors e;
  for (int j = 0; j < kStencil; ++j) {
    std::vector<Vec3> xp = g.x, xm = g.x;
    xp[nodes[j / 3]][j % 3] += 1e-6;
    xm[nodes[j / 3]][j % 3] -= 1e-6;
    const Projection a = project_slave(xp), b = project_slave(xm);
    ASSERT_EQ(a.facet, pr.facet);
    ASSERT_EQ(b.facet, pr.facet);
    e.xi = std::max(e.xi, (d.dxi.col(j) - (a.xi - b.xi) / 2e-6).norm() / d.dxi.norm());
    e.gap = std::max(e.gap, std::abs(d.dgap(j) - (a.gap - b.gap) / 2e-6) / d.dgap.norm());
    e.normal = std::max(e.normal, (d.dnormal.col(j) - (a.normal - b.normal) / 2e-6).norm() /
                                      d.dnormal.norm());
  }
  report("slave node on mesh surface", e);
}
