// SPDX-License-Identifier: MIT
// Analysis steps ([[step]]): the conditions and loads of each step (a helper of build_model;
// the analysis makes the steps active, analysis/step_state.hpp).
#pragma once

#include "trifem/model/model.hpp"

namespace trifem::model {

/// Fills model.steps from the case's [[step]] tables and returns their loads, each active
/// during its step only. model.case_conditions and the rigid-body ties must be set: InputError
/// (naming the step's key) if a step constrains a DOF that a condition of the case, a rigid body
/// or an impermeable surface of any orientation already holds.
std::vector<std::unique_ptr<physics::Term>> step_terms(const io::CaseSpec& spec, Model& model);

} // namespace trifem::model
