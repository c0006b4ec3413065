// SPDX-License-Identifier: MIT
// history.csv of an explicit run: step data, energy bookkeeping and user probes.
#pragma once

#include "trifem/explicit/explicit_solver.hpp"
#include "trifem/io/csv_writer.hpp"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace trifem::explicit_dynamics {

/// A named scalar of the solver state written as one history column (name includes the unit).
struct Probe {
  std::string name;
  std::function<Real(const ExplicitSolver&)> value;
};

/// Writes one row per recorded step (flushed, so a stopped run keeps its history):
/// step, time [s], dt [s], iterations, halvings, constraint_residual, max|Jbar-1| (cell
/// means), max_gauss|J-1|, kinetic/strain/external_work/damping_work/total_energy [mJ], then
/// the probes.
class HistoryWriter {
public:
  HistoryWriter(std::filesystem::path file, std::vector<Probe> probes);
  /// Records the state of `solver` after the step described by `report`.
  void record(const ExplicitSolver& solver, const StepReport& report);
  /// Records the initial state (step 0).
  void record_initial(const ExplicitSolver& solver);

private:
  std::vector<Probe> probes_;
  io::CsvWriter csv_;
};

/// Mean current distance of the nodes of a set from the origin, mean of |X + u| [mm].
Real mean_radius(const ExplicitSolver& solver, const std::string& node_set);

/// Mean displacement component k over a node set [mm].
Real mean_displacement(const ExplicitSolver& solver, const std::string& node_set, int k);

} // namespace trifem::explicit_dynamics
