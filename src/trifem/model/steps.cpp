// SPDX-License-Identifier: MIT
#include "trifem/model/steps.hpp"

#include "trifem/core/error.hpp"
#include "trifem/model/conditions.hpp"
#include "trifem/physics/step_window_term.hpp"

#include <unordered_set>

namespace trifem::model {
namespace {

/// DOFs a step may not constrain: those of the case's conditions (including the rotated flux
/// DOFs of impermeable surfaces and unused DOFs) and those tied to a rigid body.
std::unordered_set<Index> held_dofs(const Model& model) {
  std::unordered_set<Index> held;
  for (const auto& c : model.case_conditions)
    held.insert(c.dofs.begin(), c.dofs.end());
  for (Index d = 0; d < model.dofs.num_dofs() && model.dofs.has_ties(); ++d)
    if (const Index lead = model.dofs.leader(d); lead != d) {
      held.insert(d);
      held.insert(lead);
    }
  for (Index d = 0; d < model.dofs.num_dofs(); ++d)
    if (model.dofs.is_dependent(d)) // a node carried by a rotating body
      held.insert(d);
  return held;
}

void check_free_for_steps(const Model& model, const ModelStep& step,
                          const std::unordered_set<Index>& held) {
  for (std::size_t i = 0; i < step.conditions.size(); ++i)
    for (Index d : step.conditions[i].dofs) {
      if (!held.contains(d))
        continue;
      const dofs::FieldInfo& field = model.dofs.field(model.dofs.field_of(d));
      const Index node = (d - field.offset) / field.components;
      const Vec3& x = model.mesh.node(node);
      throw InputError(fmt::format(
          "{}: {} component {} of the node at ({:.6g}, {:.6g}, {:.6g}) is already held in every "
          "step (by a [boundary] condition, an impermeable surface or a rigid body); a step may "
          "only constrain degrees of freedom that the case leaves free",
          step.keys[i], field.name, "xyz"[(d - field.offset) % field.components], x.x(), x.y(),
          x.z()));
    }
}

} // namespace

std::vector<std::unique_ptr<physics::Term>> step_terms(const io::CaseSpec& spec, Model& model) {
  std::vector<std::unique_ptr<physics::Term>> terms;
  Real start = 0.0;
  for (const io::StepSpec& s : spec.steps) {
    ConditionSet set =
        conditions_of(spec, s.fixed, s.prescribed, s.key + ".boundary.prescribed", model);
    model.steps.push_back({s.name, s.key, start, s.time.end_time, std::move(set.conditions),
                           std::move(set.keys), std::move(set.relative), s.release_time});
    for (auto& t : surface_load_terms(spec, s.pressures, s.tractions, s.key + ".", model))
      terms.push_back(
          std::make_unique<physics::StepWindowTerm>(std::move(t), start, s.time.end_time));
    start = s.time.end_time;
  }
  const std::unordered_set<Index> held = held_dofs(model);
  for (const ModelStep& step : model.steps)
    check_free_for_steps(model, step, held);
  return terms;
}

} // namespace trifem::model
