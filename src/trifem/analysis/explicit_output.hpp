// SPDX-License-Identifier: MIT
// Result files of a dynamic-explicit run: VTU series + results.pvd at the output times, and
// history.csv (step data, energies, reactions, probes) after every step.
#pragma once

#include "trifem/analysis/explicit_case.hpp"
#include "trifem/explicit/explicit_solver.hpp"
#include "trifem/explicit/history.hpp"
#include "trifem/io/pvd_writer.hpp"
#include "trifem/io/vtu_writer.hpp"

#include <filesystem>
#include <memory>
#include <vector>

namespace trifem::analysis {

/// A time the run must land on.
struct StepTarget {
  Real time = 0.0;     ///< [s]
  bool output = false; ///< an output time (VTU file); otherwise a point of a load curve
};

/// The VTU output interval of an explicit run from `start` [s]: output.interval if given (0: every
/// step), otherwise (end_time − start) / io::kDefaultOutputCount (about 100 files, the steps
/// landing on them).
Real explicit_output_interval(const io::CaseSpec& spec, Real start = 0.0);

/// The times the run from `start` must land on, ascending, each > start: the multiples of the
/// output interval (counted from 0 if output.interval is given, from `start` otherwise),
/// output.times and time.end_time (the last) as output times, and the points of the load curves
/// in between (as the quasi-static must points).
std::vector<StepTarget> explicit_step_targets(const io::CaseSpec& spec, Real start = 0.0);

/// Where the results of a dynamic-explicit step that continues a quasi-static run go: the run's
/// results.pvd and VTU numbering continue, and the step has its own history file.
struct ExplicitContinuation {
  io::PvdWriter* pvd = nullptr; ///< the collection of the run (not owned)
  int first_index = 0;          ///< NNNN of the first VTU file of the step
  std::string history_name;     ///< e.g. "history_step2.csv"
};

/// Writes results as the run advances; everything written stays valid if the run stops.
/// VTU arrays: point data "displacement [mm]", "velocity [mm/s]" (vⁿ); cell data
/// "multiplier [MPa]" (Λ), "pressure [MPa]" (the multiplier's pressure: −Λ for Ψ = J − 1, where
/// σ = Λ I; −Λ/J̄ for Ψ = ln J, where τ = Λ I) and "Jbar-1" (cell-mean volume change).
class ExplicitOutput {
public:
  /// Creates `directory` (InputError if impossible), results.pvd and history.csv; with
  /// `continuation`, continues its collection and writes its history file instead, and the
  /// initial state (the end of the quasi-static run, already written) gets no VTU file.
  ExplicitOutput(const ExplicitCase& model, const io::OutputSpec& spec,
                 std::filesystem::path directory, const ExplicitContinuation* continuation = {});
  ~ExplicitOutput();

  /// The initial state: a history row and a VTU file.
  void write_initial(const explicit_dynamics::ExplicitSolver& solver);
  /// The state after the accepted step `report`: a history row, and a VTU file if `volume`.
  void write_step(const explicit_dynamics::ExplicitSolver& solver,
                  const explicit_dynamics::StepReport& report, bool volume);

  std::filesystem::path pvd_file() const { return pvd_->file(); }
  std::filesystem::path history_file() const { return directory_ / history_name_; }
  int vtu_count() const { return vtu_count_; }
  double seconds() const { return seconds_; } ///< wall time spent writing [s]

private:
  void write_vtu(const explicit_dynamics::ExplicitSolver& solver);

  const ExplicitCase& case_;
  bool vtu_ = true;
  std::filesystem::path directory_;
  io::UnstructuredGrid grid_; ///< the mesh; the data arrays are replaced at every write
  std::unique_ptr<io::PvdWriter> own_pvd_; ///< null when continuing a run's collection
  io::PvdWriter* pvd_ = nullptr;
  std::string history_name_ = "history.csv";
  std::unique_ptr<explicit_dynamics::HistoryWriter> history_;
  bool continued_ = false; ///< continues a quasi-static run
  int first_index_ = 0;    ///< NNNN of the first VTU file
  int vtu_count_ = 0;
  double seconds_ = 0.0;
};

} // namespace trifem::analysis
