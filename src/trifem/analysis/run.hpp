// SPDX-License-Identifier: MIT
// The `run` and `check` commands.
#pragma once

#include "trifem/analysis/restart.hpp"
#include "trifem/io/case_spec.hpp"
#include "trifem/linalg/linear_solver.hpp"
#include "trifem/model/model.hpp"
#include "trifem/solver/newton.hpp"
#include "trifem/solver/step_controller.hpp"
#include "trifem/solver/time_loop.hpp"

#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>

namespace trifem::analysis {

/// Process exit codes (documented in docs/cli.md).
enum ExitCode : int {
  kSuccess = 0,        ///< the analysis completed
  kUsage = 1,          ///< bad command line
  kInvalidInput = 2,   ///< the case file, mesh or parameters are invalid; nothing was run
  kAnalysisFailed = 3, ///< the analysis stopped early (results written so far are kept)
  kInternalError = 4,  ///< a bug in trifem
  // 128 + the signal number (130 for Ctrl-C): the run was interrupted, results kept
};

/// "completed", "failed" or "interrupted" (summary.json "status").
std::string run_status(const solver::RunReport& run);

/// Exit code of an interrupted run: 128 + the signal (130 for SIGINT, 143 for SIGTERM).
int interrupted_exit_code();

/// Step control of a quasi-static case: [time], plus the output times and the kinks of every
/// load curve as must points.
solver::StepSettings step_settings(const io::CaseSpec& spec);

/// Step control of [[step]] k: its time keys, from the end of step k - 1 (or 0) to its
/// end_time, with the output times and load-curve kinks inside it as must points.
solver::StepSettings step_settings(const io::CaseSpec& spec, std::size_t k);

/// Runs a dynamic-explicit step: [[step]] k, or the whole case (nullopt), on the model in its
/// current step and state after `steps_before` steps of the run, starting with `velocity`
/// (every DOF, global components; empty: at rest), which it replaces by the velocity of the
/// step's last accepted state.
using ExplicitRunner = std::function<solver::RunReport(std::optional<std::size_t> k,
                                                       int steps_before, Vector& velocity)>;

/// Runs every analysis step of `model` (one without [[step]] tables) from its current state:
/// quasi-static and implicit dynamic ones with Newton, calling `observer` after every accepted
/// step with the step count of the whole run; dynamic-explicit ones with `run_explicit`. A
/// dynamic step (implicit or explicit) that follows a dynamic one starts with its velocity;
/// after a quasi-static step, at rest.
/// Returns the totals of the run; it stops at the first step that fails.
/// `steps` is the run's active step (none before the first one), which the run advances.
/// With `resume`, the run continues from a restart state already read into `model`.
solver::RunReport run_steps(const io::CaseSpec& spec, model::Model& model, StepState& steps,
                            solver::NewtonSolver& newton, const solver::StepObserver& observer,
                            const std::function<void(const solver::StepController&)>& on_start,
                            const Resume* resume = nullptr,
                            const ExplicitRunner& run_explicit = {});

/// Newton settings of a case ([solver]).
solver::NewtonSettings newton_settings(const io::SolverSpec& s);

/// Options of `trifem run` beyond the case file.
struct RunOptions {
  std::filesystem::path restart_file; ///< continue from this restart file (empty: from t = 0)
  bool write_restart = false;         ///< write restart files (as [output] restart = true)
};

/// Runs a case; results go to `output_dir`. Returns an ExitCode.
int run_case(const io::CaseSpec& spec, const std::filesystem::path& output_dir,
             const RunOptions& options = {});

/// Validates a case (file, mesh, sets, materials) without solving; prints a summary.
int check_case(const io::CaseSpec& spec);

} // namespace trifem::analysis
