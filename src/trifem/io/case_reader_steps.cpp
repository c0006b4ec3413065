// SPDX-License-Identifier: MIT
// Case reader, part 5: [[step]] tables, each with its time control and the boundary conditions
// and loads that act during it only.
#include "trifem/io/toml_table.hpp"

namespace trifem::io::detail {
namespace {

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
  read_time_keys(t, step.time, start, true);
  step.release_time =
      t.number("release_time", {.range = Range::non_negative(), .fallback = 0.0, .unit = "s"});
  read_step_conditions(t, spec, step);
  return step;
}

} // namespace

void read_steps(const Table& root, CaseSpec& spec) {
  if (!root.find("step"))
    return;
  if (spec.is_explicit())
    fail(root.find("step"), "step",
         "[[step]] tables are for quasi-static analyses (a dynamic-explicit case has one [time])");
  Real start = 0.0;
  for (const Table& t : root.tables("step")) {
    spec.steps.push_back(read_step(t, spec, start, spec.steps));
    start = spec.steps.back().time.end_time;
  }
  spec.time = spec.steps.front().time; // step control of the first step,
  spec.time.end_time = start;          // the span of the whole run
}

} // namespace trifem::io::detail
