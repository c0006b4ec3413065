// SPDX-License-Identifier: MIT
// Case -> contact pairs of a model (helpers of build_model).
#pragma once

#include "trifem/model/model.hpp"

namespace trifem::model {

/// Adds one contact-pressure field per [[contact]] pair (one entity per slave-surface node).
void add_contact_fields(const io::CaseSpec& spec, Model& model);

/// The contact terms of the case (fields must exist); registers them in model.contacts.
/// Checks each pair in the reference configuration: InputError naming `contact[i]` and the
/// surfaces if most projected slave nodes have a normal on the same side as the master normal
/// (wrong faces picked) or if slave nodes penetrate the master surface by more than the pair's
/// penetration tolerance; a warning if no slave node projects onto the master surface.
std::vector<std::unique_ptr<physics::Term>> contact_terms(const io::CaseSpec& spec, Model& model);

} // namespace trifem::model
