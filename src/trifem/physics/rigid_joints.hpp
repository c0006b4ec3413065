// SPDX-License-Identifier: MIT
// The connectors a user names (docs/theory/rigid.md §5): joints, springs, cables, dampers and
// contractile forces between two rigid bodies, built from the measures of rigid_measure.hpp.
// A joint has a frame (x, y, z) fixed in body a, z its axis, and the same frame fixed in body b
// where the two coincide in the reference configuration; its constraints keep the origins and
// axes together:
//
//   spherical    (p_b − p_a)·x = (p_b − p_a)·y = (p_b − p_a)·z = 0
//   revolute     spherical and z_a·x_b = z_a·y_b = 0             angle about z free
//   prismatic    (p_b − p_a)·x = (p_b − p_a)·y = 0, z_a·x_b = z_a·y_b = x_a·y_b = 0
//   cylindrical  (p_b − p_a)·x = (p_b − p_a)·y = 0, z_a·x_b = z_a·y_b = 0
//   planar       (p_b − p_a)·z = 0, z_a·x_b = z_a·y_b = 0          (z: the plane's normal)
//   lock         all six
//
// The angle of b about z is φ = atan2(y_a·x_b, x_a·x_b), the translation along z is
// (p_b − p_a)·z_a; either may be prescribed (a further constraint) or loaded by a moment
// (force) M doing the work Mφ, and the angle may have a torsion spring ½kφ².
#pragma once

#include "trifem/physics/rigid_connector_term.hpp"

namespace trifem::physics {

enum class JointKind { Spherical, Revolute, Prismatic, Cylindrical, Planar, Lock };

/// How the free angle (translation) of a joint is driven.
struct JointDrive {
  enum class Kind { Free, Motion, Load } kind = Kind::Free;
  Real value = 0.0; ///< angle [rad] (translation [mm]), or moment [N mm] (force [N])
  dofs::LoadCurve curve = dofs::LoadCurve::constant(1.0);
};

struct JointDefinition {
  std::string name;
  JointKind kind = JointKind::Spherical;
  Vec3 origin = Vec3::Zero();
  Vec3 axis = Vec3::UnitZ();       ///< z (normalised here)
  Vec3 transverse = Vec3::UnitX(); ///< x: made orthogonal to z; any if parallel to it
  JointDrive rotation;             ///< about z (revolute, cylindrical, planar)
  JointDrive translation;          ///< along z (prismatic, cylindrical)
  Real torsion_stiffness = 0.0;    ///< [N mm/rad] about z (revolute, cylindrical, planar)
};

/// Whether a joint of `kind` has a free angle about its axis (a free translation along it).
bool has_free_rotation(JointKind kind);
bool has_free_translation(JointKind kind);

/// The joint between `bodies` (none: space). Constraints have no multiplier DOF yet.
Connector make_joint(const JointDefinition& joint,
                     std::array<std::optional<RigidBodyUnknowns>, 2> bodies);

/// A connector between a point of body a and a point of body b.
struct LinkDefinition {
  std::string name;
  enum class Kind {
    Spring,     ///< force k (ℓ − ℓ0) along the line
    Cable,      ///< the same in tension only
    Damper,     ///< force c (v_b − v_a): the relative velocity of the points
    Contractile ///< force F(t) pulling the points together
  } kind = Kind::Spring;
  Vec3 point_a = Vec3::Zero(), point_b = Vec3::Zero(); ///< reference positions [mm]
  Real stiffness = 0.0;                                ///< k [N/mm] or c [N s/mm]
  Real free_length = -1.0;                             ///< ℓ0 [mm]; < 0: the reference distance
  Real force = 0.0;                                    ///< F [N] (with curve)
  dofs::LoadCurve curve = dofs::LoadCurve::constant(1.0);
};

Connector make_link(const LinkDefinition& link,
                    std::array<std::optional<RigidBodyUnknowns>, 2> bodies);

} // namespace trifem::physics
