// SPDX-License-Identifier: MIT
// A dynamic-explicit analysis step of a run: the central-difference integrator of
// explicit_dynamics over the shared model's current step, writing through the run's
// OutputWriter.
#pragma once

#include "trifem/analysis/output_writer.hpp"
#include "trifem/analysis/restart.hpp"
#include "trifem/explicit/energy_balance.hpp"
#include "trifem/explicit/explicit_solver.hpp"
#include "trifem/io/case_spec.hpp"
#include "trifem/model/model.hpp"
#include "trifem/solver/time_loop.hpp"

#include <nlohmann/json.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace trifem::analysis {

/// Writes a restart file of the state of `resume` (its steps: those of the explicit step; its
/// integrator state: ExplicitStep::state); called at the output times.
using RestartWriter = std::function<void(const Resume& resume)>;

/// The case as its dynamic-explicit step `k` sees it: the step's end_time and dt as [time]
/// (nullopt: the whole case, a dynamic-explicit analysis).
io::CaseSpec explicit_part(const io::CaseSpec& spec, std::optional<std::size_t> k);

/// InputError if `model` has cells the explicit scheme cannot hold (ExplicitView::check_cells)
/// or outputs an explicit step cannot write (probes of quantities other than displacement and
/// position: its stresses would lack the multiplier's pressure).
void check_explicit_model(const model::Model& model);

/// One dynamic-explicit step: from the model's current displacement and a given velocity, at
/// its current time `start`, to part.time.end_time. Results: a history row after every step (with
/// the integrator's columns: halvings, constraint residual, volume changes, energies), VTU states
/// at the output times with the velocity, the multiplier, its pressure and J̄ − 1.
class ExplicitStep {
public:
  /// Builds the explicit view of `model` in its current step and the solver, which estimates
  /// the stable step at the model's state and time; `start` is that of the step (its output
  /// times count from it; a step continued from a restart file began earlier). The step
  /// starts with `velocity` (every DOF of the model, global
  /// components; empty: at rest; constrained DOFs move as prescribed). InputError if the model
  /// does not fit the explicit analysis or the step needs more than io::kMaxSteps steps. `part`
  /// (explicit_part) and `model` must outlive it.
  ExplicitStep(const io::CaseSpec& part, model::Model& model, Real start,
               const Vector& velocity = {});
  ~ExplicitStep();

  /// Logs the materials, the scheme and the time step.
  void log_settings() const;

  /// The step's state beyond the model's (restart files): the integrator's, the halvings and
  /// the energy balance.
  std::vector<double> state() const;
  /// The number of values of state() for `model`.
  static std::size_t state_size(const model::Model& model);
  /// Continues from `state` (of state()) at the model's current displacement, as if the run
  /// had not stopped there; InputError if it does not fit.
  void restore(const std::vector<double>& state);
  /// Steps to the end, history rows into `history` (a file name in the output directory), the
  /// initial state with a VTU file if `initial_volume`. Stops at the first fatal step report,
  /// on an interrupt or when a result cannot be written. The model's state is the step's end
  /// state (or the last accepted one). The history file named "history.csv" (a dynamic-explicit
  /// case) stays in use with the step's columns: the step must outlive `output`'s last write.
  solver::RunReport run(OutputWriter& output, const std::string& history, bool initial_volume,
                        const RestartWriter& restart = {});
  /// The entries of summary.json that describe the step: counts, time step, final energies, the
  /// energy balance, the largest volume change and the wall times.
  nlohmann::json summary() const;
  /// The velocity of the last accepted state at every DOF of the model (global components).
  Vector velocity() const;
  /// The steps taken so far (with those before a restart).
  long steps() const;

private:
  class Results;
  void write(OutputWriter& output, const explicit_dynamics::StepReport& report, bool volume);
  void advance(OutputWriter& output, solver::RunReport& run, const RestartWriter& restart);

  const io::CaseSpec& part_;
  model::Model& model_;
  Real start_;
  std::unique_ptr<explicit_dynamics::ExplicitView> view_;
  std::unique_ptr<explicit_dynamics::ExplicitSolver> solver_;
  std::unique_ptr<Results> results_;
  explicit_dynamics::EnergyBalance balance_;
  long halvings_ = 0;
  double wall_seconds_ = 0.0, output_seconds_ = 0.0;
};

} // namespace trifem::analysis
