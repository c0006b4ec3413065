// SPDX-License-Identifier: MIT
// Stability of the explicit scheme with its default step control: the geometric stiffness of the
// multiplier force against finite differences, the frequency bound on a deformed and stressed
// state, equal steps towards an output time, and the energy balance of a suddenly loaded,
// strongly bending cantilever whose output times are not multiples of the step.
#include "fixtures.hpp"

#include "trifem/explicit/cell_kernel.hpp"
#include "trifem/explicit/energy_balance.hpp"
#include "trifem/explicit/multiplier_stiffness.hpp"
#include "trifem/explicit/stable_step.hpp"
#include "trifem/mesh/box.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace trifem;
using namespace trifem::explicit_dynamics;

namespace {

/// A box of nx x ny x nz cells, clamped at x = 0, with a follower pressure on z = max.
test::TestModel cantilever(Vec3 size, std::array<int, 3> divisions, Real mu, Real density,
                           Real pressure) {
  mesh::BoxSpec box;
  box.name = "beam";
  box.size = size;
  box.divisions = divisions;
  test::ExplicitTestCase c(mesh::make_box(box), test::deviatoric_material(mu, density));
  c.fix("beam.xmin", {0, 1, 2}).pressure("beam.zmax", pressure, test::step_curve());
  return test::TestModel(c);
}

/// Deterministic pseudo-random displacement of amplitude `amplitude` (zero on fixed DOFs).
Vector wobble(const ExplicitView& model, Real amplitude) {
  Vector U(model.num_dofs());
  for (Index i = 0; i < U.size(); ++i)
    U[i] = model.fixed()[i] ? 0.0 : amplitude * std::sin(3.7 * i + 0.3 * (i % 5));
  return U;
}

} // namespace

TEST(ExplicitStability, MultiplierStiffnessIsTheDerivativeOfTheConstraintGradient) {
  const test::TestModel model = cantilever(Vec3(1.0, 0.8, 0.6), {1, 1, 1}, 1.0, 1.0, 0.0);
  const Vector U = wobble(model, 0.15);
  constexpr Real kLambda = 0.7, kStep = 1e-6;
  for (const Constraint constraint : {Constraint::JMinusOne, Constraint::LogJ}) {
    SCOPED_TRACE(constraint == Constraint::JMinusOne ? "J - 1" : "ln J");
    physics::HexMatrix K;
    ASSERT_TRUE(multiplier_stiffness(std::get<fe::HexGeometry>(model.geometry()[0]),
                                     model.hex8_values(0, U), constraint, kLambda, K));
    EXPECT_LT((K - K.transpose()).norm(), 1e-14 * K.norm());
    physics::HexMatrix fd;
    CellFields plus, minus;
    for (int a = 0; a < 8; ++a)
      for (int k = 0; k < 3; ++k) {
        const Index dof = 3 * model.mesh().cell(0)[a] + k;
        Vector Up = U, Um = U;
        Up[dof] += kStep;
        Um[dof] -= kStep;
        ASSERT_TRUE(evaluate_cells(model, constraint, Up, {false, true, false}, plus).ok());
        ASSERT_TRUE(evaluate_cells(model, constraint, Um, {false, true, false}, minus).ok());
        fd.col(3 * a + k) =
            kLambda * (plus.gradient.head<24>() - minus.gradient.head<24>()) / (2.0 * kStep);
      }
    const Real error = (K - fd).norm() / K.norm();
    std::printf("multiplier stiffness vs finite differences: relative error %.2e\n", error);
    EXPECT_LT(error, 1e-8);
  }
}

TEST(ExplicitStability, ElementBoundStaysAboveThePowerIterationOnAStressedState) {
  const test::TestModel model = cantilever(Vec3(4.0, 1.0, 1.0), {8, 2, 2}, 1.0, 1.0, 0.05);
  const Vector U = wobble(model, 0.05);
  Vector lambda(model.num_cells());
  for (Index c = 0; c < lambda.size(); ++c)
    lambda[c] = 0.8 * std::cos(1.3 * c); // multipliers of the order of μ, both signs
  for (const Constraint constraint : {Constraint::JMinusOne, Constraint::LogJ}) {
    const FrequencyEstimate with =
        power_iteration_omega(model, constraint, U, lambda, false, 5000, 1e-12);
    const FrequencyEstimate without =
        power_iteration_omega(model, constraint, U, {}, false, 5000, 1e-12);
    const FrequencyEstimate bound = element_bound_omega(model, constraint, U, lambda);
    std::printf("omega with K_lambda %.5f, without %.5f, element bound %.5f\n", with.omega,
                without.omega, bound.omega);
    EXPECT_LE(with.omega, bound.omega * (1.0 + 1e-9));
    // The multiplier's geometric stiffness is not negligible at λ ~ μ.
    EXPECT_GT(std::abs(with.omega - without.omega), 1e-3 * without.omega);
  }
}

TEST(ExplicitStability, StepsTowardsATargetAreEqual) {
  const test::TestModel model = cantilever(Vec3(4.0, 1.0, 1.0), {4, 1, 1}, 1.0, 1.0, 0.01);
  ExplicitSolver solver(model, ExplicitSettings{});
  const Real dt = solver.time_step_info().used;
  const Real target = 10.3 * dt; // 11 equal steps of 10.3/11 dt, not 10 full and one short
  int steps = 0;
  while (solver.time() < target * (1.0 - 1e-12)) {
    const StepReport r = solver.step(target);
    ASSERT_TRUE(r.ok()) << r.message;
    EXPECT_NEAR(r.dt, target / 11.0, 1e-12 * dt) << "step " << steps;
    ++steps;
  }
  EXPECT_EQ(steps, 11);
  EXPECT_DOUBLE_EQ(solver.time(), target);
}

// A suddenly loaded 10 x 1 x 1 mm neo-Hookean cantilever (30 x 3 x 3 cells, μ = 0.4 MPa, α = 1e4
// μ, tip deflection up to 37 % of its length), undamped, default step control, stepped to output
// times every 5e-4 s that are not multiples of the step. With the last step before each output
// time cut short (one short step in 44) the total energy grew by 0.8 % per step and reached
// 100 times the external work in 0.04 s; with equal steps it stays at round-off level.
TEST(ExplicitStability, DefaultStepKeepsTheEnergyOfABendingCantileverBalanced) {
  const test::TestModel model = cantilever(Vec3(10.0, 1.0, 1.0), {30, 3, 3}, 0.4, 1.1e-9, 1.6e-4);
  ExplicitSettings s;
  s.penalty = 4000.0;
  ExplicitSolver solver(model, s);
  Real worst = 0.0, work = 0.0, deflection = 0.0;
  for (int i = 1; i <= 80; ++i) {
    const StepReport r = solver.run(5e-4 * i);
    ASSERT_TRUE(r.ok()) << r.message;
    ASSERT_EQ(r.halvings, 0);
    const Energies e = solver.energies();
    worst = std::max(worst, std::abs(e.total()));
    work = std::max(work, std::abs(e.external_work));
    deflection = std::max(deflection, -solver.displacement().minCoeff());
  }
  std::printf("cantilever: %ld steps, largest deflection %.3f mm, largest |energy error| %.3g "
              "of the largest external work\n",
              solver.step_count(), deflection, worst / work);
  EXPECT_GT(deflection, 3.0); // large deformation indeed
  EXPECT_LT(worst, 1e-4 * work);
}

TEST(ExplicitStability, EnergyBalanceFlagsTheFirstErrorAboveTheThreshold) {
  // 4 cells of 1 x 1 x 1, mu = 1: round-off floor 1e-10 x 4 mJ.
  const test::TestModel model = cantilever(Vec3(4.0, 1.0, 1.0), {4, 1, 1}, 1.0, 1.0, 0.01);
  EnergyBalance balance(model);
  ASSERT_EQ(EnergyBalance::kThreshold, 0.05);
  EXPECT_FALSE(balance.record({1e-13, 0.0, 0.0, 0.0})) << "below the round-off floor";
  EXPECT_EQ(balance.last_error(), 0.0);
  EXPECT_FALSE(balance.record({0.4, 0.6, 1.0, 0.0})); // kinetic, strain, work, damping: balanced
  EXPECT_NEAR(balance.last_error(), 0.0, 1e-15);
  EXPECT_FALSE(balance.record({0.38, 0.6, 1.0, 0.0})); // 2 % of the work lost
  EXPECT_NEAR(balance.last_error(), 0.02, 1e-12);
  EXPECT_FALSE(balance.exceeded());
  EXPECT_TRUE(balance.record({0.5, 0.6, 1.0, 0.0})); // 10 % gained: reported
  EXPECT_NEAR(balance.last_error(), 0.1, 1e-12);
  EXPECT_FALSE(balance.record({1.0, 0.6, 1.0, 0.0})) << "reported once";
  EXPECT_NEAR(balance.max_error(), 0.6, 1e-12); // total 0.6 against the largest energy, 1.0
  EXPECT_TRUE(balance.exceeded());
}
