// SPDX-License-Identifier: MIT
#include "trifem/solver/time_loop.hpp"

#include "trifem/core/error.hpp"
#include "trifem/core/interrupt.hpp"
#include "trifem/core/log.hpp"
#include "trifem/parallel/communicator.hpp"

#include <new>

namespace trifem::solver {
namespace {

/// Ends the run early with `why`.
RunReport& stop(RunReport& run, const StepController& controller, std::string why) {
  run.failure = std::move(why);
  run.end_time = controller.time();
  run.cutbacks = controller.cutbacks();
  return run;
}

/// Most pseudo-steps of one time of a steady-state step (each leaves at most about 4e-5 of the
/// slowest transient: three are enough when the transport times are estimated well).
constexpr int kMaxPseudoSteps = 12;

/// True if the last solve changed no field by more than the Newton increment tolerance.
bool is_steady(const TransientProblem& problem, const NewtonSolver& newton) {
  const std::vector<Real> change = problem.step_change();
  const auto& scales = problem.field_scales();
  for (std::size_t f = 0; f < change.size(); ++f)
    if (change[f] > newton.settings().increment_tolerance * scales[f].size)
      return false;
  return true;
}

/// Solves one time t of a steady-state step by pseudo-transient continuation: backward-Euler
/// pseudo-steps of `pseudo_dt` at the loads of t, each from the last (committed in between),
/// until one leaves the state unchanged to the Newton increment tolerance. The residuals of the
/// later pseudo-steps are measured against the load scale of the first (their own start is
/// already near the steady state: a relative criterion would chase round-off). The last is
/// left converged but not committed, like a plain solve; if any fails, the problem returns to
/// the state before the first and the report is that failure. Iterations are summed.
NewtonReport solve_steady(TransientProblem& problem, NewtonSolver& newton, Real t, Real pseudo_dt) {
  problem.mark_committed();
  int iterations = 0, linear_iterations = 0;
  std::vector<Real> load_scale;
  for (int k = 1;; ++k) {
    problem.begin_step(t, pseudo_dt);
    NewtonReport report;
    try {
      report = newton.solve(problem, load_scale);
    } catch (...) { // e.g. out of memory: leave the step's start as the committed state
      if (k > 1)
        problem.return_to_mark();
      throw;
    }
    if (k == 1)
      load_scale = newton.reference();
    iterations += report.iterations;
    linear_iterations += report.linear_iterations;
    report.iterations = iterations;
    report.linear_iterations = linear_iterations;
    if (report.status == SolveStatus::Converged)
      if (std::string why = problem.step_rejection(); !why.empty()) {
        report.status = SolveStatus::Rejected;
        report.failure_reason = std::move(why);
      }
    if (report.status != SolveStatus::Converged) {
      if (k > 1) {
        problem.return_to_mark();
        report.failure_reason += fmt::format(" (in pseudo-step {} of the steady state)", k);
      }
      return report;
    }
    if (is_steady(problem, newton))
      return report;
    if (k == kMaxPseudoSteps) {
      log::warn("  t = {:.6g}: the steady state still changes after {} pseudo-steps of {:.3g} s "
                "(accepted; a transport time of the model is longer than its estimate)",
                t, k, pseudo_dt);
      return report;
    }
    problem.commit_step();
  }
}

} // namespace

RunReport run_time_loop(TransientProblem& problem, NewtonSolver& newton, StepController& controller,
                        const StepObserver& observer) {
  RunReport run;
  while (!controller.finished()) {
    if (parallel::any(interrupt::requested())) { // a signal to one process stops them all
      run.interrupted = true;
      return stop(run, controller, fmt::format("interrupted at t = {:.6g}", controller.time()));
    }
    const Real dt = controller.next_step();
    const Real t = controller.time() + dt;
    const Real transport_dt =
        controller.settings().steady_dt > 0.0 ? controller.settings().steady_dt : dt;
    NewtonReport report;
    try {
      if (controller.settings().steady_dt > 0.0) {
        report = solve_steady(problem, newton, t, transport_dt);
      } else {
        problem.begin_step(t, transport_dt);
        report = newton.solve(problem);
      }
    } catch (const std::bad_alloc&) { // no smaller step needs less memory: stop at once
      if (parallel::active()) // the others wait in a collective operation: stop them all (main)
        throw;
      report.status = SolveStatus::Unrecoverable;
      report.failure_reason = "out of memory (the model is too large for the memory available)";
    }
    run.iterations += report.iterations;
    run.linear_iterations += report.linear_iterations;
    if (report.status == SolveStatus::Converged)
      if (std::string why = problem.step_rejection(); !why.empty()) {
        report.status = SolveStatus::Rejected;
        report.failure_reason = std::move(why);
      }
    if (report.status == SolveStatus::Converged)
      if (std::string why = problem.step_caution(); !why.empty()) {
        if (controller.at_minimum(dt)) {
          log::warn("  step to t = {:.6g} accepted at the minimum step size {:.3g}: {}", t, dt,
                    why);
        } else {
          report.status = SolveStatus::Rejected;
          report.failure_reason = std::move(why);
        }
      }
    if (report.status == SolveStatus::Interrupted) {
      problem.reject_step();
      run.interrupted = true;
      return stop(run, controller, fmt::format("interrupted at t = {:.6g}", controller.time()));
    }
    if (report.status != SolveStatus::Converged) {
      ++run.failed_attempts;
      problem.reject_step();
      log::warn("  step to t = {:.6g} (dt = {:.3g}) failed: {}; {}", t, dt,
                to_string(report.status), report.failure_reason);
      // a failure no smaller step can cure stops the run at once, without cutbacks
      if (report.status == SolveStatus::Unrecoverable)
        return stop(run, controller,
                    fmt::format("step to t = {:.6g} failed: {}", t, report.failure_reason));
      if (!controller.reject(dt))
        return stop(run, controller,
                    fmt::format("step to t = {:.6g} failed at the minimum step size {:.3g}: {}", t,
                                dt, report.failure_reason));
      log::info("  cutting the step back to dt = {:.3g}", controller.dt());
      continue;
    }
    problem.commit_step();
    controller.accept(dt, report.iterations);
    ++run.steps;
    run.roundoff_floor_steps += report.at_roundoff_floor ? 1 : 0;
    try {
      observer(StepInfo{run.steps, t, dt, &report, transport_dt});
    } catch (const OutputError& e) { // the step is solved, but its results cannot be written
      return stop(run, controller,
                  fmt::format("the results at t = {:.6g} could not be written: {}", t, e.what()));
    }
  }
  run.success = true;
  run.end_time = controller.time();
  run.cutbacks = controller.cutbacks();
  return run;
}

} // namespace trifem::solver
