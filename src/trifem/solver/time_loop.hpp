// SPDX-License-Identifier: MIT
// The quasi-static / implicit time loop: step, Newton, cut back on failure, commit on success.
#pragma once

#include "trifem/solver/newton.hpp"
#include "trifem/solver/step_controller.hpp"

#include <functional>
#include <string>

namespace trifem::solver {

/// Information about one accepted step, passed to the observer.
struct StepInfo {
  int step = 0;    ///< 1-based count of accepted steps
  Real time = 0.0; ///< end time of the step
  Real dt = 0.0;
  const NewtonReport* newton = nullptr;
  /// The step size the problem was advanced with: dt, or the pseudo-time step of a
  /// steady-state step (StepSettings::steady_dt).
  Real transport_dt = 0.0;
};

/// Totals of a run.
struct RunReport {
  bool success = false;
  int steps = 0;
  int iterations = 0;
  int linear_iterations = 0; ///< of an iterative linear solver, over every attempt (0: direct)
  int cutbacks = 0;
  int failed_attempts = 0;
  Real end_time = 0.0;
  std::string failure;          ///< why the run stopped early (empty on success)
  bool interrupted = false;     ///< stopped on request (interrupt::requested), not by a failure
  int roundoff_floor_steps = 0; ///< steps accepted at the round-off floor (NewtonReport)
};

/// Called after every accepted step (output, progress line). An OutputError it throws ends
/// the run as a failure (the step itself was accepted); other exceptions propagate.
using StepObserver = std::function<void(const StepInfo&)>;

/// Advances `problem` from the controller's start to its end time.
RunReport run_time_loop(TransientProblem& problem, NewtonSolver& newton, StepController& controller,
                        const StepObserver& observer);

} // namespace trifem::solver
