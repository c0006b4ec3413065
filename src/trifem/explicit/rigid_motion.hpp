// SPDX-License-Identifier: MIT
// Rigid bodies in the explicit scheme (docs/theory/explicit.md §9): the nodes a body carries
// have no equation of their own; the body's pivot translates and the body turns under the
// resultant and the moment of the forces on its nodes, by central differences of the
// translation and of the angular momentum (the rotation by the exponential map of the
// mid-step angular velocity).
#pragma once

#include "trifem/tensor/tensor.hpp"

#include <array>
#include <string>
#include <vector>

namespace trifem::explicit_dynamics {

/// How the rotation of a body is driven.
enum class BodyRotation {
  None,       ///< a body that only translates
  Free,       ///< turns under its moments
  Prescribed, ///< its rotation vector is prescribed in all three components
  Axis        ///< turns about the coordinate axis `axis`, the other two rotations held at 0
};

/// A rigid body as the explicit integrator sees it (built once by ExplicitView).
struct ExplicitBody {
  std::string name;
  std::vector<Index> nodes;     ///< mesh nodes it carries
  std::vector<Vec3> arms;       ///< X_a − X_P of each node [mm]
  std::array<bool, 3> moves{};  ///< components its nodes follow (all three if it rotates)
  std::array<bool, 3> driven{}; ///< translation components prescribed (of the pivot)
  BodyRotation rotation = BodyRotation::None;
  int axis = -1;               ///< of BodyRotation::Axis
  Vec3 pivot = Vec3::Zero();   ///< X_P: the center of mass, or the center if it is driven [mm]
  Vec3 center = Vec3::Zero();  ///< X_c: the point its unknowns describe [mm]
  Vec3 offset = Vec3::Zero();  ///< X_m − X_P, the center of mass from the pivot [mm]
  Real mass = 0.0;             ///< Σ m_a of its nodes [t]
  Mat3 inertia = Mat3::Zero(); ///< J_P = Σ m_a (|S|² I − S Sᵀ), S = X_a − X_P [t mm²]
  bool rotates() const { return rotation != BodyRotation::None; }
};

/// The motion of a body: its state at t_n and its velocities at t_{n−½}.
struct BodyMotion {
  Vec3 u = Vec3::Zero();             ///< displacement of the pivot [mm]
  Mat3 R = Mat3::Identity();         ///< rotation
  Vec3 v = Vec3::Zero();             ///< pivot velocity v^{n−½} [mm/s]
  Vec3 L = Vec3::Zero();             ///< angular momentum about the pivot at t_{n−½} [t mm²/s]
  Vec3 mass_velocity = Vec3::Zero(); ///< velocity of the center of mass at t_{n−½} [mm/s]
  Vec3 step = Vec3::Zero();          ///< u^n − u^{n−1} of the pivot [mm]
  Vec3 turn = Vec3::Zero();          ///< rotation vector of R^n (R^{n−1})ᵀ [rad]
  static constexpr std::size_t kValues = 27; ///< values of to_values()
  void to_values(std::vector<double>& out) const;
  static BodyMotion from_values(const double* values);
};

/// The resultant force on a body [N] and its moment about the pivot [N mm].
struct BodyLoad {
  Vec3 force = Vec3::Zero();
  Vec3 moment = Vec3::Zero();
};

/// The central-difference coefficients of one step (explicit_solver.hpp: Δt, Δt̄, β, γ).
struct StepCoefficients {
  Real dt = 0.0, dt_avg = 0.0, beta = 1.0, gamma = 1.0, damping = 0.0;
};

/// What a body's drive prescribes at a time: the pivot's displacement (driven components) and
/// the rotation (BodyRotation::Prescribed).
struct BodyTarget {
  Vec3 u = Vec3::Zero();
  Mat3 R = Mat3::Identity();
};

/// Writes the displacements of the nodes of `body` at `motion` into U (3 a + k).
void place(const ExplicitBody& body, const BodyMotion& motion, Vector& U);

/// The resultant and moment about the pivot of the nodal forces `f` (3 a + k) on the nodes of
/// `body` at `motion`.
BodyLoad nodal_load(const ExplicitBody& body, const BodyMotion& motion, const Vector& f);

/// The motion at t_{n+1} from that at t_n under `load` (applied loads included) with the
/// drive's `target` at t_{n+1}. The pivot's acceleration of driven components enters the moment
/// about a pivot that is not the center of mass.
BodyMotion advance(const ExplicitBody& body, const BodyMotion& motion, const BodyLoad& load,
                   const BodyTarget& target, const StepCoefficients& c);

/// The velocity of the pivot and the angular velocity at t_n of a body at `motion` (velocities
/// of t_{n−½}) under `load` at t_n: half a kick after the last step of 2 `half`, or for driven
/// components the drive's central difference between its targets at t_n ∓ `half`.
struct BodyVelocity {
  Vec3 pivot = Vec3::Zero();
  Vec3 omega = Vec3::Zero();
  /// The velocity of a point of the body at arm r (current configuration) from the pivot.
  Vec3 at(const Vec3& r) const { return pivot + omega.cross(r); }
};
BodyVelocity velocity_at_step(const ExplicitBody& body, const BodyMotion& motion,
                              const BodyLoad& load, const BodyTarget& before,
                              const BodyTarget& after, Real half, Real damping);

/// Writes the velocities of the nodes of `body` into v (3 a + k).
void place_velocity(const ExplicitBody& body, const BodyMotion& motion,
                    const BodyVelocity& velocity, Vector& v);

/// The work of the drive of the driven components over the step from `before` to `after`
/// under `load` (at t_n, the step's kicks) [mJ]: the drive's force R = m a_m + c m v̄_m − F
/// times the pivot's travel, and its moment times the turn of a prescribed rotation, each over
/// the step's own interval [t_{n−½}, t_{n+½}].
Real drive_work(const ExplicitBody& body, const BodyMotion& before, const BodyMotion& after,
                const BodyLoad& load, const StepCoefficients& c);

} // namespace trifem::explicit_dynamics
