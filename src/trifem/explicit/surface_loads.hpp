// SPDX-License-Identifier: MIT
// Nodal external forces F_S of the surface loads (A2.12) at a given time and configuration.
#pragma once

#include "trifem/explicit/explicit_model.hpp"

namespace trifem::explicit_dynamics {

/// f = Σ_loads f_load(t, U) (size num_dofs, overwritten):
/// follower pressure f_a = −p(t) ∫ N_a (x,ξ × x,η) dξ dη on the current facet (2x2 Gauss,
/// exact for the bilinear facet), dead traction f_a = t(t) ∫ N_a dA [N]. Fixed DOFs included
/// (their inverse mass is zero, so they do not move).
void external_force(const ExplicitModel& model, const Vector& U, Real time, Vector& f);

/// True if any load depends on the configuration (a follower pressure).
bool has_follower_loads(const ExplicitModel& model);

} // namespace trifem::explicit_dynamics
