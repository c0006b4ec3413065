// SPDX-License-Identifier: MIT
// Step controller, linear solver backends, and Newton on a small algebraic problem.
#include "trifem/core/error.hpp"
#include "trifem/solver/newton.hpp"
#include "trifem/solver/step_controller.hpp"
#include "trifem/solver/time_loop.hpp"

#include <Eigen/SparseLU>
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

using namespace trifem;

namespace {

/// R_i(x) = x_i^3 + x_{i+1} - b_i: a small nonlinear system with a known root x = 1. With
/// `odd_scale` the odd equations are a second field, multiplied by that factor.
class CubicProblem final : public solver::NonlinearProblem {
public:
  explicit CubicProblem(Index n, std::optional<Real> odd_scale = {})
      : x_(Vector::Constant(n, 3.0)), fields_(n, 0), scale_(Vector::Ones(n)) {
    b_ = Vector::Constant(n, 2.0);
    b_[n - 1] = 1.0;
    if (odd_scale) {
      scales_.push_back({"y", *odd_scale, 1.0});
      for (Index i = 1; i < n; i += 2) {
        fields_[i] = 1;
        scale_[i] = *odd_scale;
      }
    }
  }
  Index num_equations() const override { return x_.size(); }
  const std::vector<int>& equation_fields() const override { return fields_; }
  const std::vector<solver::FieldScale>& field_scales() const override { return scales_; }
  int pattern_id() const override { return 0; }
  solver::SolveStatus linearize(solver::Linearization& lin, bool with_jacobian) override {
    const Index n = x_.size();
    lin.residual = x_.array().cube().matrix() - b_;
    lin.residual.head(n - 1) += x_.tail(n - 1);
    lin.residual = lin.residual.cwiseProduct(scale_);
    if (with_jacobian) {
      std::vector<Eigen::Triplet<Real>> t;
      for (Index i = 0; i < n; ++i) {
        t.emplace_back(i, i, scale_[i] * 3 * x_[i] * x_[i]);
        if (i + 1 < n)
          t.emplace_back(i, i + 1, scale_[i]);
      }
      lin.jacobian.resize(n, n);
      lin.jacobian.setFromTriplets(t.begin(), t.end());
      lin.constraint_rhs = Vector::Zero(n);
    }
    return solver::SolveStatus::Converged;
  }
  solver::SolveStatus update(const Vector& dx, Real step) override {
    x_ += step * dx;
    return solver::SolveStatus::Converged;
  }
  bool constraints_satisfied() const override { return true; }
  void save_iterate() override { saved_ = x_; }
  void restore_iterate() override { x_ = saved_; }
  const Vector& x() const { return x_; }

private:
  Vector x_, saved_, b_;
  std::vector<int> fields_;
  Vector scale_; ///< of each equation
  std::vector<solver::FieldScale> scales_{{"x", 1.0, 1.0}};
};

/// A linear solver that always fails: a singular factorization (direct, 0 iterations) or an
/// iterative solve that stops after `iterations` without converging.
class FailingSolver final : public linalg::LinearSolver {
public:
  explicit FailingSolver(int iterations) : iterations_(iterations) {}
  void analyze_pattern(const SparseMatrix&) override {}
  bool factorize(const SparseMatrix&) override { return iterations_ > 0; }
  bool solve(const Vector&, Vector&) override { return false; }
  int last_iterations() const override { return iterations_; }
  std::string name() const override { return "failing"; }
  linalg::LinearSolverFailure failure() const override {
    return {iterations_ > 0 ? "the Krylov solver did not converge" : "singular matrix", false};
  }

private:
  int iterations_;
};

/// An iterative solver that stops just at the tolerance it is asked for: the exact solution of
/// A x = b + tolerance |b| e (e a fixed unit vector), so |A x - b| = tolerance |b|. Records the
/// tolerances asked.
class InexactSolver final : public linalg::LinearSolver {
public:
  void analyze_pattern(const SparseMatrix& A) override { lu_.analyzePattern(A); }
  bool factorize(const SparseMatrix& A) override {
    lu_.factorize(A);
    return lu_.info() == Eigen::Success;
  }
  void set_relative_tolerance(Real tolerance) override { tolerance_ = tolerance; }
  bool solve(const Vector& b, Vector& x) override {
    asked.push_back(tolerance_);
    const Vector e = Vector::Ones(b.size()).normalized();
    x = lu_.solve(b + tolerance_ * b.norm() * e);
    return true;
  }
  int last_iterations() const override { return 1; }
  std::string name() const override { return "inexact"; }
  std::vector<Real> asked; ///< the tolerance of every solve (refine: solve again)

private:
  Eigen::SparseLU<SparseMatrix> lu_;
  Real tolerance_ = 0.0;
};

} // namespace

namespace {

/// What an inexact Newton solve asked of its linear solver.
struct InexactRun {
  std::vector<Real> asked; ///< the tolerance of every linear solve
  int iterations = 0;      ///< Newton iterations
};

/// Solves a fresh CubicProblem(n, odd_scale) with Newton over InexactSolver and compares it
/// with a direct solve: the same root to the Newton tolerance, at most one more iteration.
InexactRun solve_inexactly(Index n, std::optional<Real> odd_scale = {}) {
  CubicProblem exact_problem(n, odd_scale);
  solver::NewtonSolver exact({}, linalg::make_linear_solver({LinearSolverKind::sparselu}));
  const auto direct = exact.solve(exact_problem);
  EXPECT_EQ(direct.status, solver::SolveStatus::Converged);
  CubicProblem problem(n, odd_scale);
  auto inexact = std::make_unique<InexactSolver>();
  const InexactSolver& solver = *inexact;
  solver::NewtonSolver newton({}, std::move(inexact));
  const auto report = newton.solve(problem);
  EXPECT_EQ(report.status, solver::SolveStatus::Converged);
  EXPECT_LE((problem.x() - exact_problem.x()).norm(), 1e-7);
  EXPECT_LE(report.iterations, direct.iterations + 1);
  return {solver.asked, report.iterations};
}

} // namespace

TEST(Newton, AnIterativeSolveAsksNoMoreAccuracyThanTheResidualNeeds) {
  const InexactRun run = solve_inexactly(5);
  // the first solve at the loosest tolerance, every one within the bounds
  const solver::NewtonSettings settings;
  ASSERT_FALSE(run.asked.empty());
  EXPECT_DOUBLE_EQ(run.asked.front(), settings.linear_tolerance_max);
  for (const Real tolerance : run.asked) {
    EXPECT_LE(tolerance, settings.linear_tolerance_max);
    EXPECT_GE(tolerance, settings.linear_tolerance_min);
  }
}

TEST(Newton, AnIterativeSolveOfFieldsOfDifferentScalesIsTightEnoughForTheSmallOne) {
  // the odd equations a million times smaller: a 2-norm tolerance of the whole right-hand side
  // must be tight enough for their residual too
  for (const Real odd_scale : {1.0, 1e-6}) {
    SCOPED_TRACE(odd_scale);
    const InexactRun run = solve_inexactly(6, odd_scale);
    // the fields of different scales: the residual fell less in the convergence norm than in
    // the 2-norm, and a solve was continued to a tighter tolerance
    if (odd_scale < 1.0) {
      EXPECT_GT(run.asked.size(), static_cast<std::size_t>(run.iterations));
    }
  }
}

TEST(Newton, WithoutTheForcingTermEveryIterativeSolveAsksTheTightestTolerance) {
  solver::NewtonSettings settings;
  settings.adaptive_linear_tolerance = false;
  CubicProblem problem(5);
  auto inexact = std::make_unique<InexactSolver>();
  const InexactSolver& solver = *inexact;
  solver::NewtonSolver newton(settings, std::move(inexact));
  ASSERT_EQ(newton.solve(problem).status, solver::SolveStatus::Converged);
  ASSERT_FALSE(solver.asked.empty());
  for (const Real tolerance : solver.asked)
    EXPECT_DOUBLE_EQ(tolerance, settings.linear_tolerance_min);
  EXPECT_LE((problem.x() - Vector::Ones(5)).norm(), 1e-10);
}

TEST(Newton, AFirstSingularMatrixAsksAboutSupportsButAnUnconvergedKrylovSolveDoesNot) {
  const std::string hint = "is every body supported against rigid motion";
  for (const int iterations : {0, 50}) {
    CubicProblem problem(5);
    solver::NewtonSolver newton({}, std::make_unique<FailingSolver>(iterations));
    const auto report = newton.solve(problem);
    EXPECT_EQ(report.status, solver::SolveStatus::FactorizationFailed);
    const bool hinted = report.failure_reason.find(hint) != std::string::npos;
    EXPECT_EQ(hinted, iterations == 0) << report.failure_reason;
    EXPECT_NE(report.failure_reason.find(iterations == 0 ? "singular matrix" : "did not converge"),
              std::string::npos)
        << report.failure_reason;
  }
}

TEST(Newton, SolvesACubicSystemQuadratically) {
  using enum LinearSolverKind;
  for (const LinearSolverKind backend : {automatic, umfpack, sparselu, mumps, krylov}) {
    CubicProblem problem(5);
    solver::NewtonSolver newton({}, linalg::make_linear_solver({backend}));
    const auto report = newton.solve(problem);
    ASSERT_EQ(report.status, solver::SolveStatus::Converged) << to_string(backend);
    EXPECT_LE((problem.x() - Vector::Ones(5)).norm(), 1e-10) << to_string(backend);
    EXPECT_LE(report.iterations, 12) << to_string(backend);
  }
}

namespace {

/// x = t, one equation: a transient problem whose steps always converge; its rejection or
/// caution of every converged step larger than `limit` is set by the test.
class LinearInTime final : public solver::TransientProblem {
public:
  Index num_equations() const override { return 1; }
  const std::vector<int>& equation_fields() const override { return fields_; }
  const std::vector<solver::FieldScale>& field_scales() const override { return scales_; }
  int pattern_id() const override { return 0; }
  solver::SolveStatus linearize(solver::Linearization& lin, bool with_jacobian) override {
    lin.residual = Vector::Constant(1, x_ - time_);
    if (with_jacobian) {
      lin.jacobian.resize(1, 1);
      lin.jacobian.insert(0, 0) = 1.0;
      lin.constraint_rhs = Vector::Zero(1);
    }
    return solver::SolveStatus::Converged;
  }
  solver::SolveStatus update(const Vector& dx, Real step) override {
    x_ += step * dx[0];
    return solver::SolveStatus::Converged;
  }
  bool constraints_satisfied() const override { return true; }
  void save_iterate() override { saved_ = x_; }
  void restore_iterate() override { x_ = saved_; }
  void begin_step(Real time, Real dt) override {
    time_ = time;
    dt_ = dt;
  }
  std::string step_rejection() const override { return dt_ > limit && hard ? "too far" : ""; }
  std::string step_caution() const override { return dt_ > limit && !hard ? "watch out" : ""; }
  void commit_step() override { committed_ = x_; }
  void reject_step() override { x_ = committed_; }
  std::vector<Real> step_change() const override { return {std::abs(x_ - committed_)}; }
  void mark_committed() override {}
  void return_to_mark() override {}

  Real limit = 0.0; ///< steps larger than this are rejected (hard) or cautioned
  bool hard = false;

private:
  Real x_ = 0, saved_ = 0, committed_ = 0, time_ = 0, dt_ = 0;
  std::vector<int> fields_{0};
  std::vector<solver::FieldScale> scales_{{"x", 1.0, 1.0}};
};

solver::RunReport run_linear_in_time(LinearInTime& problem, std::vector<Real>& accepted_dt) {
  solver::StepSettings s;
  s.end_time = 0.1;
  s.dt = s.dt_max = 0.1;
  s.dt_min = 0.025;
  solver::StepController controller(s);
  solver::NewtonSolver newton({}, linalg::make_linear_solver({LinearSolverKind::sparselu}));
  return solver::run_time_loop(problem, newton, controller, [&](const solver::StepInfo& info) {
    accepted_dt.push_back(info.dt);
  });
}

} // namespace

// A caution cuts the step back while it can and lets it pass at the minimum step size; a
// rejection there stops the run.
TEST(TimeLoop, ACautionIsAcceptedAtTheMinimumStepButARejectionIsNot) {
  for (const Real limit : {0.06, 0.01}) {
    LinearInTime problem;
    problem.limit = limit;
    std::vector<Real> accepted_dt;
    const solver::RunReport run = run_linear_in_time(problem, accepted_dt);
    EXPECT_TRUE(run.success) << run.failure;
    EXPECT_NEAR(run.end_time, 0.1, 1e-15);
    ASSERT_FALSE(accepted_dt.empty());
    EXPECT_NEAR(accepted_dt.front(), limit > 0.05 ? 0.05 : 0.025, 1e-15) << "limit " << limit;
    EXPECT_GE(run.cutbacks, 1);
  }
  LinearInTime problem;
  problem.limit = 0.01;
  problem.hard = true;
  std::vector<Real> accepted_dt;
  const solver::RunReport run = run_linear_in_time(problem, accepted_dt);
  EXPECT_FALSE(run.success);
  EXPECT_TRUE(accepted_dt.empty());
  EXPECT_NE(run.failure.find("failed at the minimum step size 0.025: too far"), std::string::npos)
      << run.failure;
}

TEST(StepController, LandsOnMustPointsAndTheEnd) {
  solver::StepSettings s;
  s.end_time = 1.0;
  s.dt = s.dt_max = 0.3;
  s.dt_min = 1e-3;
  s.must_points = {0.5};
  solver::StepController c(s);
  std::vector<Real> times;
  while (!c.finished()) {
    const Real dt = c.next_step();
    c.accept(dt, 10); // hard steps: no growth
    times.push_back(c.time());
  }
  EXPECT_NEAR(times.back(), 1.0, 1e-15);
  EXPECT_NE(std::find(times.begin(), times.end(), 0.5), times.end());
}

TEST(StepController, ShortRunsTakeEveryStepAndKeepCloseMustPointsApart) {
  // a 1 ns run in 0.1 ns steps: an absolute time tolerance (1e-10 s) ended it a step early and
  // merged must points 4e-11 s apart
  solver::StepSettings s;
  s.end_time = 1e-9;
  s.dt = s.dt_max = 1e-10;
  s.dt_min = 1e-13;
  s.must_points = {5e-10, 5.4e-10};
  solver::StepController c(s);
  std::vector<Real> times;
  while (!c.finished() && times.size() < 100) {
    c.accept(c.next_step(), 10);
    times.push_back(c.time());
  }
  ASSERT_EQ(times.size(), 11u); // 5 steps to 5e-10, one of 4e-11, then 4.6e-10 in 5 steps
  EXPECT_EQ(times.back(), 1e-9);
  EXPECT_NE(std::find(times.begin(), times.end(), 5e-10), times.end());
  EXPECT_NE(std::find(times.begin(), times.end(), 5.4e-10), times.end());
}

TEST(StepController, CutsBackThenStopsAtTheMinimumStep) {
  solver::StepSettings s;
  s.dt = s.dt_max = 0.1;
  s.dt_min = 0.025;
  solver::StepController c(s);
  EXPECT_TRUE(c.reject(c.next_step()));
  EXPECT_DOUBLE_EQ(c.dt(), 0.05);
  EXPECT_TRUE(c.reject(c.next_step()));
  EXPECT_DOUBLE_EQ(c.dt(), 0.025);
  EXPECT_TRUE(c.at_minimum(c.next_step()));
  EXPECT_FALSE(c.reject(c.next_step()));
  EXPECT_EQ(c.cutbacks(), 2);
  c.accept(c.next_step(), 2); // an easy step regrows dt
  EXPECT_NEAR(c.dt(), 0.0375, 1e-15);
}
