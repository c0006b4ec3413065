// SPDX-License-Identifier: MIT
// Analysis steps ([[step]]): the conditions and loads of each step, and the change of the
// constraints from one step to the next (helpers of build_model and of the analyses).
#pragma once

#include "trifem/model/model.hpp"

namespace trifem::model {

/// Fills model.steps from the case's [[step]] tables and returns their loads, each active
/// during its step only. model.case_conditions and the rigid-body ties must be set: InputError
/// (naming the step's key) if a step constrains a DOF that a condition of the case, a rigid body
/// or an impermeable surface of any orientation already holds.
std::vector<std::unique_ptr<physics::Term>> step_terms(const io::CaseSpec& spec, Model& model);

/// Makes step k the active one at the problem's current state: the constraints become the
/// case's plus the step's (relative ones offset by the current values), the DOF map and the
/// problem are renumbered, and conditions of the previous step that step k does not repeat are
/// released: their reactions at the current state become loads that fall linearly to zero over
/// the step's release_time (none if 0). With `restored` (the step as written to a restart
/// file), its offsets and released reactions are taken instead of computed from the state.
void activate_step(Model& model, std::size_t k, const ModelStep* restored = nullptr);

} // namespace trifem::model
