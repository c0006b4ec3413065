// SPDX-License-Identifier: MIT
// [[connector]]: a bone (a rigid body of cells carrying a tissue cube that hangs from it) held
// by a joint to the ground, with closed-form answers: a revolute joint with a torsion spring
// under a moment turns by M/k, a prismatic joint with a spring under a force slides by F/k, a
// spherical joint keeps its point while the bone turns, and a prescribed revolute angle turns
// the bone through a full turn. The tissue is carried rigidly (stress free, its initial state
// unchanged) whether it is a solid, biphasic or triphasic.
#include "case_runner.hpp"
#include "tissue_materials.hpp"
#include "trifem/analysis/cell_values.hpp"
#include "trifem/model/rigid_bodies.hpp"
#include "trifem/parallel/communicator.hpp"
#include "trifem/tensor/rotation.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

using namespace trifem;
using test::kBiphasic;
using test::kSolid;
using test::kTriphasic;

namespace {

const Vec3 kAxis = Vec3(1.0, 2.0, 3.0).normalized();
const Vec3 kOrigin(-0.4, 0.3, 1.5); // the joint's origin [mm]

std::string vec(const Vec3& v) {
  return fmt::format("[{:.17g}, {:.17g}, {:.17g}]", v.x(), v.y(), v.z());
}

/// A 2x2x2 cube of `material` hanging from a bone of cells above it (the body "femur", which
/// also carries the cube's top face), with `rest` appended (the femur's drives, the connectors).
std::string hanging_cube_case(const std::string& material, const std::string& rest) {
  return R"(
[[mesh.box]]
name = "cube"
size = [1.0, 1.0, 1.0]
divisions = [2, 2, 2]
material = "tissue"
[[mesh.box]]
name = "bone"
origin = [0.0, 0.0, 1.0]
size = [1.0, 1.0, 0.3]
divisions = [1, 1, 1]
)" + material +
         R"(
[curves.ramp]
points = [[0.0, 0.0], [1.0, 1.0]]
[time]
end_time = 1.0
dt = 0.25
[solver]
residual_tolerance = 1e-12
increment_tolerance = 1e-13
[[rigid_body]]
name = "femur"
set = "cube.zmax"
blocks = ["bone"]
)" + rest;
}

Vec3 position(const model::Model& m, Index n) {
  const Vector& x = m.problem->state();
  return m.mesh.node(n) + Vec3(x[m.dofs.dof(m.fields.u, n, 0)], x[m.dofs.dof(m.fields.u, n, 1)],
                               x[m.dofs.dof(m.fields.u, n, 2)]);
}

/// The largest distance of a node from its place in the rigid motion x ↦ P + s + R(x − P).
Real rigid_motion_error(const model::Model& m, const Mat3& R, const Vec3& P,
                        const Vec3& s = Vec3::Zero()) {
  Real error = 0.0;
  for (Index n = 0; n < m.mesh.num_nodes(); ++n)
    error = std::max(error, (position(m, n) - (P + s + R * (m.mesh.node(n) - P))).norm());
  return error;
}

/// The cell quantities of a model at its current state.
std::vector<analysis::CellValues> cell_values(const model::Model& m) {
  const analysis::CellEvaluator evaluator(m);
  std::vector<analysis::CellValues> values;
  for (Index c = 0; c < m.mesh.num_cells(); ++c)
    if (!m.materials[c].rigid())
      values.push_back(evaluator.values(c, m.problem->state()));
  return values;
}

/// The cube's cells keep their initial state, tensors rotated by R (to 1e-10 of its scale).
void expect_the_initial_state_rotated(const model::Model& m,
                                      const std::vector<analysis::CellValues>& initial,
                                      const Mat3& R) {
  const std::vector<analysis::CellValues> now = cell_values(m);
  ASSERT_EQ(now.size(), initial.size());
  Real scale = 1e-3; // the solid's modulus is 0.3 to 1 MPa
  for (const auto& v : initial)
    scale = std::max({scale, v.stress.norm(), std::abs(v.fluid_pressure)});
  for (std::size_t c = 0; c < now.size(); ++c) {
    EXPECT_LT((now[c].stress - R * initial[c].stress * R.transpose()).norm(), 1e-10 * scale) << c;
    EXPECT_NEAR(now[c].fluid_pressure, initial[c].fluid_pressure, 1e-10 * scale) << c;
    EXPECT_NEAR(now[c].relative_volume, initial[c].relative_volume, 1e-12) << c;
  }
}

/// A hinge about kAxis through kOrigin with a torsion spring k = 2 N mm/rad, a moment M = 0.6
/// N mm about kAxis on the femur (its components on rx, ry, rz): φ = M/k = 0.3 rad.
void expect_the_hinge_to_turn_by_moment_over_stiffness(const std::string& material) {
  constexpr Real kM = 0.6, kK = 2.0;
  std::string rest;
  for (int k = 0; k < 3; ++k)
    rest +=
        fmt::format("r{} = {{ moment = {:.17g}, curve = \"ramp\" }}\n", "xyz"[k], kM * kAxis[k]);
  rest += fmt::format(R"(
[[connector]]
type = "revolute"
name = "hinge"
body_a = "ground"
body_b = "femur"
origin = {}
axis = {}
transverse = [1.0, 0.0, 0.0]
torsion_stiffness = {:.17g}
)",
                      vec(kOrigin), vec(kAxis), kK);
  std::vector<analysis::CellValues> initial;
  bool first = true;
  const test::CaseRun run = test::run_case_text(
      hanging_cube_case(material, rest), "hinge.toml",
      [&](const test::CaseRun& r, const solver::StepInfo&) {
        if (first)
          initial = cell_values(*r.model); // (a rigid rotation keeps it: any step will do)
        first = false;
      });
  ASSERT_TRUE(run.report.success) << run.report.failure;
  const model::Model& m = *run.model;
  const Real phi = kM / kK;
  const model::RigidBody& femur = m.rigid_bodies.at(0);
  EXPECT_LT((model::rigid_body_rotation(m, femur) - phi * kAxis).norm(), 1e-12 * phi);
  const Mat3 R = rotation::matrix(phi * kAxis);
  EXPECT_LT(rigid_motion_error(m, R, kOrigin), 1e-12); // size 1.5 mm
  // the hinge's angle and the moment it applies to the femur: −M about the axis, no force
  const physics::RigidConnectorTerm& hinge = *m.connectors;
  ASSERT_EQ(hinge.connectors().size(), 1u);
  const auto& reported = hinge.connectors()[0].reported;
  ASSERT_EQ(reported.size(), 1u);
  EXPECT_NEAR(hinge.measure(0, reported[0].measure, m.problem->state()), phi, 1e-12 * phi);
  const physics::ConnectorWrench w = hinge.committed_wrenches()[0];
  EXPECT_LT((w.moment + kM * kAxis).norm(), 1e-10 * kM);
  EXPECT_LT(w.force.norm(), 1e-10 * kM); // over a lever of ~1 mm
  // the cube hangs from the femur only: carried rigidly, stress free
  EXPECT_LT(model::rigid_body_force(m, femur, 1.0).norm(), 1e-10 * kM);
  expect_the_initial_state_rotated(m, initial, R);
}

} // namespace

TEST(Connectors, ARevoluteJointWithATorsionSpringTurnsBySolidMomentOverStiffness) {
  expect_the_hinge_to_turn_by_moment_over_stiffness(kSolid);
}

TEST(Connectors, ARevoluteJointWithATorsionSpringTurnsABiphasicCubeByMomentOverStiffness) {
  expect_the_hinge_to_turn_by_moment_over_stiffness(kBiphasic);
}

TEST(Connectors, ARevoluteJointWithATorsionSpringTurnsATriphasicCubeByMomentOverStiffness) {
  expect_the_hinge_to_turn_by_moment_over_stiffness(kTriphasic);
}

TEST(Connectors, AMomentDrivingTheHingeItselfTurnsItTheSameWay) {
  // the joint's own drive (the work Mφ) in place of a moment on the body
  constexpr Real kM = 0.6, kK = 2.0;
  const test::CaseRun run =
      test::run_case_text(hanging_cube_case(kSolid, fmt::format(R"(
[[connector]]
type = "revolute"
name = "hinge"
body_a = "ground"
body_b = "femur"
origin = {}
axis = {}
rotation = {{ moment = {:.17g}, curve = "ramp" }}
torsion_stiffness = {:.17g}
)",
                                                                vec(kOrigin), vec(kAxis), kM, kK)),
                          "hinge_moment.toml");
  ASSERT_TRUE(run.report.success) << run.report.failure;
  const model::Model& m = *run.model;
  EXPECT_LT((model::rigid_body_rotation(m, m.rigid_bodies.at(0)) - (kM / kK) * kAxis).norm(),
            1e-12);
  // the spring's moment −kφ and the drive's +M cancel on the femur
  EXPECT_LT(m.connectors->committed_wrenches()[0].moment.norm(), 1e-10 * kM);
}

TEST(Connectors, APrismaticJointWithASpringSlidesByForceOverStiffness) {
  // the femur slides along kAxis under F = 0.5 N (the joint's drive); a spring of k = 4 N/mm
  // along the axis from the ground to the femur holds it: s = F/k, the length d + s
  constexpr Real kF = 0.5, kK = 4.0, kD = 0.8;
  const Vec3 tip = kOrigin + kD * kAxis;
  const test::CaseRun run =
      test::run_case_text(hanging_cube_case(kSolid, fmt::format(R"(
[[connector]]
type = "prismatic"
name = "slider"
body_a = "ground"
body_b = "femur"
origin = {}
axis = {}
translation = {{ force = {:.17g}, curve = "ramp" }}
[[connector]]
type = "spring"
name = "spring"
body_a = "ground"
body_b = "femur"
point_a = {}
point_b = {}
stiffness = {:.17g}
)",
                                                                vec(kOrigin), vec(kAxis), kF,
                                                                vec(kOrigin), vec(tip), kK)),
                          "slider.toml");
  ASSERT_TRUE(run.report.success) << run.report.failure;
  const model::Model& m = *run.model;
  const Real s = kF / kK;
  EXPECT_LT(model::rigid_body_rotation(m, m.rigid_bodies.at(0)).norm(), 1e-14);
  EXPECT_LT((model::rigid_body_displacement(m, m.rigid_bodies.at(0)) - s * kAxis).norm(),
            1e-12 * s);
  EXPECT_LT(rigid_motion_error(m, Mat3::Identity(), kOrigin, s * kAxis), 1e-12);
  const physics::RigidConnectorTerm& c = *m.connectors;
  const Vector& x = m.problem->state();
  EXPECT_NEAR(c.measure(0, c.connectors()[0].reported[0].measure, x), s, 1e-12 * s);
  EXPECT_NEAR(c.measure(1, c.connectors()[1].reported[0].measure, x), kD + s, 1e-12);
  // the spring pulls the femur back with F; the slider carries no force along its axis
  EXPECT_LT((c.committed_wrenches()[1].force + kF * kAxis).norm(), 1e-10 * kF);
  EXPECT_LT(std::abs(c.committed_wrenches()[0].force.dot(kAxis) - kF), 1e-10 * kF);
}

TEST(Connectors, ASphericalJointKeepsItsPointWhileTheBoneTurnsAndTakesTheLoad) {
  // the femur turned by 150° about (1, −2, 1)/√6 (prescribed) and pushed by F at its center:
  // it turns about the joint's point, which holds it with −F
  const Vec3 theta = (150.0 / 180.0 * std::numbers::pi) * Vec3(1.0, -2.0, 1.0).normalized();
  const Vec3 F(0.1, -0.2, 0.3);
  std::string rest;
  for (int k = 0; k < 3; ++k)
    rest += fmt::format("r{} = {{ rotation = {:.17g}, curve = \"ramp\" }}\n"
                        "{} = {{ force = {:.17g}, curve = \"ramp\" }}\n",
                        "xyz"[k], theta[k], "xyz"[k], F[k]);
  rest += fmt::format(R"(
[[connector]]
type = "spherical"
name = "ball"
body_a = "ground"
body_b = "femur"
origin = {}
)",
                      vec(kOrigin));
  const test::CaseRun run = test::run_case_text(hanging_cube_case(kSolid, rest), "ball.toml");
  ASSERT_TRUE(run.report.success) << run.report.failure;
  const model::Model& m = *run.model;
  EXPECT_LT(rigid_motion_error(m, rotation::matrix(theta), kOrigin), 1e-12);
  const physics::ConnectorWrench w = m.connectors->committed_wrenches()[0];
  EXPECT_LT((w.force + F).norm(), 1e-10 * F.norm());
  EXPECT_LT(w.moment.norm(), 1e-10 * F.norm()); // about the joint's point
}

TEST(Connectors, APrescribedHingeAngleTurnsTheBoneThroughAFullTurn) {
  // φ(t) = 2π t in eight steps: the femur's rotation passes π (its rotation vector is then
  // carried over to the equivalent one of length below π) and comes back to where it started
  const auto text_position = [](std::string_view what) {
    return hanging_cube_case(kSolid, "").find(what);
  };
  const test::CaseRun run = test::run_case_steps(
      hanging_cube_case(kSolid, fmt::format(R"(
[[connector]]
type = "revolute"
name = "hinge"
body_a = "ground"
body_b = "femur"
origin = {}
axis = {}
rotation = {{ rotation = {:.17g}, curve = "ramp" }}
)",
                                            vec(kOrigin), vec(kAxis), 2.0 * std::numbers::pi))
          .replace(text_position("dt = 0.25"), 9, "dt = 0.125"),
      "full_turn.toml", [&](const model::Model& m, Real time) {
        const Real phi = 2.0 * std::numbers::pi * time;
        EXPECT_LT(rigid_motion_error(m, rotation::matrix(phi * kAxis), kOrigin), 1e-11) << time;
        const Vec3 r = model::rigid_body_rotation(m, m.rigid_bodies.at(0));
        EXPECT_LE(r.norm(), std::numbers::pi + 1e-12) << time;
      });
  ASSERT_TRUE(run.report.success) << run.report.failure;
}

TEST(Connectors, TwoHingesOnOneAxisHoldTheBoneOnceAndTheSpringTurnsIt) {
  // a door on two hinges: the second repeats five of the first's constraints but its position
  // along the axis; the repeated ones are found and their multipliers held at 0, and the
  // moment turns the bone by M/k of the one torsion spring
  constexpr Real kM = 0.6, kK = 2.0;
  std::string rest;
  for (int k = 0; k < 3; ++k)
    rest +=
        fmt::format("r{} = {{ moment = {:.17g}, curve = \"ramp\" }}\n", "xyz"[k], kM * kAxis[k]);
  for (const Real along : {0.0, 0.7})
    rest += fmt::format(R"(
[[connector]]
type = "revolute"
body_a = "ground"
body_b = "femur"
origin = {}
axis = {}
torsion_stiffness = {:.17g}
)",
                        vec(kOrigin + along * kAxis), vec(kAxis), along == 0.0 ? kK : 0.0);
  const test::CaseRun run = test::run_case_text(hanging_cube_case(kSolid, rest), "door.toml");
  ASSERT_TRUE(run.report.success) << run.report.failure;
  const model::Model& m = *run.model;
  EXPECT_LT((model::rigid_body_rotation(m, m.rigid_bodies.at(0)) - (kM / kK) * kAxis).norm(),
            1e-12);
  // five of the ten multipliers held: the two hinges share the load, which balances M
  int held = 0;
  for (const auto& c : m.connectors->connectors())
    for (const auto& g : c.constraints)
      held += m.dofs.is_constrained(g.multiplier) ? 1 : 0;
  EXPECT_EQ(held, 5);
  const auto& w = m.connectors->committed_wrenches();
  const Vec3 about_origin = w[0].moment + w[1].moment + (0.7 * kAxis).cross(w[1].force);
  EXPECT_LT((about_origin + kM * kAxis).norm(), 1e-10 * kM);
}

namespace {

void expect_input_error(const std::string& rest, const std::vector<std::string>& parts) {
  try {
    test::run_case_text(hanging_cube_case(kSolid, rest), "bad.toml");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    for (const std::string& part : parts)
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

} // namespace

TEST(Connectors, ConnectorsThatCannotBeBuiltAreInputErrors) {
  const std::string hinge = "[[connector]]\ntype = \"revolute\"\norigin = [0.0, 0.0, 0.0]\n"
                            "axis = [0.0, 0.0, 1.0]\n";
  expect_input_error(hinge + "body_a = \"femur\"\nbody_b = \"femur\"\n",
                     {"connector[1].body_b", "itself"});
  expect_input_error(hinge + "body_a = \"ground\"\nbody_b = \"tibia\"\n",
                     {"connector[1].body_b", "tibia", "no rigid body", "femur"});
  expect_input_error("[[connector]]\ntype = \"prismatic\"\nbody_a = \"ground\"\n"
                     "body_b = \"femur\"\norigin = [0.0, 0.0, 0.0]\naxis = [0.0, 0.0, 1.0]\n"
                     "rotation = { rotation = 0.1 }\n",
                     {"connector[1].rotation", "no free rotation"});
  expect_input_error("[[connector]]\ntype = \"revolute\"\nbody_a = \"ground\"\nbody_b = "
                     "\"femur\"\norigin = [0.0, 0.0, 0.0]\naxis = [0.0, 0.0, 0.0]\n",
                     {"connector[1].axis", "zero vector"});
  expect_input_error("[[connector]]\ntype = \"hinge\"\n", {"connector[1].type", "revolute"});
  expect_input_error("[[connector]]\ntype = \"spring\"\nbody_a = \"ground\"\nbody_b = \"femur\"\n"
                     "point_a = [0.0, 0.0, 2.0]\npoint_b = [0.0, 0.0, 2.0]\nstiffness = 1.0\n",
                     {"connector[1].point_b", "coincide"});
  expect_input_error("x = { displacement = 0.0 }\n[[rigid_body]]\nname = \"lid\"\nset = "
                     "\"cube.zmin\"\n[[connector]]\ntype = \"spherical\"\nbody_a = \"lid\"\n"
                     "body_b = \"femur\"\norigin = [0.0, 0.0, 0.0]\n",
                     {"connector[1].body_a", "does not rotate", "rotation = \"free\""});
  expect_input_error("[[rigid_body]]\nname = \"ground\"\nset = \"cube.zmin\"\n",
                     {"rigid_body[2].name", "reserved"});
}

TEST(Connectors, ABoneThatNothingHoldsIsNamedBeforeTheRun) {
  // the bone alone (its cells carry nothing), turned but free to translate: singular
  const std::string text = R"(
[[mesh.box]]
name = "cube"
size = [1.0, 1.0, 1.0]
divisions = [1, 1, 1]
material = "tissue"
[[mesh.box]]
name = "bone"
origin = [0.0, 0.0, 2.0]
size = [1.0, 1.0, 0.3]
divisions = [1, 1, 1]
)" + std::string(kSolid) + R"(
[[boundary.fixed]]
set = "cube.zmin"
[time]
end_time = 1.0
dt = 0.5
[[rigid_body]]
name = "femur"
blocks = ["bone"]
x = { displacement = 0.0 }
rz = { rotation = 0.2 }
)";
  try {
    test::run_case_text(text, "free_bone.toml");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    for (const char* part :
         {"rigid_body[1]", "'femur' is not supported in y", "y = { displacement", "[[connector]]"})
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

TEST(Connectors, AFollowerForceKeepsItsMomentAboutTheHingeAsTheBoneTurns) {
  // a force F₀ at P turning with the bone: its moment about the hinge's axis stays
  // ((P − O) × F₀)·n, so the torsion spring turns the bone by that over k (here 1.2 rad; a
  // dead force's moment would change as it turns)
  const Vec3 P = kOrigin + Vec3(1.0, -0.5, 0.2);
  const Vec3 F = (kAxis.cross(P - kOrigin)).normalized() * 0.8;
  const Real kK = ((P - kOrigin).cross(F)).dot(kAxis) / 1.2;
  const std::string rest = fmt::format(R"(
[[rigid_body.follower]]
force = {}
point = {}
curve = "ramp"
[[connector]]
type = "revolute"
name = "hinge"
body_a = "ground"
body_b = "femur"
origin = {}
axis = {}
torsion_stiffness = {:.17g}
)",
                                       vec(F), vec(P), vec(kOrigin), vec(kAxis), kK);
  const test::CaseRun run = test::run_case_text(hanging_cube_case(kSolid, rest), "follower.toml");
  ASSERT_TRUE(run.report.success) << run.report.failure;
  const model::Model& m = *run.model;
  const Vec3 theta = model::rigid_body_rotation(m, m.rigid_bodies.at(0));
  EXPECT_LT((theta - 1.2 * kAxis).norm(), 1e-12);
  // the hinge holds the turned force: −R F₀ on the femur
  const Vec3 turned = rotation::matrix(theta) * F;
  EXPECT_LT((m.connectors->committed_wrenches()[0].force + turned).norm(), 1e-10 * F.norm());
}

namespace {

/// examples/knee_flexion through its load step (to `load_end`, the full load from 0.1 s) and the
/// start of the flexion (to `flexion_end`: 0.3 rad/s): at every step the tibia holds the load on
/// the femur, and about the flexion axis its moment balances the knee's.
void expect_the_knee_to_balance(Real load_end, Real flexion_end, Real flexion, int min_steps) {
  const std::filesystem::path file =
      std::filesystem::path(TRIFEM_EXAMPLES_DIR) / "knee_flexion" / "knee_flexion.toml";
  std::ifstream in(file);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t hold = text.find("[[step]]                    # held");
  ASSERT_NE(hold, std::string::npos);
  text.erase(hold, text.find("\n\n", hold) - hold); // the load and the flexion only
  const std::size_t times = text.find("times = [");
  ASSERT_NE(times, std::string::npos);
  text.erase(times, text.find('\n', times) - times); // (outputs past the end)
  const std::size_t load_step_end = text.find("end_time = 0.5");
  ASSERT_NE(load_step_end, std::string::npos);
  text.replace(load_step_end, 14, fmt::format("end_time = {}", load_end));
  const std::size_t flex_end = text.find("end_time = 1.5");
  ASSERT_NE(flex_end, std::string::npos);
  text.replace(flex_end, 14, fmt::format("end_time = {}", flexion_end));
  const std::string flex_curve = "[[0.0, 0.0], [0.5, 0.0], [1.5, 1.0]]";
  const std::size_t curve = text.find(flex_curve);
  ASSERT_NE(curve, std::string::npos);
  text.replace(curve, flex_curve.size(), // the flexion starts when the load step ends
               fmt::format("[[0.0, 0.0], [{}, 0.0], [{}, 1.0]]", load_end, load_end + 1.0));
  text += "[solver]\nlinear_solver = \"umfpack\"\n"; // (exact solves: the same path anywhere)
  constexpr Real kLoad = 0.6;                        // [N] (per mm depth)
  const Vec3 axis_point(8.0, 10.0, 0.5);
  int steps = 0;
  const test::CaseRun run = test::run_case_steps(text, file, [&](const model::Model& m, Real time) {
    const Vector& x = m.problem->state();
    const Vector& R = m.problem->full_residual();
    // about the femur's current center, where its load and x reaction act
    const Vec3 centre = axis_point + model::rigid_body_displacement(m, m.rigid_bodies.at(0));
    Vec3 force = Vec3::Zero(), moment = Vec3::Zero();
    for (Index n : m.mesh.node_set("tibial.bone")) {
      Vec3 r, p = m.mesh.node(n);
      for (int k = 0; k < 3; ++k) {
        r[k] = R[m.dofs.dof(m.fields.u, n, k)];
        p[k] += x[m.dofs.dof(m.fields.u, n, k)];
      }
      force += r;
      moment += (p - centre).cross(r);
    }
    const Real load = kLoad * std::min(time / 0.1, 1.0);
    EXPECT_NEAR(force.y(), load, 1e-8 * kLoad) << time; // the tibia pushed down
    // the knee's moment on the femur about its axis balances the tibia's
    const Real knee = m.connectors->committed_wrenches()[0].moment.z();
    EXPECT_NEAR(moment.z(), -knee, 1e-8 * kLoad * 10.0) << time; // lever: R = 10 mm
    ++steps;
  });
  ASSERT_TRUE(run.report.success) << run.report.failure;
  EXPECT_GE(steps, min_steps);
  EXPECT_NEAR(model::rigid_body_rotation(*run.model, run.model->rigid_bodies.at(0)).z(), flexion,
              1e-12);
}

} // namespace

TEST(Connectors, TheKneeExampleBalancesItsLoadAndMomentAtEveryStep) {
  expect_the_knee_to_balance(0.5, 0.6, 0.03, 20); // a tenth of the flexion
}

TEST(Connectors, TheKneeExampleBalancesOnSeveralProcesses) {
  // the same, shorter, for the runs on 2 and 3 processes (one process runs the longer one)
  if (parallel::size() == 1)
    GTEST_SKIP() << "runs on several processes only";
  expect_the_knee_to_balance(0.1, 0.15, 0.015, 8);
}
