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

/// Fixed and prescribed conditions of the case (field DOFs on node sets).
std::vector<dofs::DirichletCondition> boundary_conditions(const io::CaseSpec& spec,
                                                          const Model& model);

/// Rotated frames for [[boundary.impermeable]] surfaces of any orientation; appends the
/// condition fixing their normal flux components to `conditions`. InputError if a rotated DOF
/// is also used by an axis-aligned condition.
dofs::NodalFrames impermeable_surfaces(const io::CaseSpec& spec, const Model& model,
                                       std::vector<dofs::DirichletCondition>& conditions);

/// Pressure and traction terms of the case.
std::vector<std::unique_ptr<physics::Term>> load_terms(const io::CaseSpec& spec,
                                                       const Model& model);

/// Reaction sets and probes of the case.
void add_outputs(const io::CaseSpec& spec, Model& model);

} // namespace trifem::model
