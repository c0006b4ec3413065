// SPDX-License-Identifier: MIT
// Support check of a quasi-static model: a body whose translation in some direction nothing
// holds (no fixed or prescribed displacement, no contact, no rigid body) has a singular
// stiffness, which a direct solver may not even notice; it is reported before the run.
#pragma once

#include "trifem/model/model.hpp"

namespace trifem::model {

/// InputError naming the first body (connected set of cells) and the translation component
/// that no fixed or prescribed displacement, contact surface or rigid body holds.
void check_support(const io::CaseSpec& spec, const Model& model);

} // namespace trifem::model
