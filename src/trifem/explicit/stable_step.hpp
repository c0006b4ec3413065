// SPDX-License-Identifier: MIT
// Critical time step of the explicit scheme (docs/theory/explicit.md §5): the largest frequency
// ω_iso of M⁻¹K restricted to isochoric modes, where K is the tangent of the explicitly
// integrated forces: the internal force of W and, since H is held at t_n, the multiplier force
// H Λ at fixed Λ.
#pragma once

#include "trifem/explicit/cell_kernel.hpp"

namespace trifem::explicit_dynamics {

/// Result of a frequency estimate.
struct FrequencyEstimate {
  Real omega = 0.0;   ///< ω_max [1/s]
  int iterations = 0; ///< power iterations done (0 for the element bound)
  bool converged = false;
};

/// Power iteration on the M-self-adjoint operator P M⁻¹ K P at displacement U, with K the
/// element-by-element tangent K_W + K_Λ (never assembled; K_Λ = multiplier_stiffness with the
/// cell multipliers `lambda`, left out if `lambda` is empty), M the lumped mass (fixed DOFs
/// removed) and, if `project` is true, P = I − M⁻¹H (HᵀM⁻¹H + δ)⁻¹Hᵀ the M-orthogonal projection on
/// ker Hᵀ (volume-preserving motions; δ = 1e-10 diag regularises a rank-deficient H).
/// ω² is the Rayleigh quotient vᵀKv / vᵀMv of the last iterate: a lower bound that converges
/// from below, hence the safety factor. Stops when ω² changes by < tolerance (relative).
FrequencyEstimate power_iteration_omega(const ExplicitView& model, Constraint constraint,
                                        const Vector& U, const Vector& lambda, bool project,
                                        int max_iterations, Real tolerance);

/// Upper bound ω_max ≤ max_e sqrt(λ_max(M_e⁻¹ K_e)), K_e = K_W,e + K_Λ,e (Irons' element
/// eigenvalue theorem for the row-sum lumped mass, which holds for indefinite K_e too; fixed
/// DOFs only lower ω). Includes the volumetric modes of W, so it is sharp only for laws whose
/// W is soft in volume (ν = 0 neo-Hookean). `lambda` empty: K_Λ left out.
FrequencyEstimate element_bound_omega(const ExplicitView& model, Constraint constraint,
                                      const Vector& U, const Vector& lambda);

} // namespace trifem::explicit_dynamics
