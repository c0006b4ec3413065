// SPDX-License-Identifier: MIT
// Implicit dynamics (generalized-α, physics/inertia_term.hpp) against the exact answer of the
// discrete linear system: a cantilever loaded suddenly by a load proportional to M φ₁, whose
// response is its first mode alone, u(t) = (c/ω₁²)(1 − cos ω₁t) φ₁ (ω₁² and φ₁ from the
// generalized eigenproblem K φ = ω² M φ of the same mesh). Small amplitude: the neo-Hookean
// solid responds linearly to 1e-6 of the amplitude.
#include "solid_model.hpp"
#include "trifem/physics/inertia_term.hpp"
#include "trifem/physics/nodal_force_term.hpp"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>

namespace trifem::test {
namespace {

constexpr Real kDensity = 1.0e-9; // t/mm^3
constexpr Real kPi = std::numbers::pi;

/// The cantilever: 10 x 1 x 1 mm, 10 x 2 x 2 cells, clamped at x = 0.
SolidModel cantilever() {
  mesh::BoxSpec box;
  box.name = "beam";
  box.size = Vec3(10.0, 1.0, 1.0);
  box.divisions = {10, 2, 2};
  SolidModel m(mesh::make_box(box), "neo-hookean", {{"E", 1.0}, {"nu", 0.3}});
  const std::vector<Index> clamped = m.mesh.node_set("beam.xmin");
  for (int k = 0; k < 3; ++k)
    m.prescribe(clamped, k, 0.0);
  return m;
}

/// The inertia term of every cell of `m`.
std::unique_ptr<physics::InertiaTerm> inertia(const SolidModel& m, physics::GeneralizedAlpha a,
                                              physics::MassMatrix mass) {
  std::vector<Index> cells(m.mesh.num_cells());
  for (Index c = 0; c < m.mesh.num_cells(); ++c)
    cells[c] = c;
  return std::make_unique<physics::InertiaTerm>(m.mesh, m.dofs, m.u, cells,
                                                std::vector<Real>(cells.size(), kDensity), mass, a);
}

/// The free equations' stiffness at u = 0 and mass, dense.
struct LinearSystem {
  Eigen::MatrixXd K, M;
};

LinearSystem linear_system(SolidModel& m, const physics::InertiaTerm& inertia) {
  solver::Linearization lin;
  EXPECT_EQ(m.problem->linearize(lin, true), solver::SolveStatus::Converged);
  LinearSystem s{Eigen::MatrixXd(lin.jacobian), Eigen::MatrixXd()};
  const Index n = m.dofs.num_equations();
  s.M.resize(n, n);
  for (Index j = 0; j < n; ++j) {
    Vector e = Vector::Zero(m.dofs.num_dofs());
    e[m.dofs.dof_of_equation(j)] = 1.0;
    const Vector column = inertia.mass_times(e);
    for (Index i = 0; i < n; ++i)
      s.M(i, j) = column[m.dofs.dof_of_equation(i)];
  }
  return s;
}

/// A run of the modal cantilever.
struct ModalRun {
  Real omega = 0.0;               ///< ω₁ [1/s]
  Real amplitude = 0.0;           ///< c/ω₁² φ₁ at the probe DOF [mm]
  std::vector<Real> times;        ///< t_n [s]
  std::vector<Real> probe;        ///< u at the probe DOF [mm]
  std::vector<Real> energy;       ///< v·M v/2 + u·K u/2 − F·u [mJ] (0 at rest)
  Real kinetic_peak = 0.0;        ///< largest v·M v/2 [mJ]
  Real initial_accel_error = 0.0; ///< |a_0 − c φ₁| / |c φ₁|
};

/// Runs `periods` periods of the first mode in `steps_per_period` steps.
ModalRun run_modal(Real rho_inf, int steps_per_period, Real periods,
                   physics::MassMatrix mass = physics::MassMatrix::Consistent) {
  SolidModel m = cantilever();
  m.build();
  auto term = inertia(m, physics::GeneralizedAlpha::from_spectral_radius(rho_inf), mass);
  const LinearSystem s = linear_system(m, *term);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> modes(s.K, s.M);
  EXPECT_EQ(modes.info(), Eigen::Success);
  ModalRun run;
  run.omega = std::sqrt(modes.eigenvalues()[0]);
  Vector phi = modes.eigenvectors().col(0);
  Index probe = 0;
  phi.cwiseAbs().maxCoeff(&probe);
  phi /= phi[probe];                           // φ₁ = 1 at the probe
  const Real c = 2e-5 * run.omega * run.omega; // u_max = 2c/ω² = 4e-5 mm
  run.amplitude = c / (run.omega * run.omega);
  const Vector F = c * s.M * phi;
  std::vector<physics::NodalForce> forces;
  for (Index eq = 0; eq < F.size(); ++eq)
    forces.push_back({m.dofs.dof_of_equation(eq), F[eq], dofs::LoadCurve::constant(1.0)});
  m.problem->add_term(std::make_unique<physics::NodalForceTerm>(std::move(forces)));
  const physics::InertiaTerm* view = term.get();
  m.problem->add_inertia(std::move(term));
  m.problem->set_dynamic(true);

  Vector a0(F.size());
  for (Index eq = 0; eq < F.size(); ++eq)
    a0[eq] = view->acceleration()[std::lower_bound(view->dofs().begin(), view->dofs().end(),
                                                   m.dofs.dof_of_equation(eq)) -
                                  view->dofs().begin()];
  run.initial_accel_error = (a0 - c * phi).norm() / (c * phi).norm();

  const Index probe_dof = m.dofs.dof_of_equation(probe);
  const Real dt = 2 * kPi / run.omega / steps_per_period;
  const int steps = static_cast<int>(std::lround(periods * steps_per_period));
  solver::NewtonSettings settings;
  settings.residual_tolerance = 1e-12;
  settings.increment_tolerance = 1e-12;
  for (int n = 1; n <= steps; ++n) {
    const auto report = m.solve_step(n * dt, dt, settings);
    EXPECT_EQ(report.status, solver::SolveStatus::Converged) << "step " << n;
    if (report.status != solver::SolveStatus::Converged)
      break;
    Vector u(F.size()), v(F.size());
    for (Index eq = 0; eq < F.size(); ++eq) {
      const Index dof = m.dofs.dof_of_equation(eq);
      u[eq] = m.problem->state()[dof];
      v[eq] = view->velocity()[std::lower_bound(view->dofs().begin(), view->dofs().end(), dof) -
                               view->dofs().begin()];
    }
    const Real kinetic = 0.5 * v.dot(s.M * v);
    run.kinetic_peak = std::max(run.kinetic_peak, kinetic);
    run.times.push_back(n * dt);
    run.probe.push_back(m.problem->state()[probe_dof]);
    run.energy.push_back(kinetic + 0.5 * u.dot(s.K * u) - F.dot(u));
  }
  return run;
}

/// Largest |u_n − u(t_n)| over the run, relative to the amplitude.
Real history_error(const ModalRun& run) {
  Real worst = 0.0;
  for (std::size_t n = 0; n < run.times.size(); ++n) {
    const Real exact = run.amplitude * (1.0 - std::cos(run.omega * run.times[n]));
    worst = std::max(worst, std::abs(run.probe[n] - exact));
  }
  return worst / run.amplitude;
}

/// The time between the first two upward crossings of the mean u = amplitude (at T/4 and
/// 5T/4), each interpolated linearly between steps.
Real measured_period(const ModalRun& run) {
  std::vector<Real> crossings;
  for (std::size_t n = 1; n < run.times.size(); ++n) {
    const Real a = run.probe[n - 1] - run.amplitude, b = run.probe[n] - run.amplitude;
    if (a < 0.0 && b >= 0.0)
      crossings.push_back(run.times[n - 1] + (run.times[n] - run.times[n - 1]) * a / (a - b));
  }
  EXPECT_GE(crossings.size(), 2u);
  return crossings.size() >= 2 ? crossings[1] - crossings[0] : 0.0;
}

TEST(ImplicitDynamics, InitialAccelerationSolvesTheEquationOfMotion) {
  // at rest under the load F = c M φ₁: a_0 = M⁻¹ F = c φ₁
  EXPECT_LT(run_modal(1.0, 40, 0.0).initial_accel_error, 1e-10);
}

TEST(ImplicitDynamics, CantileverPeriodMatchesTheModalClosedForm) {
  const ModalRun run = run_modal(1.0, 40, 1.5);
  const Real period = 2 * kPi / run.omega;
  // the trapezoidal rule lengthens the period by (ω Δt)²/12 = 0.21 % at 40 steps per period
  EXPECT_NEAR(measured_period(run) / period, 1.0, 5e-3);
  const Real h = 2 * kPi / 40;
  const Real elongation = 2 * std::atan(0.5 * h) / h; // ω̃/ω of the trapezoidal rule
  EXPECT_NEAR(measured_period(run) / period, 1.0 / elongation, 2e-4);
  std::cout << "period " << measured_period(run) / period << " of 2 pi/omega, trapezoidal "
            << 1.0 / elongation << "\n";
}

TEST(ImplicitDynamics, TrapezoidalRuleConservesEnergy) {
  const ModalRun run = run_modal(1.0, 40, 2.0);
  ASSERT_FALSE(run.energy.empty());
  // exactly conserved by the linear system; the solid's nonlinearity at strains of 1e-6
  // changes the energy by about that fraction
  for (std::size_t n = 0; n < run.energy.size(); ++n)
    EXPECT_LT(std::abs(run.energy[n]), 1e-5 * run.kinetic_peak) << "step " << n + 1;
}

TEST(ImplicitDynamics, DissipativeMethodLosesEnergy) {
  // ρ∞ = 0 damps the highest frequencies; the first mode at 20 steps per period loses a little
  const ModalRun run = run_modal(0.0, 20, 2.0);
  ASSERT_FALSE(run.energy.empty());
  EXPECT_LT(run.energy.back(), -1e-3 * run.kinetic_peak);
  for (std::size_t n = 1; n < run.energy.size(); ++n)
    EXPECT_LE(run.energy[n], run.energy[n - 1] + 1e-9 * run.kinetic_peak) << "step " << n + 1;
}

TEST(ImplicitDynamics, ConvergesAtSecondOrderInTheStep) {
  for (const Real rho_inf : {1.0, 0.5}) {
    SCOPED_TRACE(rho_inf);
    std::vector<Real> errors;
    for (const int steps : {20, 40, 80})
      errors.push_back(history_error(run_modal(rho_inf, steps, 1.0)));
    for (std::size_t k = 1; k < errors.size(); ++k) {
      const Real order = std::log2(errors[k - 1] / errors[k]);
      EXPECT_GT(order, 1.9) << "errors " << errors[k - 1] << " -> " << errors[k];
      EXPECT_LT(order, 2.1);
    }
    EXPECT_LT(errors.back(), 2e-2);
    std::cout << "rho_inf " << rho_inf << ": errors " << errors[0] << ", " << errors[1] << ", "
              << errors[2] << "\n";
  }
}

TEST(ImplicitDynamics, LumpedMassGivesALongerPeriod) {
  // a lumped mass lowers the discrete frequencies (the consistent one raises them): the same
  // mode, a few percent apart on this coarse mesh, and the step's error still of second order
  const ModalRun consistent = run_modal(1.0, 40, 0.0);
  const ModalRun lumped = run_modal(1.0, 40, 0.0, physics::MassMatrix::Lumped);
  EXPECT_LT(lumped.omega, consistent.omega);
  EXPECT_GT(lumped.omega, 0.9 * consistent.omega);
  const Real coarse = history_error(run_modal(1.0, 20, 1.0, physics::MassMatrix::Lumped));
  const Real fine = history_error(run_modal(1.0, 40, 1.0, physics::MassMatrix::Lumped));
  EXPECT_GT(std::log2(coarse / fine), 1.9);
}

} // namespace
} // namespace trifem::test
