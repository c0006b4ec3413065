// SPDX-License-Identifier: MIT
// Case reader, part 5: limits on the work a case implies, checked once every section is read,
// so that a case that cannot run is refused at once instead of exhausting time or memory: the
// number of steps and output times, and the size of the model of the structured boxes.
#include "trifem/io/toml_table.hpp"

#include <unistd.h>

#include <algorithm>
#include <climits>
#include <cmath>

namespace trifem::io::detail {
namespace {

// ---------------------------------------------------------------------------------------------
// Steps and output times

/// The node of `key` in the table `section` of `root` (null if absent), for line numbers.
const toml::node* node_of(const Table& root, std::string_view section, std::string_view key) {
  const auto t = root.table(section);
  return t ? t->find(key) : nullptr;
}

/// Fewest steps a quasi-static run can take: every step converges at once and grows by
/// `growth` from dt up to dt_max.
Real fewest_steps(const TimeSpec& s) {
  const Real dt_max = s.dt_max > 0.0 ? s.dt_max : s.dt;
  if (s.growth <= 1.0 || dt_max <= s.dt)
    return s.end_time / s.dt;
  const Real ln_g = std::log(s.growth);
  const Real growing = std::ceil(std::log(dt_max / s.dt) / ln_g); // steps to reach dt_max
  const Real covered = s.dt * std::expm1(growing * ln_g) / (s.growth - 1.0);
  if (covered >= s.end_time)
    return std::log1p(s.end_time * (s.growth - 1.0) / s.dt) / ln_g;
  return growing + (s.end_time - covered) / dt_max;
}

/// Refuses runs of more than kMaxSteps steps.
void check_step_count(const Table& root, const CaseSpec& spec) {
  const TimeSpec& s = spec.time;
  if (spec.is_explicit() && s.dt <= 0.0) // the step is the stability estimate
    return;
  const Real steps = spec.is_explicit() ? s.end_time / s.dt : fewest_steps(s);
  if (steps <= kMaxSteps)
    return;
  const bool has_dt_max = !spec.is_explicit() && node_of(root, "time", "dt_max") != nullptr;
  fail(node_of(root, "time", "end_time"), fmt::format("time.end_time = {}", s.end_time),
       fmt::format("with time.dt = {} s{} the run needs at least {:.3g} steps, more than the "
                   "{:.0e} allowed (shorten time.end_time or allow longer steps)",
                   s.dt, has_dt_max ? fmt::format(", time.dt_max = {} s", s.dt_max) : "", steps,
                   kMaxSteps));
}

/// Refuses step settings that retry a failed step more than kMaxCutbacks times before the run
/// fails (cutback close to 1, or dt_min far below dt).
void check_cutbacks(const Table& root, const CaseSpec& spec) {
  const TimeSpec& s = spec.time;
  if (spec.is_explicit())
    return;
  const Real dt_min = s.dt_min > 0.0 ? s.dt_min : s.dt * 1e-6;
  const Real cutbacks = std::log(dt_min / s.dt) / std::log(s.cutback);
  if (cutbacks <= kMaxCutbacks)
    return;
  fail(node_of(root, "time", "cutback"), fmt::format("time.cutback = {}", s.cutback),
       fmt::format("a failed step would be cut back {:.3g} times from time.dt = {} s to "
                   "time.dt_min = {} s before the run fails, more than the {} allowed (use a "
                   "smaller cutback or a larger dt_min)",
                   cutbacks, s.dt, dt_min, kMaxCutbacks));
}

/// Refuses more than kMaxOutputTimes output times or must points (every one is a step).
void check_output_count(const Table& root, const CaseSpec& spec) {
  const Real end = spec.time.end_time, interval = spec.output.interval;
  const Real periodic = interval > 0.0 ? end / interval : 0.0;
  if (periodic > kMaxOutputTimes)
    fail(node_of(root, "output", "interval"), fmt::format("output.interval = {}", interval),
         fmt::format("time.end_time / output.interval = {:.3g} output times, more than the {:.0e} "
                     "allowed (use a larger interval)",
                     periodic, kMaxOutputTimes));
  Real must = periodic + static_cast<Real>(spec.output.times.size());
  for (const auto& [name, curve] : spec.curves)
    must += static_cast<Real>(curve.points.size());
  if (must > kMaxOutputTimes)
    fail(nullptr, "output",
         fmt::format("{:.3g} times the steps must land on (output.interval, output.times and the "
                     "points of the load curves), more than the {:.0e} allowed",
                     must, kMaxOutputTimes));
}

// ---------------------------------------------------------------------------------------------
// Model size

/// Estimated size of the model of the [[mesh.box]] cells (Gmsh meshes are bounded by the size
/// of their files and not counted).
struct ModelSize {
  Real nodes = 0.0;
  Real cells = 0.0;
  Real equations = 0.0;
  Real bytes = 0.0; ///< lower bound of the memory a run needs
};

/// DOFs per node and per cell of the fields the materials of the meshes create (as the model
/// builder adds them: u; w and p with a mixture; j+, j- and eta with a triphasic material).
std::pair<int, int> dofs_per_node_and_cell(const CaseSpec& spec) {
  bool mixture = false, ions = false;
  const auto note = [&](const std::string& name) {
    const auto it = spec.materials.find(name);
    if (it == spec.materials.end())
      return;
    mixture = mixture || it->second.is_mixture();
    ions = ions || it->second.type == "triphasic";
  };
  for (const auto& b : spec.boxes)
    note(b.material);
  for (const auto& g : spec.gmsh)
    for (const auto& [volume, material] : g.materials)
      note(material);
  return {3 + (mixture ? 3 : 0) + (ions ? 6 : 0), (mixture ? 1 : 0) + (ions ? 1 : 0)};
}

ModelSize estimate_size(const CaseSpec& spec) {
  ModelSize m;
  const Real split = std::ldexp(1.0, spec.mesh_refinement); // [mesh] refine: divisions x 2^L
  for (const auto& b : spec.boxes) {
    const Vec3 n = split * Vec3(b.box.divisions[0], b.box.divisions[1], b.box.divisions[2]);
    m.nodes += (n[0] + 1.0) * (n[1] + 1.0) * (n[2] + 1.0);
    m.cells += n[0] * n[1] * n[2];
  }
  const auto [per_node, per_cell] = dofs_per_node_and_cell(spec);
  const Real dn = per_node, dc = per_cell;
  m.equations = m.nodes * dn + m.cells * dc;
  // Nonzeros of the assembled matrix: a node couples with 27 nodes and 8 cells, a cell with
  // itself. Explicit analyses assemble no stiffness matrix, only the multiplier system.
  const Real nonzeros =
      spec.is_explicit() ? 27.0 * m.cells
                         : 27.0 * m.nodes * dn * dn + 16.0 * m.cells * dn * dc + m.cells * dc * dc;
  // 12 bytes per nonzero (value and row index), the mesh (coordinates, connectivity) and about
  // ten vectors of the equations (state, residual, increments, output).
  m.bytes = 12.0 * nonzeros + 24.0 * m.nodes + 32.0 * m.cells + 80.0 * m.equations;
  return m;
}

/// Physical memory of the machine [bytes], 0 if unknown.
Real physical_memory() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
  return pages > 0 && page > 0 ? Real(pages) * Real(page) : 0.0;
}

/// The [[mesh.box]] entry with the most cells and its divisions node, for the message.
std::pair<std::string, const toml::node*> largest_box(const Table& root, const CaseSpec& spec) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < spec.boxes.size(); ++i) {
    const auto cells = [&](std::size_t k) {
      const auto& n = spec.boxes[k].box.divisions;
      return Real(n[0]) * Real(n[1]) * Real(n[2]);
    };
    if (cells(i) > cells(best))
      best = i;
  }
  const std::vector<Table> boxes = root.table("mesh")->tables("box");
  return {element_path("mesh.box", best) + ".divisions", boxes[best].find("divisions")};
}

} // namespace

void check_time_limits(const Table& root, const CaseSpec& spec) {
  check_step_count(root, spec);
  check_cutbacks(root, spec);
  check_output_count(root, spec);
}

void check_model_size(const Table& root, const CaseSpec& spec) {
  if (spec.boxes.empty())
    return;
  const ModelSize m = estimate_size(spec);
  const Real memory = physical_memory();
  const bool too_many = m.equations > INT_MAX;
  if (!too_many && (memory <= 0.0 || m.bytes <= memory))
    return;
  const auto [path, node] = largest_box(root, spec);
  const std::string size =
      fmt::format("the boxes{} make a model of {:.4g} nodes and {:.4g} cells, about {:.4g} "
                  "equations",
                  spec.mesh_refinement > 0
                      ? fmt::format(" (refined {} times by mesh.refine)", spec.mesh_refinement)
                      : "",
                  m.nodes, m.cells, m.equations);
  if (too_many)
    fail(node, path, fmt::format("{}, more than the {} a model can have", size, INT_MAX));
  fail(node, path,
       fmt::format("{}; a run needs at least {:.3g} GB of memory (the matrix of the equations and "
                   "the mesh; a direct solver needs several times more), more than the {:.3g} GB "
                   "of this machine",
                   size, m.bytes / 1e9, memory / 1e9));
}

} // namespace trifem::io::detail
