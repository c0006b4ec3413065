// SPDX-License-Identifier: MIT
// Settings of the explicit solver with a P0 Lagrange-multiplier pressure (docs/theory/explicit.md).
#pragma once

#include "trifem/core/types.hpp"
#include "trifem/io/case_spec.hpp"

/// Explicit (central-difference) dynamics of nearly incompressible solids. The namespace is not
/// called `explicit` because that is a C++ keyword.
namespace trifem::explicit_dynamics {

/// Which forces the per-step iteration re-evaluates (docs/theory/explicit.md §3, §5): A = Q_V, H
/// and follower loads at the iterate (first order, dissipative, converges for Δt < 1/ω_iso);
/// B = Q_V and loads at t_n, only H and Λ iterated (second order, stable for Δt < 2/ω_iso).
using Reading = io::ExplicitReading;
/// The volume constraint Ψ(C) of the multiplier term λ Ψ(C): J − 1 (σ = λ I) or ln J (τ = λ I).
using Constraint = io::VolumeConstraint;
/// How the critical time step is estimated.
using StableStepMethod = io::StableStepEstimate;

/// Cap of the power iteration for ω_iso.
inline constexpr int kPowerIterations = 60;
/// Relative change of ω² that stops the power iteration.
inline constexpr Real kPowerTolerance = 1e-3;
/// Successful steps before a halved Δt is doubled again.
inline constexpr int kRecoverySteps = 10;

/// All numerical options of one explicit run: the [explicit] table of a case (io::ExplicitSpec,
/// whose defaults are the solver's) and the requested step. Units: s, MPa, mm.
struct ExplicitSettings : io::ExplicitSpec {
  /// Requested step Δt [s] (time.dt); 0 = the stability estimate. A larger request is reduced.
  Real time_step = 0.0;

  /// The effective safety factor for the chosen reading: 0.8 of 2/ω (B), 0.5 of 1/ω (A).
  Real safety() const { return safety_factor.value_or(reading == Reading::B ? 0.8 : 0.5); }
  /// The ranges the solver relies on (the case reader reports them against the input).
  void verify() const;
};

} // namespace trifem::explicit_dynamics
