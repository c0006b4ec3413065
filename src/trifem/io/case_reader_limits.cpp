// SPDX-License-Identifier: MIT
// Case reader, part 5: limits on the work a case implies, checked once every section is read,
// so that a case that cannot run is refused at once instead of exhausting time or memory: the
// number of steps and output times, and the size of the model of the structured boxes.
#include "trifem/io/toml_table.hpp"

#include <unistd.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <limits>

namespace trifem::io::detail {
namespace {

// ---------------------------------------------------------------------------------------------
// Steps and output times

/// Where a set of time keys was read: its table (null when the spec was changed after reading,
/// e.g. by `trifem run --refine-time`) and its key path ("time", "step[2]").
struct TimeKeys {
  const Table* table = nullptr;
  std::string path;
  Real start = 0.0; ///< start of the span the keys cover [s]

  const toml::node* node(std::string_view key) const { return table ? table->find(key) : nullptr; }
  std::string key(std::string_view name) const { return fmt::format("{}.{}", path, name); }
};

/// Fewest steps a quasi-static run can take over `span`: every step converges at once and grows
/// by `growth` from dt up to dt_max.
Real fewest_steps(const TimeSpec& s, Real span) {
  const Real dt_max = s.dt_max > 0.0 ? s.dt_max : s.dt;
  if (s.growth <= 1.0 || dt_max <= s.dt)
    return span / s.dt;
  const Real ln_g = std::log(s.growth);
  const Real growing = std::ceil(std::log(dt_max / s.dt) / ln_g); // steps to reach dt_max
  const Real covered = s.dt * std::expm1(growing * ln_g) / (s.growth - 1.0);
  if (covered >= span)
    return std::log1p(span * (s.growth - 1.0) / s.dt) / ln_g;
  return growing + (span - covered) / dt_max;
}

/// Refuses a span of more than kMaxSteps steps (or a step that underflowed to 0).
void check_step_count(const TimeKeys& where, const TimeSpec& s, bool is_explicit) {
  if (is_explicit && s.dt <= 0.0) // the step is the stability estimate
    return;
  const Real span = s.end_time - where.start;
  const Real steps = !(s.dt > 0.0) ? std::numeric_limits<Real>::infinity()
                     : is_explicit ? span / s.dt
                                   : fewest_steps(s, span);
  if (steps <= kMaxSteps)
    return;
  const bool has_dt_max = !is_explicit && where.node("dt_max") != nullptr;
  const bool duration = where.node("duration") != nullptr;
  const std::string_view end_key = duration ? "duration" : "end_time";
  fail(where.node(end_key),
       fmt::format("{} = {}", where.key(end_key), duration ? span : s.end_time),
       fmt::format("with {} = {} s{} the {} needs at least {:.3g} steps, more than the {:.0e} "
                   "allowed (shorten it or allow longer steps)",
                   where.key("dt"), s.dt,
                   has_dt_max ? fmt::format(", {} = {} s", where.key("dt_max"), s.dt_max) : "",
                   where.path == "time" ? "run" : "step", steps, kMaxSteps));
}

/// Refuses step settings that retry a failed step more than kMaxCutbacks times before the run
/// fails (cutback close to 1, or dt_min far below dt).
void check_cutbacks(const TimeKeys& where, const TimeSpec& s) {
  const Real dt_min = s.dt_min > 0.0 ? s.dt_min : s.dt * 1e-6;
  const Real cutbacks = std::log(dt_min / s.dt) / std::log(s.cutback);
  if (cutbacks <= kMaxCutbacks)
    return;
  fail(where.node("cutback"), fmt::format("{} = {}", where.key("cutback"), s.cutback),
       fmt::format("a failed step would be cut back {:.3g} times from {} = {} s to {} = {} s "
                   "before the run fails, more than the {} allowed (use a smaller cutback or a "
                   "larger dt_min)",
                   cutbacks, where.key("dt"), s.dt, where.key("dt_min"), dt_min, kMaxCutbacks));
}

/// The step and cutback limits of [time], or of every [[step]] where the case has them.
void check_steps_and_cutbacks(const Table* root, const CaseSpec& spec) {
  if (spec.steps.empty()) {
    const auto time = root ? root->table("time") : std::nullopt;
    const TimeKeys where{time ? &*time : nullptr, "time", 0.0};
    check_step_count(where, spec.time, spec.is_explicit());
    if (!spec.is_explicit())
      check_cutbacks(where, spec.time);
    return;
  }
  const std::vector<Table> tables = root ? root->tables("step") : std::vector<Table>{};
  Real start = 0.0;
  for (std::size_t i = 0; i < spec.steps.size(); ++i) {
    const StepSpec& step = spec.steps[i];
    const TimeKeys where{i < tables.size() ? &tables[i] : nullptr, step.key, start};
    check_step_count(where, step.time, step.is_explicit());
    if (!step.is_explicit())
      check_cutbacks(where, step.time);
    start = step.time.end_time;
  }
}

/// The must points a load curve adds to a run over [0, end] (at most): its points, in every
/// period the run meets if the curve repeats.
Real curve_must_points(const CurveSpec& c, Real end) {
  const auto n = static_cast<Real>(c.points.size());
  if (c.extension == dofs::Extension::Constant || c.points.size() < 2)
    return n;
  const Real period = c.points.back().first - c.points.front().first;
  return (n - 1.0) * (std::ceil(std::max(end, 0.0) / period) + 1.0) + 1.0;
}

/// Refuses more than kMaxOutputTimes output times or must points (every one is a step).
void check_output_count(const Table* root, const CaseSpec& spec) {
  const auto node_of = [&](std::string_view key) {
    const auto t = root ? root->table("output") : std::nullopt;
    return t ? t->find(key) : nullptr;
  };
  const Real end = spec.time.end_time, interval = spec.output.interval;
  const Real periodic = interval > 0.0 ? end / interval : 0.0;
  if (periodic > kMaxOutputTimes)
    fail(node_of("interval"), fmt::format("output.interval = {}", interval),
         fmt::format("time.end_time / output.interval = {:.3g} output times, more than the {:.0e} "
                     "allowed (use a larger interval)",
                     periodic, kMaxOutputTimes));
  Real must = periodic + static_cast<Real>(spec.output.times.size());
  for (const auto& [name, curve] : spec.curves)
    must += curve_must_points(curve, end);
  if (must > kMaxOutputTimes)
    fail(nullptr, "output",
         fmt::format("{:.3g} times the steps must land on (output.interval, output.times and the "
                     "points of the load curves, in every period of a repeating one), more than "
                     "the {:.0e} allowed",
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

/// Cells per hex of the grid and nodes per grid node (about, with the mid-edge nodes: a hex
/// grid has 3 edges per node, 7 with the diagonals of Kuhn's split) of a box's cells.
std::pair<Real, Real> box_cell_factors(mesh::CellType cell) {
  switch (cell) {
  case mesh::CellType::Tet4:
    return {6.0, 1.0};
  case mesh::CellType::Tet10:
    return {6.0, 8.0};
  case mesh::CellType::Penta6:
    return {2.0, 1.0};
  case mesh::CellType::Hex20:
    return {1.0, 4.0};
  case mesh::CellType::Hex8:
    break;
  }
  return {1.0, 1.0};
}

ModelSize estimate_size(const CaseSpec& spec) {
  ModelSize m;
  const Real split = std::ldexp(1.0, spec.mesh_refinement); // [mesh] refine: divisions x 2^L
  for (const auto& b : spec.boxes) {
    const Vec3 n = split * Vec3(b.box.divisions[0], b.box.divisions[1], b.box.divisions[2]);
    const auto [cells_per_hex, nodes_per_node] = box_cell_factors(b.box.cell);
    m.nodes += nodes_per_node * (n[0] + 1.0) * (n[1] + 1.0) * (n[2] + 1.0);
    m.cells += cells_per_hex * n[0] * n[1] * n[2];
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
std::pair<std::string, const toml::node*> largest_box(const Table* root, const CaseSpec& spec) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < spec.boxes.size(); ++i) {
    const auto cells = [&](std::size_t k) {
      const auto& n = spec.boxes[k].box.divisions;
      return Real(n[0]) * Real(n[1]) * Real(n[2]);
    };
    if (cells(i) > cells(best))
      best = i;
  }
  const std::string path = element_path("mesh.box", best) + ".divisions";
  const auto mesh = root ? root->table("mesh") : std::nullopt;
  if (!mesh)
    return {path, nullptr};
  const std::vector<Table> boxes = mesh->tables("box");
  return {path, best < boxes.size() ? boxes[best].find("divisions") : nullptr};
}

} // namespace

void check_time_limits(const Table* root, const CaseSpec& spec) {
  check_steps_and_cutbacks(root, spec);
  check_output_count(root, spec);
}

void check_model_size(const Table* root, const CaseSpec& spec) {
  if (spec.boxes.empty())
    return;
  const ModelSize m = estimate_size(spec);
  const Real memory = physical_memory();
  const bool too_many = m.equations > INT_MAX;
  if (!too_many && (memory <= 0.0 || m.bytes <= memory))
    return;
  const auto [path, node] = largest_box(root, spec);
  const std::string size = fmt::format(
      "the boxes{} make a model of {:.4g} nodes and {:.4g} cells, about {:.4g} "
      "equations",
      spec.mesh_refinement > 0 ? fmt::format(" (refined {} times by mesh.refine and --refine-mesh)",
                                             spec.mesh_refinement)
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
