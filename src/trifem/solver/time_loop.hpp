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
};

/// Totals of a run.
struct RunReport {
  bool success = false;
  int steps = 0;
  int iterations = 0;
  int cutbacks = 0;
  int failed_attempts = 0;
  Real end_time = 0.0;
  std::string failure; ///< why the run stopped early (empty on success)
};

/// Called after every accepted step (output, progress line). May throw to abort the run.
using StepObserver = std::function<void(const StepInfo&)>;

/// Advances `problem` from the controller's start to its end time.
RunReport run_time_loop(TransientProblem& problem, NewtonSolver& newton, StepController& controller,
                        const StepObserver& observer);

} // namespace trifem::solver
