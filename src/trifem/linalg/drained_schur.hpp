// SPDX-License-Identifier: MIT
// The Schur approximation of the potentials that keeps the drained part whole
// (docs/theory/solvers.md §4): the approximation PETSc's "selfp" makes of the undrained part,
// and the exact Schur complement of the flux block with its friction mass lumped, in an
// augmented system that stays sparse.
#pragma once

#include "trifem/core/types.hpp"
#include "trifem/linalg/block_split.hpp"
#include "trifem/linalg/transport_cells.hpp"

namespace trifem::linalg {

/// The augmented system
///
///     [ Ŝ_u       T    ] [π]   [r]
///     [ −L Tᵀ  I + G D⁻¹ R ] [z] = [0]
///
/// whose Schur complement onto π is Ŝ = Ŝ_u + T (I + G D⁻¹ R)⁻¹ L Tᵀ, the potentials' Schur
/// complement of the Jacobian `A` with its potential rows negated (krylov_solver.cpp):
/// - Ŝ_u = −A_ππ + A_πu diag(A_uu)⁻¹ A_uπ, plus A_πf diag(A_ff)⁻¹ A_fπ where a row or a column
///   is a potential of no transport cell (contact multipliers), plus the fixed-stress term on
///   the cells' pressures filtered of the checkerboards: Σ over the mesh nodes a of
///   β̄_a / (8 n_a) on every pair of the n_a cells around a, β̄_a the mean over them of the
///   diagonal β_c of −A_ππ + A_πu diag(A_uu)⁻¹ A_uπ (≈ V_c / H_c, H_c the constrained modulus; this
///   is what the undrained part of a smooth pressure is, where the diagonal approximation
///   sees almost nothing);
/// - the flux block with its friction mass lumped, F_L = D + R G (D: per node and component
///   a fields × fields block, G: the cells' divergences, R = Gᵀ Γ + the flux rates: the flux
///   equations' derivatives by the divergences), whose Schur complement T G F_L⁻¹ Gᵀ Tᵀ equals
///   T (I + G D⁻¹ R)⁻¹ L Tᵀ with L = G D⁻¹ Gᵀ (Woodbury; no inverse of Γ, which is singular).
/// Rows and columns 0 … P−1 are the potentials in the order of `split.potential`, then three
/// unknowns z per cell (one per field; an absent field's row is the identity).
/// `fixed_stress` weighs the fixed-stress term (0: without it).
SparseMatrix drained_schur_system(const SparseMatrix& A, const BlockSplit& split,
                                  const TransportCells& cells, Real fixed_stress = 1.0);

/// The transport block (fluxes f, potentials π) of the Jacobian `A` with its potential rows
/// negated (K), after the displacement is eliminated with diag(A_uu), and with its flux block
/// lumped:
///
///     [ F_L    K_fπ ] [f]   [r_f]
///     [ K_πf   Ŝ_u  ] [π] = [r_π]
///
/// solved exactly through the augmented system of drained_schur_system: with s = G f,
/// f = D⁻¹ (r_f − R s − K_fπ π), and the system's unknowns are (π, z = −s) with right-hand
/// side (r_π, −G D⁻¹ r_f). Fluxes of no cell use 1 / diag(A_ff) for D⁻¹; the rows of potentials
/// of no cell (contact multipliers) eliminate the fluxes with D⁻¹ (as Ŝ_u does with diag(A_ff)).
/// Vectors of fluxes follow `split.flux`, of potentials `split.potential`.
class DrainedTransport {
public:
  DrainedTransport(const SparseMatrix& A, const BlockSplit& split, const TransportCells& cells,
                   Real fixed_stress = 1.0);

  /// The augmented system (drained_schur_system).
  const SparseMatrix& system() const { return system_; }
  /// Its right-hand side for the transport residual (r_f, r_π).
  Vector right_hand_side(const Vector& r_flux, const Vector& r_potential) const;
  /// The fluxes, from r_f and the augmented system's solution (π, z).
  Vector fluxes(const Vector& r_flux, const Vector& solution) const;

private:
  SparseMatrix system_;
  SparseMatrix flux_inverse_;    ///< D⁻¹ (fluxes × fluxes)
  SparseMatrix divergence_;      ///< G (3 per cell × fluxes)
  SparseMatrix divergence_rate_; ///< R (fluxes × 3 per cell)
  SparseMatrix flux_potential_;  ///< K_fπ = A_fπ
  SparseMatrix multiplier_flux_; ///< K_πf on the rows of potentials of no cell
};

} // namespace trifem::linalg
