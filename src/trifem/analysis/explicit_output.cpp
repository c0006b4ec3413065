// SPDX-License-Identifier: MIT
#include "trifem/analysis/explicit_output.hpp"

#include "trifem/core/error.hpp"
#include "trifem/core/log.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace trifem::analysis {
namespace {

namespace ed = explicit_dynamics;
using Clock = std::chrono::steady_clock;

constexpr const char* kAxis[3] = {"x", "y", "z"};

/// reaction_force() of the solver's current state, computed once per history row.
class ReactionCache {
public:
  /// Q + Hλ − F_ext per DOF at the solver's current state.
  const Vector& get(const ed::ExplicitSolver& s) {
    if (s.step_count() != step_ || s.time() != time_) {
      force_ = s.reaction_force();
      step_ = s.step_count();
      time_ = s.time();
    }
    return force_;
  }

private:
  long step_ = -1;
  Real time_ = -1.0;
  Vector force_;
};

/// History columns after the solver's own: reactions (sum over a node set) then probes.
std::vector<ed::Probe> history_columns(const ExplicitCase& c) {
  std::vector<ed::Probe> columns;
  auto cache = std::make_shared<ReactionCache>();
  for (const ExplicitReaction& r : c.reactions)
    for (int k = 0; k < 3; ++k)
      columns.push_back({fmt::format("{}.R{} [N]", r.name, kAxis[k]),
                         [cache, dofs = r.dofs[k]](const ed::ExplicitSolver& s) {
                           const Vector& f = cache->get(s);
                           Real sum = 0.0;
                           for (Index d : dofs)
                             sum += f[d];
                           return sum;
                         }});
  for (const ExplicitProbe& p : c.probes) {
    const bool position = p.position;
    for (int k = 0; k < 3; ++k)
      columns.push_back({fmt::format("{}.{}{} [mm]", p.name, position ? "" : "u", kAxis[k]),
                         [node = p.node, k, position](const ed::ExplicitSolver& s) {
                           const Real u = s.displacement()[3 * node + k];
                           return position ? s.model().mesh().node(node)[k] + u : u;
                         }});
  }
  return columns;
}

/// A 3-component point array from a DOF vector (3 a + k).
io::DataArray vector_array(std::string name, const Vector& v) {
  return {std::move(name), 3, std::vector<double>(v.data(), v.data() + v.size())};
}

/// A scalar array from a per-cell vector.
io::DataArray scalar_array(std::string name, const Vector& v) {
  return {std::move(name), 1, std::vector<double>(v.data(), v.data() + v.size())};
}

/// The multiplier's pressure per cell: −Λ (Ψ = J − 1) or −Λ/J̄ (Ψ = ln J).
Vector multiplier_pressure(const ed::ExplicitSolver& s) {
  const Vector& lambda = s.multiplier();
  if (s.settings().constraint == ed::Constraint::JMinusOne)
    return -lambda;
  const Vector J = s.fields().volume_change.array() + 1.0;
  return -lambda.cwiseQuotient(J);
}

} // namespace

Real explicit_output_interval(const io::CaseSpec& spec, Real start) {
  return spec.output.interval_given ? spec.output.interval
                                    : (spec.time.end_time - start) / io::kDefaultOutputCount;
}

std::vector<StepTarget> explicit_step_targets(const io::CaseSpec& spec, Real start) {
  const Real end = spec.time.end_time, interval = explicit_output_interval(spec, start);
  const Real origin = spec.output.interval_given ? 0.0 : start; // of the periodic output times
  std::vector<StepTarget> targets;
  if (interval > 0.0)
    for (long k = 1; origin + static_cast<Real>(k) * interval < end; ++k)
      targets.push_back({origin + static_cast<Real>(k) * interval, true});
  for (const Real t : spec.output.times)
    targets.push_back({t, true});
  for (const auto& [name, curve] : spec.curves)
    for (const auto& point : curve.points)
      targets.push_back({point.first, false});
  const Real eps = 1e-12 * end;
  std::erase_if(targets,
                [&](const StepTarget& t) { return t.time <= start + eps || t.time >= end - eps; });
  targets.push_back({end, true});
  std::sort(targets.begin(), targets.end(),
            [](const StepTarget& a, const StepTarget& b) { return a.time < b.time; });
  std::vector<StepTarget> merged; // near-equal times once, an output time if any of them is
  for (const StepTarget& t : targets) {
    if (!merged.empty() && t.time - merged.back().time <= eps)
      merged.back().output = merged.back().output || t.output;
    else
      merged.push_back(t);
  }
  return merged;
}

ExplicitOutput::ExplicitOutput(const ExplicitCase& model, const io::OutputSpec& spec,
                               std::filesystem::path directory,
                               const ExplicitContinuation* continuation)
    : case_(model), vtu_(spec.vtu), directory_(std::move(directory)) {
  std::error_code ec;
  std::filesystem::create_directories(directory_, ec);
  TRIFEM_CHECK(!ec, "cannot create the output directory {}: {}", directory_.string(), ec.message());
  if (continuation) {
    continued_ = true;
    pvd_ = continuation->pvd;
    first_index_ = continuation->first_index;
    history_name_ = continuation->history_name;
  } else {
    own_pvd_ = std::make_unique<io::PvdWriter>(directory_ / "results.pvd");
    pvd_ = own_pvd_.get();
  }
  history_ = std::make_unique<ed::HistoryWriter>(history_file(), history_columns(model));
  const mesh::Mesh& mesh = model.model->mesh();
  grid_.points = mesh.nodes();
  for (const mesh::Hex8& cell : mesh.cells())
    grid_.add_cell(io::vtk_cell::kHexahedron, cell);
}

ExplicitOutput::~ExplicitOutput() = default;

void ExplicitOutput::write_initial(const ed::ExplicitSolver& solver) {
  const auto start = Clock::now();
  history_->record_initial(solver);
  if (vtu_ && !continued_) // a continued run wrote this state at the end of its last step
    write_vtu(solver);
  seconds_ += std::chrono::duration<double>(Clock::now() - start).count();
}

void ExplicitOutput::write_step(const ed::ExplicitSolver& solver, const ed::StepReport& report,
                                bool volume) {
  const auto start = Clock::now();
  history_->record(solver, report);
  if (volume && vtu_)
    write_vtu(solver);
  seconds_ += std::chrono::duration<double>(Clock::now() - start).count();
}

void ExplicitOutput::write_vtu(const ed::ExplicitSolver& solver) {
  grid_.point_data = {vector_array("displacement [mm]", solver.displacement()),
                      vector_array("velocity [mm/s]", solver.velocity())};
  grid_.cell_data = {scalar_array("multiplier [MPa]", solver.multiplier()),
                     scalar_array("pressure [MPa]", multiplier_pressure(solver)),
                     scalar_array("Jbar-1", solver.fields().volume_change)};
  const auto file = directory_ / fmt::format("volume_{:04d}.vtu", first_index_ + vtu_count_++);
  if (const auto bad = io::write_vtu(file, grid_); bad > 0)
    log::warn("  {} non-finite values written to {}", bad, file.string());
  pvd_->add(solver.time(), file);
}

} // namespace trifem::analysis
