// SPDX-License-Identifier: MIT
#include "trifem/model/steps.hpp"

#include "trifem/core/error.hpp"
#include "trifem/model/conditions.hpp"
#include "trifem/physics/nodal_force_term.hpp"
#include "trifem/physics/step_window_term.hpp"

#include <algorithm>
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

/// The constrained DOFs of `conditions`.
std::unordered_set<Index> constrained(const std::vector<dofs::DirichletCondition>& conditions) {
  std::unordered_set<Index> out;
  for (const auto& c : conditions)
    out.insert(c.dofs.begin(), c.dofs.end());
  return out;
}

/// The reactions at the current state of the released DOFs (those of `before` not in
/// `after`), by DOF.
std::vector<std::pair<Index, Real>> released_reactions(const Model& model,
                                                       const std::unordered_set<Index>& before,
                                                       const std::unordered_set<Index>& after) {
  const Vector& R = model.problem->full_residual();
  std::vector<std::pair<Index, Real>> out;
  for (Index d : before)
    if (!after.contains(d) && R[d] != 0.0)
      out.emplace_back(d, R[d]);
  std::sort(out.begin(), out.end());
  return out;
}

/// The term applying the step's released reactions, falling linearly from their value at the
/// step start to zero after its release_time.
std::unique_ptr<physics::Term> release_term(const ModelStep& step) {
  const dofs::LoadCurve fall({{step.start_time, 1.0}, {step.start_time + step.release_time, 0.0}},
                             dofs::Interpolation::Linear, "release");
  std::vector<physics::NodalForce> forces;
  for (const auto& [dof, force] : step.released)
    forces.push_back({dof, force, fall});
  return std::make_unique<physics::NodalForceTerm>(std::move(forces));
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

void activate_step(Model& model, std::size_t k, const ModelStep* restored) {
  ModelStep& step = model.steps.at(k);
  const std::unordered_set<Index> before = constrained(model.problem->conditions());
  std::vector<dofs::DirichletCondition> conditions = model.case_conditions;
  const Vector& x = model.problem->local_state();
  step.offsets.assign(step.conditions.size(), {});
  for (std::size_t i = 0; i < step.conditions.size(); ++i) {
    dofs::DirichletCondition c = step.conditions[i];
    if (restored)
      step.offsets[i] = restored->offsets.at(i);
    else if (step.relative[i])
      for (Index d : c.dofs)
        step.offsets[i].push_back(x[d]);
    c.offsets = step.offsets[i];
    conditions.push_back(std::move(c));
  }
  const std::unordered_set<Index> after = constrained(conditions);
  step.released.clear();
  if (restored) {
    step.released = restored->released;
  } else if (step.release_time > 0.0) {
    // reactions of the current state (the last evaluation may be of a rejected attempt); after
    // a dynamic step full_residual() holds those of its commit, g + M a
    solver::Linearization lin;
    if (model.problem->dynamic() ||
        model.problem->linearize(lin, false) == solver::SolveStatus::Converged)
      step.released = released_reactions(model, before, after);
  }
  model.dofs.reset_constraints();
  dofs::constrain_all(conditions, model.dofs);
  model.dofs.finalize();
  model.problem->set_conditions(std::move(conditions));
  if (!step.released.empty())
    model.problem->add_term(release_term(step));
  model.active_step = static_cast<int>(k);
}

} // namespace trifem::model
