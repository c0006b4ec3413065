// SPDX-License-Identifier: MIT
// Case -> boundary conditions, surface loads and outputs of a model (helpers of build_model).
#pragma once

#include "trifem/core/error.hpp"
#include "trifem/model/model.hpp"

namespace trifem::model {

/// Runs f, prefixing any InputError with the case key it concerns.
template <class F>
decltype(auto) with_context(const std::string& key, F&& f) {
  try {
    return f();
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: {}", key, e.what()));
  }
}

/// The load curve `name` of the case (constant 1 if empty).
dofs::LoadCurve make_curve(const io::CaseSpec& spec, const std::string& name);

/// Conditions with the case key of each and whether it is relative to the state at the start
/// of its step.
struct ConditionSet {
  std::vector<dofs::DirichletCondition> conditions;
  std::vector<std::string> keys;
  std::vector<bool> relative;
};

/// The conditions of `fixed` and `prescribed` (field DOFs on node sets); `prescribed_key` names
/// the array of the prescribed entries, e.g. "step[2].boundary.prescribed". InputError if a
/// prescribed DOF gets two values.
ConditionSet conditions_of(const io::CaseSpec& spec, const std::vector<io::FixedSpec>& fixed,
                           const std::vector<io::PrescribedSpec>& prescribed,
                           const std::string& prescribed_key, const Model& model);

/// Fixed and prescribed conditions of the case (field DOFs on node sets).
std::vector<dofs::DirichletCondition> boundary_conditions(const io::CaseSpec& spec,
                                                          const Model& model);

/// Rotated frames for [[boundary.impermeable]] surfaces of any orientation; appends the
/// condition fixing their normal flux components to `conditions`. InputError if a rotated DOF
/// is also used by an axis-aligned condition.
dofs::NodalFrames impermeable_surfaces(const io::CaseSpec& spec, const Model& model,
                                       std::vector<dofs::DirichletCondition>& conditions);

/// Pressure and traction terms of `pressures` and `tractions`; `prefix` precedes the keys in
/// messages, e.g. "step[2]." ("" for the case's own).
std::vector<std::unique_ptr<physics::Term>>
surface_load_terms(const io::CaseSpec& spec, const std::vector<io::PressureSpec>& pressures,
                   const std::vector<io::TractionSpec>& tractions, const std::string& prefix,
                   const Model& model);

/// Pressure, traction, body force and bath terms of the case.
std::vector<std::unique_ptr<physics::Term>> load_terms(const io::CaseSpec& spec,
                                                       const Model& model);

/// Reaction sets and probes of the case.
void add_outputs(const io::CaseSpec& spec, Model& model);

} // namespace trifem::model
