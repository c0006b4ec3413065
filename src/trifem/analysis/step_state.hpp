// SPDX-License-Identifier: MIT
// What a run changes of its model's analysis steps: which step is active, the offsets of its
// relative conditions and the reactions it released. The model describes the steps; the
// analysis makes them active one after another.
#pragma once

#include "trifem/model/model.hpp"

#include <utility>
#include <vector>

namespace trifem::analysis {

/// The active step of a run (none before the first step begins, or in a case without steps).
struct StepState {
  int active = -1; ///< index into model.steps (-1: none)
  /// The offsets of the active step's relative conditions (per condition, per DOF; empty for
  /// the others): the values of their DOFs when the step began.
  std::vector<std::vector<Real>> offsets;
  /// The reactions the step released when it began (DOF, force at the step start), unloaded
  /// over its release_time.
  std::vector<std::pair<Index, Real>> released;
};

/// Makes step k of `model` the active one at its problem's current state: the problem's
/// conditions become the case's plus the step's (relative ones offset by the current values;
/// the equations are renumbered), and conditions of the previous step that step k does not
/// repeat are released: their reactions at the current state become loads that fall linearly
/// to zero over the step's release_time (none if 0). With `restored` (the state written to a
/// restart file), its offsets and released reactions are taken instead of computed.
void activate_step(model::Model& model, std::size_t k, StepState& state,
                   const StepState* restored = nullptr);

/// The state of a run at its start: the first step active, if the model has steps.
StepState start_steps(model::Model& model);

} // namespace trifem::analysis
