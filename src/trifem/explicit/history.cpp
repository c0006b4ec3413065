// SPDX-License-Identifier: MIT
#include "trifem/explicit/history.hpp"

namespace trifem::explicit_dynamics {
namespace {

std::vector<std::string> columns(const std::vector<Probe>& probes) {
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

} // namespace

HistoryWriter::HistoryWriter(std::filesystem::path file, std::vector<Probe> probes)
    : probes_(std::move(probes)), csv_(std::move(file), columns(probes_)) {}

void HistoryWriter::record(const ExplicitSolver& solver, const StepReport& report) {
  const Energies e = solver.energies();
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

void HistoryWriter::record_initial(const ExplicitSolver& solver) {
  record(solver, StepReport{});
}

Real mean_radius(const ExplicitSolver& solver, const std::string& node_set) {
  const auto& nodes = solver.model().mesh().node_set(node_set);
  Real sum = 0.0;
  for (Index a : nodes)
    sum += (solver.model().mesh().node(a) + solver.displacement().segment<3>(3 * a)).norm();
  return sum / static_cast<Real>(nodes.size());
}

Real mean_displacement(const ExplicitSolver& solver, const std::string& node_set, int k) {
  const auto& nodes = solver.model().mesh().node_set(node_set);
  Real sum = 0.0;
  for (Index a : nodes)
    sum += solver.displacement()[3 * a + k];
  return sum / static_cast<Real>(nodes.size());
}

} // namespace trifem::explicit_dynamics
