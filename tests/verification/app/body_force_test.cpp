// SPDX-License-Identifier: MIT
// [[loads.body_force]] against closed forms:
//   * a column of height H under its own weight, bottom fixed, sides sliding (uniaxial strain):
//     the bottom's reaction is the weight ρ g V, and the top settles by ρ g H² / (2 M) (M the
//     P-wave modulus; small strains);
//   * a rigid body of cells with a density, held at a point away from its center of mass by its
//     prescribed translation and rotation about that point, or by a spherical joint to the ground
//     with its rotation held: the support carries the weight m g and the moment (X_G − P) × m g;
//   * a free block in an implicit dynamic analysis falls as u = b t² / 2 (the generalized-α
//     steps integrate a constant acceleration exactly).
#include "case_runner.hpp"

#include <gtest/gtest.h>

#include <string>

using namespace trifem;

namespace {

std::string vec(const Vec3& v) {
  return fmt::format("[{:.17g}, {:.17g}, {:.17g}]", v.x(), v.y(), v.z());
}

constexpr Real kE = 1.0, kNu = 0.3;        // [MPa]
constexpr Real kRho = 1.0e-9, kG = 9810.0; // [t/mm^3], [mm/s^2]
constexpr Real kH = 10.0;                  // [mm]

/// A 1 x 1 x H column of `divisions` cells along z with its sides sliding and its bottom fixed,
/// under gravity (−z) ramped over the run.
std::string column_case(int divisions, const char* cell = "hex8") {
  return fmt::format(R"(
[[mesh.box]]
name = "column"
size = [1.0, 1.0, {}]
divisions = [1, 1, {}]
cell = "{}"
material = "tissue"
[materials.tissue]
type = "neo-hookean"
E = {}
nu = {}
density = {}
[curves.ramp]
points = [[0.0, 0.0], [1.0, 1.0]]
[[boundary.fixed]]
set = "column.xmin"
components = ["x"]
[[boundary.fixed]]
set = "column.xmax"
components = ["x"]
[[boundary.fixed]]
set = "column.ymin"
components = ["y"]
[[boundary.fixed]]
set = "column.ymax"
components = ["y"]
[[boundary.fixed]]
set = "column.zmin"
components = ["z"]
[[loads.body_force]]
force = [0.0, 0.0, {:.17g}]
curve = "ramp"
[time]
end_time = 1.0
dt = 0.5
[solver]
residual_tolerance = 1e-13
increment_tolerance = 1e-14
)",
                     kH, divisions, cell, kE, kNu, kRho, -kG);
}

Real sum_of_reactions(const model::Model& m, const std::string& set, int k) {
  Real f = 0.0;
  for (Index n : m.mesh.node_set(set))
    f += m.problem->full_residual()[m.dofs.dof(m.fields.u, n, k)];
  return f;
}

Real mean_displacement(const model::Model& m, const std::string& set, int k) {
  Real u = 0.0;
  const auto& nodes = m.mesh.node_set(set);
  for (Index n : nodes)
    u += m.problem->state()[m.dofs.dof(m.fields.u, n, k)];
  return u / static_cast<Real>(nodes.size());
}

// The bone: a 2 x 1 x 0.5 box of rigid cells with the density kBoneRho, and a cube of tissue
// (without density: no weight) bonded below it so that the model has a material.
constexpr Real kBoneRho = 2.0e-9;
const Vec3 kBoneOrigin(1.0, -0.5, 1.0), kBoneSize(2.0, 1.0, 0.5);
const Vec3 kGravity(300.0, -500.0, -9810.0); // [mm/s^2], oblique
const Vec3 kPivot(-0.3, 0.4, 2.2);           // the point the bone is held at [mm]

std::string bone_case(const std::string& holding) {
  return fmt::format(R"(
[[mesh.box]]
name = "bone"
origin = {}
size = {}
divisions = [2, 1, 1]
[[mesh.box]]
name = "cube"
origin = [1.5, -0.5, 0.0]
size = [1.0, 1.0, 1.0]
divisions = [1, 1, 1]
material = "tissue"
[materials.tissue]
type = "neo-hookean"
E = 1.0
nu = 0.3
[[loads.body_force]]
force = {}
blocks = ["bone"]
[time]
end_time = 1.0
dt = 1.0
[solver]
residual_tolerance = 1e-13
increment_tolerance = 1e-14
[[rigid_body]]
name = "femur"
blocks = ["bone"]
set = "cube.zmax"
density = {}
)",
                     vec(kBoneOrigin), vec(kBoneSize), vec(kGravity), kBoneRho) +
         holding;
}

/// The weight m b of the bone and its moment about the pivot (X_G − P) × m b.
std::pair<Vec3, Vec3> bone_weight_and_moment() {
  const Real m = kBoneRho * kBoneSize.prod();
  const Vec3 centre = kBoneOrigin + 0.5 * kBoneSize;
  return {m * kGravity, (centre - kPivot).cross(m * kGravity)};
}

} // namespace

TEST(BodyForce, AColumnUnderItsOwnWeightCarriesItOnItsBaseAndSettlesAsInOneDimension) {
  const test::CaseRun run = test::run_case_text(column_case(40), "column.toml");
  ASSERT_TRUE(run.report.success) << run.report.failure;
  const model::Model& m = *run.model;
  const Real weight = kRho * kG * kH; // V = 1 x 1 x H
  const Real base = sum_of_reactions(m, "column.zmin", 2);
  EXPECT_NEAR(base, weight, 1e-10 * weight); // the support pushes up
  const Real M = kE * (1.0 - kNu) / ((1.0 + kNu) * (1.0 - 2.0 * kNu));
  const Real exact = -kRho * kG * kH * kH / (2.0 * M);
  const Real top = mean_displacement(m, "column.zmax", 2);
  EXPECT_NEAR(top, exact, 0.01 * std::abs(exact));
  EXPECT_LT(kRho * kG * kH / M, 1e-4); // the largest strain: small
  std::printf("column: base reaction %.17g N, weight %.17g N (relative difference %.2e); top "
              "%.10g mm, 1-D linear %.10g mm (relative difference %.2e)\n",
              base, weight, std::abs(base - weight) / weight, top, exact,
              std::abs(top - exact) / std::abs(exact));
}

TEST(BodyForce, ARigidBodyHeldAtAPointCarriesItsWeightAndItsMomentThere) {
  // center = the pivot; its translation and rotation held: the reactions at the body's unknowns
  // are the support's force −m b... with R = f_int − f_ext, R = −m b and −(X_G − P) × m b
  const test::CaseRun run = test::run_case_text(bone_case(fmt::format(R"(
center = {}
x = {{ displacement = 0.0 }}
y = {{ displacement = 0.0 }}
z = {{ displacement = 0.0 }}
rx = {{ rotation = 0.0 }}
ry = {{ rotation = 0.0 }}
rz = {{ rotation = 0.0 }}
)",
                                                                      vec(kPivot))),
                                                "held.toml");
  ASSERT_TRUE(run.report.success) << run.report.failure;
  const model::Model& m = *run.model;
  const dofs::RigidBodyDofs& body = m.problem->rigid_map().bodies().at(0);
  const Vector& R = m.problem->full_residual();
  Vec3 force, moment;
  for (int k = 0; k < 3; ++k) {
    force[k] = R[body.translation[k]];
    moment[k] = R[body.rotation[k]];
  }
  const auto [weight, arm_moment] = bone_weight_and_moment();
  EXPECT_LT((force + weight).norm(), 1e-10 * weight.norm()) << force.transpose();
  EXPECT_LT((moment + arm_moment).norm(), 1e-10 * arm_moment.norm()) << moment.transpose();
  std::printf("held bone: |F + m b| / |m b| = %.2e, |M + (X_G - P) x m b| / |.| = %.2e\n",
              (force + weight).norm() / weight.norm(),
              (moment + arm_moment).norm() / arm_moment.norm());
}

TEST(BodyForce, ARigidBodyOnASphericalJointLoadsTheJointWithItsWeight) {
  // the joint at the pivot takes the weight (the force it applies to the body: −m b); the
  // held rotation (about the body's center X_G) takes the moment of the joint's force there
  const test::CaseRun run = test::run_case_text(bone_case(fmt::format(R"(
rx = {{ rotation = 0.0 }}
ry = {{ rotation = 0.0 }}
rz = {{ rotation = 0.0 }}
[[connector]]
type = "spherical"
name = "pivot"
body_a = "ground"
body_b = "femur"
origin = {}
)",
                                                                      vec(kPivot))),
                                                "spherical.toml");
  ASSERT_TRUE(run.report.success) << run.report.failure;
  const model::Model& m = *run.model;
  const auto [weight, arm_moment] = bone_weight_and_moment();
  const physics::ConnectorWrench w = m.connectors->committed_wrenches().at(0);
  EXPECT_LT((w.force + weight).norm(), 1e-10 * weight.norm()) << w.force.transpose();
  const dofs::RigidBodyDofs& body = m.problem->rigid_map().bodies().at(0);
  const Vector& R = m.problem->full_residual();
  Vec3 moment;
  for (int k = 0; k < 3; ++k)
    moment[k] = R[body.rotation[k]];
  EXPECT_LT((moment + arm_moment).norm(), 1e-10 * arm_moment.norm()) << moment.transpose();
  std::printf("spherical joint: |F_joint + m b| / |m b| = %.2e, |M + (X_G - P) x m b| / |.| = "
              "%.2e\n",
              (w.force + weight).norm() / weight.norm(),
              (moment + arm_moment).norm() / arm_moment.norm());
}

/// A free block of `cell` cells under a body force b in a dynamic analysis (`mass` matrix): every
/// node at b t^2 / 2 (the consistent mass times a uniform acceleration is the body force's load);
/// returns the largest relative difference over the nodes and steps.
Real free_fall_error(const char* cell, const Vec3& b, const char* mass = "consistent") {
  const std::string text = fmt::format(R"(
[analysis]
type = "dynamic"
[dynamic]
mass = "{}"
[[mesh.box]]
name = "block"
size = [1.0, 2.0, 1.5]
divisions = [2, 2, 2]
cell = "{}"
material = "tissue"
[materials.tissue]
type = "neo-hookean"
E = 1.0
nu = 0.3
density = 1.1e-9
[[loads.body_force]]
force = {}
[time]
end_time = 0.01
dt = 0.001
[solver]
residual_tolerance = 1e-12
increment_tolerance = 1e-14
)",
                                       mass, cell, vec(b));
  int steps = 0;
  Real worst = 0.0;
  const test::CaseRun run =
      test::run_case_steps(text, "fall.toml", [&](const model::Model& m, Real t) {
        const Vec3 exact = 0.5 * t * t * b;
        for (Index n = 0; n < m.mesh.num_nodes(); ++n) {
          Vec3 u;
          for (int k = 0; k < 3; ++k)
            u[k] = m.problem->state()[m.dofs.dof(m.fields.u, n, k)];
          worst = std::max(worst, (u - exact).norm() / exact.norm());
        }
        ++steps;
      });
  EXPECT_TRUE(run.report.success) << cell << ": " << run.report.failure;
  EXPECT_EQ(steps, 10) << cell;
  return worst;
}

TEST(BodyForce, AFreeBlockFallsWithTheAccelerationOfItsBodyForce) {
  const Real worst = free_fall_error("hex8", Vec3(200.0, 0.0, -9810.0));
  EXPECT_LT(worst, 1e-10);
  std::printf("free fall: largest |u - b t^2/2| / |b t^2/2| over the nodes and steps = %.2e\n",
              worst);
}

// The cells of the other families: their consistent mass (by their family's rule) and their
// body-force loads; a column of them settles under its weight as the hex8 column does, a free
// block of them falls with b, with their mass lumped too.
TEST(BodyForce, CellsOfEveryFamilyCarryTheirWeightAndFallWithTheirBodyForce) {
  const Real weight = kRho * kG * kH;
  const Real M = kE * (1.0 - kNu) / ((1.0 + kNu) * (1.0 - 2.0 * kNu));
  const Real exact = -kRho * kG * kH * kH / (2.0 * M);
  for (const char* cell : {"tet4", "tet10", "penta6", "hex20"}) {
    const test::CaseRun run = test::run_case_text(column_case(20, cell), "column.toml");
    ASSERT_TRUE(run.report.success) << cell << ": " << run.report.failure;
    EXPECT_NEAR(sum_of_reactions(*run.model, "column.zmin", 2), weight, 1e-10 * weight) << cell;
    EXPECT_NEAR(mean_displacement(*run.model, "column.zmax", 2), exact, 0.01 * std::abs(exact))
        << cell;
    EXPECT_LT(free_fall_error(cell, Vec3(200.0, 0.0, -9810.0)), 1e-10) << cell;
  }
  // lumped, the masses of quadratic cells are their diagonals scaled to the cell's mass and the
  // body force is lumped with them: a free block falls with b
  for (const char* cell : {"tet10", "hex20"}) {
    EXPECT_LT(free_fall_error(cell, Vec3(200.0, 0.0, -9810.0), "lumped"), 1e-10) << cell;
  }
}

// ---------------------------------------------------------------------------------------------
// [[loads.nodal_force]]

namespace {

const Vec3 kNodalForce(0.01, -0.02, 0.05); // [N] per node

/// A unit cube of one hex8 cell, its base fixed, loaded on its top face by `load` (ramped).
std::string loaded_cube(const std::string& load) {
  return R"(
[[mesh.box]]
name = "cube"
size = [1.0, 1.0, 1.0]
divisions = [1, 1, 1]
material = "tissue"
[materials.tissue]
type = "neo-hookean"
E = 1.0
nu = 0.3
[curves.ramp]
points = [[0.0, 0.0], [1.0, 1.0]]
[[boundary.fixed]]
set = "cube.zmin"
[time]
end_time = 1.0
dt = 0.5
[solver]
residual_tolerance = 1e-13
increment_tolerance = 1e-14
)" + load;
}

} // namespace

// The same dead load given two ways: a force F on each of the 4 nodes of the top face of one
// hex8 cell, or the uniform traction 4 F / A on that face (its consistent nodal forces on a
// flat quad are t A / 4 each): the same state to round-off, and the base carries 4 F.
TEST(NodalForce, ForcesOnTheNodesOfAFaceActAsTheTractionTheyLump) {
  const test::CaseRun nodal = test::run_case_text(loaded_cube(fmt::format(R"(
[[loads.nodal_force]]
set = "cube.zmax"
value = {}
curve = "ramp"
)",
                                                                          vec(kNodalForce))),
                                                  "nodal.toml");
  const test::CaseRun traction =
      test::run_case_text(loaded_cube(fmt::format(R"(
[[loads.traction]]
surface = "cube.zmax"
value = {}
curve = "ramp"
)",
                                                  vec(4.0 * kNodalForce))),
                          "traction.toml");
  ASSERT_TRUE(nodal.report.success) << nodal.report.failure;
  ASSERT_TRUE(traction.report.success) << traction.report.failure;
  const Vector& a = nodal.model->problem->state();
  const Vector& b = traction.model->problem->state();
  ASSERT_EQ(a.size(), b.size());
  EXPECT_GT(b.norm(), 1e-3); // the load deforms the cube
  EXPECT_LE((a - b).norm(), 1e-12 * b.norm());
  for (int k = 0; k < 3; ++k) // R = f_int − f_ext: the support's reaction is −4 F
    EXPECT_NEAR(sum_of_reactions(*nodal.model, "cube.zmin", k), -4.0 * kNodalForce[k],
                1e-12 * kNodalForce.norm())
        << k;
  std::printf("nodal forces vs traction: |u_nodal - u_traction| / |u| = %.2e\n",
              (a - b).norm() / b.norm());
}

// Forces on the nodes of a rigid body reach its unknowns as any load on its DOFs does: held at
// the pivot under its weight, the body's reactions are the weight and the forces' sum, and
// their moments about the pivot.
TEST(NodalForce, ForcesOnTheNodesOfARigidBodyLoadTheBodyWithTheirSumAndMoment) {
  const test::CaseRun run =
      test::run_case_text(bone_case(fmt::format(R"(
center = {}
x = {{ displacement = 0.0 }}
y = {{ displacement = 0.0 }}
z = {{ displacement = 0.0 }}
rx = {{ rotation = 0.0 }}
ry = {{ rotation = 0.0 }}
rz = {{ rotation = 0.0 }}
[[loads.nodal_force]]
set = "bone.zmax"
value = {}
)",
                                                vec(kPivot), vec(kNodalForce))),
                          "nodal_bone.toml");
  ASSERT_TRUE(run.report.success) << run.report.failure;
  const model::Model& m = *run.model;
  auto [load, moment_about_pivot] = bone_weight_and_moment();
  for (Index n : m.mesh.node_set("bone.zmax")) {
    load += kNodalForce;
    moment_about_pivot += (m.mesh.node(n) - kPivot).cross(kNodalForce);
  }
  const dofs::RigidBodyDofs& body = m.problem->rigid_map().bodies().at(0);
  const Vector& R = m.problem->full_residual();
  Vec3 force, moment;
  for (int k = 0; k < 3; ++k) {
    force[k] = R[body.translation[k]];
    moment[k] = R[body.rotation[k]];
  }
  EXPECT_LT((force + load).norm(), 1e-10 * load.norm()) << force.transpose();
  EXPECT_LT((moment + moment_about_pivot).norm(), 1e-10 * moment_about_pivot.norm())
      << moment.transpose();
}
