// SPDX-License-Identifier: MIT
// The rigid-body modes a problem gives algebraic multigrid (FeProblem::rigid_body_modes): the
// three translations and three rotations of the solid are the null space of its stiffness at
// the undeformed state, so K times each mode vanishes to round-off, on a graded, off-origin
// box; and a prescribed component removes its equations from the modes.
#include "solid_model.hpp"

#include <gtest/gtest.h>

using namespace trifem;

namespace {

test::SolidModel graded_box() {
  mesh::BoxSpec spec;
  spec.origin = Vec3(3.0, -2.0, 0.5); // rotations about the centroid, not the origin
  spec.size = Vec3(2.0, 1.0, 0.5);
  spec.divisions = {4, 3, 2};
  spec.grading = Vec3(2.0, 1.0, 0.5);
  return test::SolidModel(mesh::make_box(spec), "saint-venant-kirchhoff",
                          {{"E", 10.0}, {"nu", 0.3}});
}

SparseMatrix stiffness(test::SolidModel& model) {
  model.problem->begin_step(1.0, 1.0);
  solver::Linearization lin;
  EXPECT_EQ(model.problem->linearize(lin, true), solver::SolveStatus::Converged);
  return lin.jacobian;
}

} // namespace

TEST(RigidBodyModes, AreTheNullSpaceOfTheUndeformedStiffness) {
  test::SolidModel model = graded_box();
  model.build();
  EXPECT_TRUE(model.problem->rigid_body_modes().empty()); // no positions given yet
  model.problem->set_node_positions(model.u, model.mesh.nodes());
  const std::vector<Vector> modes = model.problem->rigid_body_modes();
  ASSERT_EQ(modes.size(), 6u);
  const SparseMatrix K = stiffness(model);
  const Real scale = K.norm();
  for (std::size_t m = 0; m < modes.size(); ++m) {
    SCOPED_TRACE(m);
    ASSERT_EQ(modes[m].size(), K.rows());
    ASSERT_GT(modes[m].norm(), 0.1);
    EXPECT_LT((K * modes[m]).norm(), 1e-12 * scale * modes[m].norm());
  }
  // a translation moves every node by one in its direction
  EXPECT_DOUBLE_EQ(modes[0].sum(), static_cast<Real>(model.mesh.num_nodes()));
  // a deformation that is not rigid is not in the null space
  Vector stretch = Vector::Zero(K.rows());
  for (Index n = 0; n < model.mesh.num_nodes(); ++n)
    stretch[model.dofs.equation(model.dofs.dof(model.u, n, 0))] = model.mesh.node(n).x();
  EXPECT_GT((K * stretch).norm(), 1e-3 * scale * stretch.norm());
}

TEST(RigidBodyModes, LeavePrescribedComponentsOut) {
  test::SolidModel model = graded_box();
  const std::vector<Index>& bottom = model.mesh.node_set("box.zmin");
  model.prescribe(bottom, 2, 0.0);
  model.build();
  model.problem->set_node_positions(model.u, model.mesh.nodes());
  const std::vector<Vector> modes = model.problem->rigid_body_modes();
  ASSERT_EQ(modes.size(), 6u);
  EXPECT_EQ(model.problem->num_equations(),
            3 * model.mesh.num_nodes() - static_cast<Index>(bottom.size()));
  // the z translation has a one on every free z equation: all nodes but the bottom ones
  EXPECT_DOUBLE_EQ(modes[2].sum(),
                   static_cast<Real>(model.mesh.num_nodes() - static_cast<Index>(bottom.size())));
}
