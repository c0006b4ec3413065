// SPDX-License-Identifier: MIT
// Thick incompressible neo-Hookean sphere A = 1, B = 2 (octant with symmetry planes):
// (b) quasi-static inner radius vs pressure by damped dynamics against the closed form, with
//     refinement; (d) step-pressure oscillation from rest against the radial ODE, and energy
//     conservation of reading B over five periods.
#include "exact_sphere.hpp"
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

const test::sphere::Sphere kSphere{};

/// The octant of n x n x n cells per patch with follower pressure μ curve(t) inside.
test::TestModel sphere_model(int n, const io::CurveSpec& curve) {
  test::ShellOctantSpec shell;
  shell.divisions = n;
  shell.layers = n;
  test::ExplicitTestCase c(test::make_shell_octant(shell),
                           test::deviatoric_material(kSphere.mu, kSphere.rho));
  c.fix("shell.x0", {0}).fix("shell.y0", {1}).fix("shell.z0", {2});
  c.pressure("shell.inner", kSphere.mu, curve);
  return test::TestModel(c);
}

/// Inner radii after damped holds at the pressure levels P/μ = 0.158081, 0.551869, 0.755433
/// (λ_a = 1.05, 1.25, 1.5 exactly).
std::vector<Real> quasi_static_radii(int n, const std::vector<Real>& levels) {
  io::CurveSpec curve{dofs::Interpolation::Smooth, {{0.0, 0.0}}};
  const Real ramp = 5.0, hold = 15.0;
  for (std::size_t i = 0; i < levels.size(); ++i) {
    const Real t0 = static_cast<Real>(i) * (ramp + hold);
    curve.points.push_back({t0 + ramp, levels[i]});
    curve.points.push_back({t0 + ramp + hold, levels[i]});
  }
  const test::TestModel model = sphere_model(n, curve);
  ExplicitSettings s;
  s.damping = 2.0; // ≈ critical for the breathing mode at λ_a = 1.5 (ω ≈ 0.9; 2.4 at λ_a = 1)
  ExplicitSolver solver(model, s);
  std::vector<Real> radii;
  for (std::size_t i = 0; i < levels.size(); ++i) {
    const StepReport r = solver.run(static_cast<Real>(i + 1) * (ramp + hold));
    EXPECT_TRUE(r.ok()) << r.message;
    radii.push_back(mean_radius(solver, "shell.inner"));
  }
  return radii;
}

} // namespace

TEST(ExplicitSphere, QuasiStaticInnerRadiusMatchesClosedFormAndConverges) {
  const std::vector<Real> levels = {0.158081, 0.551869, 0.755433};
  const std::vector<Real> exact = {1.05, 1.25, 1.5};
  for (std::size_t i = 0; i < levels.size(); ++i)
    ASSERT_NEAR(kSphere.static_radius(levels[i]), exact[i], 2e-6);
  std::vector<Real> worst;       // max over the levels of |a − a_exact| / a_exact, per mesh
  std::vector<Real> below_limit; // the same for λ_a ≤ 1.25 (away from the limit point)
  for (int n : {2, 4, 6}) {
    const std::vector<Real> a = quasi_static_radii(n, levels);
    Real max_err = 0.0, max_low = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
      const Real err = std::abs(a[i] - exact[i]) / exact[i];
      std::printf("sphere n=%d cells=%d P/mu=%.6f a=%.6f exact=%.6f rel.err(a)=%.3e "
                  "rel.err(a-A)=%.3e\n",
                  n, 3 * n * n * n, levels[i], a[i], exact[i], err,
                  std::abs(a[i] - exact[i]) / (exact[i] - 1.0));
      max_err = std::max(max_err, err);
      if (exact[i] <= 1.25)
        max_low = std::max(max_low, err);
    }
    worst.push_back(max_err);
    below_limit.push_back(max_low);
  }
  const Real rate_24 = std::log(worst[0] / worst[1]) / std::log(2.0);
  const Real rate_46 = std::log(worst[1] / worst[2]) / std::log(1.5);
  std::printf("sphere observed rates: %.2f (n 2->4), %.2f (n 4->6)\n", rate_24, rate_46);
  EXPECT_LT(worst[2], 0.01) << "moderate mesh n = 6 (648 cells) not within 1 % up to 1.5";
  EXPECT_LT(below_limit[1], 0.01) << "n = 4 (192 cells) not within 1 % up to 1.25";
  EXPECT_GT(rate_24, 1.8); // Q1 nodal values: O(h²)
  EXPECT_GT(rate_46, 1.8);
}

namespace {

/// Undamped reading-B response to a step pressure P = 0.3 μ from rest: (t, a, total energy,
/// external work) per step.
struct Oscillation {
  std::vector<Real> t, a, energy, work;
};

Oscillation step_pressure_run(int n, Reading reading, Real t_end) {
  const test::TestModel model = sphere_model(n, {dofs::Interpolation::Step, {{0.0, 0.3}}});
  ExplicitSettings s;
  s.reading = reading;
  ExplicitSolver solver(model, s);
  Oscillation o;
  auto record = [&](const ExplicitSolver& sv) {
    const Energies e = sv.energies();
    o.t.push_back(sv.time());
    o.a.push_back(mean_radius(sv, "shell.inner"));
    o.energy.push_back(e.total());
    o.work.push_back(e.external_work);
  };
  record(solver);
  const StepReport r =
      solver.run(t_end, [&](const ExplicitSolver& sv, const StepReport&) { record(sv); });
  EXPECT_TRUE(r.ok()) << r.message;
  return o;
}

} // namespace

TEST(ExplicitSphere, StepPressureOscillationMatchesRadialOde) {
  const auto ode = test::sphere::integrate_radial(
      kSphere, [](Real) { return 0.3; }, 20.0, 1e-4);
  const Real period = test::sphere::first_period(ode);
  ASSERT_GT(period, 0.0);
  const Oscillation o = step_pressure_run(4, Reading::B, period);
  Real max_err = 0.0, amplitude = 0.0;
  for (std::size_t i = 0; i < o.t.size(); ++i) {
    const Real a_ode = test::sphere::radius_at(ode, o.t[i]);
    max_err = std::max(max_err, std::abs(o.a[i] - a_ode) / a_ode);
    amplitude = std::max(amplitude, a_ode - kSphere.A);
  }
  std::printf("sphere oscillation: period %.4f, steps %zu, max |a - a_ode|/a_ode = %.3e "
              "(%.3e of the amplitude %.4f)\n",
              period, o.t.size() - 1, max_err, max_err * (1.0 + amplitude) / amplitude, amplitude);
  EXPECT_LT(max_err, 0.02);
}

TEST(ExplicitSphere, ReadingBConservesEnergyOverFivePeriods) {
  const Oscillation o = step_pressure_run(4, Reading::B, 5 * 2.9);
  Real drift = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < o.t.size(); ++i) {
    drift = std::max(drift, std::abs(o.energy[i] - o.energy[0]));
    scale = std::max(scale, std::abs(o.work[i]));
  }
  std::printf("sphere energy: max |E - E0| / max W_ext = %.3e over %zu steps\n", drift / scale,
              o.t.size() - 1);
  EXPECT_LT(drift / scale, 0.005);
}
