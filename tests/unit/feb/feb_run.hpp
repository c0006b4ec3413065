// SPDX-License-Identifier: MIT
// Runs a case read from a .feb file through the analysis steps (the tests of tests/unit/feb).
#pragma once

#include "trifem/analysis/run.hpp"
#include "trifem/linalg/linear_solver.hpp"
#include "trifem/model/model.hpp"

#include <functional>
#include <memory>

namespace trifem::test {

/// A case, its model and the report of its run.
struct FebRun {
  io::CaseSpec spec;
  std::unique_ptr<model::Model> model;
  solver::RunReport report;
};

/// Builds the model of `spec` and runs all its steps, calling `observer` after every step.
inline FebRun run_feb_case(io::CaseSpec spec,
                           const std::function<void(const model::Model&, Real)>& observer = {}) {
  FebRun r;
  r.spec = std::move(spec);
  r.model = model::build_model(r.spec);
  solver::NewtonSolver newton(analysis::newton_settings(r.spec.solver),
                              linalg::make_linear_solver(r.spec.solver.linear_solver));
  analysis::StepState steps = analysis::start_steps(*r.model);
  solver::Linearization initial;
  r.model->problem->linearize(initial, false);
  r.report = analysis::run_steps(
      r.spec, *r.model, steps, newton,
      [&](const solver::StepInfo& info) {
        if (observer)
          observer(*r.model, info.time);
      },
      [](const solver::StepController&) {});
  return r;
}

} // namespace trifem::test
