// SPDX-License-Identifier: MIT
#include "trifem/analysis/step_state.hpp"

#include "trifem/physics/nodal_force_term.hpp"

#include <algorithm>
#include <unordered_set>

namespace trifem::analysis {
namespace {

/// The constrained DOFs of `conditions`.
std::unordered_set<Index> constrained(const std::vector<dofs::DirichletCondition>& conditions) {
  std::unordered_set<Index> out;
  for (const auto& c : conditions)
    out.insert(c.dofs.begin(), c.dofs.end());
  return out;
}

/// The reactions at the current state of the released DOFs (those of `before` not in
/// `after`), by DOF.
std::vector<std::pair<Index, Real>> released_reactions(const model::Model& model,
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

/// The term applying the `released` reactions, falling linearly from their value at the start
/// of `step` to zero after its release_time.
std::unique_ptr<physics::Term> release_term(const model::ModelStep& step,
                                            const std::vector<std::pair<Index, Real>>& released) {
  const dofs::LoadCurve fall({{step.start_time, 1.0}, {step.start_time + step.release_time, 0.0}},
                             dofs::Interpolation::Linear, "release");
  std::vector<physics::NodalForce> forces;
  for (const auto& [dof, force] : released)
    forces.push_back({dof, force, fall});
  return std::make_unique<physics::NodalForceTerm>(std::move(forces));
}

} // namespace

void activate_step(model::Model& model, std::size_t k, StepState& state,
                   const StepState* restored) {
  const model::ModelStep& step = model.steps.at(k);
  const std::unordered_set<Index> before = constrained(model.problem->conditions());
  std::vector<dofs::DirichletCondition> conditions = model.case_conditions;
  const Vector& x = model.problem->local_state();
  state.offsets.assign(step.conditions.size(), {});
  for (std::size_t i = 0; i < step.conditions.size(); ++i) {
    dofs::DirichletCondition c = step.conditions[i];
    if (restored)
      state.offsets[i] = restored->offsets.at(i);
    else if (step.relative[i])
      for (Index d : c.dofs)
        state.offsets[i].push_back(x[d]);
    c.offsets = state.offsets[i];
    conditions.push_back(std::move(c));
  }
  const std::unordered_set<Index> after = constrained(conditions);
  state.released.clear();
  if (restored) {
    state.released = restored->released;
  } else if (step.release_time > 0.0) {
    // reactions of the current state (the last evaluation may be of a rejected attempt); after
    // a dynamic step full_residual() holds those of its commit, g + M a
    solver::Linearization lin;
    if (model.problem->dynamic() ||
        model.problem->linearize(lin, false) == solver::SolveStatus::Converged)
      state.released = released_reactions(model, before, after);
  }
  model.problem->set_conditions(std::move(conditions));
  if (!state.released.empty())
    model.problem->add_term(release_term(step, state.released));
  state.active = static_cast<int>(k);
}

StepState start_steps(model::Model& model) {
  StepState state;
  if (!model.steps.empty())
    activate_step(model, 0, state);
  return state;
}

} // namespace trifem::analysis
