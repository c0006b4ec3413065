// SPDX-License-Identifier: MIT
// Construction, step-size choice and control (halving, recovery), run loop and energies.
// The per-step iteration itself is in step_iteration.cpp.
#include "trifem/explicit/explicit_solver.hpp"

#include "trifem/core/error.hpp"
#include "trifem/core/log.hpp"
#include "trifem/explicit/lambda_system.hpp"
#include "trifem/explicit/stable_step.hpp"

#include <cmath>
#include <limits>

namespace trifem::explicit_dynamics {

const char* to_string(StepStatus status) {
  switch (status) {
  case StepStatus::Converged:
    return "converged";
  case StepStatus::NotConverged:
    return "not converged";
  case StepStatus::NegativeJacobian:
    return "negative Jacobian";
  case StepStatus::FactorizationFailed:
    return "factorization failed";
  case StepStatus::NonFinite:
    return "non-finite value";
  case StepStatus::TooManyHalvings:
    return "too many step halvings";
  }
  return "?";
}

ExplicitSolver::ExplicitSolver(const ExplicitView& model, ExplicitSettings settings,
                               const InitialState& initial)
    : model_(model), settings_(std::move(settings)) {
  settings_.verify();
  if (settings_.multiplier)
    system_ = std::make_unique<LambdaSystem>(model_);
  initialize(initial);
  choose_time_step();
}

ExplicitSolver::~ExplicitSolver() = default;

Real ExplicitSolver::inverse_penalty() const {
  return std::isinf(settings_.penalty) ? 0.0 : 1.0 / settings_.penalty;
}

Vector ExplicitSolver::multiplier_diagonal() const {
  Vector diagonal = inverse_penalty() * model_.volumes();
  for (Index c = 0; c < model_.num_cells(); ++c)
    if (!model_.deformable(c)) // H_e = 0, Ψ_e = 0: a row of its own keeps Λ_e = 0
      diagonal[c] = model_.volumes()[c];
  return diagonal;
}

namespace {

/// `v`, or zeros if it is empty; InputError naming `what` if its size is not `n`.
Vector given_or_zero(const Vector& v, Index n, const char* what) {
  if (v.size() == 0)
    return Vector::Zero(n);
  TRIFEM_CHECK(v.size() == n, "explicit: the initial {} has {} values, the model {} DOFs", what,
               v.size(), n);
  return v;
}

} // namespace

void ExplicitSolver::initialize(const InitialState& initial) {
  const Index n = model_.num_dofs();
  U_ = given_or_zero(initial.displacement, n, "displacement");
  V_ = given_or_zero(initial.velocity, n, "velocity");
  const Real largest = U_.lpNorm<Eigen::Infinity>();
  Vector prescribed = Vector::Zero(n);
  model_.prescribe(initial.time, prescribed);
  for (Index d = 0; d < n; ++d) {
    if (!model_.fixed()[d])
      continue;
    // a constrained DOF holds its prescribed value: another one would jump in the first step
    TRIFEM_CHECK(std::abs(U_[d] - prescribed[d]) <= 1e-12 * largest,
                 "explicit: node {} is constrained in component {} to {:.6g} mm but starts at "
                 "{:.6g} mm",
                 d / 3, "xyz"[d % 3], prescribed[d], U_[d]);
    U_[d] = prescribed[d];
    V_[d] = 0.0;
  }
  time_ = initial.time;
  motions_ = initial.bodies;
  if (motions_.empty())
    motions_.assign(model_.bodies().size(), BodyMotion{});
  TRIFEM_CHECK(motions_.size() == model_.bodies().size(),
               "explicit: the initial state has {} rigid bodies, the model {}", motions_.size(),
               model_.bodies().size());
  trial_motions_ = motions_;
  targets_.assign(motions_.size(), BodyTarget{});
  for (std::size_t b = 0; b < motions_.size(); ++b)
    place(model_.bodies()[b], motions_[b], U_);
  lambda_ = Vector::Zero(model_.num_cells());
  const CellStatus status =
      evaluate_cells(model_, settings_.constraint, U_, {true, true, true, false}, fields_);
  TRIFEM_CHECK(status.ok(), "explicit: initial state: {} in cell {}", status.quantity, status.cell);
  if (settings_.multiplier)
    initial_multiplier();
  lambda_old_ = lambda_;
  update_end_forces();
  support_step_ = Vector::Zero(n); // from rest
  const Energies e = energies();
  initial_energy_ = e.kinetic + e.strain;
}

void ExplicitSolver::initial_multiplier() {
  const Vector& V = model_.volumes();
  if (!std::isinf(settings_.penalty)) { // the penalty relation Ψ_e = V_e Λ_e/α holds at once
    lambda_ = settings_.penalty * fields_.psi.cwiseQuotient(V);
    return;
  }
  const Real violation = fields_.psi.cwiseQuotient(V).lpNorm<Eigen::Infinity>();
  if (violation > settings_.constraint_tolerance)
    log::warn("explicit: the initial state violates the volume constraint (max |Psi_e|/V_e = "
              "{:.3g}); with explicit.penalty = inf the first step enforces it at once. Use "
              "explicit.multiplier = false (the law's own bulk stiffness) or a finite penalty",
              violation);
}

void ExplicitSolver::update_end_forces() {
  gather(model_, fields_.internal, nullptr, f_int_);
  model_.external_force(U_, time_, f_ext_, motions_, &body_loads_);
}

void ExplicitSolver::estimate_stable_step() {
  TimeStepInfo& info = dt_info_;
  const Vector lambda = settings_.multiplier ? lambda_ : Vector();
  const FrequencyEstimate est =
      settings_.stable_step == StableStepMethod::PowerIteration
          ? power_iteration_omega(model_, settings_.constraint, U_, lambda, settings_.multiplier,
                                  kPowerIterations, kPowerTolerance)
          : element_bound_omega(model_, settings_.constraint, U_, lambda);
  info.omega = est.omega;
  info.critical = (settings_.reading == Reading::B ? 2.0 : 1.0) / est.omega;
  info.stable = settings_.safety() * info.critical;
  log::info("explicit: t = {:.6g} s: omega_iso = {:.6g} 1/s ({} iterations{}), critical dt = "
            "{:.6g} s, stable dt = {:.6g} s",
            time_, est.omega, est.iterations, est.converged ? "" : ", not converged", info.critical,
            info.stable);
}

void ExplicitSolver::choose_time_step() {
  TimeStepInfo& info = dt_info_;
  info.requested = settings_.time_step;
  if (settings_.stable_step != StableStepMethod::None)
    estimate_stable_step();
  info.used = info.requested > 0.0 ? info.requested : info.stable;
  info.reduced = false;
  if (info.stable > 0.0 && info.requested > info.stable) {
    info.used = info.stable;
    info.reduced = true;
    log::warn("explicit: requested dt = {:.6g} s exceeds the stability estimate {:.6g} s "
              "(reading {}, safety {}); reduced to {:.6g} s",
              info.requested, info.stable, settings_.reading == Reading::B ? "B" : "A",
              settings_.safety(), info.used);
  }
  TRIFEM_CHECK(std::isfinite(info.used) && info.used > 0.0,
               "explicit: no usable time step (estimate {} s)", info.used);
  // A smaller step takes effect at once; a larger one is reached through the recovery doubling.
  dt_current_ = dt_current_ > 0.0 ? std::min(dt_current_, info.used) : info.used;
}

StepReport ExplicitSolver::with_stable_step_hint(StepReport r) const {
  // a run that had to halve its steps before it diverged: the estimate fell behind
  const bool diverged = r.status == StepStatus::TooManyHalvings ||
                        (r.status == StepStatus::NonFinite && halvings_ > 0);
  if (diverged && settings_.stable_step_interval == 0 &&
      settings_.stable_step != StableStepMethod::None)
    r.message += ". The stable step was estimated once, at the start: a body that deforms much "
                 "stiffens and needs it re-estimated (set explicit.stable_step_interval, e.g. "
                 "50 steps)";
  return r;
}

StepReport ExplicitSolver::fatal(StepStatus status, const std::string& what) const {
  StepReport r;
  r.status = status;
  r.message = fmt::format("step {} (t = {:.9g} s): {}", step_count_ + 1, time_, what);
  return r;
}

namespace {

/// The time to t_end split into equal steps of at most dt_max (the last one may exceed dt_max
/// by round-off only). Truncating only the last step before each output time instead gives a
/// periodic short step, and central differences with a periodically varying step are
/// parametrically unstable for some frequencies below the critical one: on a 30 x 3 x 3
/// cantilever at 0.8 of the critical step, one short step in 44 made the energy grow by about
/// 0.8 % per step. Equal steps per output interval keep the step sequence uniform.
Real equal_step(Real remaining, Real dt_max) {
  const Real n = std::max(1.0, std::ceil(remaining / dt_max - 1e-9));
  return remaining / n;
}

} // namespace

StepReport ExplicitSolver::step(Real t_end) {
  const int interval = settings_.stable_step_interval;
  if (interval > 0 && step_count_ > 0 && step_count_ % interval == 0 &&
      settings_.stable_step != StableStepMethod::None)
    choose_time_step(); // re-estimate on the deformed configuration
  int halvings = 0;
  for (;;) {
    const Real dt = equal_step(t_end - time_, dt_current_);
    StepReport r = try_step(dt);
    r.halvings = halvings;
    if (r.ok()) {
      if (dt_current_ < dt_info_.used && ++successes_since_halving_ >= kRecoverySteps) {
        dt_current_ = std::min(2.0 * dt_current_, dt_info_.used);
        successes_since_halving_ = 0;
      }
      return r;
    }
    const bool retry =
        r.status == StepStatus::NotConverged || r.status == StepStatus::NegativeJacobian;
    if (!retry)
      return with_stable_step_hint(r);
    if (++halvings > settings_.max_halvings) {
      r.status = StepStatus::TooManyHalvings;
      r.message += fmt::format(" (given up after {} halvings of the step)", settings_.max_halvings);
      return with_stable_step_hint(r);
    }
    log::warn("explicit: {}; repeating with dt = {:.6g} s", r.message, 0.5 * dt_current_);
    dt_current_ *= 0.5;
    ++halvings_;
    successes_since_halving_ = 0;
  }
}

StepReport
ExplicitSolver::run(Real t_end,
                    const std::function<void(const ExplicitSolver&, const StepReport&)>& observer) {
  StepReport last;
  const Real eps = 1e-12 * std::max(std::abs(t_end), dt_info_.used);
  while (time_ < t_end - eps) {
    last = step(t_end);
    if (!last.ok()) {
      log::error("explicit: run stopped: {}", last.message);
      return last;
    }
    if (observer)
      observer(*this, last);
  }
  return last;
}

Real ExplicitSolver::max_volume_change() const {
  return fields_.volume_change.lpNorm<Eigen::Infinity>();
}

Real ExplicitSolver::max_gauss_volume_change() const {
  return fields_.gauss_volume_change.lpNorm<Eigen::Infinity>();
}

Vector ExplicitSolver::reaction_force(const Vector& lambda) const {
  Vector force = f_int_ - f_ext_;
  if (settings_.multiplier) {
    Vector pressure;
    gather(model_, fields_.gradient, &lambda, pressure);
    force += pressure;
  }
  return force;
}

Vector ExplicitSolver::velocity() const {
  // v^n = (v^{n-1/2} + Δt/2 a^n) / (1 + c Δt/2), a^n = M⁻¹(F^n − Q^n − H^n Λ^n).
  const Real half = 0.5 * dt_prev_;
  if (half == 0.0)
    return V_; // the initial state (a non-finite initial force must not make it NaN)
  if (motions_.empty())
    return (V_ - half * model_.inverse_mass().cwiseProduct(reaction_force())) /
           (1.0 + half * settings_.damping);
  const Vector reaction = reaction_force();
  Vector v =
      (V_ - half * model_.inverse_mass().cwiseProduct(reaction)) / (1.0 + half * settings_.damping);
  const std::vector<BodyVelocity> bodies = body_velocities();
  for (std::size_t b = 0; b < bodies.size(); ++b)
    place_velocity(model_.bodies()[b], motions_[b], bodies[b], v);
  return v;
}

std::vector<BodyVelocity> ExplicitSolver::body_velocities() const {
  const std::vector<ExplicitBody>& bodies = model_.bodies();
  std::vector<BodyVelocity> out(bodies.size());
  if (bodies.empty())
    return out;
  const Real half = 0.5 * dt_prev_;
  if (half == 0.0) { // the initial state: the velocities it was given
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      const BodyMotion& m = motions_[b];
      out[b].pivot = m.v;
      if (bodies[b].rotation == BodyRotation::Axis)
        out[b].omega = m.L / bodies[b].inertia(bodies[b].axis, bodies[b].axis);
      else if (bodies[b].rotates()) // (a body on a line has no velocity along it)
        out[b].omega = m.R * bodies[b].inertia.completeOrthogonalDecomposition().pseudoInverse() *
                       m.R.transpose() * m.L;
    }
    return out;
  }
  const Vector force = -reaction_force();
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    BodyLoad load = nodal_load(bodies[b], motions_[b], force);
    load.force += body_loads_[b].force;
    load.moment += body_loads_[b].moment;
    out[b] = velocity_at_step(bodies[b], motions_[b], load, model_.target(b, time_ - half),
                              model_.target(b, time_ + half), half, settings_.damping);
  }
  return out;
}

Energies ExplicitSolver::energies() const {
  Energies e;
  e.initial = initial_energy_;
  e.external_work = external_work_;
  if (model_.has_prescribed_motion()) { // the supports' work from t_{n−½} to t_n
    const Vector R = reaction_force();
    for (Index d = 0; d < R.size(); ++d)
      if (model_.fixed()[d])
        e.external_work += 0.5 * R[d] * support_step_[d];
  }
  e.external_work += 0.5 * drive_work_; // the bodies' drives from t_{n−½} to t_n
  e.damping_work = damping_work_;
  const Vector v = velocity();
  e.kinetic = 0.5 * v.cwiseAbs2().dot(model_.kinetic_mass()); // prescribed DOFs: the support's
  CellFields w;
  const CellStatus s =
      evaluate_cells(model_, settings_.constraint, U_, {false, false, false, true}, w);
  e.strain = s.ok() ? w.energy.sum() : std::numeric_limits<Real>::quiet_NaN();
  if (settings_.multiplier)
    e.strain += 0.5 * lambda_.dot(fields_.psi);
  return e;
}

} // namespace trifem::explicit_dynamics
