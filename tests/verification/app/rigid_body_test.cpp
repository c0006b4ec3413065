// SPDX-License-Identifier: MIT
// [[rigid_body]]: a bonded cube stretched through its top face three ways: the top prescribed
// node by node, the top as a displacement-driven rigid body and as a force-driven one. All
// three are the same boundary value problem, so reactions and displacements must agree.
#include "case_runner.hpp"
#include "trifem/analysis/cell_values.hpp"
#include "trifem/analysis/run.hpp"
#include "trifem/model/rigid_bodies.hpp"
#include "trifem/tensor/rotation.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <numbers>
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

namespace {

/// A 2x2x2 neo-Hookean cube without supports; `bodies` is appended.
std::string free_cube_case(const std::string& bodies) {
  return R"(
[[mesh.box]]
name = "cube"
size = [1.0, 1.0, 1.0]
divisions = [2, 2, 2]
grading = [1.5, 0.8, 1.2]
material = "soft"
[materials.soft]
type = "neo-hookean"
E = 1.0
nu = 0.3
[curves.ramp]
points = [[0.0, 0.0], [1.0, 1.0]]
[time]
end_time = 1.0
dt = 0.25
[solver]
residual_tolerance = 1e-12
increment_tolerance = 1e-13
)" + bodies;
}

/// Expects `run` to fail with an InputError whose message contains every one of `parts`.
void expect_input_error(const std::string& text, const std::vector<std::string>& parts) {
  try {
    test::run_case_text(text, "bad.toml");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    for (const std::string& part : parts)
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

} // namespace

TEST(RigidBody, ACubeCarriedThroughHalfATurnByARotatingBodyMovesRigidly) {
  // the top face carries the cube: a translation and half a turn about (1, 2, 3)/√14 through
  // the given center, in four steps; the cube stays stress free, so every node moves rigidly
  const Vec3 axis = Vec3(1.0, 2.0, 3.0).normalized(), center(0.3, -0.2, 0.5), shift(0.2, -0.1, 0.4);
  const Vec3 theta = std::numbers::pi * axis;
  std::string body = fmt::format(R"(
[[rigid_body]]
name = "lid"
set = "cube.zmax"
rotation = "free"
center = [{:.17g}, {:.17g}, {:.17g}]
)",
                                 center.x(), center.y(), center.z());
  for (int k = 0; k < 3; ++k)
    body += fmt::format("{} = {{ displacement = {:.17g}, curve = \"ramp\" }}\n"
                        "r{} = {{ rotation = {:.17g}, curve = \"ramp\" }}\n",
                        "xyz"[k], shift[k], "xyz"[k], theta[k]);
  const test::CaseRun run = test::run_case_text(free_cube_case(body), "turn.toml");
  ASSERT_TRUE(run.report.success) << run.report.failure;
  const model::Model& m = *run.model;
  const Mat3 R = rotation::matrix(theta);
  Real error = 0.0;
  for (Index n = 0; n < m.mesh.num_nodes(); ++n) {
    const Vec3 X = m.mesh.node(n);
    const Vector& x = m.problem->state();
    const Vec3 u(x[m.dofs.dof(m.fields.u, n, 0)], x[m.dofs.dof(m.fields.u, n, 1)],
                 x[m.dofs.dof(m.fields.u, n, 2)]);
    error = std::max(error, (X + u - (center + shift + R * (X - center))).norm());
  }
  EXPECT_LT(error, 1e-12); // cube size 1
  const model::RigidBody& lid = m.rigid_bodies.at(0);
  EXPECT_LT((model::rigid_body_rotation(m, lid) - theta).norm(), 1e-15 * std::numbers::pi);
  EXPECT_LT((model::rigid_body_displacement(m, lid) - shift).norm(), 1e-15);
  // a stress-free cube: no force, no moment
  EXPECT_LT(model::rigid_body_force(m, lid, 1.0).norm(), 1e-12);
  EXPECT_LT(model::rigid_body_moment(m, lid).norm(), 1e-12);
}

TEST(RigidBody, EulerAnglesTurnTheCubeByTheProductOfTheirRotations) {
  // 50°, -70° and 120° about x, y and z, each ramped by its own curve: at the end the cube has
  // turned rigidly by R_z R_y R_x about the body's center (a total angle above π/2 about an
  // axis no angle names); halfway the angles are those of the curves
  const Vec3 angles(50.0, -70.0, 120.0), center(0.5, 0.5, 1.0);
  const std::string body =
      fmt::format(R"(
[curves.early]
points = [[0.0, 0.0], [0.5, 1.0], [1.0, 1.0]]
[[rigid_body]]
name = "lid"
set = "cube.zmax"
center = [0.5, 0.5, 1.0]
x = {{ displacement = 0.0 }}
y = {{ displacement = 0.0 }}
z = {{ displacement = 0.0 }}
euler_angles = {{ x = {{ rotation = {:.17g}, curve = "early" }}, y = {{ rotation = {:.17g}, curve = "ramp" }}, z = {{ rotation = {:.17g}, curve = "ramp" }} }}
)",
                  angles.x() * std::numbers::pi / 180, angles.y() * std::numbers::pi / 180,
                  angles.z() * std::numbers::pi / 180);
  const auto rotation_at = [&](Real t) {
    const Real ramp = t, early = std::min(1.0, 2.0 * t);
    const Vec3 a = angles * std::numbers::pi / 180;
    return rotation::matrix(a.z() * ramp * Vec3::UnitZ()) *
           rotation::matrix(a.y() * ramp * Vec3::UnitY()) *
           rotation::matrix(a.x() * early * Vec3::UnitX());
  };
  Real worst = 0.0;
  const test::CaseRun run = test::run_case_text(
      free_cube_case(body), "euler.toml", [&](const test::CaseRun& r, const solver::StepInfo& s) {
        const model::Model& m = *r.model;
        const Mat3 R = rotation_at(s.time);
        const Vector& x = m.problem->state();
        for (Index n = 0; n < m.mesh.num_nodes(); ++n) {
          const Vec3 X = m.mesh.node(n);
          const Vec3 u(x[m.dofs.dof(m.fields.u, n, 0)], x[m.dofs.dof(m.fields.u, n, 1)],
                       x[m.dofs.dof(m.fields.u, n, 2)]);
          worst = std::max(worst, (X + u - (center + R * (X - center))).norm());
        }
      });
  ASSERT_TRUE(run.report.success) << run.report.failure;
  EXPECT_EQ(run.report.steps, 4);
  EXPECT_LT(worst, 1e-12); // cube size 1
  EXPECT_GT(rotation::vector(rotation_at(1.0)).norm(), std::numbers::pi / 2);
}

TEST(RigidBody, AMomentOnARotatingBodyTwistsTheCubeAndTheBaseBalancesIt) {
  constexpr Real kMoment = 0.02; // [N mm] on a cube of modulus 1 and size 1: a few degrees
  const test::CaseRun run = test::run_case_text(cube_case(R"(
[[rigid_body]]
name = "lid"
set = "cube.zmax"
rz = { moment = 0.02, curve = "ramp" }
)"),
                                                "twist.toml");
  ASSERT_TRUE(run.report.success) << run.report.failure;
  const model::Model& m = *run.model;
  const model::RigidBody& lid = m.rigid_bodies.at(0);
  const Vec3 moment = model::rigid_body_moment(m, lid);
  EXPECT_NEAR(moment.z(), kMoment, 1e-10 * kMoment); // the applied moment, at equilibrium
  EXPECT_LT(moment.head<2>().norm(), 1e-10 * kMoment);
  EXPECT_LT(model::rigid_body_force(m, lid, 1.0).norm(), 1e-10 * kMoment); // L = 1
  EXPECT_GT(model::rigid_body_rotation(m, lid).z(), 0.01);                 // it turned, about z
  // the clamped base holds the cube with the opposite moment
  const Vector& x = m.problem->state();
  const Vector& R = m.problem->full_residual();
  Vec3 base = Vec3::Zero();
  for (Index n : m.mesh.node_set("cube.zmin")) {
    Vec3 position = m.mesh.node(n), reaction;
    for (int k = 0; k < 3; ++k) {
      position[k] += x[m.dofs.dof(m.fields.u, n, k)];
      reaction[k] = R[m.dofs.dof(m.fields.u, n, k)];
    }
    base += position.cross(reaction);
  }
  EXPECT_NEAR(base.z(), -kMoment, 1e-10 * kMoment);
}

TEST(RigidBody, RotationKeysOfABodyThatDoesNotRotateAreInputErrors) {
  expect_input_error(cube_case(R"(
[[rigid_body]]
name = "lid"
set = "cube.zmax"
rotation = "fixed"
rx = { rotation = 0.1 }
)"),
                     {"rigid_body[1].rotation", "rx, ry and rz"});
  expect_input_error(cube_case(R"(
[[rigid_body]]
name = "lid"
set = "cube.zmax"
components = ["x", "y"]
rotation = "free"
)"),
                     {"rigid_body[1].components", "all three"});
  expect_input_error(cube_case(R"(
[[rigid_body]]
name = "lid"
set = "cube.zmax"
rz = { rotation = 0.1, moment = 1.0 }
)"),
                     {"rigid_body[1].rz", "either rotation or moment"});
}

namespace {

/// A clamped 2x2x2 cube whose top face a rigid body turns by 0.4 rad about z, its center and
/// its other rotations held; `body` is appended (its blocks or set, center).
std::string turned_top_case(const std::string& mesh, const std::string& body) {
  return R"(
[[mesh.box]]
name = "tissue"
size = [1.0, 1.0, 1.0]
divisions = [2, 2, 2]
material = "soft"
)" + mesh +
         R"(
[materials.soft]
type = "neo-hookean"
E = 1.0
nu = 0.3
[curves.ramp]
points = [[0.0, 0.0], [1.0, 1.0]]
[[boundary.fixed]]
set = "tissue.zmin"
[time]
end_time = 1.0
dt = 0.5
[solver]
residual_tolerance = 1e-12
increment_tolerance = 1e-13
[[rigid_body]]
name = "bone"
rotation = "free"
x = { displacement = 0.0 }
y = { displacement = 0.0 }
z = { displacement = 0.0 }
rx = { rotation = 0.0 }
ry = { rotation = 0.0 }
rz = { rotation = 0.4, curve = "ramp" }
)" + body;
}

Vec3 position(const model::Model& m, Index n) {
  const Vector& x = m.problem->state();
  return m.mesh.node(n) + Vec3(x[m.dofs.dof(m.fields.u, n, 0)], x[m.dofs.dof(m.fields.u, n, 1)],
                               x[m.dofs.dof(m.fields.u, n, 2)]);
}

} // namespace

TEST(RigidBody, ABodyOfCellsMovesRigidlyAboutItsCentroidAndCarriesNoStiffness) {
  // the bone: a block of cells without material above the tissue, its center by default the
  // centroid of its cells (0.5, 0.5, 1.45); the same body given as the tissue's top face and
  // that center must turn the tissue the same way (rigid cells add no stiffness)
  const test::CaseRun cells = test::run_case_text(turned_top_case(R"(
[[mesh.box]]
name = "bone"
origin = [0.0, 0.0, 1.2]
size = [1.0, 1.0, 0.5]
divisions = [2, 2, 1]
)",
                                                                  R"(blocks = ["bone"]
set = "tissue.zmax"
)"),
                                                  "cells.toml");
  ASSERT_TRUE(cells.report.success) << cells.report.failure;
  const test::CaseRun face = test::run_case_text(turned_top_case("", R"(set = "tissue.zmax"
center = [0.5, 0.5, 1.45]
)"),
                                                 "face.toml");
  ASSERT_TRUE(face.report.success) << face.report.failure;
  const model::Model &a = *cells.model, &b = *face.model;
  const Vec3 center = a.problem->rigid_map().bodies().at(0).centre;
  EXPECT_LT((center - Vec3(0.5, 0.5, 1.45)).norm(), 1e-15);
  Real difference = 0.0, motion = 0.0;
  for (Index n = 0; n < b.mesh.num_nodes(); ++n) { // the tissue's nodes come first in both
    difference = std::max(difference, (position(a, n) - position(b, n)).norm());
    motion = std::max(motion, (position(b, n) - b.mesh.node(n)).norm());
  }
  EXPECT_GT(motion, 0.1);
  EXPECT_LT(difference, 1e-12);
  const model::RigidBody &bone_a = a.rigid_bodies.at(0), &bone_b = b.rigid_bodies.at(0);
  EXPECT_NEAR(model::rigid_body_moment(a, bone_a).z(), model::rigid_body_moment(b, bone_b).z(),
              1e-12 * std::abs(model::rigid_body_moment(b, bone_b).z()));
  // the bone's own nodes turned rigidly about its center
  const Mat3 R = rotation::matrix(Vec3(0.0, 0.0, 0.4));
  Real rigid_error = 0.0;
  for (Index n : a.mesh.node_set("bone.all"))
    rigid_error =
        std::max(rigid_error, (position(a, n) - (center + R * (a.mesh.node(n) - center))).norm());
  EXPECT_LT(rigid_error, 1e-14);
}

// The same bone meshed with tet10 or penta6 cells: its default center is again the centroid of
// its cells (by their own rules), and it turns the tissue as the hex8 bone does.
TEST(RigidBody, ABodyOfTetsOrWedgesMovesRigidlyAboutItsCentroid) {
  const auto bone = [](const char* cell) {
    return test::run_case_text(turned_top_case(fmt::format(R"(
[[mesh.box]]
name = "bone"
origin = [0.0, 0.0, 1.2]
size = [1.0, 1.0, 0.5]
divisions = [2, 2, 1]
cell = "{}"
)",
                                                           cell),
                                               R"(blocks = ["bone"]
set = "tissue.zmax"
)"),
                               fmt::format("{}.toml", cell));
  };
  const test::CaseRun hexes = bone("hex8");
  ASSERT_TRUE(hexes.report.success) << hexes.report.failure;
  for (const char* cell : {"tet10", "penta6"}) {
    const test::CaseRun other = bone(cell);
    ASSERT_TRUE(other.report.success) << cell << ": " << other.report.failure;
    const Vec3 center = other.model->problem->rigid_map().bodies().at(0).centre;
    EXPECT_LT((center - Vec3(0.5, 0.5, 1.45)).norm(), 1e-14) << cell;
    Real difference = 0.0;
    const auto tissue = static_cast<Index>(hexes.model->mesh.node_set("tissue.all").size());
    for (Index n = 0; n < tissue; ++n) // the tissue's nodes come first
      difference =
          std::max(difference, (position(*other.model, n) - position(*hexes.model, n)).norm());
    EXPECT_LT(difference, 1e-12) << cell;
  }
}

TEST(RigidBody, CellsWithoutAMaterialOrABodyAreInputErrors) {
  const std::string bone_box = R"(
[[mesh.box]]
name = "bone"
origin = [0.0, 0.0, 1.2]
size = [1.0, 1.0, 0.5]
divisions = [2, 2, 1]
)";
  expect_input_error(turned_top_case(bone_box, "set = \"tissue.zmax\"\n"),
                     {"has no material", "[[rigid_body]]'s blocks"});
  expect_input_error(turned_top_case("", "blocks = [\"tissue\"]\n"),
                     {"rigid_body[1].blocks[1]", "has the material 'soft'"});
  std::string fixed = turned_top_case(bone_box, "blocks = [\"bone\"]\n");
  fixed.replace(fixed.find("rotation = \"free\""), 17, "rotation = \"fixed\"");
  expect_input_error(fixed, {"rigid_body[1].rotation", "rotates"});
}

namespace {

/// A 2x2x2 cube of `material` between two rigid bones (impermeable: their nodes' fluxes fixed),
/// its free sides draining to the bath: steady states (each step time the steady state of its
/// conditions). The top bone compresses it by 20 % (t: 0 → 1), then both bones turn 90° about
/// (1, 2, 3)/√14 through P (t: 1 → 2).
std::string turned_mixture_case(const std::string& material) {
  const Vec3 axis = Vec3(1.0, 2.0, 3.0).normalized(), P(0.7, -0.3, 0.2);
  std::string text = R"(
[[mesh.box]]
name = "cube"
size = [1.0, 1.0, 1.0]
divisions = [2, 2, 2]
grading = [1.5, 0.8, 1.2]
material = "tissue"
)" + material + R"(
[[boundary.fixed]]
set = "cube.zmin"
field = "fluxes"
[[boundary.fixed]]
set = "cube.zmax"
field = "fluxes"
[[step]]
name = "compress"
end_time = 1.0
dt = 0.5
steady = true
[[step]]
name = "turn"
end_time = 2.0
dt = 0.3333333333333333
steady = true
[solver]
residual_tolerance = 1e-12
increment_tolerance = 1e-13
)";
  const std::array<Vec3, 2> centers{Vec3(0.5, 0.5, 0.0), Vec3(0.5, 0.5, 1.0)};
  const std::array<const char*, 2> sets{"cube.zmin", "cube.zmax"};
  for (int b = 0; b < 2; ++b) {
    const Vec3 start = centers[b] - (b == 1 ? Vec3(0.0, 0.0, 0.2) : Vec3::Zero());
    text += fmt::format("[[rigid_body]]\nname = \"bone{}\"\nset = \"{}\"\nrotation = \"free\"\n"
                        "center = [{:.17g}, {:.17g}, {:.17g}]\n",
                        b, sets[b], centers[b].x(), centers[b].y(), centers[b].z());
    std::array<std::string, 6> points;
    for (int k = 0; k < 6; ++k)
      points[k] = "[0.0, 0.0]";
    for (const Real t : {1.0, 4.0 / 3.0, 5.0 / 3.0, 2.0}) { // the center's path P + R(t)(start − P)
      const Vec3 theta = (t - 1.0) * (std::numbers::pi / 2.0) * axis;
      const Vec3 uc = P + rotation::matrix(theta) * (start - P) - centers[b];
      for (int k = 0; k < 3; ++k) {
        points[k] += fmt::format(", [{:.17g}, {:.17g}]", t, uc[k]);
        points[k + 3] += fmt::format(", [{:.17g}, {:.17g}]", t, theta[k]);
      }
    }
    for (int k = 0; k < 6; ++k) {
      const std::string curve = fmt::format("bone{}_{}", b, k);
      text += fmt::format("{}{} = {{ {} = 1.0, curve = \"{}\" }}\n", k < 3 ? "" : "r", "xyz"[k % 3],
                          k < 3 ? "displacement" : "rotation", curve);
    }
    for (int k = 0; k < 6; ++k)
      text += fmt::format("[curves.bone{}_{}]\npoints = [{}]\n", b, k, points[k]);
  }
  return text;
}

/// The cell quantities of a model at its current state.
std::vector<analysis::CellValues> cell_values(const model::Model& m) {
  const analysis::CellEvaluator evaluator(m);
  std::vector<analysis::CellValues> values;
  for (Index c = 0; c < m.mesh.num_cells(); ++c)
    values.push_back(evaluator.values(c, m.problem->state()));
  return values;
}

/// Runs `text` through its steps, keeping the cell quantities at t = 1; expects those at t = 2
/// to be the same, tensors rotated by R (90° about (1, 2, 3)/√14), to 1e-10 of their scale.
void expect_the_turned_state(const std::string& text, bool ions) {
  std::vector<analysis::CellValues> compressed;
  const test::CaseRun run =
      test::run_case_steps(text, "turned.toml", [&](const model::Model& m, Real time) {
        if (std::abs(time - 1.0) < 1e-9)
          compressed = cell_values(m);
      });
  ASSERT_TRUE(run.report.success) << run.report.failure;
  ASSERT_EQ(compressed.size(), 8u);
  const std::vector<analysis::CellValues> turned = cell_values(*run.model);
  const Mat3 R = rotation::matrix((std::numbers::pi / 2.0) * Vec3(1.0, 2.0, 3.0).normalized());
  Real stress_scale = 0.0, pressure_scale = 0.0, potential_scale = 1e-300;
  for (const auto& v : compressed) {
    stress_scale = std::max(stress_scale, v.stress.norm());
    pressure_scale = std::max(pressure_scale, std::abs(v.fluid_pressure));
    potential_scale = std::max(potential_scale, std::abs(v.electric_potential));
  }
  ASSERT_GT(stress_scale, 0.01);
  ASSERT_GT(pressure_scale, ions ? 0.01 : 0.0); // the Donnan pressure
  for (std::size_t c = 0; c < turned.size(); ++c) {
    const auto &a = compressed[c], &b = turned[c];
    EXPECT_LT((b.stress - R * a.stress * R.transpose()).norm(), 1e-10 * stress_scale) << c;
    EXPECT_LT((b.solid_stress - R * a.solid_stress * R.transpose()).norm(), 1e-10 * stress_scale)
        << c;
    EXPECT_NEAR(b.fluid_pressure, a.fluid_pressure, 1e-10 * std::max(pressure_scale, stress_scale))
        << c;
    EXPECT_NEAR(b.relative_volume, a.relative_volume, 1e-12) << c;
    if (!ions)
      continue;
    EXPECT_NEAR(b.electric_potential, a.electric_potential, 1e-10 * potential_scale) << c;
    EXPECT_NEAR(b.cation_concentration, a.cation_concentration, 1e-10 * a.cation_concentration)
        << c;
    EXPECT_NEAR(b.anion_concentration, a.anion_concentration, 1e-10 * a.anion_concentration) << c;
  }
}

} // namespace

TEST(RigidBody, ABiphasicCubeTurnedByItsBonesKeepsItsSteadyStateRotated) {
  expect_the_turned_state(turned_mixture_case(R"(
[materials.tissue]
type = "biphasic"
phi_s0 = 0.25
permeability = 1.07e-3
[materials.tissue.solid]
type = "neo-hookean"
E = 0.3
nu = 0.2
)"),
                          false);
}

// (prestressed: the Donnan state is in equilibrium at t = 0, so the steady states are the
// compressed ones, not a free swelling)
TEST(RigidBody, ATriphasicCubeTurnedByItsBonesKeepsItsDonnanStateRotated) {
  expect_the_turned_state(turned_mixture_case(R"(
[materials.tissue]
type = "triphasic"
phi_s0 = 0.25
permeability = 1.07e-3
fixed_charge = 2.0e-4
d_plus = 5.0e-4
d_minus = 8.0e-4
[materials.tissue.solid]
type = "neo-hookean"
E = 0.3
nu = 0.2
[analysis]
initial_state = "donnan-prestressed"
)"),
                          true);
}
