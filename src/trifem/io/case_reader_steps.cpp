// SPDX-License-Identifier: MIT
// Case reader, part 5: [[step]] tables, each with its analysis, its time control and the
// boundary conditions and loads that act during it only. A quasi-static case may end with a
// dynamic-explicit step (a mixed run) on a solid model.
#include "trifem/io/toml_table.hpp"

#include <algorithm>

namespace trifem::io::detail {
namespace {

constexpr std::string_view kExplicitName = "dynamic-explicit";

/// The analysis types a step may name.
const Options<AnalysisType>& analysis_options() {
  static const Options<AnalysisType> types = {{"quasi-static", AnalysisType::QuasiStatic},
                                              {"dynamic", AnalysisType::Dynamic},
                                              {"dynamic-explicit", AnalysisType::DynamicExplicit}};
  return types;
}

/// The conditions and loads of the step table `t`, read as the case's [boundary] and [loads]
/// are (the paths name the step, e.g. step[2].boundary.prescribed[1]).
void read_step_conditions(const Table& t, const CaseSpec& spec, StepSpec& step) {
  CaseSpec conditions; // the materials and curves decide which fields and curves exist
  conditions.materials = spec.materials;
  conditions.curves = spec.curves;
  if (const auto boundary = t.table("boundary")) {
    boundary->allow({"fixed", "bonded", "impermeable", "prescribed"});
    for (const Table& i : boundary->tables("impermeable"))
      if (i.find("surface"))
        fail(i.find("surface"), i.path("surface"),
             "an impermeable surface of any orientation acts in every step: give it in "
             "[[boundary.impermeable]] (a step may use 'set' and 'normal')");
  }
  read_boundary(t, conditions);
  read_loads(t, conditions);
  step.fixed = std::move(conditions.fixed);
  step.prescribed = std::move(conditions.prescribed);
  step.pressures = std::move(conditions.pressures);
  step.tractions = std::move(conditions.tractions);
}

/// The time keys of a dynamic-explicit step: end_time or duration, and the optional dt (without
/// it the stability estimate); the adaptive keys of quasi-static steps are errors.
void read_explicit_step_time(const Table& t, TimeSpec& s, Real start) {
  for (const std::string_view key : {"dt_min", "dt_max", "target_iterations", "growth", "cutback"})
    if (const toml::node* n = t.find(key))
      fail(n, t.path(key),
           "applies to quasi-static steps only; a dynamic-explicit step steps with dt or the "
           "stability estimate (see [explicit])");
  if (const toml::node* n = t.find("release_time"))
    fail(n, t.path("release_time"),
         "not supported in dynamic-explicit steps: the conditions of the previous step that the "
         "step does not repeat are released at once");
  t.allow({"end_time", "duration", "dt"}, {"name", "analysis", "boundary", "loads"});
  if (t.find("duration") && t.find("end_time"))
    fail(t.find("duration"), t.path("duration"),
         fmt::format("give either end_time or duration, not both (end_time is {})",
                     t.path("end_time")));
  if (t.find("duration"))
    s.end_time = start + t.number("duration",
                                  {.range = {kMinEndTime, kUnbounded, false, false}, .unit = "s"});
  else
    s.end_time =
        t.number("end_time", {.range = {start + kMinEndTime, kUnbounded, false, false},
                              .unit = "s",
                              .hint = fmt::format("after the previous step's end, {} s", start)});
  s.dt = t.number("dt", {.range = {0.0, s.end_time - start, true, false},
                         .fallback = 0.0,
                         .unit = "s",
                         .hint = "at most the step's length; omit it to use the stability "
                                 "estimate"});
}

/// Throws "step[i].analysis = 'dynamic-explicit': <why>".
[[noreturn]] void explicit_step_error(const Table& t, std::string_view why) {
  fail(t.find("analysis"), fmt::format("{} = '{}'", t.path("analysis"), kExplicitName), why);
}

/// What a dynamic-explicit step needs of the whole case: solid materials with a density, no
/// contact or conditions it cannot apply, and a step before it.
void check_explicit_step(const Table& t, const CaseSpec& spec,
                         const std::vector<StepSpec>& earlier) {
  if (earlier.empty())
    explicit_step_error(t, "a dynamic-explicit step follows at least one other step (for "
                           "a run that is dynamic-explicit from t = 0 use [analysis] type = "
                           "\"dynamic-explicit\" without [[step]])");
  for (const auto& [name, m] : spec.materials) {
    if (m.is_mixture())
      explicit_step_error(t, fmt::format("material '{}' is {}: dynamic-explicit steps need solid "
                                         "models (solid laws only)",
                                         name, m.type));
    if (!m.density)
      explicit_step_error(t, fmt::format("material '{}' has no density (materials.{}.density, "
                                         "e.g. 1e-9 t/mm^3 for water-like tissue)",
                                         name, name));
    if (m.axes)
      explicit_step_error(t, fmt::format("material '{}' has material axes (materials.{}.axes), "
                                         "which dynamic-explicit analyses do not support yet",
                                         name, name));
  }
  if (!spec.contacts.empty())
    explicit_step_error(t, "the case has [[contact]] pairs (contact needs the implicit solver)");
  if (!spec.connectors.empty())
    explicit_step_error(t, "the case has [[connector]] tables (joints need the implicit solver)");
  if (!spec.constraints.empty())
    explicit_step_error(t, "the case has [[constraint]] tables (constraints are imposed with "
                           "Lagrange multipliers, which need the implicit solver)");
  if (!spec.impermeable_surfaces.empty() || !spec.baths.empty())
    explicit_step_error(t, "the case has impermeable surfaces or baths (no fluid or ion fields "
                           "in dynamic-explicit steps)");
  if (spec.explicit_dynamics.stable_step == StableStepEstimate::None && !t.find("dt"))
    explicit_step_error(t, "explicit.stable_step = 'none' needs the step's dt");
}

StepSpec read_step(const Table& t, const CaseSpec& spec, Real start,
                   const std::vector<StepSpec>& earlier) {
  StepSpec step;
  step.key = t.path();
  step.name =
      t.find("name") ? read_identifier(t, "name", true) : fmt::format("step{}", earlier.size() + 1);
  for (std::size_t i = 0; i < earlier.size(); ++i)
    if (earlier[i].name == step.name)
      fail(t.find("name"), fmt::format("{} = '{}'", t.path("name"), step.name),
           fmt::format("duplicate step name (already used by {})", earlier[i].key));
  step.analysis =
      t.choice("analysis", analysis_options(), std::optional(spec.analysis.type), "analysis type");
  if (step.is_explicit()) {
    check_explicit_step(t, spec, earlier);
    read_explicit_step_time(t, step.time, start);
  } else {
    read_time_keys(t, step.time, start, true);
    step.release_time =
        t.number("release_time", {.range = Range::non_negative(), .fallback = 0.0, .unit = "s"});
    step.steady = t.get<bool>("steady").value_or(false);
    if (step.steady && std::none_of(spec.materials.begin(), spec.materials.end(),
                                    [](const auto& m) { return m.second.is_mixture(); }))
      fail(t.find("steady"), t.path("steady"),
           "a steady-state step needs a biphasic or triphasic material (a solid model is "
           "quasi-static already)");
  }
  read_step_conditions(t, spec, step);
  return step;
}

} // namespace

bool declares_explicit_step(const Table& root) {
  for (const Table& t : root.tables("step"))
    if (const toml::node* n = t.find("analysis"); n && n->value<std::string>() == kExplicitName)
      return true;
  return false;
}

void read_steps(const Table& root, CaseSpec& spec) {
  if (!root.find("step"))
    return;
  if (spec.is_explicit())
    fail(root.find("step"), "step",
         "[[step]] tables are for quasi-static analyses (a dynamic-explicit case has one [time]; "
         "a quasi-static case may end with a step of analysis = \"dynamic-explicit\")");
  const std::vector<Table> tables = root.tables("step");
  if (tables.empty())
    fail(root.find("step"), "step",
         "expected one [[step]] table per analysis step, got an empty array (remove the key for "
         "a run of one step with [time])");
  Real start = 0.0;
  for (const Table& t : tables) {
    spec.steps.push_back(read_step(t, spec, start, spec.steps));
    start = spec.steps.back().time.end_time;
  }
  spec.time = spec.steps.front().time; // step control of the first step,
  spec.time.end_time = start;          // the span of the whole run
}

} // namespace trifem::io::detail
