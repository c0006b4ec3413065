// SPDX-License-Identifier: MIT
// The `dynamic-explicit` time integrator: central differences with a lumped mass and a P0
// Lagrange-multiplier pressure, iterated per step as A2.16 → A2.21 → A2.17
// (docs/theory/explicit.md §3).
#pragma once

#include "trifem/explicit/cell_kernel.hpp"
#include "trifem/explicit/settings.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace trifem::explicit_dynamics {

class LambdaSystem;

/// Outcome of one step.
enum class StepStatus {
  Converged,
  NotConverged,        ///< iteration cap reached or diverging (the step is retried at Δt/2)
  NegativeJacobian,    ///< det F ≤ 0 in a cell (retried at Δt/2)
  FactorizationFailed, ///< A2.21 matrix not positive definite (fatal; use a finite α)
  NonFinite,           ///< NaN/Inf in a result (fatal; message names step, cell/node, quantity)
  TooManyHalvings      ///< max_halvings consecutive halvings did not help (fatal)
};

/// What one (possibly retried) step did.
struct StepReport {
  StepStatus status = StepStatus::Converged;
  int iterations = 0;             ///< multiplier solves of the accepted attempt
  int halvings = 0;               ///< retries of this step
  Real dt = 0.0;                  ///< accepted step [s]
  Real constraint_residual = 0.0; ///< max_e |Ψ_e − Γ_e Λ_e/α| / Γ_e at the accepted state
  Real increment_ratio = 0.0;     ///< ‖ΔU^(k)‖∞ / ‖U^(k) − U^n‖∞ at acceptance
  std::string message;            ///< set when status is not Converged
  bool ok() const { return status == StepStatus::Converged; }
};

/// Energy bookkeeping [mJ]. Balance: kinetic + strain − external + damping ≈ const = the kinetic
/// + strain energy at the start (0 from rest), the external and damping work counted from there.
struct Energies {
  Real kinetic = 0.0; ///< ½ vᵀ M v, v at t_n (half-step velocity plus half a kick)
  Real strain = 0.0; ///< Σ ∫ W dV + Σ ½ Λ_e Ψ_e (the penalty part λ²/(2α) at convergence)
  Real external_work = 0.0; ///< Σ ½ (F^n + F^{n+1})·ΔU (trapezoidal)
  Real damping_work = 0.0;  ///< dissipated by C = c M
  Real initial = 0.0;       ///< kinetic + strain at the initial state (t0)
  Real total() const { return kinetic + strain - external_work + damping_work; }
  /// The balance error total − initial (≈ 0 up to the time-discretisation error).
  Real balance() const { return total() - initial; }
};

/// The state a run starts from; the default is at rest in the reference configuration at t = 0.
/// A run that continues a quasi-static analysis starts from its final displacement.
struct InitialState {
  Vector displacement;            ///< U0 per DOF 3 a + k [mm] (empty: 0); 0 on fixed DOFs
  Vector velocity;                ///< v0 per DOF [mm/s] (empty: 0); set to 0 on fixed DOFs
  Real time = 0.0;                ///< t0 [s]
  std::vector<BodyMotion> bodies; ///< of ExplicitView::bodies() (empty: at rest, unturned)
};

/// How the step size was chosen.
struct TimeStepInfo {
  Real omega = 0.0;     ///< estimated ω_iso [1/s] (0 if not estimated)
  Real critical = 0.0;  ///< 2/ω (B) or 1/ω (A) [s]
  Real stable = 0.0;    ///< safety × critical [s]
  Real requested = 0.0; ///< settings.time_step [s]
  Real used = 0.0;      ///< the step taken [s]
  bool reduced = false; ///< the request exceeded the estimate and was reduced
};

/// Wall-clock seconds spent in the two parts of a step.
struct SolverTimings {
  double forces = 0.0; ///< cell loops (Q_V, H, Ψ), gathers and surface loads
  double lambda = 0.0; ///< multiplier system: assembly, factorization, solve
  double assemble = 0.0, factorize = 0.0, solve = 0.0; ///< parts of `lambda`
  long factorizations = 0; ///< numeric factorizations of the multiplier matrix
};

/// Explicit dynamics of one ExplicitView. The model must outlive the solver.
class ExplicitSolver {
public:
  /// Verifies the settings' ranges, evaluates the initial state (by default U = 0, at rest, t = 0)
  /// and chooses Δt on it. With a multiplier, Λ0 = α Ψ_e(U0)/V_e (0 for α = inf: the first step
  /// then enforces the constraint, with a warning if U0 violates it). InputError if `initial` does
  /// not fit the model (sizes, a displaced fixed DOF).
  ExplicitSolver(const ExplicitView& model, ExplicitSettings settings,
                 const InitialState& initial = {});
  ~ExplicitSolver();

  /// Advances one step (truncated at t_end), halving Δt on NotConverged/NegativeJacobian.
  StepReport step(Real t_end);
  /// Steps until t_end; calls observer after every accepted step; stops at the first fatal
  /// report and returns it (the observer has seen every accepted step before).
  StepReport
  run(Real t_end,
      const std::function<void(const ExplicitSolver&, const StepReport&)>& observer = {});

  Real time() const { return time_; }
  long step_count() const { return step_count_; }
  /// Current target step (after halvings) [s].
  Real time_step() const { return dt_current_; }
  const TimeStepInfo& time_step_info() const { return dt_info_; }
  const ExplicitView& model() const { return model_; }
  const ExplicitSettings& settings() const { return settings_; }

  const Vector& displacement() const { return U_; } ///< U^n [mm]
  /// Velocity at t_n, vⁿ = (v^{n−½} + Δt/2 M⁻¹(F_Sⁿ − Q_Vⁿ − H_n Λⁿ)) / (1 + cΔt/2) [mm/s]
  /// (the half-step velocity plus half a kick; 0 on fixed DOFs).
  Vector velocity() const;
  /// Q_V(Uⁿ) + H_n Λⁿ − F_S(t_n, Uⁿ) per DOF [N]. On fixed DOFs (zero acceleration) this is the
  /// support reaction, the force the support exerts on the body; on free DOFs it is −M aⁿ.
  Vector reaction_force() const { return reaction_force(lambda_); }
  const Vector& multiplier() const { return lambda_; } ///< Λ^n per cell [MPa]
  /// The motion of every body of the model at t_n (its velocities of t_{n−½}).
  const std::vector<BodyMotion>& body_motions() const { return motions_; }
  /// The velocity of every body at t_n (as velocity()).
  std::vector<BodyVelocity> body_velocities() const;
  const CellFields& fields() const { return fields_; } ///< cell results at U^n
  /// max over cells of |J̄_e − 1|, J̄_e = cell-mean J, at U^n: the volume change the P0
  /// multiplier controls (|J̄ − 1| = |Λ|/α at convergence for Ψ = J − 1).
  Real max_volume_change() const;
  /// max over cells and Gauss points of |J − 1| at U^n (Q1–P0 lets J vary inside a cell).
  Real max_gauss_volume_change() const;
  /// Energies at t_n (evaluates the strain energy: one cell loop); `initial` is that of t0.
  Energies energies() const;
  /// Kinetic + strain energy at the initial state [mJ] (0 from rest).
  Real initial_energy() const { return initial_energy_; }
  const SolverTimings& timings() const { return timings_; }
  /// Total multiplier solves so far.
  long total_iterations() const { return total_iterations_; }

  /// The integrator's state at t_n beyond Uⁿ, for restart files (solver_state.cpp): the time,
  /// the counters, the step sizes and the stability estimate, the work done so far, v^{n−½},
  /// Λⁿ, Λ^{n−1} and the supports' last step.
  std::vector<double> state() const;
  /// The number of values of state() for a model of `dofs` DOFs, `cells` cells and `bodies`
  /// rigid bodies.
  static std::size_t state_size(Index dofs, Index cells, std::size_t bodies);
  /// Continues from `state` (of state()) at the displacement `U` as if the run had not stopped
  /// there; InputError if it does not fit the model. The next step factorizes the multiplier
  /// matrix anew.
  void restore(const Vector& U, const std::vector<double>& state);
  /// The next step factorizes the multiplier matrix anew, as a run continued from a restart
  /// file written at this state does (the two then take the same steps).
  void refactorize() { factorization_.age = -1; }

private:
  void initialize(const InitialState& initial);
  void initial_multiplier();
  void choose_time_step();
  void estimate_stable_step();
  StepReport try_step(Real dt);
  StepReport iterate_forces(Real h2, const Vector& U_pred, Real t_new, Vector& U, Vector& lambda,
                            CellFields& fields);
  StepReport iterate_multiplier(Real h2, const Vector& U_pred, Vector& U, Vector& lambda,
                                CellFields& fields);
  StepReport multiplier_loop(Real h2, Vector& U, Vector& lambda, CellFields& fields);
  bool needs_factorization(Real h2) const;
  bool factorize_multiplier_matrix(Real h2);
  bool converged(int k, const Vector& U, const Vector& U_prev, const Vector& lambda,
                 const CellFields& f, StepReport& r, Real& du_prev, int& growing) const;
  Real constraint_residual(const CellFields& f, const Vector& lambda) const;
  /// Evaluates the cells at U (timed as forces); the step's failure if a cell fails.
  StepReport evaluate(const Vector& U, const CellRequest& request, CellFields& fields);
  StepReport factorization_failure() const;
  StepReport check_finite(const Vector& U, const Vector& lambda) const;
  void commit(Real dt, Real dt_avg, Vector& U, Vector& lambda, CellFields& fields);
  void update_end_forces();
  void sync_lambda_timings();
  /// F_S − Q_V at U and `time`; the loads applied to the bodies into `body_loads`.
  Vector explicit_force(const CellFields& f, const Vector& U, Real time,
                        std::vector<BodyLoad>& body_loads) const;
  /// Moves the bodies through the step to their drives' targets_ under the nodal forces `force`
  /// and the loads `applied` (into trial_motions_) and writes their nodes into U.
  void move_bodies(const Vector& force, const std::vector<BodyLoad>& applied, Vector& U);
  /// The work of the bodies' drives over the step to trial_motions_ and of their applied loads.
  Real body_work(const std::vector<BodyLoad>& applied_before) const;
  Real inverse_penalty() const;
  /// Γ/α: V_e/α per cell, the diagonal of the multiplier matrix A2.21.
  Vector multiplier_diagonal() const;
  /// Q_V + H Λ − F_S at U^n with the multiplier `lambda`.
  Vector reaction_force(const Vector& lambda) const;
  StepReport fatal(StepStatus status, const std::string& what) const;
  /// `r` with a hint at stable_step_interval if the run diverged on a step estimated only once.
  StepReport with_stable_step_hint(StepReport r) const;

  const ExplicitView& model_;
  ExplicitSettings settings_;
  std::unique_ptr<LambdaSystem> system_;
  Vector U_, V_, lambda_, lambda_old_; ///< U^n, v^{n-1/2}, Λ^n, Λ^{n-1}
  Vector f_ext_;                       ///< F_S(t_n, U^n)
  Vector f_int_;                       ///< Q_V(U^n) gathered
  Vector support_step_; ///< U^n − U^{n−1} (the work of moving supports over the last step)
  std::vector<BodyMotion> motions_;        ///< of the bodies at t_n
  std::vector<BodyMotion> trial_motions_;  ///< at t_{n+1} in the current iterate
  std::vector<BodyLoad> body_loads_;       ///< applied to the bodies at t_n
  std::vector<BodyLoad> trial_body_loads_; ///< applied at t_{n+1} (reading A)
  std::vector<BodyTarget> targets_;        ///< the bodies' drives at t_{n+1} of the step tried
  Vector body_force_;     ///< the nodal forces that move the bodies in the current iterate
  StepCoefficients step_; ///< of the step being tried
  Real drive_work_ = 0.0; ///< the bodies' drives' work over the last step
  CellFields fields_;
  CellFields work_; ///< scratch of the iteration, swapped with fields_ on acceptance
  Real time_ = 0.0, dt_prev_ = 0.0, dt_current_ = 0.0;
  long step_count_ = 0, total_iterations_ = 0;
  int successes_since_halving_ = 0;
  long halvings_ = 0; ///< of this solver (not kept by restart files)
  Real external_work_ = 0.0, damping_work_ = 0.0;
  Real initial_energy_ = 0.0; ///< kinetic + strain at t0
  TimeStepInfo dt_info_;
  SolverTimings timings_;

  /// Reading B: which A_n the current CHOLMOD factor holds and how well it still serves.
  struct FactorizationState {
    Real h2 = 0.0;             ///< h² it was built with
    int age = -1;              ///< steps served (−1: none)
    int fresh_iterations = -1; ///< iterations of the first step it served
    int last_iterations = 0;   ///< iterations of the last step it served
    void record(int iterations);
  };
  FactorizationState factorization_;
};

/// Human-readable name of a status.
const char* to_string(StepStatus status);

} // namespace trifem::explicit_dynamics
