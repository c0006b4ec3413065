// SPDX-License-Identifier: MIT
// Newton's round-off floor: a residual that cannot fall below the noise of its evaluation while
// the increments are at the round-off of the unknowns is accepted (and reported as such); a
// residual that stalls for any other reason is not.
#include "trifem/solver/newton.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace trifem;

namespace {

/// R(x) = K (x - x*) + noise: a stiff linear system (K = k I, x* = 1) whose residual evaluation
/// carries a deterministic pseudo-random error of size `noise` (what round-off does on a graded
/// mesh: a stiff tiny cell times the round-off of the unknowns). The Jacobian is `jacobian_factor`
/// times the true one (1 = consistent).
class NoisyLinearProblem final : public solver::NonlinearProblem {
public:
  NoisyLinearProblem(Index n, Real k, Real start_offset, Real noise, Real jacobian_factor = 1.0)
      : k_(k), noise_(noise), factor_(jacobian_factor), x_(Vector::Constant(n, 1.0 + start_offset)),
        fields_(n, 0) {}
  Index num_equations() const override { return x_.size(); }
  const std::vector<int>& equation_fields() const override { return fields_; }
  const std::vector<solver::FieldScale>& field_scales() const override { return scales_; }
  int pattern_id() const override { return 0; }
  solver::SolveStatus linearize(solver::Linearization& lin, bool with_jacobian) override {
    const Index n = x_.size();
    std::uniform_real_distribution<Real> unit(-1.0, 1.0);
    lin.residual = k_ * (x_ - Vector::Ones(n));
    for (Index i = 0; i < n; ++i)
      lin.residual[i] += noise_ * unit(random_);
    if (with_jacobian) {
      lin.jacobian.resize(n, n);
      lin.jacobian.setIdentity();
      lin.jacobian *= factor_ * k_;
      lin.constraint_rhs = Vector::Zero(n);
    }
    return solver::SolveStatus::Converged;
  }
  solver::SolveStatus update(const Vector& dx, Real step) override {
    x_ += step * dx;
    return solver::SolveStatus::Converged;
  }
  bool constraints_satisfied() const override { return true; }
  std::vector<Real> field_magnitudes() const override { return {x_.cwiseAbs().maxCoeff()}; }
  void save_iterate() override { saved_ = x_; }
  void restore_iterate() override { x_ = saved_; }
  Real error() const { return (x_ - Vector::Ones(x_.size())).cwiseAbs().maxCoeff(); }

private:
  Real k_, noise_, factor_;
  Vector x_, saved_;
  std::vector<int> fields_;
  std::vector<solver::FieldScale> scales_{{"x", 1.0, 1.0}};
  std::mt19937_64 random_{12345};
};

solver::NewtonReport solve(NoisyLinearProblem& problem) {
  solver::NewtonSettings settings;
  settings.line_search = false;
  solver::NewtonSolver newton(settings, linalg::make_linear_solver({LinearSolverKind::sparselu}));
  return newton.solve(problem);
}

} // namespace

TEST(NewtonRoundoffFloor, AStalledResidualWithRoundoffIncrementsIsAccepted) {
  // k = 1e6, start 1e-10 off: the reference residual is 1e-4; the noise 1e-7 is 1e-3 of it
  // (far above the 1e-8 tolerance) while the increments it causes, 1e-13, are round-off of x = 1
  NoisyLinearProblem problem(20, 1e6, 1e-10, 1e-7);
  const solver::NewtonReport report = solve(problem);
  ASSERT_EQ(report.status, solver::SolveStatus::Converged) << report.failure_reason;
  EXPECT_TRUE(report.at_roundoff_floor);
  EXPECT_LE(report.iterations, 6);
  EXPECT_LE(problem.error(), 1e-12); // the noise limits x to 1e-13: the state is converged
}

TEST(NewtonRoundoffFloor, AnOrdinarySolveDoesNotReportTheFloor) {
  NoisyLinearProblem problem(20, 1e6, 1e-2, 0.0);
  const solver::NewtonReport report = solve(problem);
  ASSERT_EQ(report.status, solver::SolveStatus::Converged);
  EXPECT_FALSE(report.at_roundoff_floor);
  EXPECT_LE(problem.error(), 1e-14);
}

TEST(NewtonRoundoffFloor, AStallWithIncrementsAboveRoundoffIsNotAccepted) {
  // a Jacobian 1e3 times too stiff: each iteration removes only 1e-3 of the error, so the
  // residual stalls while the increments (1e-3 of an error of 1e-2) are far above round-off
  NoisyLinearProblem problem(20, 1e6, 1e-2, 0.0, 1e3);
  const solver::NewtonReport report = solve(problem);
  EXPECT_EQ(report.status, solver::SolveStatus::MaxIterations);
  EXPECT_FALSE(report.at_roundoff_floor);
}
