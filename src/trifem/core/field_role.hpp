// SPDX-License-Identifier: MIT
// What an unknown field is to the solvers, given by the model that adds it (never read from its
// name).
#pragma once

namespace trifem {

/// The role of a field of unknowns: block preconditioners split the system by it.
enum class FieldRole {
  displacement, ///< the solid's displacement (a primal unknown)
  flux,         ///< a relative flux: water, cations, anions (primal unknowns)
  potential,    ///< a per-cell Lagrange multiplier: pressure, electric potential
  multiplier,   ///< the multipliers of a contact interface
  rigid_motion  ///< translation and rotation of a rigid body (primal, like displacement)
};

} // namespace trifem
