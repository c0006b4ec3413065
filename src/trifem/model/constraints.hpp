// SPDX-License-Identifier: MIT
// [[constraint]]: symmetry planes, fixed normal displacements, linear constraints and rigid
// walls (helpers of build_model; docs/theory/constraints.md).
#pragma once

#include "trifem/model/model.hpp"

namespace trifem::model {

/// Builds every [[constraint]] of `spec`: must run after the case's fixed and prescribed
/// conditions are in `conditions` and before the rigid bodies are built (it may add to
/// `conditions`). Equations n·u_a = 0 whose normal is a coordinate axis become fixed
/// components (added to `conditions`); the others, and the linear constraints, are equations
/// with a multiplier (field model.constraint_forces). An equation at a node that repeats the
/// directions already held there (fixed components, earlier equations) is dropped, with a log
/// line. Each rigid wall has its own multiplier field (model.walls). InputError (naming
/// `constraint[i]`) for a missing surface, a curved symmetry plane, a node out of range or
/// carried by a rigid body, or a linear constraint all of whose components are fixed.
std::vector<std::unique_ptr<physics::Term>>
constraint_terms(const io::CaseSpec& spec, Model& model,
                 std::vector<dofs::DirichletCondition>& conditions);

} // namespace trifem::model
