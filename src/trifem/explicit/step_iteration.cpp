// SPDX-License-Identifier: MIT
// One step of the explicit scheme: the iteration A2.16 → A2.21 → A2.17 of
// docs/theory/explicit.md §3.
//
// Variable-step central differences with mass-proportional damping c (velocities at half
// steps, Δt̄ = (Δt_{n-1/2} + Δt)/2, β = 1 + c Δt̄/2):
//   U_pred = U^n + Δt (1 − c Δt̄/2)/β v^{n-1/2},   h² = Δt Δt̄ / β   (= Δt² for c = 0, uniform Δt)
// Reading A (all forces iterated, literal A2.15–A2.21, H_k = H(U^(k))):
//   (A2.16) U_m      = U_pred + h² M⁻¹ (F_S(U^(k), t+Δt) − Q_V(U^(k)))
//   (A2.21) [Γ/α + h² H_kᵀ M⁻¹ H_k] Λ^(k+1) = Ψ(U^(k)) − H_kᵀ (U^(k) − U_m)
//   (A2.17) U^(k+1)  = U_m − h² M⁻¹ H_k Λ^(k+1)
// A2.21 is a Newton step on the constraint Ψ(U) = Γ Λ/α along U(Λ) = U_m − h² M⁻¹ H_k Λ.
// Reading B (internal force, loads and the pressure direction H_n at t_n; only Λ iterated):
//   U_m = U_pred + h² M⁻¹ (F_S^n − Q_V^n),  A_n = Γ/α + h² H_nᵀ M⁻¹ H_n (factorized once per step)
//   Λ^(k+1) = Λ^(k) + A_n⁻¹ [Ψ(U^(k)) − Γ Λ^(k)/α],   U^(k+1) = U_m − h² M⁻¹ H_n Λ^(k+1)
// i.e. central differences with the constraint force H_n Λ^{n+1} chosen so that the constraint
// holds at t_{n+1} (SHAKE): second order, time-reversible, no energy drift. A_n is the exact
// Jacobian at U^n, so the iteration contracts by O(‖H(U^(k)) − H_n‖) = O(Δt) per iteration.
// Its factorization may be reused for up to factorization_age steps (a modified Newton
// iteration: same fixed point, slightly slower contraction); it is refreshed when h² changes,
// when the iteration count grows by more than 3, or when a step fails with a reused one.
// Both readings start from the explicit predictor with the forces of t_n and the multiplier
// Λ^n (B: extrapolated linearly from Λ^{n-1}, Λ^n).
#include "trifem/explicit/explicit_solver.hpp"

#include "trifem/core/error.hpp"
#include "trifem/core/timer.hpp"
#include "trifem/explicit/lambda_system.hpp"

#include <cmath>
#include <limits>

namespace trifem::explicit_dynamics {
namespace {

/// Index of the first non-finite entry, or -1.
Index first_non_finite(const Vector& v) {
  for (Index i = 0; i < v.size(); ++i)
    if (!std::isfinite(v[i]))
      return i;
  return -1;
}

constexpr const char* kAxis[3] = {"x", "y", "z"};

} // namespace

Vector ExplicitSolver::explicit_force(const CellFields& f, const Vector& U, Real time,
                                      std::vector<BodyLoad>& body_loads) const {
  Vector q, fs;
  gather(model_, f.internal, nullptr, q);
  model_.external_force(U, time, fs, motions_, &body_loads); // a follower pressure depends on U
  return fs - q;
}

void ExplicitSolver::move_bodies(const Vector& force, const std::vector<BodyLoad>& applied,
                                 Vector& U) {
  const std::vector<ExplicitBody>& bodies = model_.bodies();
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    BodyLoad load = nodal_load(bodies[b], motions_[b], force);
    load.force += applied[b].force;
    load.moment += applied[b].moment;
    trial_motions_[b] = advance(bodies[b], motions_[b], load, targets_[b], step_);
    place(bodies[b], trial_motions_[b], U);
  }
}

Real ExplicitSolver::body_work(const std::vector<BodyLoad>& applied_before) const {
  const std::vector<ExplicitBody>& bodies = model_.bodies();
  Real work = 0.0;
  for (std::size_t b = 0; b < bodies.size(); ++b) { // motions_ at t_{n+1}: the step's travel
    const BodyMotion& after = motions_[b];
    const BodyLoad& old_load = applied_before[b];
    const BodyLoad& new_load = body_loads_[b];
    work += 0.5 * (old_load.force + new_load.force).dot(after.step) +
            0.5 * (old_load.moment + new_load.moment).dot(after.turn);
  }
  return work + drive_work_;
}

StepReport ExplicitSolver::try_step(Real dt) {
  const Real dt_avg = 0.5 * (dt_prev_ + dt);
  const Real beta = 1.0 + 0.5 * settings_.damping * dt_avg;
  const Real gamma = (1.0 - 0.5 * settings_.damping * dt_avg) / beta;
  const Real h2 = dt * dt_avg / beta;
  step_ = {dt, dt_avg, beta, gamma, settings_.damping};
  for (std::size_t b = 0; b < targets_.size(); ++b) // the drives at t_{n+1}, once per try
    targets_[b] = model_.target(b, time_ + dt);
  Vector U_pred = U_ + (dt * gamma) * V_;
  if (model_.has_prescribed_motion()) // constrained DOFs move as prescribed (m⁻¹ = 0 there)
    model_.prescribe(time_ + dt, U_pred);
  if (const Index i = first_non_finite(f_ext_); i >= 0)
    return fatal(StepStatus::NonFinite,
                 fmt::format("non-finite external force F_{} at node {}", kAxis[i % 3], i / 3));
  // First iterate: forces of t_n and Λ^n (reading B: Λ linearly extrapolated from the last
  // two steps, which saves about 0.15 iterations per step; in reading A it costs 0.9).
  Vector lambda = lambda_;
  if (settings_.reading == Reading::B && step_count_ >= 2)
    lambda += (dt / dt_prev_) * (lambda_ - lambda_old_);
  Vector force = f_ext_ - f_int_;
  if (settings_.multiplier) {
    ScopedTimer timer(timings_.forces);
    Vector pressure;
    gather(model_, fields_.gradient, &lambda, pressure);
    force -= pressure;
  }
  Vector U = U_pred + h2 * model_.inverse_mass().cwiseProduct(force);
  if (!motions_.empty()) {
    body_force_ = force;
    move_bodies(body_force_, body_loads_, U);
  }
  StepReport r = settings_.reading == Reading::A
                     ? iterate_forces(h2, U_pred, time_ + dt, U, lambda, work_)
                     : iterate_multiplier(h2, U_pred, U, lambda, work_);
  r.dt = dt;
  if (r.ok() && settings_.reading == Reading::B) // Q_V, H, Ψ at U^{n+1} for the next step
    if (StepReport bad = evaluate(U, {}, work_); !bad.ok())
      r = bad;
  if (r.ok()) {
    commit(dt, dt_avg, U, lambda, work_);
    total_iterations_ += r.iterations;
  }
  sync_lambda_timings();
  return r;
}

void ExplicitSolver::sync_lambda_timings() {
  const LambdaTimings lt = system_ ? system_->timings() : LambdaTimings{};
  timings_.assemble = lt.assemble;
  timings_.factorize = lt.factorize;
  timings_.solve = lt.solve;
  timings_.lambda = lt.assemble + lt.factorize + lt.solve;
  timings_.factorizations = lt.factorizations;
}

Real ExplicitSolver::constraint_residual(const CellFields& f, const Vector& lambda) const {
  const Vector& V = model_.volumes();
  return ((f.psi - inverse_penalty() * V.cwiseProduct(lambda)).cwiseQuotient(V))
      .lpNorm<Eigen::Infinity>();
}

bool ExplicitSolver::converged(int k, const Vector& U, const Vector& U_prev, const Vector& lambda,
                               const CellFields& f, StepReport& r, Real& du_prev,
                               int& growing) const {
  r.iterations = k;
  const Real du = (U - U_prev).lpNorm<Eigen::Infinity>();
  const Real scale = (U - U_).lpNorm<Eigen::Infinity>();
  const Real floor = 64.0 * std::numeric_limits<Real>::epsilon() *
                     (model_.lengths().maxCoeff() + U.lpNorm<Eigen::Infinity>());
  r.increment_ratio = scale > 0.0 ? du / scale : 0.0;
  r.constraint_residual = settings_.multiplier ? constraint_residual(f, lambda) : 0.0;
  if (du <= settings_.displacement_tolerance * scale + floor &&
      r.constraint_residual <= settings_.constraint_tolerance)
    return true;
  growing = du > du_prev ? growing + 1 : 0;
  du_prev = du;
  if (k >= settings_.max_iterations || growing >= 3)
    r = fatal(StepStatus::NotConverged,
              fmt::format("iteration {} after {} iterations (|dU|/|U-U^n| = {:.3g}, "
                          "constraint residual {:.3g})",
                          growing >= 3 ? "diverging" : "not converged", k, r.increment_ratio,
                          r.constraint_residual));
  return false;
}

StepReport ExplicitSolver::iterate_forces(Real h2, const Vector& U_pred, Real t_new, Vector& U,
                                          Vector& lambda, CellFields& fields) {
  const CellRequest request{true, settings_.multiplier, settings_.multiplier, false};
  const Vector& minv = model_.inverse_mass();
  Vector U_m, U_prev;
  Real du_prev = std::numeric_limits<Real>::infinity();
  int growing = 0;
  for (int k = 0;; ++k) {
    if (StepReport bad = evaluate(U, request, fields); !bad.ok())
      return bad;
    StepReport r;
    if (k > 0 && (converged(k, U, U_prev, lambda, fields, r, du_prev, growing) || !r.ok()))
      return r;
    Vector force;
    {
      ScopedTimer timer(timings_.forces);
      force = explicit_force(fields, U, t_new, trial_body_loads_);
      U_m = U_pred + h2 * minv.cwiseProduct(force); // A2.16
    }
    if (!motions_.empty()) // the bodies under the same forces, as the nodes
      move_bodies(force, trial_body_loads_, U_m);
    U_prev = U;
    if (settings_.multiplier) {
      if (!system_->factorize(fields.gradient, minv, h2, multiplier_diagonal()))
        return factorization_failure();
      Vector HtdU, dU = U - U_m;
      // A2.21 leaves out the bodies' mobility (M⁻¹ = 0 on their nodes), so must its right-hand
      // side: the bodies follow Λ by iteration, and the fixed point is Ψ = ΓΛ/α
      for (const ExplicitBody& body : model_.bodies())
        for (Index a : body.nodes)
          for (int k = 0; k < 3; ++k)
            if (body.moves[k])
              dU[3 * a + k] = 0.0;
      cell_dot(model_, fields.gradient, dU, HtdU);
      system_->solve(fields.psi - HtdU, lambda); // A2.21
      if (const StepReport bad = check_finite(U_m, lambda); !bad.ok())
        return bad;
      Vector pressure;
      gather(model_, fields.gradient, &lambda, pressure);
      U = U_m - h2 * minv.cwiseProduct(pressure); // A2.17
      if (!motions_.empty())
        force -= pressure;
    } else {
      U = U_m;
    }
    if (!motions_.empty()) { // (the forces of the last iterate: the drives' work)
      body_force_ = std::move(force);
      move_bodies(body_force_, trial_body_loads_, U);
    }
    if (const StepReport bad = check_finite(U, lambda); !bad.ok())
      return bad;
  }
}

StepReport ExplicitSolver::iterate_multiplier(Real h2, const Vector& U_pred, Vector& U,
                                              Vector& lambda, CellFields& fields) {
  const Vector& minv = model_.inverse_mass();
  const Vector U_m = U_pred + h2 * minv.cwiseProduct(f_ext_ - f_int_); // A2.16 at t_n
  if (!settings_.multiplier) {
    U = U_m;
    if (!motions_.empty())
      move_bodies(body_force_, body_loads_, U);
    return check_finite(U, lambda);
  }
  const Vector U_0 = U, lambda_0 = lambda, body_force_0 = body_force_;
  const bool stale = factorization_.age > 0;
  if (needs_factorization(h2) && !factorize_multiplier_matrix(h2))
    return factorization_failure();
  StepReport r = multiplier_loop(h2, U, lambda, fields);
  if (r.status == StepStatus::NotConverged && stale && factorization_.age > 0) {
    // A reused factorization may be too far from A_n: retry once with a fresh one.
    U = U_0;
    lambda = lambda_0;
    body_force_ = body_force_0;
    if (!factorize_multiplier_matrix(h2))
      return factorization_failure();
    r = multiplier_loop(h2, U, lambda, fields);
  }
  if (r.ok())
    factorization_.record(r.iterations);
  return r;
}

bool ExplicitSolver::needs_factorization(Real h2) const {
  const FactorizationState& f = factorization_;
  // h² equal up to round-off: equal steps towards a target differ in the last bits.
  const bool same_step = std::abs(h2 - f.h2) <= 1e-9 * f.h2;
  return f.age < 0 || !same_step || f.age >= settings_.factorization_age ||
         f.last_iterations > f.fresh_iterations + 3;
}

bool ExplicitSolver::factorize_multiplier_matrix(Real h2) {
  factorization_ = {h2, 0, -1, 0};
  if (system_->factorize(fields_.gradient, model_.inverse_mass(), h2, multiplier_diagonal()))
    return true;
  factorization_.age = -1;
  return false;
}

void ExplicitSolver::FactorizationState::record(int iterations) {
  if (age == 0)
    fresh_iterations = iterations;
  last_iterations = iterations;
  ++age;
}

StepReport ExplicitSolver::multiplier_loop(Real h2, Vector& U, Vector& lambda, CellFields& fields) {
  const Vector& minv = model_.inverse_mass();
  const Vector diagonal = multiplier_diagonal();
  Vector U_prev, delta, pressure;
  Real du_prev = std::numeric_limits<Real>::infinity();
  int growing = 0;
  for (int k = 0;; ++k) {
    if (StepReport bad = evaluate(U, {false, false, true, false}, fields); !bad.ok())
      return bad;
    StepReport r;
    if (k > 0 && (converged(k, U, U_prev, lambda, fields, r, du_prev, growing) || !r.ok()))
      return r;
    system_->solve(fields.psi - diagonal.cwiseProduct(lambda), delta); // Newton on Ψ = ΓΛ/α
    lambda += delta;
    U_prev = U;
    {
      ScopedTimer timer(timings_.forces);
      gather(model_, fields_.gradient, &delta, pressure);
    }
    U -= h2 * minv.cwiseProduct(pressure); // A2.17 with H_n
    if (!motions_.empty()) {
      body_force_ -= pressure;
      move_bodies(body_force_, body_loads_, U);
    }
    if (const StepReport bad = check_finite(U, lambda); !bad.ok())
      return bad;
  }
}

StepReport ExplicitSolver::evaluate(const Vector& U, const CellRequest& request,
                                    CellFields& fields) {
  ScopedTimer timer(timings_.forces);
  const CellStatus s = evaluate_cells(model_, settings_.constraint, U, request, fields);
  if (s.ok())
    return {};
  if (s.failure == CellFailure::NegativeJacobian)
    return fatal(StepStatus::NegativeJacobian,
                 fmt::format("{} <= 0 in cell {}", s.quantity, s.cell));
  return fatal(StepStatus::NonFinite, fmt::format("non-finite {} in cell {}", s.quantity, s.cell));
}

StepReport ExplicitSolver::factorization_failure() const {
  return fatal(StepStatus::FactorizationFailed,
               "the multiplier matrix Gamma/alpha + dt^2 H^T M^-1 H is not positive definite "
               "(H rank deficient with alpha = inf? use a finite penalty, e.g. 1e4 mu)");
}

StepReport ExplicitSolver::check_finite(const Vector& U, const Vector& lambda) const {
  if (const Index e = first_non_finite(lambda); e >= 0)
    return fatal(StepStatus::NonFinite, fmt::format("non-finite multiplier Lambda in cell {}", e));
  if (const Index i = first_non_finite(U); i >= 0)
    return fatal(StepStatus::NonFinite,
                 fmt::format("non-finite displacement u_{} at node {}", kAxis[i % 3], i / 3));
  return {};
}

void ExplicitSolver::commit(Real dt, Real dt_avg, Vector& U, Vector& lambda, CellFields& fields) {
  // The force of the step on the moving supports, as the free DOFs felt it: reading B
  // Q_n + H_n Λ^{n+1} − F_n (after update_end_forces, reading A: all of it at U^{n+1}).
  Vector support;
  if (model_.has_prescribed_motion() && settings_.reading == Reading::B)
    support = reaction_force(lambda);
  Vector V_new = (U - U_) / dt;
  const Vector v_mid = 0.5 * (V_ + V_new);
  damping_work_ += settings_.damping * dt_avg * v_mid.cwiseAbs2().dot(model_.kinetic_mass());
  std::vector<BodyLoad> applied_before;
  if (!motions_.empty()) {
    drive_work_ = 0.0;
    const std::vector<ExplicitBody>& bodies = model_.bodies();
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      BodyLoad load = nodal_load(bodies[b], motions_[b], body_force_);
      load.force += body_loads_[b].force;
      load.moment += body_loads_[b].moment;
      drive_work_ += drive_work(bodies[b], motions_[b], trial_motions_[b], load, step_);
    }
    applied_before = body_loads_;
    motions_.swap(trial_motions_);
  }
  Vector f_ext_old = f_ext_;
  const Vector dU = U - U_;
  U_.swap(U);
  V_.swap(V_new);
  lambda_old_.swap(lambda_);
  lambda_.swap(lambda);
  std::swap(fields_, fields);
  time_ += dt;
  dt_prev_ = dt;
  ++step_count_;
  {
    ScopedTimer timer(timings_.forces);
    update_end_forces();
  }
  external_work_ += 0.5 * (f_ext_old + f_ext_).dot(dU);
  if (!motions_.empty())
    external_work_ += body_work(applied_before);
  if (model_.has_prescribed_motion()) { // the work of the supports that move the body
    if (settings_.reading == Reading::A)
      support = reaction_force();
    Real work = 0.0; // over the step's own interval [t_{n−½}, t_{n+½}], as its kicks
    for (Index d = 0; d < support.size(); ++d)
      if (model_.fixed()[d])
        work += support[d] * 0.5 * (support_step_[d] + dU[d]);
    external_work_ += work;
    support_step_ = dU;
  }
}

} // namespace trifem::explicit_dynamics
