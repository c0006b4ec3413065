// SPDX-License-Identifier: MIT
#include "trifem/solver/time_loop.hpp"

#include "trifem/core/log.hpp"

namespace trifem::solver {

RunReport run_time_loop(TransientProblem& problem, NewtonSolver& newton, StepController& controller,
                        const StepObserver& observer) {
  RunReport run;
  while (!controller.finished()) {
    const Real dt = controller.next_step();
    const Real t = controller.time() + dt;
    problem.begin_step(t, dt);
    NewtonReport report = newton.solve(problem);
    run.iterations += report.iterations;
    if (report.status == SolveStatus::Converged)
      if (std::string why = problem.step_rejection(); !why.empty()) {
        report.status = SolveStatus::Rejected;
        report.failure_reason = std::move(why);
      }
    if (report.status != SolveStatus::Converged) {
      ++run.failed_attempts;
      problem.reject_step();
      log::warn("  step to t = {:.6g} (dt = {:.3g}) failed: {}; {}", t, dt,
                to_string(report.status), report.failure_reason);
      if (!controller.reject(dt)) {
        run.failure = fmt::format("step to t = {:.6g} failed at the minimum step size {:.3g}: {}",
                                  t, dt, report.failure_reason);
        run.end_time = controller.time();
        run.cutbacks = controller.cutbacks();
        return run;
      }
      log::info("  cutting the step back to dt = {:.3g}", controller.dt());
      continue;
    }
    problem.commit_step();
    controller.accept(dt, report.iterations);
    ++run.steps;
    observer(StepInfo{run.steps, t, dt, &report});
  }
  run.success = true;
  run.end_time = controller.time();
  run.cutbacks = controller.cutbacks();
  return run;
}

} // namespace trifem::solver
