// SPDX-License-Identifier: MIT
// Rigid bodies that rotate (dofs::RigidMap in an FeProblem): a stress-free block carried through
// half a turn ends exactly rotated; a compressed block between two bodies that then rotate 90°
// keeps its stresses, rotated (objectivity); the Jacobian with freely rotating bodies is the
// derivative of the residual; a body whose rotation is held equals tied nodes.
#include "trifem/assembly/fe_problem.hpp"
#include "trifem/linalg/linear_solver.hpp"
#include "trifem/material/registry.hpp"
#include "trifem/mesh/box.hpp"
#include "trifem/physics/nodal_force_term.hpp"
#include "trifem/physics/rigid_moment_term.hpp"
#include "trifem/physics/solid_term.hpp"
#include "trifem/solver/newton.hpp"
#include "trifem/tensor/rotation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>

using namespace trifem;

namespace {

constexpr Real kPi = std::numbers::pi;

/// How one of a body's six unknowns (u_c then Θ) is driven: free, or prescribed along a curve.
using Drive = std::optional<dofs::LoadCurve>;

/// A body carrying the nodes of a node set of the block.
struct Body {
  std::string set;
  Vec3 centre;
  std::array<Drive, 6> drives;
};

/// A curve through (time, value) points, linear between them.
dofs::LoadCurve through(std::vector<std::pair<Real, Real>> points) {
  return dofs::LoadCurve(std::move(points), dofs::Interpolation::Linear);
}

/// A 2 × 2 × 2 block of neo-Hookean solid (E = 1, ν = 0.3, graded cells) whose node sets may
/// be carried by rigid bodies; the other nodes are free unless clamped.
struct Block {
  mesh::Mesh mesh;
  dofs::DofMap dofs;
  dofs::FieldId u, translation, rotation;
  std::vector<Body> bodies;
  std::vector<dofs::DirichletCondition> conditions;
  std::vector<physics::NodalForce> forces;
  physics::SolidElement element = physics::SolidElement::Displacement;
  const physics::SolidTerm* solid = nullptr;
  std::unique_ptr<assembly::FeProblem> problem;

  Block() {
    mesh::BoxSpec box;
    box.origin = Vec3(-0.4, 0.1, 0.0);
    box.divisions = {2, 2, 2};
    box.grading = Vec3(1.5, 0.8, 1.2);
    mesh = mesh::make_box(box);
    u = dofs.add_field("displacement", FieldRole::displacement, mesh.num_nodes(), 3);
  }

  Index node_dof(Index node, int k) const { return dofs.dof(u, node, k); }
  Index body_dof(int b, int k) const {
    return k < 3 ? dofs.dof(translation, b, k) : dofs.dof(rotation, b, k - 3);
  }
  void clamp(const std::string& set) {
    dofs::DirichletCondition c{{}, 0.0, dofs::LoadCurve::constant(1.0)};
    for (Index n : mesh.node_set(set))
      for (int k = 0; k < 3; ++k)
        c.dofs.push_back(node_dof(n, k));
    conditions.push_back(std::move(c));
  }

  /// Adds the bodies' fields, makes their nodes dependent and builds the problem.
  void build() {
    const Index nb = static_cast<Index>(bodies.size());
    std::vector<dofs::RigidBodyDofs> rigid;
    if (nb > 0) {
      translation = dofs.add_field("rigid_translation", FieldRole::rigid_motion, nb, 3);
      rotation = dofs.add_field("rigid_rotation", FieldRole::rigid_motion, nb, 3);
    }
    for (int b = 0; b < static_cast<int>(nb); ++b) {
      dofs::RigidBodyDofs r;
      r.centre = bodies[b].centre;
      for (int k = 0; k < 3; ++k) {
        r.translation[k] = body_dof(b, k);
        r.rotation[k] = body_dof(b, k + 3);
      }
      for (Index n : mesh.node_set(bodies[b].set)) {
        r.followers.push_back({node_dof(n, 0), node_dof(n, 1), node_dof(n, 2)});
        r.arms.push_back(mesh.node(n) - r.centre);
        for (int k = 0; k < 3; ++k)
          dofs.make_dependent(node_dof(n, k));
      }
      for (int k = 0; k < 6; ++k)
        if (bodies[b].drives[k])
          conditions.push_back({{body_dof(b, k)}, 1.0, *bodies[b].drives[k]});
      rigid.push_back(std::move(r));
    }
    dofs::constrain_all(conditions, dofs);
    dofs.finalize();
    std::vector<Index> cells(mesh.num_cells());
    for (Index c = 0; c < mesh.num_cells(); ++c)
      cells[c] = c;
    const std::shared_ptr<const material::ElasticLaw> law =
        material::create_law("neo-hookean", {{"E", 1.0}, {"nu", 0.3}}, "law");
    std::vector<std::unique_ptr<physics::Term>> terms;
    auto s = std::make_unique<physics::SolidTerm>(
        mesh, dofs, u, cells, std::vector<std::shared_ptr<const material::ElasticLaw>>(8, law),
        std::vector<physics::SolidElement>(cells.size(), element));
    solid = s.get();
    terms.push_back(std::move(s));
    if (!forces.empty())
      terms.push_back(std::make_unique<physics::NodalForceTerm>(forces));
    std::vector<solver::FieldScale> scales{{"displacement", 1.0, 1.0}};
    if (nb > 0) {
      scales.push_back({"rigid_translation", 1.0, 1.0});
      scales.push_back({"rigid_rotation", 1.0, 1.0});
    }
    problem = std::make_unique<assembly::FeProblem>(
        dofs, conditions, std::move(terms), std::move(scales), dofs::NodalFrames{},
        dofs::RigidMap(std::move(rigid), dofs.num_dofs()));
  }

  /// Steps of `dt` to `end`, each solved to round-off; false if one fails.
  bool solve_to(Real end, Real dt) {
    solver::NewtonSettings settings;
    settings.residual_tolerance = 1e-12;
    settings.increment_tolerance = 1e-13;
    solver::NewtonSolver newton(settings, linalg::make_linear_solver({LinearSolverKind::umfpack}));
    for (Real t = problem->time() + dt; t <= end + 1e-12; t += dt) {
      problem->begin_step(t, dt);
      if (newton.solve(*problem).status != solver::SolveStatus::Converged)
        return false;
      problem->commit_step();
    }
    return true;
  }

  /// Current position of a node.
  Vec3 position(Index node) const {
    const Vector& x = problem->state();
    return mesh.node(node) + Vec3(x[node_dof(node, 0)], x[node_dof(node, 1)], x[node_dof(node, 2)]);
  }
};

const Vec3 kAxis = Vec3(1.0, 2.0, 3.0).normalized();

} // namespace

TEST(RigidRotation, AStressFreeBlockCarriedThroughHalfATurnEndsExactlyRotated) {
  Block block;
  const Vec3 centre(0.3, -0.2, 0.5), shift(0.2, -0.1, 0.4);
  Body body{"box.zmin", centre, {}};
  for (int k = 0; k < 3; ++k) {
    body.drives[k] = through({{0.0, 0.0}, {1.0, shift[k]}});
    body.drives[k + 3] = through({{0.0, 0.0}, {1.0, kPi * kAxis[k]}});
  }
  block.bodies = {body};
  block.build();
  ASSERT_TRUE(block.solve_to(1.0, 1.0 / 3.0)); // three steps of 60°
  const Mat3 R = rotation::matrix(kPi * kAxis);
  Real error = 0.0;
  for (Index n = 0; n < block.mesh.num_nodes(); ++n)
    error = std::max(
        error, (block.position(n) - (centre + shift + R * (block.mesh.node(n) - centre))).norm());
  EXPECT_LT(error, 1e-12); // block size 1
  EXPECT_LT(block.solid->stress(0, block.problem->state()).cauchy.norm(), 1e-12);
}

TEST(RigidRotation, ABlockCompressedBetweenTwoBodiesKeepsItsStressesRotated) {
  for (const physics::SolidElement element :
       {physics::SolidElement::Displacement, physics::SolidElement::MeanDilatation}) {
    Block block;
    block.element = element;
    // the bottom body stays, the top one compresses the block by 20 % (t: 0 → 1); then both
    // turn 90° about an axis through P (t: 1 → 2, three steps)
    const Vec3 P(0.7, -0.3, 0.2);
    const Real quarter = kPi / 2.0;
    const std::vector<Real> times{1.0, 4.0 / 3.0, 5.0 / 3.0, 2.0};
    std::array<Body, 2> bodies{Body{"box.zmin", Vec3(-0.1, 0.4, 0.0), {}},
                               Body{"box.zmax", Vec3(0.2, 0.7, 1.1), {}}};
    for (int b = 0; b < 2; ++b) {
      const Vec3 start = bodies[b].centre + (b == 1 ? Vec3(0.0, 0.0, -0.2) : Vec3::Zero());
      std::array<std::vector<std::pair<Real, Real>>, 6> points;
      for (int k = 0; k < 6; ++k)
        points[k] = {{0.0, 0.0}};
      for (Real t : times) { // the centre's path: P + R(t)(start − P)
        const Vec3 theta = (t - 1.0) * quarter * kAxis;
        const Vec3 uc = P + rotation::matrix(theta) * (start - P) - bodies[b].centre;
        for (int k = 0; k < 3; ++k) {
          points[k].push_back({t, uc[k]});
          points[k + 3].push_back({t, theta[k]});
        }
      }
      for (int k = 0; k < 6; ++k)
        bodies[b].drives[k] = through(points[k]);
    }
    block.bodies = {bodies[0], bodies[1]};
    block.build();
    ASSERT_TRUE(block.solve_to(1.0, 0.5));
    std::vector<Vec3> compressed;
    for (Index n = 0; n < block.mesh.num_nodes(); ++n)
      compressed.push_back(block.position(n));
    std::vector<Mat3> stress;
    for (Index c = 0; c < block.mesh.num_cells(); ++c)
      stress.push_back(block.solid->stress(c, block.problem->state()).cauchy);
    ASSERT_GT(stress[0].norm(), 0.05);
    ASSERT_TRUE(block.solve_to(2.0, 1.0 / 3.0));
    const Mat3 R = rotation::matrix(quarter * kAxis);
    Real position_error = 0.0, stress_error = 0.0, stress_scale = 0.0;
    for (Index n = 0; n < block.mesh.num_nodes(); ++n)
      position_error =
          std::max(position_error, (block.position(n) - (P + R * (compressed[n] - P))).norm());
    for (Index c = 0; c < block.mesh.num_cells(); ++c) {
      const Mat3 rotated = block.solid->stress(c, block.problem->state()).cauchy;
      stress_error = std::max(stress_error, (rotated - R * stress[c] * R.transpose()).norm());
      stress_scale = std::max(stress_scale, stress[c].norm());
    }
    EXPECT_LT(position_error, 1e-10) << static_cast<int>(element); // block size 1
    EXPECT_LT(stress_error, 1e-10 * stress_scale) << static_cast<int>(element);
  }
}

TEST(RigidRotation, TheJacobianWithFreelyRotatingBodiesIsTheDerivativeOfTheResidual) {
  Block block;
  block.bodies = {Body{"box.zmin", Vec3(0.1, 0.5, -0.2), {}},
                  Body{"box.zmax", Vec3(-0.3, 0.4, 1.3), {}}};
  block.forces = {{block.node_dof(13, 0), 0.05, dofs::LoadCurve::constant(1.0)}};
  block.build();
  // both bodies turned by about 2.5 rad, the block nearly carried along, slightly deformed
  const Vec3 theta = 2.5 * Vec3(0.6, -0.48, 0.64);
  const Mat3 R = rotation::matrix(theta);
  Vector x = Vector::Zero(block.dofs.num_dofs());
  for (Index n = 0; n < block.mesh.num_nodes(); ++n) {
    const Vec3 X = block.mesh.node(n);
    const Vec3 wobble = 0.03 * Vec3(std::sin(3.0 * X.y()), std::cos(2.0 * X.z()), X.x() * X.y());
    const Vec3 un = (R - Mat3::Identity()) * X + wobble;
    for (int k = 0; k < 3; ++k)
      x[block.node_dof(n, k)] = un[k];
  }
  for (int b = 0; b < 2; ++b) {
    const Vec3 c = block.bodies[b].centre;
    const Vec3 uc = (R - Mat3::Identity()) * c + Vec3(0.01, -0.02, 0.015) * (b + 1);
    const Vec3 tb = theta + Vec3(0.02, 0.05, -0.03) * b;
    for (int k = 0; k < 3; ++k) {
      x[block.body_dof(b, k)] = uc[k];
      x[block.body_dof(b, k + 3)] = tb[k];
    }
  }
  assembly::FeProblem& p = *block.problem;
  p.set_state(x);
  solver::Linearization lin;
  ASSERT_EQ(p.linearize(lin, true), solver::SolveStatus::Converged);
  const Eigen::MatrixXd J(lin.jacobian);
  const Vector r0 = lin.residual;
  ASSERT_GT(r0.norm(), 1e-3); // away from equilibrium: the geometric stiffness counts
  const Index neq = p.num_equations();
  const Real h = 1e-6;
  Eigen::MatrixXd fd(neq, neq);
  for (Index j = 0; j < neq; ++j) {
    Vector e = Vector::Zero(neq);
    e[j] = h;
    p.save_iterate();
    p.update(e, 1.0);
    solver::Linearization plus;
    p.linearize(plus, false);
    p.restore_iterate();
    p.update(-e, 1.0);
    solver::Linearization minus;
    p.linearize(minus, false);
    p.restore_iterate();
    fd.col(j) = (plus.residual - minus.residual) / (2.0 * h);
  }
  const Real scale = J.cwiseAbs().maxCoeff();
  EXPECT_LT((J - fd).cwiseAbs().maxCoeff(), 1e-7 * scale);
  // the residual of a hyperelastic body under a dead load has a symmetric Jacobian
  EXPECT_LT((J - J.transpose()).cwiseAbs().maxCoeff(), 1e-12 * scale);
}

TEST(RigidRotation, ABodyWhoseRotationIsHeldEqualsTiedNodes) {
  // top face pressed down by 0.2 and pulled sideways at a free node; the face may slide in x, y
  const auto press = [](Block& block) {
    block.clamp("box.zmin");
    block.forces = {{block.node_dof(14, 0), 0.05, through({{0.0, 0.0}, {1.0, 1.0}})}};
  };
  Block rotating;
  press(rotating);
  Body top{"box.zmax", Vec3(0.0, 0.6, 1.0), {}};
  top.drives[2] = through({{0.0, 0.0}, {1.0, -0.2}});
  for (int k = 3; k < 6; ++k)
    top.drives[k] = dofs::LoadCurve::constant(0.0);
  rotating.bodies = {top};
  rotating.build();
  ASSERT_TRUE(rotating.solve_to(1.0, 0.5));

  Block tied;
  press(tied);
  const std::vector<Index>& face = tied.mesh.node_set("box.zmax");
  dofs::DirichletCondition down{{}, -0.2, through({{0.0, 0.0}, {1.0, 1.0}})};
  for (Index n : face) {
    down.dofs.push_back(tied.node_dof(n, 2));
    for (int k = 0; k < 2; ++k)
      if (n != face.front())
        tied.dofs.tie(tied.node_dof(n, k), tied.node_dof(face.front(), k));
  }
  tied.conditions.push_back(down);
  tied.build();
  ASSERT_TRUE(tied.solve_to(1.0, 0.5));
  Real difference = 0.0, motion = 0.0;
  for (Index n = 0; n < tied.mesh.num_nodes(); ++n) {
    difference = std::max(difference, (rotating.position(n) - tied.position(n)).norm());
    motion = std::max(motion, (tied.position(n) - tied.mesh.node(n)).norm());
  }
  ASSERT_GT(std::abs(tied.position(face.front()).x() - tied.mesh.node(face.front()).x()), 1e-3);
  EXPECT_LT(difference, 1e-12 * (1.0 + motion));
}

TEST(RigidRotation, TheTangentOfADeadMomentIsTheDerivativeOfItsResidual) {
  // R_Θ = −T(Θ)ᵀ M(t), K = −H(Θ, M): central differences in Θ at rotations across the
  // series threshold and up to 3 rad
  const physics::RigidMomentTerm term(
      {{{0, 1, 2}, Vec3(0.4, -1.1, 0.7), through({{0.0, 0.0}, {1.0, 2.0}})}});
  for (const Real angle : {0.0, 0.2, 1.0, 3.0}) {
    Vector x = angle * kAxis;
    const physics::EvalState state{x, x, 0.5, 0.5};
    physics::LocalVector r;
    physics::LocalMatrix K;
    ASSERT_TRUE(term.evaluate(0, state, r, &K));
    const Vec3 moment = Vec3(0.4, -1.1, 0.7); // curve(0.5) = 1
    EXPECT_LT((r + rotation::tangent(angle * kAxis).transpose() * moment).norm(), 1e-15) << angle;
    const Real h = 1e-6;
    for (int j = 0; j < 3; ++j) {
      Vector plus = x, minus = x;
      plus[j] += h;
      minus[j] -= h;
      physics::LocalVector rp, rm;
      term.evaluate(0, {plus, plus, 0.5, 0.5}, rp, nullptr);
      term.evaluate(0, {minus, minus, 0.5, 0.5}, rm, nullptr);
      EXPECT_LT((K.col(j) - (rp - rm) / (2.0 * h)).norm(), 1e-8 * moment.norm())
          << angle << " column " << j;
    }
  }
}
