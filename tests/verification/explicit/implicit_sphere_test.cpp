// SPDX-License-Identifier: MIT
// The step-pressure oscillation of the thick incompressible sphere (sphere_test.cpp) by implicit
// dynamics (generalized-α, mean-dilatation cells of a nearly incompressible neo-Hookean law)
// against the radial ODE of the exactly incompressible sphere and against the dynamic-explicit
// answer (P0 multiplier, exact constraint) on the same mesh.
#include "exact_sphere.hpp"
#include "fixtures.hpp"
#include "generated_meshes.hpp"
#include "solver_history.hpp"
#include "trifem/analysis/run.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace trifem;
using namespace trifem::test;

namespace {

const sphere::Sphere kSphere{};
constexpr int kDivisions = 4;   // 192 cells
constexpr Real kPressure = 0.3; // P/μ of the step

/// The octant with the step pressure inside, of `material`.
ExplicitTestCase sphere_case(const io::MaterialSpec& material) {
  ShellOctantSpec shell;
  shell.divisions = kDivisions;
  shell.layers = kDivisions;
  ExplicitTestCase c(make_shell_octant(shell), material);
  c.fix("shell.x0", {0}).fix("shell.y0", {1}).fix("shell.z0", {2});
  c.pressure("shell.inner", kSphere.mu, {dofs::Interpolation::Step, {{0.0, kPressure}}});
  return c;
}

/// Mean current radius of the nodes of `set` in the model's state.
Real mean_radius(const model::Model& m, const std::string& set) {
  const Vector& x = m.problem->state();
  Real sum = 0.0;
  for (Index a : m.mesh.node_set(set)) {
    Vec3 position = m.mesh.node(a);
    for (int k = 0; k < 3; ++k)
      position[k] += x[m.dofs.dof(m.displacement(), a, k)];
    sum += position.norm();
  }
  return sum / static_cast<Real>(m.mesh.node_set(set).size());
}

} // namespace

TEST(ImplicitSphere, StepPressureOscillationMatchesTheRadialOdeAndTheExplicitAnswer) {
  const auto ode = sphere::integrate_radial(
      kSphere, [](Real) { return kPressure; }, 20.0, 1e-4);
  const Real period = sphere::first_period(ode);
  ASSERT_GT(period, 0.0);

  // implicit: κ = 10⁴ μ (mean-dilatation cells), 50 steps per period, ρ∞ = 0.9
  ExplicitTestCase implicit = sphere_case(compressible_material(kSphere.mu, 1e4, kSphere.rho));
  io::CaseSpec& spec = implicit.spec();
  spec.analysis.type = io::AnalysisType::Dynamic;
  spec.dynamics.rho_inf = 0.9;
  spec.time.end_time = period;
  spec.time.dt = spec.time.dt_max = period / 50.0;
  const std::unique_ptr<model::Model> model = implicit.build();
  solver::NewtonSolver newton(analysis::newton_settings(spec.solver),
                              linalg::make_linear_solver({LinearSolverKind::umfpack}));
  std::vector<Real> times = {0.0}, radii = {mean_radius(*model, "shell.inner")};
  analysis::StepState steps;
  const solver::RunReport run = analysis::run_steps(
      spec, *model, steps, newton,
      [&](const solver::StepInfo& info) {
        times.push_back(info.time);
        radii.push_back(mean_radius(*model, "shell.inner"));
      },
      [](const solver::StepController&) {});
  ASSERT_TRUE(run.success) << run.failure;
  ASSERT_GE(times.size(), 51u);

  // explicit, the same mesh and pressure (sphere_test.cpp)
  const TestModel explicit_model(sphere_case(deviatoric_material(kSphere.mu, kSphere.rho)));
  explicit_dynamics::ExplicitSolver solver(explicit_model, {});
  Real max_ode = 0.0, max_explicit = 0.0, amplitude = 0.0;
  for (std::size_t i = 0; i < times.size(); ++i) {
    const Real a_ode = sphere::radius_at(ode, times[i]);
    amplitude = std::max(amplitude, a_ode - kSphere.A);
    max_ode = std::max(max_ode, std::abs(radii[i] - a_ode));
    if (i > 0) {
      ASSERT_TRUE(solver.run(times[i]).ok());
      max_explicit =
          std::max(max_explicit, std::abs(radii[i] - test::mean_radius(solver, "shell.inner")));
    }
  }
  std::printf("implicit sphere over one period (%zu steps): max |a - a_ode| = %.3e, |a - "
              "a_explicit| = %.3e of the amplitude %.4f\n",
              times.size() - 1, max_ode / amplitude, max_explicit / amplitude, amplitude);
  // the mesh's error of the radius (the explicit test allows 2 % of a, 0.11 of the amplitude)
  EXPECT_LT(max_ode / amplitude, 0.04);
  // the two formulations on one mesh: their time-discretization and constraint errors
  EXPECT_LT(max_explicit / amplitude, 0.03);
}
