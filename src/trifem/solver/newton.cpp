// SPDX-License-Identifier: MIT
#include "trifem/solver/newton.hpp"

#include "trifem/core/interrupt.hpp"
#include "trifem/core/log.hpp"
#include "trifem/core/timer.hpp"
#include "trifem/parallel/communicator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace trifem::solver {
const char* to_string(SolveStatus status) {
  switch (status) {
  case SolveStatus::Converged:
    return "converged";
  case SolveStatus::Inadmissible:
    return "inadmissible state (e.g. J <= 0)";
  case SolveStatus::Diverged:
    return "diverged";
  case SolveStatus::MaxIterations:
    return "maximum Newton iterations reached";
  case SolveStatus::FactorizationFailed:
    return "linear solver failed";
  case SolveStatus::Rejected:
    return "converged state rejected";
  case SolveStatus::Unrecoverable:
    return "unrecoverable failure";
  case SolveStatus::Interrupted:
    return "interrupted";
  }
  return "unknown";
}

NewtonSolver::NewtonSolver(NewtonSettings settings,
                           std::unique_ptr<linalg::LinearSolver> linear_solver)
    : settings_(settings), linear_(std::move(linear_solver)) {}

std::vector<Real> NewtonSolver::field_norms(const NonlinearProblem& problem, const Vector& v,
                                            bool inf) const {
  std::vector<Real> norms(problem.field_scales().size(), 0.0);
  const auto& fields = problem.equation_fields();
  for (Index i = 0; i < v.size(); ++i) {
    Real& n = norms[fields[i]];
    n = inf ? std::max(n, std::abs(v[i])) : n + v[i] * v[i];
  }
  if (!inf)
    for (Real& n : norms)
      n = std::sqrt(n);
  return norms;
}

Real NewtonSolver::scaled_residual(const NonlinearProblem& problem, const Vector& r) const {
  const std::vector<Real> norms = field_norms(problem, r, false);
  Real sum = 0.0;
  for (std::size_t f = 0; f < norms.size(); ++f)
    sum += std::pow(norms[f] / reference_[f], 2);
  return std::sqrt(sum);
}

Real NewtonSolver::convergence_weight(const NonlinearProblem& problem, std::size_t f) const {
  return 1.0 / std::max(settings_.residual_tolerance * reference_[f],
                        settings_.absolute_floor * problem.field_scales()[f].residual);
}

Real NewtonSolver::convergence_norm(const NonlinearProblem& problem, const Vector& r) const {
  const std::vector<Real> norms = field_norms(problem, r, false);
  Real sum = 0.0;
  for (std::size_t f = 0; f < norms.size(); ++f)
    sum += std::pow(norms[f] * convergence_weight(problem, f), 2);
  return std::sqrt(sum);
}

bool NewtonSolver::residual_converged(const NonlinearProblem& problem, const Vector& r) const {
  const std::vector<Real> norms = field_norms(problem, r, false);
  const auto& scales = problem.field_scales();
  for (std::size_t f = 0; f < norms.size(); ++f) {
    const bool relative = norms[f] <= settings_.residual_tolerance * reference_[f];
    const bool absolute = norms[f] <= settings_.absolute_floor * scales[f].residual;
    if (!relative && !absolute)
      return false;
  }
  return true;
}

bool NewtonSolver::at_roundoff_floor(const NonlinearProblem& problem, const Vector& dx, Real step,
                                     const std::vector<Real>& history) const {
  // The residual has not halved over the last two iterations ...
  const std::size_t k = history.size() - 1;
  if (k < 3 || history[k] < 0.5 * history[k - 2])
    return false;
  // ... while the increments change the unknowns only at the round-off of their magnitude.
  constexpr Real kRoundoff = 1e4 * std::numeric_limits<Real>::epsilon();
  const std::vector<Real> norms = field_norms(problem, dx, true);
  const std::vector<Real> magnitudes = problem.field_magnitudes();
  const auto& scales = problem.field_scales();
  for (std::size_t f = 0; f < norms.size(); ++f)
    if (const Real x = f < magnitudes.size() ? magnitudes[f] : 0.0;
        step * norms[f] > kRoundoff * std::max(x, scales[f].size))
      return false;
  return true;
}

bool NewtonSolver::increment_converged(const NonlinearProblem& problem, const Vector& dx,
                                       Real step) const {
  const std::vector<Real> norms = field_norms(problem, dx, true);
  const auto& scales = problem.field_scales();
  for (std::size_t f = 0; f < norms.size(); ++f)
    if (step * norms[f] > settings_.increment_tolerance * scales[f].size)
      return false;
  return true;
}

Real NewtonSolver::linear_reduction(const std::vector<Real>& history) const {
  const Real loosest = settings_.linear_tolerance_max, tightest = settings_.linear_tolerance_min;
  if (!settings_.adaptive_linear_tolerance || history.empty())
    return tightest;
  const std::size_t k = history.size() - 1;
  Real tolerance = loosest;
  // Eisenstat-Walker choice 2: 0.9 (|R_k| / |R_k-1|)^2, the reduction quadratic convergence
  // would give
  if (k > 0 && history[k - 1] > 0.0)
    tolerance = 0.9 * std::pow(history[k] / history[k - 1], 2);
  // no more than convergence needs (a norm of 1), with a margin of ten
  if (history[k] > 0.0)
    tolerance = std::max(tolerance, 0.1 / history[k]);
  return std::clamp(tolerance, tightest, loosest);
}

Real NewtonSolver::in_linear_norm(const NonlinearProblem& problem, const Vector& rhs,
                                  Real reduction) const {
  // The Krylov solvers measure ‖J dx − rhs‖₂ against ‖rhs‖₂, Newton ‖W R‖₂ with the
  // convergence weights W per field. ‖W r‖₂ ≤ max W ‖r‖₂, so ‖r‖₂ ≤ t ‖rhs‖₂ with
  // t = reduction ‖W rhs‖₂ / (max W ‖rhs‖₂) gives ‖W r‖₂ ≤ reduction ‖W rhs‖₂.
  const std::vector<Real> norms = field_norms(problem, rhs, false);
  std::vector<bool> present(norms.size(), false);
  for (const int f : problem.equation_fields())
    present[f] = true;
  Real weighted = 0.0, plain = 0.0, largest_weight = 0.0;
  for (std::size_t f = 0; f < norms.size(); ++f) {
    if (!present[f])
      continue;
    const Real weight = convergence_weight(problem, f);
    weighted += std::pow(norms[f] * weight, 2);
    plain += norms[f] * norms[f];
    largest_weight = std::max(largest_weight, weight);
  }
  if (plain == 0.0 || largest_weight == 0.0)
    return reduction;
  return reduction * std::sqrt(weighted) / (largest_weight * std::sqrt(plain));
}

bool NewtonSolver::solve_to(const NonlinearProblem& problem, const SparseMatrix& jacobian,
                            const Vector& rhs, Vector& dx, Real reduction, bool first) {
  // the first iteration of a step (its right-hand side carries the new loads) and the later
  // ones differ in how the residual spreads over the fields: each keeps its own record
  Real& amplification = amplification_[first ? 0 : 1];
  const Real tightest = settings_.linear_tolerance_min;
  const bool distributed = !problem.equation_owners().empty(); // the jacobian is this part
  // the 2-norm tolerance expected to reduce the convergence norm by `reduction`
  Real tolerance =
      distributed ? in_linear_norm(problem, rhs, reduction) : reduction / amplification;
  tolerance = settings_.adaptive_linear_tolerance
                  ? std::clamp(tolerance, tightest, settings_.linear_tolerance_max)
                  : tightest;
  linear_->set_relative_tolerance(tolerance);
  bool solved = linear_->solve(rhs, dx);
  linear_iterations_ = linear_->last_iterations();
  if (!solved || linear_iterations_ == 0 || distributed)
    return solved; // a direct solve, or no check possible
  // the reduction of the convergence norm reached; continued to a tighter tolerance if too
  // little
  const Real scaled_rhs = convergence_norm(problem, rhs);
  if (scaled_rhs == 0.0)
    return true;
  constexpr int kMaxRefinements = 3;
  // A reduction within twice the one asked is accepted: the forcing term is a rate, not a
  // bound, and a continuation restarts FGMRES without its Krylov space (about ten iterations).
  constexpr Real kSlack = 2.0;
  for (int refinement = 0;; ++refinement) {
    const Real reached = convergence_norm(problem, jacobian * dx - rhs) / scaled_rhs;
    if (refinement == 0) // (a continued solve overshoots its tolerance: not representative)
      amplification = std::max(reached / tolerance, 1e-3);
    if (reached <= kSlack * reduction || tolerance <= tightest || refinement == kMaxRefinements)
      return true;
    tolerance = std::max(tightest, 0.5 * reduction / amplification);
    linear_->set_relative_tolerance(tolerance);
    solved = linear_->refine(rhs, dx);
    linear_iterations_ += linear_->last_iterations();
    log::debug("    the linear residual in the convergence norm fell to {:.2e} of the "
               "right-hand side, {:.1e} asked: solve continued to a 2-norm tolerance of {:.1e}",
               reached, reduction, tolerance);
    if (!solved)
      return false;
  }
}

SolveStatus NewtonSolver::factor_and_solve(NonlinearProblem& problem, Linearization& lin,
                                           Vector& dx, Real reduction, bool first) {
  if (problem.num_equations() == 0) { // every unknown is prescribed: nothing to solve
    dx.resize(0);
    return SolveStatus::Converged;
  }
  auto start = WallClock::now();
  if (analyzed_pattern_ != problem.pattern_id()) {
    linear_->set_hints({problem.equation_fields(), problem.field_roles(),
                        problem.rigid_body_modes(), problem.equation_owners()});
    linear_->analyze_pattern(lin.jacobian);
    analyzed_pattern_ = problem.pattern_id();
  }
  if (linear_->wants_transport_cells())
    linear_->set_transport_cells(problem.transport_cells());
  const bool factored = linear_->factorize(lin.jacobian);
  times_.factorization += seconds_since(start);
  if (!factored)
    return linear_failure_status();
  start = WallClock::now();
  const Vector rhs = -(lin.residual + lin.constraint_rhs);
  const bool solved = solve_to(problem, lin.jacobian, rhs, dx, reduction, first);
  times_.solve += seconds_since(start);
  return solved ? SolveStatus::Converged : linear_failure_status();
}

SolveStatus NewtonSolver::linear_failure_status() const {
  return linear_->failure().permanent ? SolveStatus::Unrecoverable
                                      : SolveStatus::FactorizationFailed;
}

SolveStatus NewtonSolver::line_search(NonlinearProblem& problem, const Vector& dx, const Vector& r0,
                                      Real& step, Linearization& lin) {
  // Energy line search (Bathe, FE Procedures, sec. 8.4.2): find s with g(s) = dx . R(x + s dx)
  // small compared with g(0); secant updates of s, halving after inadmissible trials.
  const Real g0 = dx.dot(r0);
  const bool search = settings_.line_search && problem.constraints_satisfied() && g0 < 0.0;
  problem.save_iterate();
  step = 1.0;
  for (int trial = 0; trial <= settings_.max_backtracks; ++trial) {
    if (trial > 0)
      problem.restore_iterate();
    const auto start = WallClock::now();
    const bool admissible = problem.update(dx, step) == SolveStatus::Converged &&
                            problem.linearize(lin, true) == SolveStatus::Converged &&
                            lin.residual.allFinite();
    times_.assembly += seconds_since(start);
    if (!admissible) {
      step *= 0.5;
      continue;
    }
    const Real g = dx.dot(lin.residual);
    if (!search || std::abs(g) <= settings_.line_search_tolerance * std::abs(g0) ||
        trial == settings_.max_backtracks)
      return SolveStatus::Converged;
    // secant estimate of the zero of g, kept in [0.1 step, 1]
    const Real secant = (g0 - g) != 0.0 ? step * g0 / (g0 - g) : 0.5 * step;
    const Real next = std::clamp(secant, 0.1 * step, 1.0);
    if (std::abs(next - step) <= 0.05 * step)
      return SolveStatus::Converged;
    step = next;
  }
  problem.restore_iterate();
  return SolveStatus::Inadmissible;
}

NewtonReport NewtonSolver::solve(NonlinearProblem& problem) {
  return solve(problem, {});
}

NewtonReport NewtonSolver::solve(NonlinearProblem& problem, const std::vector<Real>& reference) {
  NewtonReport report;
  Linearization& lin = lin_; // kept between solves: the problem lends it its matrix storage
  auto start = WallClock::now();
  if (problem.linearize(lin, true) != SolveStatus::Converged) {
    report.status = SolveStatus::Inadmissible;
    report.failure_reason =
        "the state at the start of the step cannot be evaluated (an element is inverted)";
    return report;
  }
  times_.assembly += seconds_since(start);

  // Reference residual per field: the larger of the residual and the residual the pending
  // constraint increment would cause, never below the absolute floor.
  const auto& scales = problem.field_scales();
  const std::vector<Real> r0 = field_norms(problem, lin.residual, false);
  const std::vector<Real> c0 = field_norms(problem, lin.residual + lin.constraint_rhs, false);
  reference_.assign(scales.size(), 0.0);
  for (std::size_t f = 0; f < scales.size(); ++f)
    reference_[f] = std::max({r0[f], c0[f], settings_.absolute_floor * scales[f].residual,
                              f < reference.size() ? reference[f] : 0.0});

  Vector dx = Vector::Zero(problem.num_equations());
  Real step = 1.0;
  std::vector<Real> convergence_history; ///< convergence_norm of the residual per iteration
  for (int k = 0;; ++k) {
    if (!lin.residual.allFinite()) {
      report.status = SolveStatus::Diverged;
      report.failure_reason = "non-finite residual";
      return report;
    }
    // The reference of each field is the largest residual seen in this solve (its load scale).
    const std::vector<Real> norms = field_norms(problem, lin.residual, false);
    for (std::size_t f = 0; f < norms.size(); ++f)
      reference_[f] = std::max(reference_[f], norms[f]);
    const Real merit = scaled_residual(problem, lin.residual);
    report.residual_history.push_back(merit);
    convergence_history.push_back(convergence_norm(problem, lin.residual));
    report.final_residual = merit;
    report.iterations = k;
    const bool increment_ok = k == 0 || increment_converged(problem, dx, step);
    if (problem.constraints_satisfied() && residual_converged(problem, lin.residual) &&
        increment_ok) {
      report.status = SolveStatus::Converged;
      return report;
    }
    if (problem.constraints_satisfied() &&
        at_roundoff_floor(problem, dx, step, report.residual_history)) {
      report.status = SolveStatus::Converged;
      report.at_roundoff_floor = true;
      return report;
    }
    if (parallel::any(interrupt::requested())) { // the same iteration on every process
      report.status = SolveStatus::Interrupted;
      report.failure_reason = "interrupted";
      return report;
    }
    if (k == settings_.max_iterations) {
      report.status = SolveStatus::MaxIterations;
      report.failure_reason =
          fmt::format("no convergence in {} iterations (residual {:.3e})", k, merit);
      return report;
    }
    const Real reduction = linear_reduction(convergence_history);
    const SolveStatus solved = factor_and_solve(problem, lin, dx, reduction, k == 0);
    report.linear_iterations += linear_iterations_;
    if (solved != SolveStatus::Converged) {
      report.status = solved;
      const std::string why = linear_->failure().reason;
      report.failure_reason = "the linear solve failed: " +
                              (why.empty() ? std::string("the Jacobian is singular") : why);
      if (const Index eq = linear_->failure().equation; eq >= 0 && eq < problem.num_equations())
        if (const std::string name = problem.equation_name(eq); !name.empty())
          report.failure_reason += fmt::format("; that equation is {}", name);
      // a singular first matrix (not an iterative solve that ran out of iterations)
      if (solved == SolveStatus::FactorizationFailed && k == 0 && linear_iterations_ == 0)
        report.failure_reason +=
            " (at the first iteration: is every body supported against rigid motion, and "
            "every field constrained where it needs to be?)";
      return report;
    }
    const Vector r0 = lin.residual;
    const SolveStatus searched = line_search(problem, dx, r0, step, lin);
    if (searched != SolveStatus::Converged) {
      report.status = searched;
      report.failure_reason = "every trial step of the line search inverts an element (J <= 0)";
      return report;
    }
    if (linear_iterations_ > 0)
      log::debug("    iteration {:2d}: residual {:.3e}, step {:.3g}, {} linear iterations "
                 "(reduction {:.1e} asked)",
                 k + 1, scaled_residual(problem, lin.residual), step, linear_iterations_,
                 reduction);
    else
      log::debug("    iteration {:2d}: residual {:.3e}, step {:.3g}", k + 1,
                 scaled_residual(problem, lin.residual), step);
  }
}

} // namespace trifem::solver
