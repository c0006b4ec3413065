// SPDX-License-Identifier: MIT
// Finite-difference check of the tangent of an implicit dynamic step (generalized-α): the
// Jacobian of (1 − α_f) g(x) + α_f g_n + M a_{n+1-α_m}(x) over the free equations, in motion
// (after a step that left a velocity, an acceleration and a residual history), on a graded
// mesh with a dead nodal load.
#include "trifem/assembly/fe_problem.hpp"
#include "trifem/linalg/linear_solver.hpp"
#include "trifem/material/registry.hpp"
#include "trifem/mesh/box.hpp"
#include "trifem/physics/inertia_term.hpp"
#include "trifem/physics/nodal_force_term.hpp"
#include "trifem/physics/solid_term.hpp"
#include "trifem/solver/newton.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace trifem;

namespace {

struct DynamicBlock {
  mesh::Mesh mesh;
  dofs::DofMap dofs;
  dofs::FieldId u;
  std::unique_ptr<assembly::FeProblem> problem;

  explicit DynamicBlock(physics::MassMatrix mass) {
    mesh::BoxSpec box;
    box.size = Vec3(2.0, 1.0, 1.0);
    box.divisions = {2, 1, 2};
    box.grading = Vec3(1.7, 1.0, 0.6); // cells of different shapes
    mesh = mesh::make_box(box);
    u = dofs.add_field("displacement", mesh.num_nodes(), 3);
    dofs::DirichletCondition clamp{{}, 0.0, dofs::LoadCurve::constant(1.0)};
    for (Index n : mesh.node_set("box.xmin"))
      for (int k = 0; k < 3; ++k)
        clamp.dofs.push_back(dofs.dof(u, n, k));
    dofs::constrain_all({clamp}, dofs);
    dofs.finalize();
    std::vector<Index> cells(mesh.num_cells());
    for (Index c = 0; c < mesh.num_cells(); ++c)
      cells[c] = c;
    std::vector<std::unique_ptr<physics::Term>> terms;
    const std::shared_ptr<const material::ElasticLaw> law =
        material::create_law("neo-hookean", {{"E", 1.0}, {"nu", 0.3}}, "law");
    terms.push_back(std::make_unique<physics::SolidTerm>(
        mesh, dofs, u, cells,
        std::vector<std::shared_ptr<const material::ElasticLaw>>(cells.size(), law)));
    std::vector<physics::NodalForce> forces;
    const dofs::LoadCurve ramp({{0.0, 0.0}, {1e-3, 1.0}}, dofs::Interpolation::Linear, "ramp");
    for (Index n : mesh.node_set("box.xmax"))
      forces.push_back({dofs.dof(u, n, 2), -0.01, ramp});
    terms.push_back(std::make_unique<physics::NodalForceTerm>(std::move(forces)));
    problem = std::make_unique<assembly::FeProblem>(
        dofs, std::vector<dofs::DirichletCondition>{clamp}, std::move(terms),
        std::vector<solver::FieldScale>{{"displacement", 1.0, 1.0}});
    problem->add_inertia(std::make_unique<physics::InertiaTerm>(
        mesh, dofs, u, cells, std::vector<Real>(cells.size(), 1e-9), mass,
        physics::GeneralizedAlpha::from_spectral_radius(0.6)));
    problem->set_dynamic(true);
  }
};

void expect_the_finite_difference_tangent(physics::MassMatrix mass) {
  DynamicBlock block(mass);
  assembly::FeProblem& p = *block.problem;
  solver::NewtonSolver newton({}, linalg::make_linear_solver("umfpack"));
  p.begin_step(2e-4, 2e-4); // one step in motion: v, a and g of step n are not zero
  ASSERT_EQ(newton.solve(p).status, solver::SolveStatus::Converged);
  p.commit_step();
  ASSERT_GT(p.inertia()->velocity().norm(), 0.0);

  p.begin_step(5e-4, 3e-4);
  const Index n = p.num_equations();
  std::mt19937 random(11);
  std::uniform_real_distribution<Real> shift(-1e-3, 1e-3);
  Vector dx(n);
  for (Index i = 0; i < n; ++i)
    dx[i] = shift(random);
  p.update(dx, 1.0); // a state inside the step
  solver::Linearization lin;
  ASSERT_EQ(p.linearize(lin, true), solver::SolveStatus::Converged);
  const Eigen::MatrixXd K(lin.jacobian);
  p.save_iterate();
  const Real h = 1e-7;
  Eigen::MatrixXd fd(n, n);
  for (Index j = 0; j < n; ++j) {
    Vector e = Vector::Zero(n);
    e[j] = h;
    solver::Linearization plus, minus;
    p.update(e, 1.0);
    ASSERT_EQ(p.linearize(plus, false), solver::SolveStatus::Converged);
    p.restore_iterate();
    p.update(-e, 1.0);
    ASSERT_EQ(p.linearize(minus, false), solver::SolveStatus::Converged);
    p.restore_iterate();
    fd.col(j) = (plus.residual - minus.residual) / (2 * h);
  }
  const Real scale = K.cwiseAbs().maxCoeff();
  EXPECT_LT((fd - K).cwiseAbs().maxCoeff(), 1e-6 * scale)
      << "largest entry " << scale << ", inertia part " << p.inertia()->method().alpha_m;
}

TEST(DynamicTangent, ConsistentMassStepMatchesFiniteDifferences) {
  expect_the_finite_difference_tangent(physics::MassMatrix::Consistent);
}

TEST(DynamicTangent, LumpedMassStepMatchesFiniteDifferences) {
  expect_the_finite_difference_tangent(physics::MassMatrix::Lumped);
}

} // namespace
