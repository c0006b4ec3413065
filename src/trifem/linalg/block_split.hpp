// SPDX-License-Identifier: MIT
// The equations of the mixed system grouped by role, for block preconditioners
// (docs/theory/solvers.md).
#pragma once

#include "trifem/core/types.hpp"

#include <string>
#include <vector>

namespace trifem::linalg {

/// Equation indices (ascending) of the primal unknowns, split into displacement and fluxes, and
/// of the potentials (Lagrange multipliers: pressure, electric potential, contact multipliers).
struct BlockSplit {
  std::vector<Index> displacement; ///< displacement (and every field that is not named below)
  std::vector<Index> flux;         ///< fluid_flux, cation_flux, anion_flux
  std::vector<Index> potential;    ///< pressure, electric_potential, contact_multipliers_*

  /// From the field of each equation (an index into `field_names`).
  static BlockSplit from_fields(const std::vector<int>& equation_fields,
                                const std::vector<std::string>& field_names);
  /// Displacement and flux equations together, ascending.
  std::vector<Index> primal() const;
  bool empty() const { return displacement.empty() && flux.empty() && potential.empty(); }
};

} // namespace trifem::linalg
