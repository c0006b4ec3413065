// SPDX-License-Identifier: MIT
// Runs a case (TOML text) through the application's model building and a plain time loop.
#pragma once

#include "model.hpp"
#include "trifem/io/case_reader.hpp"
#include "trifem/linalg/linear_solver.hpp"
#include "trifem/solver/time_loop.hpp"

#include <functional>
#include <memory>
#include <string_view>

namespace trifem::test {

/// A built model with the solver objects of a run.
struct CaseRun {
  io::CaseSpec spec;
  std::unique_ptr<app::Model> model;
  solver::RunReport report;
};

/// Parses `text` (relative paths resolved against `file`), builds the model and runs it to
/// time.end_time with the [time] settings (as `trifem run`), calling `observer` after every
/// step.
inline CaseRun
run_case_text(std::string_view text, const std::filesystem::path& file,
              const std::function<void(const CaseRun&, const solver::StepInfo&)>& observer = {}) {
  CaseRun run;
  run.spec = io::parse_case(text, file);
  run.model = app::build_model(run.spec);
  solver::NewtonSettings newton_settings;
  newton_settings.max_iterations = run.spec.solver.max_iterations;
  newton_settings.residual_tolerance = run.spec.solver.residual_tolerance;
  newton_settings.increment_tolerance = run.spec.solver.increment_tolerance;
  solver::NewtonSolver newton(newton_settings, linalg::make_linear_solver("umfpack"));
  const io::TimeSpec& t = run.spec.time;
  solver::StepSettings steps;
  steps.end_time = t.end_time;
  steps.dt = t.dt;
  steps.dt_max = t.dt_max > 0 ? t.dt_max : t.dt;
  steps.dt_min = t.dt_min > 0 ? t.dt_min : t.dt * 1e-6;
  steps.growth = t.growth;
  steps.cutback = t.cutback;
  steps.target_iterations = t.target_iterations;
  for (const auto& [name, curve] : run.spec.curves) // land on the kinks of the load curves
    for (const auto& [time, value] : curve.points)
      if (time > 0 && time < t.end_time)
        steps.must_points.push_back(time);
  solver::StepController controller(steps);
  solver::Linearization initial; // the state at t = 0 (reactions of the initial state)
  run.model->problem->linearize(initial, false);
  run.report = solver::run_time_loop(*run.model->problem, newton, controller,
                                     [&](const solver::StepInfo& info) {
                                       if (observer)
                                         observer(run, info);
                                     });
  return run;
}

} // namespace trifem::test
