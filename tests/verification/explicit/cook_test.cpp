// SPDX-License-Identifier: MIT
// Cook's membrane (plane strain, one cell through the thickness), μ = ρ = 1 units:
// iteration counts independent of α (docs/theory/explicit.md §5), volume change |J̄ − 1| ≈ |Λ|/α,
// and volumetric locking of the pure-displacement Q1 version of the same problem
// (docs/theory/reference-solutions.md §R8.5).
#include "fixtures.hpp"

#include "generated_meshes.hpp"
#include "solver_history.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace trifem;
using namespace trifem::explicit_dynamics;
using namespace trifem::test;

namespace {

constexpr Real kCookMu = 1.0;
constexpr Real kShear = 0.02; ///< shear traction on the loaded edge [MPa] (resultant 0.32 N)

/// Cook's membrane: x = 0 clamped, u_z = 0 everywhere (plane strain), vertical dead traction
/// on x = 48 with the given load curve. `material` = the explicit part W.
test::TestModel cook_model(int n, const io::MaterialSpec& material, const io::CurveSpec& curve) {
  test::CookSpec cook;
  cook.nx = cook.ny = n;
  test::ExplicitTestCase c(test::make_cook_membrane(cook), material);
  c.fix("cook.xmin", {0, 1}).fix("cook.all", {2});
  c.traction("cook.xmax", Vec3(0.0, kShear, 0.0), curve);
  return test::TestModel(c);
}

struct SuddenLoad {
  std::vector<int> iterations;
  Real max_volume_change = 0.0, max_gauss_volume_change = 0.0, dt = 0.0;
};

SuddenLoad sudden_load(Reading reading, Real alpha, Real t_end) {
  const test::TestModel model =
      cook_model(8, test::deviatoric_material(kCookMu, 1.0), test::step_curve());
  ExplicitSettings s;
  s.reading = reading;
  s.penalty = alpha;
  ExplicitSolver solver(model, s);
  SuddenLoad out;
  out.dt = solver.time_step();
  const StepReport r = solver.run(t_end, [&](const ExplicitSolver& sv, const StepReport& rep) {
    out.iterations.push_back(rep.iterations);
    out.max_volume_change = std::max(out.max_volume_change, sv.max_volume_change());
    out.max_gauss_volume_change =
        std::max(out.max_gauss_volume_change, sv.max_gauss_volume_change());
  });
  EXPECT_TRUE(r.ok()) << r.message;
  return out;
}

void expect_alpha_independent(Reading reading, Real t_end) {
  const SuddenLoad soft = sudden_load(reading, 1e3 * kCookMu, t_end);
  const SuddenLoad stiff = sudden_load(reading, 1e6 * kCookMu, t_end);
  EXPECT_EQ(soft.dt, stiff.dt) << "the stable step must not depend on alpha";
  ASSERT_EQ(soft.iterations.size(), stiff.iterations.size());
  int max_diff = 0;
  Real mean_soft = 0.0, mean_stiff = 0.0;
  for (std::size_t i = 0; i < soft.iterations.size(); ++i) {
    max_diff = std::max(max_diff, std::abs(soft.iterations[i] - stiff.iterations[i]));
    mean_soft += soft.iterations[i];
    mean_stiff += stiff.iterations[i];
  }
  mean_soft /= static_cast<Real>(soft.iterations.size());
  mean_stiff /= static_cast<Real>(stiff.iterations.size());
  std::printf("Cook reading %s: %zu steps of %.4g, mean iterations %.3f (alpha = 1e3 mu) vs "
              "%.3f (1e6 mu), max per-step difference %d; max|Jbar-1| = %.3e, max Gauss "
              "|J-1| = %.3e at alpha = 1e3 mu\n",
              reading == Reading::A ? "A" : "B", soft.iterations.size(), soft.dt, mean_soft,
              mean_stiff, max_diff, soft.max_volume_change, soft.max_gauss_volume_change);
  EXPECT_LE(max_diff, 1);
  EXPECT_LE(soft.max_volume_change, 1e-3);
}

} // namespace

TEST(ExplicitCook, IterationCountsIndependentOfPenaltyReadingB) {
  expect_alpha_independent(Reading::B, 130.0); // about half the first bending period
}

TEST(ExplicitCook, IterationCountsIndependentOfPenaltyReadingA) {
  expect_alpha_independent(Reading::A, 40.0);
}

namespace {

/// Tip deflection (mean u_y of the loaded edge) after a slow ramp and damped hold.
Real quasi_static_tip(int n, bool mixed) {
  const io::MaterialSpec material = mixed
                                        ? test::deviatoric_material(kCookMu, 1.0)
                                        : test::compressible_material(kCookMu, 1e3 * kCookMu, 1.0);
  const test::TestModel model = cook_model(n, material, test::smooth_ramp(50.0));
  ExplicitSettings s;
  s.multiplier = mixed;
  s.penalty = 1e3 * kCookMu;
  s.damping = 0.05; // ≈ 2 ω of the first bending mode (period ≈ 250)
  ExplicitSolver solver(model, s);
  const StepReport r = solver.run(500.0);
  EXPECT_TRUE(r.ok()) << r.message;
  return mean_displacement(solver, "cook.xmax", 1);
}

} // namespace

TEST(ExplicitCook, PureDisplacementQ1LocksWhereTheMultiplierDoesNot) {
  // Same bulk stiffness: α = 1e3 μ in the mixed form, κ = 1e3 μ (ν = 0.4995) in Q1.
  const Real mixed_8 = quasi_static_tip(8, true);
  const Real mixed_16 = quasi_static_tip(16, true);
  const Real q1_8 = quasi_static_tip(8, false);
  std::printf("Cook quasi-static tip deflection: mixed 8x8 %.5f, mixed 16x16 %.5f, "
              "Q1 8x8 %.5f (ratio Q1/mixed %.3f)\n",
              mixed_8, mixed_16, q1_8, q1_8 / mixed_8);
  EXPECT_NEAR(mixed_8, mixed_16, 0.05 * mixed_16); // the mixed answer is nearly converged
  EXPECT_LT(q1_8, 0.5 * mixed_8);                  // Q1 is far too stiff: locking
}

TEST(ExplicitCook, ReusedFactorizationGivesTheSameSolution) {
  const test::TestModel model =
      cook_model(8, test::deviatoric_material(kCookMu, 1.0), test::step_curve());
  Vector tip[2];
  long solves[2], factorizations[2];
  for (int i = 0; i < 2; ++i) {
    ExplicitSettings s;
    s.penalty = 1e3 * kCookMu;
    s.factorization_age = i == 0 ? 1 : 25;
    ExplicitSolver solver(model, s);
    ASSERT_TRUE(solver.run(130.0).ok());
    tip[i] = solver.displacement();
    solves[i] = solver.total_iterations();
    factorizations[i] = solver.timings().factorizations;
  }
  std::printf("Cook factorization reuse: %ld factorizations / %ld solves (every step) vs %ld / "
              "%ld (age <= 25)\n",
              factorizations[0], solves[0], factorizations[1], solves[1]);
  EXPECT_LT((tip[0] - tip[1]).lpNorm<Eigen::Infinity>(), 1e-7 * tip[0].lpNorm<Eigen::Infinity>());
  EXPECT_LT(factorizations[1], factorizations[0] / 5);
}
