// SPDX-License-Identifier: MIT
// Result files of a run: VTU series + .pvd, contact-surface files, history.csv, summary.json.
#pragma once

#include "trifem/analysis/mass_balance.hpp"
#include "trifem/io/csv_writer.hpp"
#include "trifem/io/pvd_writer.hpp"
#include "trifem/io/vtu_writer.hpp"
#include "trifem/model/model.hpp"
#include "trifem/solver/time_loop.hpp"

#include <filesystem>
#include <memory>
#include <optional>

namespace trifem::analysis {

class ContactOutput;
class CellEvaluator;

/// What an integrator adds to the results of its steps (the explicit one: its counters and
/// energies, its velocity and multiplier arrays, its reactions).
class StepResults {
public:
  virtual ~StepResults() = default;
  /// Names of the history columns it adds after "iterations".
  virtual std::vector<std::string> columns() const = 0;
  /// Their values at the state being written.
  virtual void append_values(std::vector<double>& row) const = 0;
  /// The residual at every DOF (the reactions at constrained DOFs) of the state being written,
  /// instead of the problem's.
  virtual const Vector& full_residual() const = 0;
  /// The arrays of a VTU state: adds to (or replaces) the model's point and cell arrays.
  virtual void add_arrays(std::vector<io::DataArray>& point,
                          std::vector<io::DataArray>& cell) const = 0;
};

/// Writes results as the run advances; everything written stays valid if the run stops.
class OutputWriter {
public:
  /// Creates `directory` (InputError if impossible) and the history file. `end_time`: of the
  /// run (for the default output times).
  OutputWriter(const model::Model& model, const io::OutputSpec& spec,
               std::filesystem::path directory, Real end_time);
  ~OutputWriter();

  /// Water and ion balances (mixture models; null otherwise).
  MassBalance* balance() { return balance_.get(); }
  /// From now on the history rows go to `file_name` in the output directory with the columns
  /// `results` adds (null: none) after "iterations", as do the VTU states, until the next call.
  /// The run's history.csv is continued when `file_name` is it and `results` is null, replaced
  /// (a new header) otherwise; another name starts a new file. `results` must outlive its use.
  void use_history(const std::string& file_name, const StepResults* results);
  /// Writes the state at `time`: a history row always; if `volume` is set (an output time) the
  /// VTU file (unless output.vtu = false) and the contact-surface files of every contact pair.
  void write(Real time, int step, Real dt, int iterations, bool volume);
  /// After a run that stopped early: the current (last accepted) state at `time` as a VTU file
  /// and contact-surface files, unless it was the last state written.
  void write_last_state(Real time);
  /// True if the state at `time` is written as a VTU file: a listed time, a multiple of
  /// output.interval (every step if it is 0), or without output.interval the first step at or
  /// after each of io::kDefaultOutputCount equal parts of [0, end_time].
  bool is_output_time(Real time);

  std::filesystem::path pvd_file() const { return directory_ / "results.pvd"; }
  /// surfaces.pvd, the surface meshes' states, if the mesh has any (empty otherwise).
  std::filesystem::path surfaces_pvd_file() const {
    return surfaces_pvd_ ? directory_ / "surfaces.pvd" : std::filesystem::path();
  }
  /// The history file rows go to now (history.csv unless use_history chose another).
  std::filesystem::path history_file() const { return directory_ / history_name_; }
  int vtu_count() const { return vtu_count_; }
  /// The NNNN of the last output state written (-1: none).
  int last_state_index() const { return state_count_ - 1; }
  double seconds() const { return seconds_; }

private:
  /// The VTU state numbered `number` (on several processes: this process's piece, and on
  /// rank 0 the .pvtu file).
  void write_vtu(Real time, int number);
  /// surfaces_NNNN.vtu: the surface meshes with their nodes' displacement.
  void write_free_surfaces(Real time, int number);
  void write_state(Real time);
  std::vector<std::string> history_columns() const;
  std::vector<double> history_row(Real time, int step, Real dt, int iterations) const;

  const model::Model& model_;
  io::OutputSpec spec_;
  std::filesystem::path directory_;
  std::unique_ptr<io::PvdWriter> pvd_;
  /// The surface meshes (facets that bound no cell: rigid bodies given by their surface) and
  /// their surfaces.pvd; empty grid and null without any.
  io::UnstructuredGrid free_surfaces_;
  std::vector<Index> free_surface_nodes_; ///< the mesh node of each point of free_surfaces_
  std::unique_ptr<io::PvdWriter> surfaces_pvd_;
  std::unique_ptr<io::CsvWriter> history_;      ///< the run's history.csv
  std::unique_ptr<io::CsvWriter> step_history_; ///< another history file of the current step
  std::string history_name_ = "history.csv";
  const StepResults* results_ = nullptr; ///< the integrator's additions (null: none)
  std::unique_ptr<MassBalance> balance_;
  std::unique_ptr<ContactOutput> contact_; ///< null without contact pairs
  std::unique_ptr<CellEvaluator> cells_;   ///< for cell-quantity probes and averages
  Real end_time_ = 0.0;                    ///< of the run (default output times)
  Real next_default_ = 0.0;                ///< next default output time (no output.interval)
  int state_count_ = 0;                    ///< output states written (the NNNN of the files)
  Real last_state_time_ = -1.0;            ///< time of the last output state written
  int vtu_count_ = 0;
  double seconds_ = 0.0;
  /// False on the processes of a parallel run other than rank 0: they write no file.
  bool writes_files_ = true;
  /// On several processes: the cells of this process's piece of each VTU state.
  std::optional<std::vector<Index>> piece_cells_;
};

} // namespace trifem::analysis
