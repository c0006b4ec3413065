// SPDX-License-Identifier: MIT
// A history.csv of a direct explicit-solver run (tests and examples): step data, energy
// bookkeeping and probes of the solver state.
#pragma once

#include "trifem/explicit/explicit_solver.hpp"
#include "trifem/io/csv_writer.hpp"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace trifem::test {

/// A named scalar of the solver state written as one history column (name includes the unit).
struct Probe {
  std::string name;
  std::function<Real(const explicit_dynamics::ExplicitSolver&)> value;
};

/// Writes one row per recorded step (flushed, so a stopped run keeps its history):
/// step, time [s], dt [s], iterations, halvings, constraint_residual, max|Jbar-1| (cell
/// means), max_gauss|J-1|, kinetic/strain/external_work/damping_work/total_energy [mJ], then
/// the probes.
class HistoryWriter {
public:
  HistoryWriter(std::filesystem::path file, std::vector<Probe> probes)
      : probes_(std::move(probes)), csv_(std::move(file), columns(probes_)) {}

  /// Records the state of `solver` after the step described by `report`.
  void record(const explicit_dynamics::ExplicitSolver& solver,
              const explicit_dynamics::StepReport& report) {
    const explicit_dynamics::Energies e = solver.energies();
    std::vector<double> row = {static_cast<double>(solver.step_count()),
                               solver.time(),
                               report.dt,
                               static_cast<double>(report.iterations),
                               static_cast<double>(report.halvings),
                               report.constraint_residual,
                               solver.max_volume_change(),
                               solver.max_gauss_volume_change(),
                               e.kinetic,
                               e.strain,
                               e.external_work,
                               e.damping_work,
                               e.total()};
    for (const Probe& p : probes_)
      row.push_back(p.value(solver));
    csv_.write_row(row);
  }
  /// Records the initial state (step 0).
  void record_initial(const explicit_dynamics::ExplicitSolver& solver) {
    record(solver, explicit_dynamics::StepReport{});
  }

private:
  static std::vector<std::string> columns(const std::vector<Probe>& probes) {
    std::vector<std::string> c = {"step",
                                  "time [s]",
                                  "dt [s]",
                                  "iterations",
                                  "halvings",
                                  "constraint_residual",
                                  "max|Jbar-1|",
                                  "max_gauss|J-1|",
                                  "kinetic [mJ]",
                                  "strain [mJ]",
                                  "external_work [mJ]",
                                  "damping_work [mJ]",
                                  "total_energy [mJ]"};
    for (const Probe& p : probes)
      c.push_back(p.name);
    return c;
  }

  std::vector<Probe> probes_;
  io::CsvWriter csv_;
};

/// Mean current distance of the nodes of a set from the origin, mean of |X + u| [mm].
inline Real mean_radius(const explicit_dynamics::ExplicitSolver& solver,
                        const std::string& node_set) {
  const auto& nodes = solver.model().mesh().node_set(node_set);
  Real sum = 0.0;
  for (Index a : nodes)
    sum += (solver.model().mesh().node(a) + solver.displacement().segment<3>(3 * a)).norm();
  return sum / static_cast<Real>(nodes.size());
}

/// Mean displacement component k over a node set [mm].
inline Real mean_displacement(const explicit_dynamics::ExplicitSolver& solver,
                              const std::string& node_set, int k) {
  const auto& nodes = solver.model().mesh().node_set(node_set);
  Real sum = 0.0;
  for (Index a : nodes)
    sum += solver.displacement()[3 * a + k];
  return sum / static_cast<Real>(nodes.size());
}

} // namespace trifem::test
