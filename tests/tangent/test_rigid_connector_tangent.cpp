// SPDX-License-Identifier: MIT
// Rigid connectors: finite-difference checks of the tangent of every joint and link at finite
// rotations of both bodies, the balance of their loads, and exact joint kinematics (a motion
// the joint allows leaves its constraints at zero and its angle or translation is the one
// applied).
#include "trifem/physics/rigid_joints.hpp"
#include "trifem/physics/rigid_moment_term.hpp"
#include "trifem/tensor/rotation.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace trifem;
using physics::Connector;
using physics::JointDefinition;
using physics::JointDrive;
using physics::JointKind;
using physics::LinkDefinition;

namespace {

constexpr JointKind kJoints[] = {JointKind::Spherical,   JointKind::Revolute, JointKind::Prismatic,
                                 JointKind::Cylindrical, JointKind::Planar,   JointKind::Lock};

/// Body a on DOFs 0..5, body b on 6..11 (centers apart), multipliers from 12.
std::array<std::optional<physics::RigidBodyUnknowns>, 2> two_bodies(bool a_moves = true,
                                                                    bool b_moves = true) {
  std::array<std::optional<physics::RigidBodyUnknowns>, 2> bodies;
  if (a_moves)
    bodies[0] = physics::RigidBodyUnknowns{{0, 1, 2}, {3, 4, 5}, Vec3(-1.0, 0.2, 0.1)};
  if (b_moves)
    bodies[1] = physics::RigidBodyUnknowns{{6, 7, 8}, {9, 10, 11}, Vec3(1.2, -0.3, 0.5)};
  return bodies;
}

void number_multipliers(Connector& c) {
  Index next = 12;
  for (auto& g : c.constraints)
    g.multiplier = next++;
}

JointDefinition driven_joint(JointKind kind) {
  JointDefinition j;
  j.name = "joint";
  j.kind = kind;
  j.origin = Vec3(0.1, 0.3, -0.2);
  j.axis = Vec3(0.2, 1.0, 0.4);
  j.transverse = Vec3(1.0, 0.0, 0.3);
  j.rotation = {JointDrive::Kind::Motion, 0.7, dofs::LoadCurve::constant(1.0)};
  j.translation = {JointDrive::Kind::Load, 3.0, dofs::LoadCurve::constant(1.0)};
  j.torsion_stiffness = 5.0;
  return j;
}

/// Every connector kind, with drives of both sorts.
std::vector<Connector> all_connectors(bool a_moves = true, bool b_moves = true) {
  std::vector<Connector> out;
  for (JointKind kind : kJoints)
    out.push_back(physics::make_joint(driven_joint(kind), two_bodies(a_moves, b_moves)));
  JointDefinition loaded = driven_joint(JointKind::Cylindrical);
  loaded.rotation = {JointDrive::Kind::Load, -2.0, dofs::LoadCurve::constant(1.0)};
  loaded.translation = {JointDrive::Kind::Motion, 0.4, dofs::LoadCurve::constant(1.0)};
  out.push_back(physics::make_joint(loaded, two_bodies(a_moves, b_moves)));
  using LK = LinkDefinition::Kind;
  for (LK kind : {LK::Spring, LK::Cable, LK::Damper, LK::Contractile}) {
    LinkDefinition l;
    l.kind = kind;
    l.point_a = Vec3(-0.5, 0.1, 0.2);
    l.point_b = Vec3(0.7, -0.2, 0.9);
    l.stiffness = 4.0;
    l.free_length = 0.5; // stretched: the cable pulls
    l.force = 2.5;
    out.push_back(physics::make_link(l, two_bodies(a_moves, b_moves)));
  }
  for (Connector& c : out)
    number_multipliers(c);
  return out;
}

/// A state with both bodies moved and turned (rotation angle `angle` about varied axes).
Vector random_state(std::mt19937& rng, Real angle, Index size) {
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  Vector x(size);
  for (Index i = 0; i < size; ++i)
    x[i] = 0.3 * u(rng);
  for (int k = 0; k < 2; ++k) {
    Vec3 axis(u(rng), u(rng), u(rng));
    x.segment<3>(6 * k + 3) = angle * axis.normalized();
  }
  return x;
}

} // namespace

TEST(RigidConnectorTangent, EveryConnectorsJacobianIsTheDerivativeOfItsResidual) {
  std::mt19937 rng(7);
  const physics::RigidConnectorTerm term(all_connectors());
  for (Index e = 0; e < term.num_elements(); ++e) {
    const Index size = 12 + static_cast<Index>(term.connectors()[e].constraints.size());
    for (const Real angle : {0.0, 0.1, 0.8, 2.5}) {
      const Vector x = random_state(rng, angle, size);
      const Vector x_old = random_state(rng, angle, size);
      const physics::EvalState state{x, x_old, 0.5, 0.25};
      physics::LocalVector r;
      physics::LocalMatrix K;
      ASSERT_TRUE(term.evaluate(e, state, r, &K));
      ASSERT_EQ(K.rows(), size);
      const Real h = 1e-6;
      const Real scale = std::max(1.0, K.cwiseAbs().maxCoeff());
      for (Index j = 0; j < size; ++j) {
        Vector plus = x, minus = x;
        plus[j] += h;
        minus[j] -= h;
        physics::LocalVector rp, rm;
        ASSERT_TRUE(term.evaluate(e, {plus, x_old, 0.5, 0.25}, rp, nullptr));
        ASSERT_TRUE(term.evaluate(e, {minus, x_old, 0.5, 0.25}, rm, nullptr));
        EXPECT_LT((K.col(j) - (rp - rm) / (2.0 * h)).norm(), 1e-7 * scale)
            << "connector " << e << " angle " << angle << " column " << j;
      }
    }
  }
}

TEST(RigidConnectorTangent, AConnectorToSpaceHasTheUnknownsOfItsOneBody) {
  std::mt19937 rng(11);
  for (const auto& [a_moves, b_moves] : {std::pair{true, false}, {false, true}}) {
    const physics::RigidConnectorTerm term(all_connectors(a_moves, b_moves));
    for (Index e = 0; e < term.num_elements(); ++e) {
      std::vector<Index> dofs;
      term.element_dofs(e, dofs);
      const Index constraints = static_cast<Index>(term.connectors()[e].constraints.size());
      ASSERT_EQ(static_cast<Index>(dofs.size()), 6 + constraints);
      EXPECT_EQ(dofs.front(), a_moves ? 0 : 6);
      const Vector x = random_state(rng, 0.6, 12 + constraints);
      physics::LocalVector r, rp, rm;
      physics::LocalMatrix K;
      ASSERT_TRUE(term.evaluate(e, {x, x, 0.5, 0.25}, r, &K));
      const Real h = 1e-6, scale = std::max(1.0, K.cwiseAbs().maxCoeff());
      for (Index j = 0; j < static_cast<Index>(dofs.size()); ++j) {
        Vector plus = x, minus = x;
        plus[dofs[j]] += h;
        minus[dofs[j]] -= h;
        term.evaluate(e, {plus, x, 0.5, 0.25}, rp, nullptr);
        term.evaluate(e, {minus, x, 0.5, 0.25}, rm, nullptr);
        EXPECT_LT((K.col(j) - (rp - rm) / (2.0 * h)).norm(), 1e-7 * scale) << e << " " << j;
      }
    }
  }
}

TEST(RigidConnectorTangent, AConnectorsLoadsOnItsTwoBodiesBalance) {
  // translation and rotation invariance of every measure: Σ F = 0 and Σ (M_c + c × F) = 0
  std::mt19937 rng(3);
  const physics::RigidConnectorTerm term(all_connectors());
  for (Index e = 0; e < term.num_elements(); ++e) {
    if (term.connectors()[e].energies.size() == 3 && term.connectors()[e].constraints.empty())
      continue; // the damper's directions are fixed in space
    const Index size = 12 + static_cast<Index>(term.connectors()[e].constraints.size());
    const Vector x = random_state(rng, 1.3, size);
    physics::LocalVector r;
    ASSERT_TRUE(term.evaluate(e, {x, x, 0.5, 0.25}, r, nullptr));
    Vec3 force = Vec3::Zero(), moment = Vec3::Zero();
    const auto& bodies = term.connectors()[e].bodies;
    for (int k = 0; k < 2; ++k) {
      const Vec3 f = -r.segment<3>(6 * k);
      const Vec3 theta = x.segment<3>(6 * k + 3);
      const Vec3 m =
          -rotation::tangent(theta).transpose().lu().solve(Vec3(r.segment<3>(6 * k + 3)));
      const Vec3 centre = bodies[k]->centre + x.segment<3>(6 * k);
      force += f;
      moment += m + centre.cross(f);
    }
    const Real scale = r.head<12>().norm();
    EXPECT_LT(force.norm(), 1e-13 * scale) << e;
    EXPECT_LT(moment.norm(), 1e-12 * scale) << e;
  }
}

TEST(RigidConnectorTangent, AMotionAJointAllowsKeepsItsConstraintsAndIsMeasured) {
  // body a moved and turned; body b turned about the joint's current axis by φ and slid along
  // it by s where the joint allows (the drives of driven_joint prescribe φ = 0.7, s = 0.4)
  const std::vector<Connector> connectors = all_connectors();
  const physics::RigidConnectorTerm term(connectors);
  for (std::size_t e = 0; e < 7; ++e) { // the joints
    const Connector& c = connectors[e];
    const JointKind kind = e < 6 ? kJoints[e] : JointKind::Cylindrical;
    const Real phi = physics::has_free_rotation(kind) ? 0.7 : 0.0;
    const Real s = physics::has_free_translation(kind) ? 0.4 : 0.0;
    const Vec3 theta_a(0.3, -1.2, 0.8), u_a(0.05, -0.1, 0.2);
    const Mat3 Ra = rotation::matrix(theta_a);
    const JointDefinition j = driven_joint(kind);
    const Vec3 z = Ra * j.axis.normalized();
    Vec3 x_dir = j.transverse - j.transverse.dot(j.axis.normalized()) * j.axis.normalized();
    x_dir = Ra * x_dir.normalized();
    Mat3 Rb = rotation::matrix(phi * z) * Ra;
    Vec3 slide = s * z;
    if (kind == JointKind::Spherical)
      Rb = rotation::matrix(Vec3(-0.4, 0.9, 0.2)) * Ra;
    if (kind == JointKind::Planar)
      slide = 0.3 * x_dir + 0.5 * z.cross(x_dir);
    const Vec3 ca = c.bodies[0]->centre, cb = c.bodies[1]->centre;
    const Vec3 p_a = ca + u_a + Ra * (j.origin - ca);
    const Vec3 p_b = p_a + slide;
    const Vec3 u_b = p_b - Rb * (j.origin - cb) - cb;
    Vector x = Vector::Zero(12 + static_cast<Index>(c.constraints.size()));
    x.segment<3>(0) = u_a;
    x.segment<3>(3) = theta_a;
    x.segment<3>(6) = u_b;
    x.segment<3>(9) = rotation::vector(Rb);
    physics::LocalVector r;
    ASSERT_TRUE(term.evaluate(static_cast<Index>(e), {x, x, 0.5, 0.25}, r, nullptr));
    EXPECT_LT(r.tail(static_cast<Index>(c.constraints.size())).norm(), 1e-14) << e;
    for (const auto& m : c.reported) {
      const Real expected = m.name == "angle" ? phi : s;
      EXPECT_NEAR(term.measure(static_cast<Index>(e), m.measure, x), expected, 1e-14)
          << e << " " << m.name;
    }
  }
}

TEST(RigidConnectorTangent, AFollowerLoadsTangentIsTheDerivativeOfItsResidual) {
  // a force at a point of the body and a moment, both turning with it, at rotations across the
  // series threshold and up to 3 rad
  const Vec3 arm(0.4, -0.7, 1.1), force(0.3, 1.2, -0.5), moment(-0.8, 0.2, 0.6);
  const physics::RigidFollowerTerm term(
      {{{0, 1, 2}, {3, 4, 5}, arm, force, moment, dofs::LoadCurve::constant(1.0)}});
  const Vec3 axis = Vec3(1.0, -2.0, 0.5).normalized();
  for (const Real angle : {0.0, 0.2, 1.0, 3.0}) {
    Vector x(6);
    x << 0.1, -0.2, 0.3, angle * axis;
    physics::LocalVector r;
    physics::LocalMatrix K;
    ASSERT_TRUE(term.evaluate(0, {x, x, 0.5, 0.5}, r, &K));
    const Mat3 R = rotation::matrix(angle * axis), T = rotation::tangent(angle * axis);
    EXPECT_LT((r.head<3>() + R * force).norm(), 1e-15) << angle;
    EXPECT_LT(
        (r.tail<3>() + T.transpose() * (R * arm).cross(R * force) + T.transpose() * R * moment)
            .norm(),
        1e-14)
        << angle;
    const Real h = 1e-6;
    for (int j = 0; j < 6; ++j) {
      Vector plus = x, minus = x;
      plus[j] += h;
      minus[j] -= h;
      physics::LocalVector rp, rm;
      term.evaluate(0, {plus, plus, 0.5, 0.5}, rp, nullptr);
      term.evaluate(0, {minus, minus, 0.5, 0.5}, rm, nullptr);
      EXPECT_LT((K.col(j) - (rp - rm) / (2.0 * h)).norm(), 1e-8) << angle << " column " << j;
    }
  }
}
