// SPDX-License-Identifier: MIT
#include "trifem/explicit/rigid_motion.hpp"

#include "trifem/tensor/rotation.hpp"

namespace trifem::explicit_dynamics {
namespace {

/// Fixed-point iterations of the mid-step rotation of a freely turning body: each gains about a
/// factor Δt ω; four leave the angular velocity at round-off for Δt ω below 1e-2.
constexpr int kMidpointIterations = 4;

/// The inertia about the pivot in the configuration R: R J_P Rᵀ.
Mat3 spatial_inertia(const ExplicitBody& body, const Mat3& R) {
  return R * body.inertia * R.transpose();
}

/// The angular velocity of angular momentum L over a step of Δt from R: the inertia at the
/// mid-step rotation, found by fixed-point iteration (exact for a turn about a principal axis).
Vec3 free_angular_velocity(const ExplicitBody& body, const Mat3& R, const Vec3& L, Real dt) {
  const Mat3 inverse = body.inertia.inverse();
  Vec3 omega = R * inverse * R.transpose() * L;
  for (int i = 0; i < kMidpointIterations; ++i) {
    const Mat3 mid = rotation::matrix(0.5 * dt * omega) * R;
    omega = mid * inverse * mid.transpose() * L;
  }
  return omega;
}

/// The moment about the pivot of the inertia of the pivot's acceleration a_P: −m s × a_P with
/// s the center of mass from the pivot (0 where the pivot is the center of mass).
Vec3 pivot_inertia_moment(const ExplicitBody& body, const Mat3& R, const Vec3& a) {
  return -body.mass * (R * body.offset).cross(a);
}

} // namespace

void BodyMotion::to_values(std::vector<double>& out) const {
  for (const Vec3* p : {&u, &v, &L, &mass_velocity, &step, &turn})
    out.insert(out.end(), p->data(), p->data() + 3);
  out.insert(out.end(), R.data(), R.data() + 9);
}

BodyMotion BodyMotion::from_values(const double* values) {
  BodyMotion m;
  for (Vec3* p : {&m.u, &m.v, &m.L, &m.mass_velocity, &m.step, &m.turn}) {
    *p = Eigen::Map<const Vec3>(values);
    values += 3;
  }
  m.R = Eigen::Map<const Mat3>(values);
  return m;
}

void place(const ExplicitBody& body, const BodyMotion& motion, Vector& U) {
  const Mat3 turn = motion.R - Mat3::Identity();
  for (std::size_t i = 0; i < body.nodes.size(); ++i) {
    const Vec3 u = body.rotates() ? Vec3(motion.u + turn * body.arms[i]) : motion.u;
    for (int k = 0; k < 3; ++k)
      if (body.moves[k])
        U[3 * body.nodes[i] + k] = u[k];
  }
}

BodyLoad nodal_load(const ExplicitBody& body, const BodyMotion& motion, const Vector& f) {
  BodyLoad load;
  for (std::size_t i = 0; i < body.nodes.size(); ++i) {
    Vec3 fa = f.segment<3>(3 * body.nodes[i]);
    for (int k = 0; k < 3; ++k)
      if (!body.moves[k])
        fa[k] = 0.0;
    load.force += fa;
    if (body.rotates())
      load.moment += (motion.R * body.arms[i]).cross(fa);
  }
  return load;
}

BodyMotion advance(const ExplicitBody& body, const BodyMotion& motion, const BodyLoad& load,
                   const BodyTarget& target, const StepCoefficients& c) {
  BodyMotion next = motion;
  const Real kick = c.dt_avg / c.beta;
  for (int k = 0; k < 3; ++k) {
    if (!body.moves[k])
      continue;
    next.v[k] = body.driven[k] ? (target.u[k] - motion.u[k]) / c.dt
                               : c.gamma * motion.v[k] + kick * load.force[k] / body.mass;
    next.u[k] = body.driven[k] ? target.u[k] : motion.u[k] + c.dt * next.v[k];
  }
  next.step = next.u - motion.u;
  if (body.rotates()) {
    const Vec3 pivot_acceleration = (next.v - motion.v) / c.dt_avg;
    const Vec3 moment = load.moment + pivot_inertia_moment(body, motion.R, pivot_acceleration);
    switch (body.rotation) {
    case BodyRotation::Free: {
      next.L = c.gamma * motion.L + kick * moment;
      next.R =
          rotation::matrix(c.dt * free_angular_velocity(body, motion.R, next.L, c.dt)) * motion.R;
      break;
    }
    case BodyRotation::Axis: { // R turns about e_k, so e_kᵀ J(R) e_k = J_kk stays
      const int k = body.axis;
      next.L = (c.gamma * motion.L[k] + kick * moment[k]) * Vec3::Unit(k);
      next.R = rotation::matrix(c.dt * next.L / body.inertia(k, k)) * motion.R;
      break;
    }
    case BodyRotation::Prescribed: {
      next.R = target.R;
      const Vec3 turn = rotation::vector(target.R * motion.R.transpose());
      next.L = spatial_inertia(body, rotation::matrix(0.5 * turn) * motion.R) * (turn / c.dt);
      break;
    }
    case BodyRotation::None:
      break;
    }
    next.turn = rotation::vector(next.R * motion.R.transpose());
  }
  next.mass_velocity = (next.step + (next.R - motion.R) * body.offset) / c.dt;
  return next;
}

BodyVelocity velocity_at_step(const ExplicitBody& body, const BodyMotion& motion,
                              const BodyLoad& load, const BodyTarget& before,
                              const BodyTarget& after, Real half, Real damping) {
  BodyVelocity out;
  const Real scale = 1.0 / (1.0 + half * damping);
  for (int k = 0; k < 3; ++k)
    if (body.moves[k])
      out.pivot[k] = body.driven[k] ? (after.u[k] - before.u[k]) / (2.0 * half)
                                    : (motion.v[k] + half * load.force[k] / body.mass) * scale;
  if (!body.rotates())
    return out;
  const Vec3 moment =
      load.moment + pivot_inertia_moment(body, motion.R, (out.pivot - motion.v) / half);
  switch (body.rotation) {
  case BodyRotation::Free:
    out.omega = motion.R * body.inertia.inverse() * motion.R.transpose() *
                ((motion.L + half * moment) * scale);
    break;
  case BodyRotation::Axis: {
    const int k = body.axis;
    out.omega = (motion.L[k] + half * moment[k]) * scale / body.inertia(k, k) * Vec3::Unit(k);
    break;
  }
  case BodyRotation::Prescribed:
    out.omega = rotation::vector(after.R * before.R.transpose()) / (2.0 * half);
    break;
  case BodyRotation::None:
    break;
  }
  return out;
}

void place_velocity(const ExplicitBody& body, const BodyMotion& motion,
                    const BodyVelocity& velocity, Vector& v) {
  for (std::size_t i = 0; i < body.nodes.size(); ++i) {
    const Vec3 va = velocity.at(motion.R * body.arms[i]);
    for (int k = 0; k < 3; ++k)
      if (body.moves[k])
        v[3 * body.nodes[i] + k] = va[k];
  }
}

Real drive_work(const ExplicitBody& body, const BodyMotion& before, const BodyMotion& after,
                const BodyLoad& load, const StepCoefficients& c) {
  Real work = 0.0;
  const Vec3 mass_acceleration = (after.mass_velocity - before.mass_velocity) / c.dt_avg;
  const Vec3 mean_velocity = 0.5 * (after.mass_velocity + before.mass_velocity);
  const Vec3 force = body.mass * (mass_acceleration + c.damping * mean_velocity) - load.force;
  for (int k = 0; k < 3; ++k)
    if (body.driven[k])
      work += force[k] * 0.5 * (before.step[k] + after.step[k]);
  if (body.rotation == BodyRotation::Prescribed) {
    const Vec3 pivot_acceleration = (after.v - before.v) / c.dt_avg;
    const Vec3 applied = load.moment + pivot_inertia_moment(body, before.R, pivot_acceleration);
    const Vec3 moment =
        (after.L - before.L) / c.dt_avg + c.damping * 0.5 * (after.L + before.L) - applied;
    work += moment.dot(0.5 * (before.turn + after.turn));
  }
  return work;
}

} // namespace trifem::explicit_dynamics
