// SPDX-License-Identifier: MIT
// The equations of the mixed system grouped by role, for block preconditioners
// (docs/theory/solvers.md).
#pragma once

#include "trifem/core/field_role.hpp"
#include "trifem/core/types.hpp"

#include <vector>

namespace trifem::linalg {

/// Equation indices (ascending) of the primal unknowns, split into displacement and fluxes, and
/// of the potentials (the cells' Lagrange multipliers: pressure, electric potential).
struct BlockSplit {
  /// displacement, with rigid bodies and the contact multipliers (the primal block's LU factorizes
  /// their saddle point; the potentials' Schur approximations leave them out) and equations of no
  /// field
  std::vector<Index> displacement;
  std::vector<Index> flux;      ///< water, cation and anion fluxes
  std::vector<Index> potential; ///< pressure, electric potential

  /// From the field of each equation (an index into `roles`).
  static BlockSplit from_fields(const std::vector<int>& equation_fields,
                                const std::vector<FieldRole>& roles);
  /// Displacement and flux equations together, ascending.
  std::vector<Index> primal() const;
  bool empty() const { return displacement.empty() && flux.empty() && potential.empty(); }
};

} // namespace trifem::linalg
