// SPDX-License-Identifier: MIT
// What the Schur approximation of the drained (Darcy and ion-diffusion) part needs of each
// mixture cell: the parts of the flux block that the assembled matrix mixes
// (docs/theory/solvers.md §4).
#pragma once

#include "trifem/core/types.hpp"

#include <Eigen/Core>

#include <array>
#include <vector>

namespace trifem::linalg {

/// One hex8 mixture cell in the scaled equations of the Jacobian. Its flux block is
///
///     F_e = m_ab ⊗ friction ⊗ I + (Gᵀ γ + flux_rate) G
///
/// over the fields (fluid, cation, anion flux), the nodes and the components, m_ab the cell's
/// mass matrix and G its divergences (Σ_a g_a·w_a, Σ_a g_a·ĵ+_a, Σ_a g_a·ĵ−_a with the area
/// vectors g_a = ∫ ∇N_a dv), and its potential rows couple to the fluxes through them:
/// rows (p, η) = coupling · G.
struct TransportCell {
  std::array<Index, 2> potential{-1, -1}; ///< equations of p and η (−1: none)
  Eigen::Matrix<Real, 2, 3> coupling;     ///< rows (p, η), columns (w, ĵ+, ĵ−)
  Eigen::Matrix3d friction;               ///< per unit mass (rows and columns: fields)
  Eigen::Matrix3d gamma;                  ///< of the divergences (rows and columns: fields)
  /// Row 3a + k (local components, as flux_equation), column 3 field + field': the flux
  /// equation's derivative by the divergence of field' beyond its divergence coefficient times
  /// gamma (proportional to the fluxes)
  Eigen::Matrix<Real, 24, 9> flux_rate = Eigen::Matrix<Real, 24, 9>::Zero();
  std::array<Index, 8> node{};           ///< mesh nodes of the flux fields
  Eigen::Matrix<Real, 8, 1> lumped_mass; ///< Σ_b m_ab
  /// Row 3a + k (node a, component k of the equations: local in a rotated nodal frame),
  /// column field: the equation (−1: prescribed or absent) and its coefficient in G (g_a[k]
  /// in global components).
  Eigen::Matrix<Index, 24, 3> flux_equation;
  Eigen::Matrix<Real, 24, 3> divergence;
};

/// The mixture cells of a model (empty when the model has none, or when they cannot serve:
/// fluxes in rotated nodal frames, several processes).
using TransportCells = std::vector<TransportCell>;

} // namespace trifem::linalg
