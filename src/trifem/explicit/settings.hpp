// SPDX-License-Identifier: MIT
// Settings of the explicit solver with a P0 Lagrange-multiplier pressure (docs/theory/explicit.md).
#pragma once

#include "trifem/core/types.hpp"
#include "trifem/io/case_spec.hpp"

#include <limits>
#include <optional>
#include <string>

/// Explicit (central-difference) dynamics of nearly incompressible solids. The namespace is not
/// called `explicit` because that is a C++ keyword.
namespace trifem::explicit_dynamics {

/// Which forces the per-step iteration re-evaluates (docs/theory/explicit.md §3, §5).
enum class Reading {
  /// Q_V, H and follower loads at the iterate U^(k) ("all forces at t+Δt", literal A2.15):
  /// first order, dissipative, |z| = 1/sqrt(1 + ω²Δt²); the iteration converges for Δt < 1/ω_iso.
  A,
  /// Q_V and loads at t_n (central difference for the deviatoric part), only H and Λ iterated:
  /// second order, non-dissipative, stable for Δt < 2/ω_iso.
  B
};

/// The volume constraint Ψ(C) of the multiplier term λ Ψ(C).
enum class Constraint {
  JMinusOne, ///< Ψ = J − 1, D_C = 2 ∂Ψ/∂C = J C⁻¹ (σ = λ I: λ is minus the pressure)
  LogJ       ///< Ψ = ln J,  D_C = C⁻¹ (τ = λ I)
};

/// How the critical time step is estimated.
enum class StableStepMethod {
  PowerIteration, ///< ω_iso by power iteration on M⁻¹K projected onto isochoric modes
  ElementBound, ///< max over cells of the element eigenvalue of M_e⁻¹K_e (an upper bound of ω)
  None          ///< trust the requested step (benchmarks)
};

/// All numerical options of one explicit run. Units: s, MPa, mm.
struct ExplicitSettings {
  Reading reading = Reading::B;
  Constraint constraint = Constraint::JMinusOne;
  /// false: no multiplier at all (pure-displacement Q1, the law carries the bulk stiffness).
  bool multiplier = true;
  /// Penalty α of (1/α) Γ Λ = Ψ [MPa]; +inf enforces Ψ = 0 exactly.
  Real penalty = std::numeric_limits<Real>::infinity();
  /// Mass-proportional damping coefficient c of C = c M [1/s]; 0 = undamped.
  Real damping = 0.0;
  /// Requested step Δt [s]; 0 = the stability estimate. A larger request is reduced.
  Real time_step = 0.0;
  /// Fraction of the critical step used; default 0.8 (reading B, of 2/ω), 0.5 (A, of 1/ω).
  std::optional<Real> safety_factor;
  /// Reading B: steps one numeric factorization of A_n = Γ/α + h² H_nᵀM⁻¹H_n may serve
  /// (1 = refactorize every step). Reuse turns the Λ iteration into a modified Newton
  /// iteration with the same fixed point; worthwhile on large meshes where the factorization
  /// costs more than a cell loop. Refreshed early when h² changes or iterations grow by > 3.
  int max_factorization_age = 1;
  StableStepMethod stable_step = StableStepMethod::PowerIteration;
  /// Re-estimate the stable step every this many steps on the deformed configuration
  /// (0 = only at the start). Cost of one estimate ≈ power_iterations tangent cell loops.
  int stable_step_interval = 0;
  int power_iterations = 60;           ///< cap of the power iteration
  Real power_tolerance = 1e-3;         ///< relative change of ω² that stops it
  Real displacement_tolerance = 1e-10; ///< ‖ΔU^(k)‖∞ ≤ ε ‖U^(k) − U^n‖∞
  Real constraint_tolerance = 1e-11;   ///< max_e |Ψ_e − Γ_e Λ_e/α| / Γ_e ≤ ε_Ψ
  int max_iterations = 50;             ///< per step; more = not converged → Δt halved
  int max_halvings = 8;                ///< consecutive halvings before the run stops
  int recovery_steps = 10;             ///< successful steps before a halved Δt is doubled again

  /// The effective safety factor for the chosen reading.
  Real safety() const { return safety_factor.value_or(reading == Reading::B ? 0.8 : 0.5); }
  /// Throws InputError naming the first invalid option.
  void validate() const;
};

/// The settings of an [explicit] table with the requested step `time_step` (time.dt, 0: the
/// stability estimate), validated (InputError names the key).
ExplicitSettings explicit_settings(const io::ExplicitSpec& spec, Real time_step);

/// Parses "A"/"B" (case-insensitive); InputError otherwise.
Reading parse_reading(const std::string& text);
/// Parses "J-1" or "lnJ"; InputError otherwise.
Constraint parse_constraint(const std::string& text);

} // namespace trifem::explicit_dynamics
