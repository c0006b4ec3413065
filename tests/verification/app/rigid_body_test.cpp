// SPDX-License-Identifier: MIT
// [[rigid_body]]: a bonded cube stretched through its top face three ways: the top prescribed
// node by node, the top as a displacement-driven rigid body and as a force-driven one. All
// three are the same boundary value problem, so reactions and displacements must agree.
#include "case_runner.hpp"
#include "trifem/model/rigid_bodies.hpp"

#include <gtest/gtest.h>

#include <string>

using namespace trifem;

namespace {

/// A 2x2x2 neo-Hookean cube with a bonded bottom; `top` is appended (the top's conditions).
std::string cube_case(const std::string& top) {
  return R"(
[[mesh.box]]
name = "cube"
size = [1.0, 1.0, 1.0]
divisions = [2, 2, 2]
material = "soft"
[materials.soft]
type = "neo-hookean"
E = 1.0
nu = 0.3
[curves.ramp]
points = [[0.0, 0.0], [1.0, 1.0]]
[[boundary.fixed]]
set = "cube.zmin"
[time]
end_time = 1.0
dt = 0.25
[solver]
residual_tolerance = 1e-12
increment_tolerance = 1e-12
)" + top;
}

constexpr Real kStretch = 0.2; // top displacement [mm]

/// Sum of the z residual over the top nodes: the force on the top [N].
Real top_reaction(const model::Model& m) {
  Real f = 0.0;
  for (Index n : m.mesh.node_set("cube.zmax"))
    f += m.problem->full_residual()[m.dofs.dof(m.fields.u, n, 2)];
  return f;
}

} // namespace

TEST(RigidBody, DisplacementAndForceDrivenBodiesReproduceThePrescribedTop) {
  const test::CaseRun nodal = test::run_case_text(cube_case(R"(
[[boundary.fixed]]
set = "cube.zmax"
components = ["x", "y"]
[[boundary.prescribed]]
set = "cube.zmax"
component = "z"
value = 0.2
curve = "ramp"
)"),
                                                  "nodal.toml");
  ASSERT_TRUE(nodal.report.success) << nodal.report.failure;
  const Real force = top_reaction(*nodal.model);
  ASSERT_GT(force, 0.05); // a real stretch, not a trivial state

  const test::CaseRun driven = test::run_case_text(cube_case(R"(
[[rigid_body]]
name = "plate"
set = "cube.zmax"
x = { displacement = 0.0 }
y = { displacement = 0.0 }
z = { displacement = 0.2, curve = "ramp" }
)"),
                                                   "driven.toml");
  ASSERT_TRUE(driven.report.success) << driven.report.failure;
  const model::RigidBody& plate = driven.model->rigid_bodies.at(0);
  const Vec3 f_driven = model::rigid_body_force(*driven.model, plate, 1.0);
  EXPECT_NEAR(f_driven.z(), force, 1e-10 * force);
  // tolerances on the scales of the problem: the stretch kStretch and the top force
  EXPECT_NEAR(model::rigid_body_displacement(*driven.model, plate).z(), kStretch,
              5e-15 * kStretch); // prescribed
  EXPECT_LT((driven.model->problem->state() - nodal.model->problem->state()).norm(),
            5e-10 * kStretch);

  // Force-driven: the applied force of the nodal run moves the plate by the same stretch; x
  // and y are free but stay 0 by symmetry, and the plate carries no lateral force.
  const std::string force_top = R"(
[[rigid_body]]
name = "plate"
set = "cube.zmax"
z = { force = )" + fmt::format("{:.17g}", force) +
                                ", curve = \"ramp\" }\n";
  const test::CaseRun loaded = test::run_case_text(cube_case(force_top), "loaded.toml");
  ASSERT_TRUE(loaded.report.success) << loaded.report.failure;
  const model::RigidBody& body = loaded.model->rigid_bodies.at(0);
  const Vec3 u = model::rigid_body_displacement(*loaded.model, body);
  EXPECT_NEAR(u.z(), kStretch, 5e-9 * kStretch);
  // zero by symmetry: round-off of the solve, on the scale of the stretch and of the force (a
  // lateral coupling error would show at order 1e-2 of them)
  EXPECT_NEAR(u.x(), 0.0, 5e-12 * kStretch);
  EXPECT_NEAR(u.y(), 0.0, 5e-12 * kStretch);
  const Vec3 f = model::rigid_body_force(*loaded.model, body, 1.0);
  EXPECT_NEAR(f.z(), force, 1e-10 * force);
  EXPECT_NEAR(f.x(), 0.0, 5e-12 * force);
  // every top node moved by the same translation (the tie)
  for (Index n : loaded.model->mesh.node_set("cube.zmax"))
    EXPECT_NEAR(
        loaded.model->problem->state()[loaded.model->dofs.dof(loaded.model->fields.u, n, 2)], u.z(),
        5e-15 * kStretch);
  EXPECT_LT(
      (loaded.model->problem->state() - nodal.model->problem->state()).lpNorm<Eigen::Infinity>(),
      5e-8 * kStretch);
}

TEST(RigidBody, AComponentAlsoConstrainedByABoundaryConditionIsAnInputError) {
  EXPECT_THROW(
      {
        try {
          test::run_case_text(cube_case(R"(
[[boundary.fixed]]
set = "cube.xmax"
components = ["x"]
[[rigid_body]]
name = "plate"
set = "cube.zmax"
)"),
                              "conflict.toml");
        } catch (const InputError& e) {
          EXPECT_NE(std::string(e.what()).find("rigid_body[1]"), std::string::npos) << e.what();
          throw;
        }
      },
      InputError);
}
