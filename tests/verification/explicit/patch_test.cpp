// SPDX-License-Identifier: MIT
// Homogeneous-deformation patch test of the multiplier pressure
// (docs/theory/reference-solutions.md §R8.1, §R8.5): a distorted 2x2x2 cube under a dead uniaxial
// traction, damped to rest, must reach the exact homogeneous state with a uniform Λ, J − 1 = Λ/α
// to round-off and the constraint satisfied to round-off in every step.
#include "fixtures.hpp"

#include "trifem/explicit/mesh_builders.hpp"
#include "trifem/mesh/box.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace trifem;
using namespace trifem::explicit_dynamics;

namespace {

constexpr Real kMu = 1.0;

/// Homogeneous uniaxial state (stretches a, b, b) of S = μ(I − C⁻¹) + λ D_C/… under nominal
/// stress P: lateral S_22 = 0, a S_11 = P, λ = α Ψ(J) (Ψ = J − 1 or ln J).
struct Uniaxial {
  Real a, b, lambda;
};

Uniaxial uniaxial_exact(Real P, Real alpha, Constraint constraint) {
  auto residual = [&](Real a, Real b) {
    const Real J = a * b * b;
    const bool jm1 = constraint == Constraint::JMinusOne;
    const Real lam = alpha * (jm1 ? J - 1.0 : std::log(J));
    const Real p = jm1 ? lam * J : lam; // S = μ(I − C⁻¹) + p C⁻¹
    return Vec2(kMu * (1.0 - 1.0 / (b * b)) + p / (b * b),
                a * (kMu * (1.0 - 1.0 / (a * a)) + p / (a * a)) - P);
  };
  Vec2 x(1.5, 1.0 / std::sqrt(1.5));
  for (int it = 0; it < 100; ++it) {
    const Vec2 r = residual(x[0], x[1]);
    Mat2 Jac;
    for (int k = 0; k < 2; ++k) {
      Vec2 d = x;
      d[k] += 1e-7 * x[k];
      Jac.col(k) = (residual(d[0], d[1]) - r) / (1e-7 * x[k]);
    }
    x -= Jac.partialPivLu().solve(r);
  }
  const Real J = x[0] * x[1] * x[1];
  return {x[0], x[1], alpha * (constraint == Constraint::JMinusOne ? J - 1.0 : std::log(J))};
}

/// Unit cube, 2x2x2 cells, with the centre node and two face-centre nodes moved (in plane).
mesh::Mesh distorted_cube() {
  mesh::BoxSpec box;
  box.name = "cube";
  box.divisions = {2, 2, 2};
  return transform_nodes(mesh::make_box(box), [](const Vec3& X) {
    if ((X - Vec3(0.5, 0.5, 0.5)).norm() < 1e-12)
      return Vec3(0.62, 0.43, 0.56);
    if ((X - Vec3(1.0, 0.5, 0.5)).norm() < 1e-12)
      return Vec3(1.0, 0.57, 0.44);
    if ((X - Vec3(0.5, 0.0, 0.5)).norm() < 1e-12)
      return Vec3(0.45, 0.0, 0.58);
    return X;
  });
}

struct PatchResult {
  Vector U, lambda, psi;
  Real max_step_residual = 0.0;
  StepReport last;
  const ExplicitModel* model = nullptr;
};

PatchResult run_patch(const ExplicitModel& model, Real alpha, Constraint constraint) {
  ExplicitSettings s;
  s.penalty = alpha;
  s.constraint = constraint;
  s.damping = 2.0;
  ExplicitSolver solver(model, s);
  PatchResult r;
  r.last = solver.run(100.0, [&](const ExplicitSolver&, const StepReport& rep) {
    r.max_step_residual = std::max(r.max_step_residual, rep.constraint_residual);
  });
  r.U = solver.displacement();
  r.lambda = solver.multiplier();
  r.psi = solver.fields().psi;
  return r;
}

ModelSpec uniaxial_spec(Real P) {
  ModelSpec spec;
  spec.law = test::deviatoric_neo_hookean(kMu);
  spec.density = 1.0;
  spec.fixities = {{"cube.xmin", 0}, {"cube.ymin", 1}, {"cube.zmin", 2}};
  SurfaceLoad load;
  load.kind = LoadKind::DeadTraction;
  load.surface = "cube.xmax";
  load.traction = Vec3(P, 0.0, 0.0);
  load.curve = dofs::LoadCurve({{0.0, 0.0}, {5.0, 1.0}}, dofs::Interpolation::Smooth);
  spec.loads = {load};
  return spec;
}

void expect_homogeneous(const ExplicitModel& model, const PatchResult& r, const Uniaxial& exact,
                        Real alpha) {
  ASSERT_TRUE(r.last.ok()) << r.last.message;
  EXPECT_LT(r.max_step_residual, 1e-12) << "constraint not at round-off in some step";
  const Vector& V = model.volumes();
  const Real mean = r.lambda.mean();
  for (Index e = 0; e < model.num_cells(); ++e) {
    EXPECT_NEAR(r.lambda[e], mean, 1e-10 * std::abs(mean)) << "Lambda not uniform, cell " << e;
    EXPECT_NEAR(r.psi[e] / V[e], r.lambda[e] / alpha, 1e-14) << "J - 1 != lambda/alpha, cell " << e;
  }
  EXPECT_NEAR(mean, exact.lambda, 1e-7 * std::abs(exact.lambda));
  const Vec3 stretch(exact.a, exact.b, exact.b);
  Real err = 0.0;
  for (Index n = 0; n < model.mesh().num_nodes(); ++n) {
    const Vec3 X = model.mesh().node(n);
    const Vec3 u_exact = (stretch.array() - 1.0).matrix().cwiseProduct(X);
    err = std::max(err, (r.U.segment<3>(3 * n) - u_exact).lpNorm<Eigen::Infinity>());
  }
  EXPECT_LT(err, 1e-8) << "displacement not the homogeneous field";
}

} // namespace

TEST(ExplicitPatch, UniaxialJMinusOneIsHomogeneousWithUniformMultiplier) {
  const Real P = 1.055556 * kMu, alpha = 1e3 * kMu;
  const ExplicitModel model(distorted_cube(), uniaxial_spec(P));
  const PatchResult r = run_patch(model, alpha, Constraint::JMinusOne);
  expect_homogeneous(model, r, uniaxial_exact(P, alpha, Constraint::JMinusOne), alpha);
}

TEST(ExplicitPatch, UniaxialLogJIsHomogeneousWithUniformMultiplier) {
  const Real P = 1.055556 * kMu, alpha = 1e3 * kMu;
  const ExplicitModel model(distorted_cube(), uniaxial_spec(P));
  const PatchResult r = run_patch(model, alpha, Constraint::LogJ);
  expect_homogeneous(model, r, uniaxial_exact(P, alpha, Constraint::LogJ), alpha);
}

TEST(ExplicitPatch, NearlyIncompressibleLimitMatchesClosedForm) {
  // reference-solutions.md §R8.1: stretch 1.5 needs P = 1.055556 μ when J = 1.
  const Real P = 1.055556 * kMu, alpha = 1e6 * kMu;
  const Uniaxial exact = uniaxial_exact(P, alpha, Constraint::JMinusOne);
  EXPECT_NEAR(exact.a, 1.5, 1e-5);
  const ExplicitModel model(distorted_cube(), uniaxial_spec(P));
  const PatchResult r = run_patch(model, alpha, Constraint::JMinusOne);
  expect_homogeneous(model, r, exact, alpha);
}
