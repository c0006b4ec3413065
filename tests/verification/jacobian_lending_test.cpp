// SPDX-License-Identifier: MIT
// FeProblem::linearize hands the caller its assembled matrix storage instead of a copy and
// takes it back at the next linearize. Whatever the sequence of linearizations (the same one
// again, a new one, an old one, residual-only ones in between), each gets the full Jacobian of
// the state: the same bits as the first.
#include "solid_model.hpp"

#include <gtest/gtest.h>

using namespace trifem;

namespace {

test::SolidModel stretched_box() {
  mesh::BoxSpec spec;
  spec.divisions = {3, 2, 2};
  test::SolidModel model(mesh::make_box(spec), "neo-hookean", {{"E", 5.0}, {"nu", 0.3}});
  model.prescribe(model.mesh.node_set("box.xmin"), 0, 0.0);
  model.prescribe(model.mesh.node_set("box.xmin"), 1, 0.0);
  model.prescribe(model.mesh.node_set("box.xmin"), 2, 0.0);
  model.prescribe(model.mesh.node_set("box.xmax"), 0, 0.1);
  model.build();
  return model;
}

bool same_bits(const SparseMatrix& a, const SparseMatrix& b) {
  if (a.rows() != b.rows() || a.cols() != b.cols() || a.nonZeros() != b.nonZeros())
    return false;
  const SparseMatrix difference = a - b;
  return difference.coeffs().cwiseAbs().maxCoeff() == 0.0;
}

} // namespace

TEST(JacobianLending, EveryLinearizationGetsTheWholeJacobian) {
  test::SolidModel model = stretched_box();
  model.problem->begin_step(0.5, 0.5);
  Vector dx = Vector::Constant(model.problem->num_equations(), 1e-3); // a state off the origin
  ASSERT_EQ(model.problem->update(dx, 1.0), solver::SolveStatus::Converged);

  solver::Linearization first, again, other;
  ASSERT_EQ(model.problem->linearize(first, true), solver::SolveStatus::Converged);
  const SparseMatrix reference = first.jacobian; // a copy of the first Jacobian
  ASSERT_GT(reference.nonZeros(), 0);
  ASSERT_GT(reference.norm(), 0.0);

  // the same linearization again: its storage is taken back, filled and handed out
  ASSERT_EQ(model.problem->linearize(first, true), solver::SolveStatus::Converged);
  EXPECT_TRUE(same_bits(first.jacobian, reference));
  // residual only: the Jacobian stays with the caller
  ASSERT_EQ(model.problem->linearize(again, false), solver::SolveStatus::Converged);
  EXPECT_TRUE(same_bits(first.jacobian, reference));
  // a new linearization gets the whole Jacobian; the last one keeps its own
  ASSERT_EQ(model.problem->linearize(other, true), solver::SolveStatus::Converged);
  EXPECT_TRUE(same_bits(other.jacobian, reference));
  EXPECT_TRUE(same_bits(first.jacobian, reference));
  // and an older one once more
  ASSERT_EQ(model.problem->linearize(first, true), solver::SolveStatus::Converged);
  EXPECT_TRUE(same_bits(first.jacobian, reference));
  EXPECT_TRUE(same_bits(other.jacobian, reference));
  ASSERT_EQ(model.problem->linearize(other, true), solver::SolveStatus::Converged);
  EXPECT_TRUE(same_bits(other.jacobian, reference));
}

TEST(JacobianLending, OneNewtonSolverForAllStepsGivesTheStatesOfANewOnePerStep) {
  // one Newton solver keeps its linearization (and the lent storage) between steps; a new
  // solver per step starts each step with a new one (the pattern built anew)
  test::SolidModel kept = stretched_box(), fresh = stretched_box();
  solver::NewtonSolver newton({}, linalg::make_linear_solver({LinearSolverKind::sparselu}));
  for (const Real t : {0.5, 1.0}) {
    for (test::SolidModel* model : {&kept, &fresh}) {
      solver::NewtonSolver once({}, linalg::make_linear_solver({LinearSolverKind::sparselu}));
      model->problem->begin_step(t, 0.5);
      const solver::NewtonReport report = (model == &kept ? newton : once).solve(*model->problem);
      ASSERT_EQ(report.status, solver::SolveStatus::Converged);
      model->problem->commit_step();
    }
    const Vector& a = kept.problem->state();
    const Vector& b = fresh.problem->state();
    EXPECT_GE(a.cwiseAbs().maxCoeff(), 0.1 * t - 1e-12); // the stretch happened
    EXPECT_LE((a - b).cwiseAbs().maxCoeff(), 1e-13 * 0.1) << "t = " << t;
  }
}
