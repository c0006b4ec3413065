// SPDX-License-Identifier: MIT
#include "trifem/physics/rigid_joints.hpp"

namespace trifem::physics {
namespace {

using rigid::Attachment;
using rigid::Measure;
using rigid::MeasureKind;

// attachments of a joint: the origin in a and in b, then the frame in a and in b
constexpr int kOriginA = 0, kOriginB = 1, kXa = 2, kYa = 3, kZa = 4, kXb = 5, kYb = 6;

/// (p_b − p_a)·e, e an attachment.
Measure gap_along(int e) {
  return {MeasureKind::Sum, {{kOriginB, e, 1.0}, {kOriginA, e, -1.0}}, {}};
}

Measure dot(int i, int j) {
  return {MeasureKind::Sum, {{i, j, 1.0}}, {}};
}

/// The angle of x_b about z_a: atan2(y_a·x_b, x_a·x_b).
Measure angle() {
  return {MeasureKind::Angle, {{kYa, kXb, 1.0}}, {{kXa, kXb, 1.0}}};
}

/// The orthonormal frame (x, y, z) of a joint.
std::array<Vec3, 3> joint_frame(const JointDefinition& j) {
  const Vec3 z = j.axis.normalized();
  Vec3 x = j.transverse - j.transverse.dot(z) * z;
  if (x.norm() < 1e-8 * j.transverse.norm() || x.norm() == 0.0) {
    // any direction normal to z: from the axis least aligned with it
    Eigen::Index least = 0;
    z.cwiseAbs().minCoeff(&least);
    x = Vec3::Unit(least) - z[least] * z;
  }
  x.normalize();
  return {x, z.cross(x), z};
}

void constrain(Connector& c, Measure m, bool angular, Real value = 0.0,
               dofs::LoadCurve curve = dofs::LoadCurve::constant(1.0)) {
  c.constraints.push_back({std::move(m), value, std::move(curve), -1, angular});
}

/// The drive of a free angle (translation) measured by `m`: a constraint, the work of a load
/// or nothing.
void drive(Connector& c, const JointDrive& d, const Measure& m, bool angular) {
  if (d.kind == JointDrive::Kind::Motion)
    constrain(c, m, angular, d.value, d.curve);
  else if (d.kind == JointDrive::Kind::Load)
    c.energies.push_back({m, ConnectorEnergyKind::Force, 0.0, 0.0, d.value, d.curve});
}

} // namespace

bool has_free_rotation(JointKind kind) {
  return kind == JointKind::Revolute || kind == JointKind::Cylindrical || kind == JointKind::Planar;
}

bool has_free_translation(JointKind kind) {
  return kind == JointKind::Prismatic || kind == JointKind::Cylindrical;
}

Connector make_joint(const JointDefinition& j,
                     std::array<std::optional<RigidBodyUnknowns>, 2> bodies) {
  Connector c;
  c.name = j.name;
  c.bodies = std::move(bodies);
  c.attachments = {{0, j.origin, true}, {1, j.origin, true}};
  const auto frame = joint_frame(j);
  for (int body = 0; body < 2; ++body)
    for (const Vec3& e : frame)
      c.attachments.push_back({body, e, false});
  c.origin_b = kOriginB;
  const bool force = false, moment = true;
  const JointKind k = j.kind;
  if (k == JointKind::Spherical || k == JointKind::Revolute || k == JointKind::Lock)
    for (int e : {kXa, kYa, kZa})
      constrain(c, gap_along(e), force);
  if (k == JointKind::Prismatic || k == JointKind::Cylindrical)
    for (int e : {kXa, kYa})
      constrain(c, gap_along(e), force);
  if (k == JointKind::Planar)
    constrain(c, gap_along(kZa), force);
  if (k != JointKind::Spherical)
    for (int e : {kXb, kYb})
      constrain(c, dot(kZa, e), moment);
  if (k == JointKind::Prismatic || k == JointKind::Lock)
    constrain(c, dot(kXa, kYb), moment);
  if (has_free_rotation(k)) {
    drive(c, j.rotation, angle(), moment);
    if (j.torsion_stiffness > 0.0)
      c.energies.push_back({angle(), ConnectorEnergyKind::Spring, j.torsion_stiffness, 0.0});
    c.reported.push_back({"angle", "rad", angle()});
  }
  if (has_free_translation(k)) {
    drive(c, j.translation, gap_along(kZa), force);
    c.reported.push_back({"translation", "mm", gap_along(kZa)});
  }
  return c;
}

Connector make_link(const LinkDefinition& l,
                    std::array<std::optional<RigidBodyUnknowns>, 2> bodies) {
  using Kind = LinkDefinition::Kind;
  Connector c;
  c.name = l.name;
  c.bodies = std::move(bodies);
  c.attachments = {{0, l.point_a, true}, {1, l.point_b, true}};
  c.origin_b = 1;
  const Measure length{MeasureKind::Length, {{0, 0, 1.0}, {1, 1, 1.0}, {0, 1, -2.0}}, {}};
  c.reported.push_back({"length", "mm", length});
  switch (l.kind) {
  case Kind::Spring:
  case Kind::Cable: {
    const Real rest = l.free_length >= 0.0 ? l.free_length : (l.point_b - l.point_a).norm();
    c.energies.push_back(
        {length, l.kind == Kind::Spring ? ConnectorEnergyKind::Spring : ConnectorEnergyKind::Cable,
         l.stiffness, rest});
    break;
  }
  case Kind::Contractile: // energy F ℓ: the work −F ℓ of a force −F along ℓ
    c.energies.push_back({length, ConnectorEnergyKind::Force, 0.0, 0.0, -l.force, l.curve});
    break;
  case Kind::Damper: // the relative displacement of the points in each direction of space
    for (int k = 0; k < 3; ++k) {
      c.attachments.push_back({-1, Vec3::Unit(k), false});
      const int e = static_cast<int>(c.attachments.size()) - 1;
      c.energies.push_back({{MeasureKind::Sum, {{1, e, 1.0}, {0, e, -1.0}}, {}},
                            ConnectorEnergyKind::Viscous,
                            l.stiffness});
    }
    break;
  }
  return c;
}

} // namespace trifem::physics
