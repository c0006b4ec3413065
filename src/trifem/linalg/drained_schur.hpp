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
///     [ Ŝ_u      T    ] [π]   [r]
///     [ −L Tᵀ  I + LΓ ] [z] = [0]
///
/// whose Schur complement onto π is Ŝ = Ŝ_u + T (I + LΓ)⁻¹ L Tᵀ, the potentials' Schur
/// complement of the Jacobian `A` with its potential rows negated (krylov_solver.cpp):
/// - Ŝ_u = −A_ππ + A_πu diag(A_uu)⁻¹ A_uπ, plus A_πf diag(A_ff)⁻¹ A_fπ where a row or a column
///   is a potential of no transport cell (contact multipliers);
/// - the flux block with its friction mass lumped, F_L = D + Gᵀ Γ G (D: per node and component
///   a fields × fields block, G: the cells' divergences, Γ: their gamma), whose Schur complement
///   T G F_L⁻¹ Gᵀ Tᵀ equals T (I + LΓ)⁻¹ L Tᵀ with L = G D⁻¹ Gᵀ (Woodbury; no inverse of Γ).
/// Rows and columns 0 … P−1 are the potentials in the order of `split.potential`, then three
/// unknowns z per cell (one per field; an absent field's row is the identity).
SparseMatrix drained_schur_system(const SparseMatrix& A, const BlockSplit& split,
                                  const TransportCells& cells);

} // namespace trifem::linalg
