// SPDX-License-Identifier: MIT
// Runs a case (TOML text) through the application's model building and a plain time loop.
#pragma once

#include "trifem/analysis/run.hpp"
#include "trifem/io/case_reader.hpp"
#include "trifem/linalg/linear_solver.hpp"
#include "trifem/model/model.hpp"
#include "trifem/solver/time_loop.hpp"

#include <functional>
#include <memory>
#include <string_view>

namespace trifem::test {

/// A built model with the solver objects of a run.
struct CaseRun {
  io::CaseSpec spec;
  std::unique_ptr<model::Model> model;
  solver::RunReport report;
};

/// Called after every step of a run.
using CaseObserver = std::function<void(const CaseRun&, const solver::StepInfo&)>;

/// Builds the model of `spec` and runs it to time.end_time with the step and Newton settings
/// of `trifem run`, calling `observer` after every step.
inline CaseRun run_case_spec(io::CaseSpec spec, const CaseObserver& observer = {}) {
  CaseRun run;
  run.spec = std::move(spec);
  run.model = model::build_model(run.spec);
  solver::NewtonSolver newton(analysis::newton_settings(run.spec.solver),
                              linalg::make_linear_solver(run.spec.solver.linear_solver));
  solver::StepController controller(analysis::step_settings(run.spec));
  solver::Linearization initial; // the state at t = 0 (reactions of the initial state)
  run.model->problem->linearize(initial, false);
  run.report = solver::run_time_loop(*run.model->problem, newton, controller,
                                     [&](const solver::StepInfo& info) {
                                       if (observer)
                                         observer(run, info);
                                     });
  return run;
}

/// Runs `spec` through its analysis steps as `trifem run` does (each [[step]] with its
/// conditions; analysis::run_steps), calling `observer` with the model and the time after every
/// step.
inline CaseRun run_case_steps(io::CaseSpec spec,
                              const std::function<void(const model::Model&, Real)>& observer = {}) {
  CaseRun run;
  run.spec = std::move(spec);
  run.model = model::build_model(run.spec);
  solver::NewtonSolver newton(analysis::newton_settings(run.spec.solver),
                              linalg::make_linear_solver(run.spec.solver.linear_solver));
  analysis::StepState steps = analysis::start_steps(*run.model);
  solver::Linearization initial; // the state at t = 0 (reactions of the initial state)
  run.model->problem->linearize(initial, false);
  run.report = analysis::run_steps(
      run.spec, *run.model, steps, newton,
      [&](const solver::StepInfo& info) {
        if (observer)
          observer(*run.model, info.time);
      },
      [](const solver::StepController&) {});
  return run;
}

/// Parses `text` and runs it through its analysis steps (run_case_steps of its spec).
inline CaseRun run_case_steps(std::string_view text, const std::filesystem::path& file,
                              const std::function<void(const model::Model&, Real)>& observer = {}) {
  return run_case_steps(io::parse_case(text, file), observer);
}

/// Parses `text` (relative paths resolved against `file`) and runs it (run_case_spec).
inline CaseRun run_case_text(std::string_view text, const std::filesystem::path& file,
                             const CaseObserver& observer = {}) {
  return run_case_spec(io::parse_case(text, file), observer);
}

} // namespace trifem::test
