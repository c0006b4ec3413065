// SPDX-License-Identifier: MIT
// Central-difference checks of the projection linearisation (docs/theory/contact.md §2.4): dξ,
// dg and dn with respect to all coordinates (x_s, x_0..x_(n-1)) on twisted quad4 and curved
// tri3, tri6 and quad8 facets, at interior projections, near a facet edge, and for edge/corner
// (clamped, on curved edges too) projections.
#include "contact_test_utils.hpp"

#include "trifem/contact/projection_derivatives.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

using namespace trifem;
using namespace trifem::contact;

namespace {

constexpr mesh::FacetType kFacetTypes[] = {mesh::FacetType::Quad4, mesh::FacetType::Tri3,
                                           mesh::FacetType::Tri6, mesh::FacetType::Quad8};

using Coords = Eigen::VectorXd;

/// A random facet of `type` (twisted quad4, curved tri6 and quad8).
FacetCoords facet_of(mesh::FacetType type, std::mt19937& rng) {
  return type == mesh::FacetType::Quad4 ? test::warped_quad(rng) : test::random_facet(type, rng);
}

Coords stack(const Vec3& p, const FacetCoords& X) {
  Coords c(3 * (1 + X.num_nodes()));
  c.head<3>() = p;
  for (int a = 0; a < X.num_nodes(); ++a)
    c.segment<3>(3 + 3 * a) = X.node(a);
  return c;
}

FacetCoords unstack(const Coords& c, mesh::FacetType type) {
  FacetNodePositions X(c.size() / 3 - 1, 3);
  for (Index a = 0; a < X.rows(); ++a)
    X.row(a) = c.segment<3>(3 + 3 * a).transpose();
  return {type, X};
}

Projection project_coords(const Coords& c, mesh::FacetType type) {
  return *project_onto_facet(c.head<3>(), unstack(c, type));
}

/// max |A - B| / max |A| (B: finite differences).
template <class A, class B>
Real relative_error(const A& a, const B& b) {
  return (a - b).cwiseAbs().maxCoeff() / std::max(a.cwiseAbs().maxCoeff(), 1e-300);
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
Errors check_derivatives(const Vec3& p, const FacetCoords& X) {
  const Projection pr = *project_onto_facet(p, X);
  const ProjectionDerivatives d = projection_derivatives(pr, X);
  const Coords c = stack(p, X);
  const auto n = c.size();
  Eigen::MatrixXd fd_xi(2, n), fd_gap(1, n), fd_normal(3, n);
  const Real h = 1e-6;
  for (Index j = 0; j < n; ++j) {
    Coords cp = c, cm = c;
    cp[j] += h;
    cm[j] -= h;
    const Projection a = project_coords(cp, X.type()), b = project_coords(cm, X.type());
    EXPECT_EQ(a.on_boundary, pr.on_boundary);
    EXPECT_EQ(b.corner, pr.corner);
    if (pr.corner < 0) {
      EXPECT_EQ(b.edge, pr.edge);
    }
    fd_xi.col(j) = (a.xi - b.xi) / (2 * h);
    fd_gap(0, j) = (a.gap - b.gap) / (2 * h);
    fd_normal.col(j) = (a.normal - b.normal) / (2 * h);
  }
  Errors e;
  e.xi = d.dxi.isZero(0) && fd_xi.norm() < 1e-9 ? 0 : relative_error(d.dxi, fd_xi);
  e.gap = relative_error(d.dgap, fd_gap);
  e.normal = relative_error(d.dnormal, fd_normal);
  return e;
}

void report(const std::string& what, const Errors& e) {
  std::printf("[ tangent ] %-34s worst relative FD error: dxi %.2e, dgap %.2e, dnormal %.2e\n",
              what.c_str(), e.xi, e.gap, e.normal);
  EXPECT_LE(e.xi, 1e-6) << what;
  EXPECT_LE(e.gap, 1e-6) << what;
  EXPECT_LE(e.normal, 1e-6) << what;
}

Vec3 offset_point(const FacetCoords& X, const Vec2& xi, Real g) {
  const FacetPoint fp = evaluate_facet(X, xi);
  return fp.x + g * fp.normal;
}

/// A random point well inside the reference facet (ξ ∈ [-0.9, 0.9]² or barycentrics ≥ 0.05).
Vec2 interior_point(mesh::FacetType type, std::mt19937& rng) {
  std::uniform_real_distribution<Real> u(-0.9, 0.9);
  const Vec2 r(u(rng), u(rng));
  if (!is_triangle(type))
    return r;
  const Vec2 s = 0.5 * (r + Vec2::Ones()); // [0.05, 0.95]²
  return s.sum() <= 0.95 ? s : Vec2(0.95 - s[1], 0.95 - s[0]);
}

/// The in-plane direction out of the facet across edge e at ξ on it: x_u × n.
Vec3 outward(const FacetCoords& X, int e, const Vec2& xi) {
  const FacetPoint fp = evaluate_facet(X, xi);
  const Vec2 v = edge_direction(X.type(), e);
  return (fp.t[0] * v[0] + fp.t[1] * v[1]).cross(fp.normal).normalized();
}

} // namespace

TEST(ProjectionDerivatives, InteriorMatchFiniteDifferences) {
  for (const auto type : kFacetTypes) {
    std::mt19937 rng(21);
    std::uniform_real_distribution<Real> g(0.01, 0.1);
    Errors worst;
    for (int q = 0; q < 20; ++q) {
      const FacetCoords X = facet_of(type, rng);
      for (int k = 0; k < 10; ++k) {
        const Vec3 p = offset_point(X, interior_point(type, rng), (k % 2 ? 1 : -1) * g(rng));
        ASSERT_FALSE(project_onto_facet(p, X)->on_boundary);
        worst.update(check_derivatives(p, X));
      }
    }
    report(fmt::format("{} interior (200 points)", mesh::name(type)), worst);
  }
}

TEST(ProjectionDerivatives, NearFacetEdgeMatchFiniteDifferences) {
  for (const auto type : kFacetTypes) {
    std::mt19937 rng(22);
    std::uniform_real_distribution<Real> u(-0.9, 0.9), g(0.01, 0.1);
    Errors worst;
    for (int q = 0; q < 20; ++q) {
      const FacetCoords X = facet_of(type, rng);
      const Real s = q % 2 ? 0.95 : -0.95, t = 0.5 * (u(rng) + 1) * 0.9;
      const std::vector<Vec2> points =
          is_triangle(type)
              ? std::vector<Vec2>{Vec2(0.025, t), Vec2(t, 0.025), Vec2(t, 0.975 - t)}
              : std::vector<Vec2>{Vec2(s, u(rng)), Vec2(u(rng), s), Vec2(s, -s), Vec2(s, s)};
      for (const Vec2& xi : points) {
        const Vec3 p = offset_point(X, xi, (q % 3 ? 1 : -1) * g(rng));
        const Projection pr = *project_onto_facet(p, X);
        ASSERT_FALSE(pr.on_boundary);
        EXPECT_LE((pr.xi - xi).norm(), 1e-11);
        worst.update(check_derivatives(p, X));
      }
    }
    report(fmt::format("{} near an edge", mesh::name(type)), worst);
  }
}

TEST(ProjectionDerivatives, EdgeAndCornerProjectionsMatchFiniteDifferences) {
  for (const auto type : kFacetTypes) {
    std::mt19937 rng(23);
    std::uniform_real_distribution<Real> u(0.1, 0.9), g(0.05, 0.3);
    Errors edge_worst, corner_worst;
    for (int q = 0; q < 20; ++q) {
      const FacetCoords X = facet_of(type, rng);
      // Beyond edge 1 (quads ξ = +1; the hypotenuse of triangles), off the surface.
      const Vec2 xi_e = facet_corner(type, 1) + u(rng) * edge_direction(type, 1);
      const FacetPoint fe_ = evaluate_facet(X, xi_e);
      const Vec3 p_edge = fe_.x + 0.2 * outward(X, 1, xi_e) + g(rng) * fe_.normal;
      const Projection pe = *project_onto_facet(p_edge, X);
      ASSERT_TRUE(pe.on_boundary);
      ASSERT_EQ(pe.edge, 1);
      ASSERT_LT(pe.corner, 0);
      edge_worst.update(check_derivatives(p_edge, X));
      // Beyond corner 2, between its edges 1 and 2.
      const Vec2 xi_c = facet_corner(type, 2);
      const FacetPoint fc = evaluate_facet(X, xi_c);
      const Vec3 p_corner = fc.x + 0.2 * (outward(X, 1, xi_c) + outward(X, 2, xi_c)) +
                            (q % 2 ? 1 : -1) * g(rng) * fc.normal;
      const Projection pc = *project_onto_facet(p_corner, X);
      ASSERT_TRUE(pc.on_boundary);
      ASSERT_EQ(pc.corner, 2);
      corner_worst.update(check_derivatives(p_corner, X));
    }
    report(fmt::format("{} clamped to an edge (20)", mesh::name(type)), edge_worst);
    report(fmt::format("{} clamped to a corner (20)", mesh::name(type)), corner_worst);
  }
}

TEST(ProjectionDerivatives, InterpolatedMasterFieldThroughXi) {
  // q = (w^m(ξ) - w_s)·n with fixed nodal w_a: Δq = n·(Σ w_a N_a,α) Δξ^α + (w^m - w_s)·Δn.
  for (const auto type : kFacetTypes) {
    std::mt19937 rng(24);
    std::uniform_real_distribution<Real> g(0.01, 0.1);
    Real worst = 0;
    for (int q = 0; q < 20; ++q) {
      const FacetCoords X = facet_of(type, rng);
      const FacetNodeValues<3> w = FacetNodeValues<3>::Random(X.num_nodes(), 3);
      const Vec3 w_s = Vec3::Random();
      const Vec3 p = offset_point(X, interior_point(type, rng), g(rng));
      const fe::ReferenceFacet& ref = *X.reference;
      const auto value = [&](const Coords& c) {
        const Projection pr = project_coords(c, type);
        return (interpolate<3>(ref, w, pr.xi) - w_s).dot(pr.normal);
      };
      const Projection pr = *project_onto_facet(p, X);
      const ProjectionDerivatives d = projection_derivatives(pr, X);
      const StencilRows<1> dq =
          pr.normal.transpose() * interpolation_derivative<3>(ref, w, pr.xi, d) +
          (interpolate<3>(ref, w, pr.xi) - w_s).transpose() * d.dnormal;
      const Coords c = stack(p, X);
      Eigen::RowVectorXd fd(c.size());
      for (Index j = 0; j < c.size(); ++j) {
        Coords cp = c, cm = c;
        cp[j] += 1e-6;
        cm[j] -= 1e-6;
        fd(j) = (value(cp) - value(cm)) / 2e-6;
      }
      worst = std::max(worst, relative_error(dq, fd));
    }
    std::printf("[ tangent ] %s (w^m(xi) - w_s).n through xi and n: worst relative FD error "
                "%.2e\n",
                std::string(mesh::name(type)).c_str(), worst);
    EXPECT_LE(worst, 1e-6) << mesh::name(type);
  }
}

TEST(ProjectionDerivatives, GapVariationIsExactAtClosestPoint) {
  // Δg = n·(Δx_s - Σ N_a Δx_a): equals the full chain rule of g = (x_s - x(ξ))·n(ξ).
  for (const auto type : kFacetTypes) {
    std::mt19937 rng(25);
    const FacetCoords X = facet_of(type, rng);
    const Vec3 p = offset_point(X, facet_centre(type) + Vec2(0.1, -0.1), 0.15);
    const Projection pr = *project_onto_facet(p, X);
    const ProjectionDerivatives d = projection_derivatives(pr, X);
    const FacetPoint fp = evaluate_facet(X, pr.xi);
    // Full chain rule: Δg = Δd·n + d·Δn with Δd = Δx_s - ΣN_aΔx_a - t_α Δξ^α.
    Eigen::MatrixXd Dd = Eigen::MatrixXd::Zero(3, 3 * (1 + X.num_nodes()));
    Dd.block<3, 3>(0, 0).setIdentity();
    for (int a = 0; a < X.num_nodes(); ++a)
      Dd.block<3, 3>(0, 3 + 3 * a) = -fp.N[a] * Mat3::Identity();
    Dd -= fp.t[0] * d.dxi.row(0) + fp.t[1] * d.dxi.row(1);
    const Eigen::RowVectorXd chain =
        pr.normal.transpose() * Dd + pr.gap * pr.normal.transpose() * d.dnormal;
    EXPECT_LE((chain - d.dgap).norm(), 1e-13 * d.dgap.norm()) << mesh::name(type);
  }
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
  const StencilNodes nodes = stencil_nodes(slave, s, pr.facet);
  ASSERT_EQ(nodes.size, 5);
  Errors e;
  for (int j = 0; j < 3 * nodes.size; ++j) {
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
