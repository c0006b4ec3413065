// SPDX-License-Identifier: MIT
// Constraints: finite-difference checks of the tangent of the linear constraints and of the
// rigid wall (active and inactive nodes), and the wall's gap and force.
#include "trifem/contact/rigid_wall_term.hpp"
#include "trifem/mesh/box.hpp"
#include "trifem/physics/linear_constraint_term.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace trifem;

namespace {

/// Max over the columns of |K_j − (R(x + h e_j) − R(x − h e_j)) / 2h|, relative to max |K|.
Real tangent_error(const physics::Term& term, Index e, const Vector& x, Real time) {
  std::vector<Index> dofs;
  term.element_dofs(e, dofs);
  physics::LocalVector r;
  physics::LocalMatrix K;
  EXPECT_TRUE(term.evaluate(e, {x, x, time, 0.1}, r, &K));
  const Real h = 1e-6;
  Real worst = 0.0;
  for (std::size_t j = 0; j < dofs.size(); ++j) {
    Vector plus = x, minus = x;
    plus[dofs[j]] += h;
    minus[dofs[j]] -= h;
    physics::LocalVector rp, rm;
    EXPECT_TRUE(term.evaluate(e, {plus, x, time, 0.1}, rp, nullptr));
    EXPECT_TRUE(term.evaluate(e, {minus, x, time, 0.1}, rm, nullptr));
    worst = std::max(worst, (K.col(static_cast<Index>(j)) - (rp - rm) / (2.0 * h)).norm());
  }
  return worst / std::max(1.0, K.cwiseAbs().maxCoeff());
}

Vector random_vector(Index size, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  Vector x(size);
  for (Index i = 0; i < size; ++i)
    x[i] = u(rng);
  return x;
}

/// A unit cube of one cell: displacements on 8 nodes, one multiplier per node of its top face.
struct WallSetup {
  mesh::Mesh mesh = mesh::make_box({});
  dofs::DofMap dofs;
  dofs::FieldId u, lambda;
  std::vector<Index> nodes = mesh::surface_nodes(mesh.surface("box.zmax"));

  WallSetup() {
    u = dofs.add_field("displacement", FieldRole::displacement, mesh.num_nodes(), 3);
    lambda = dofs.add_field("wall", FieldRole::multiplier, static_cast<Index>(nodes.size()), 1);
    dofs.finalize();
  }
  contact::RigidWallTerm wall(Real offset) const {
    contact::RigidWallSettings s;
    s.point = Vec3(0.0, 0.0, 1.5);
    s.normal = Vec3(0.1, -0.2, -1.0).normalized(); // above the top face, facing down
    s.offset = offset;
    s.curve = dofs::LoadCurve({{0.0, 0.0}, {1.0, 1.0}}, dofs::Interpolation::Linear);
    s.scale = 7.0;
    s.gap_tolerance = 1e-9;
    s.release_threshold = 1e-12;
    return {mesh, dofs, u, lambda, nodes, s};
  }
};

} // namespace

TEST(ConstraintTangent, ALinearConstraintsJacobianIsTheDerivativeOfItsResidual) {
  physics::LinearConstraint c;
  c.coefficients = {{0, 0.6}, {3, -1.0}, {5, 2.5}};
  c.multiplier = 6;
  c.value = 0.3;
  c.curve = dofs::LoadCurve({{0.0, 0.0}, {1.0, 2.0}}, dofs::Interpolation::Linear);
  const physics::LinearConstraintTerm term({c});
  const Vector x = random_vector(7, 3);
  EXPECT_LT(tangent_error(term, 0, x, 0.5), 1e-9);
  // the residual: R_λ = Σ c_j x_j − value·curve(t), R_{d_j} = λ c_j
  physics::LocalVector r;
  ASSERT_TRUE(term.evaluate(0, {x, x, 0.5, 0.1}, r, nullptr));
  EXPECT_NEAR(r[3], 0.6 * x[0] - x[3] + 2.5 * x[5] - 0.3, 1e-15);
  EXPECT_NEAR(r[1], -x[6], 1e-15);
}

TEST(ConstraintTangent, ARigidWallsJacobianIsTheDerivativeOfItsResidualActiveOrNot) {
  const WallSetup setup;
  contact::RigidWallTerm wall = setup.wall(0.4);
  Vector x = 0.05 * random_vector(setup.dofs.num_dofs(), 5);
  // push two top nodes through the (moved) wall so that they become active
  const Real t = 0.5;
  for (Index k : {Index(0), Index(2)})
    x[setup.dofs.dof(setup.u, setup.nodes[k], 2)] += 0.5;
  wall.prepare({x, x, t, 0.1});
  Index active = 0;
  for (Index k = 0; k < wall.num_elements(); ++k) {
    active += wall.active_set().active(k) ? 1 : 0;
    EXPECT_LT(tangent_error(wall, k, x, t), 1e-9) << "node " << k;
  }
  EXPECT_EQ(active, 2); // the gap decides at the first evaluation
}

TEST(ConstraintTangent, ARigidWallsGapIsTheSignedDistanceToTheMovedPlane) {
  const WallSetup setup;
  const contact::RigidWallTerm wall = setup.wall(0.4);
  const Vec3 n = Vec3(0.1, -0.2, -1.0).normalized();
  const Vector x = 0.05 * random_vector(setup.dofs.num_dofs(), 9);
  for (Index k = 0; k < wall.num_elements(); ++k) {
    const Index node = setup.nodes[k];
    const Vec3 p = setup.mesh.node(node) + Vec3(x[setup.dofs.dof(setup.u, node, 0)],
                                                x[setup.dofs.dof(setup.u, node, 1)],
                                                x[setup.dofs.dof(setup.u, node, 2)]);
    // the plane through (0, 0, 1.5) moved by 0.4 * 0.25 along n at t = 0.25
    EXPECT_NEAR(wall.gap(k, x, 0.25), n.dot(p - Vec3(0.0, 0.0, 1.5)) - 0.1, 1e-14);
  }
  // the force on the body is −Σ λ_k n
  Real sum = 0.0;
  for (Index k = 0; k < wall.num_elements(); ++k)
    sum += x[wall.multiplier_dof(k)];
  EXPECT_LT((wall.force(x) + sum * n).norm(), 1e-14);
}
