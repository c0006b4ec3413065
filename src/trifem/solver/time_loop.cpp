// SPDX-License-Identifier: MIT
#include "trifem/solver/time_loop.hpp"

#include "trifem/core/error.hpp"
#include "trifem/core/interrupt.hpp"
#include "trifem/core/log.hpp"

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

} // namespace

RunReport run_time_loop(TransientProblem& problem, NewtonSolver& newton, StepController& controller,
                        const StepObserver& observer) {
  RunReport run;
  while (!controller.finished()) {
    if (interrupt::requested()) {
      run.interrupted = true;
      return stop(run, controller, fmt::format("interrupted at t = {:.6g}", controller.time()));
    }
    const Real dt = controller.next_step();
    const Real t = controller.time() + dt;
    const Real transport_dt =
        controller.settings().steady_dt > 0.0 ? controller.settings().steady_dt : dt;
    problem.begin_step(t, transport_dt);
    NewtonReport report;
    try {
      report = newton.solve(problem);
    } catch (const std::bad_alloc&) { // no smaller step needs less memory: stop at once
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
