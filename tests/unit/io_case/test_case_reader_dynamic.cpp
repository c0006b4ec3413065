// SPDX-License-Identifier: MIT
// Implicit dynamic analyses: [analysis] type = "dynamic", dynamic [[step]]s, the [dynamic]
// table and the densities they need, and the errors of bad input; the TOML writer keeps them.
#include "bad_input.hpp"
#include "trifem/io/case_writer.hpp"

#include <gtest/gtest.h>

using namespace trifem;
using namespace trifem::test;

namespace {

const std::string kBlock = R"(
[[mesh.box]]
name = "block"
size = [1, 1, 1]
divisions = [2, 2, 2]
material = "soft"

[materials.soft]
type = "neo-hookean"
E = 1.0
density = 1.1e-9

[[boundary.fixed]]
set = "block.zmin"
)";

const std::string kDynamic = kBlock + R"(
[analysis]
type = "dynamic"

[dynamic]
rho_inf = 0.8
mass = "lumped"

[time]
end_time = 0.01
dt = 0.001
)";

const std::string kSteps = kBlock + R"(
[dynamic]
rho_inf = 0.5

[[step]]
name = "press"
end_time = 1.0
dt = 0.1

[[step]]
name = "drop"
analysis = "dynamic"
duration = 0.01
dt = 0.001
)";

TEST(CaseReaderDynamic, ReadsTheAnalysisTypeAndTheDynamicTable) {
  const io::CaseSpec c = io::parse_case(kDynamic, kMemoryFile);
  EXPECT_EQ(c.analysis.type, io::AnalysisType::Dynamic);
  EXPECT_TRUE(c.has_dynamic_step());
  EXPECT_FALSE(c.is_explicit());
  EXPECT_EQ(c.dynamics.rho_inf, 0.8);
  EXPECT_EQ(c.dynamics.mass, io::MassMatrixSpec::Lumped);
  EXPECT_EQ(c.materials.at("soft").density, 1.1e-9);
}

TEST(CaseReaderDynamic, DefaultsAreTheTrapezoidalRuleWithAConsistentMass) {
  const io::CaseSpec c = io::parse_case(
      replaced_in(replaced_in(kDynamic, "rho_inf = 0.8\n", ""), "mass = \"lumped\"\n", ""),
      kMemoryFile);
  EXPECT_EQ(c.dynamics.rho_inf, 1.0);
  EXPECT_EQ(c.dynamics.mass, io::MassMatrixSpec::Consistent);
}

TEST(CaseReaderDynamic, AStepMayBeDynamicAfterAQuasiStaticOne) {
  const io::CaseSpec c = io::parse_case(kSteps, kMemoryFile);
  ASSERT_EQ(c.steps.size(), 2u);
  EXPECT_FALSE(c.steps[0].is_dynamic());
  EXPECT_TRUE(c.steps[1].is_dynamic());
  EXPECT_TRUE(c.has_dynamic_step());
  EXPECT_EQ(c.dynamics.rho_inf, 0.5);
}

TEST(CaseReaderDynamic, AMixtureTakesTheDensityOfTheSaturatedTissue) {
  const std::string text = replaced_in(kDynamic, R"([materials.soft]
type = "neo-hookean"
E = 1.0
density = 1.1e-9
)",
                                       R"([materials.soft]
type = "biphasic"
phi_s0 = 0.2
permeability = 1e-3
density = 1.05e-9
[materials.soft.solid]
type = "neo-hookean"
E = 1.0
)");
  const io::CaseSpec c = io::parse_case(text, kMemoryFile);
  EXPECT_EQ(c.materials.at("soft").density, 1.05e-9);
}

TEST(CaseReaderDynamic, TheWriterKeepsTheDynamicKeys) {
  for (const std::string& text : {kDynamic, kSteps}) {
    const io::CaseSpec c = io::parse_case(text, kMemoryFile);
    const io::CaseSpec again = io::parse_case(io::case_toml(c), kMemoryFile);
    EXPECT_EQ(again.analysis.type, c.analysis.type);
    EXPECT_EQ(again.dynamics.rho_inf, c.dynamics.rho_inf);
    EXPECT_EQ(again.dynamics.mass, c.dynamics.mass);
    ASSERT_EQ(again.steps.size(), c.steps.size());
    for (std::size_t k = 0; k < c.steps.size(); ++k)
      EXPECT_EQ(again.steps[k].analysis, c.steps[k].analysis);
    EXPECT_EQ(again.materials.at("soft").density, c.materials.at("soft").density);
  }
}

/// kDynamic with a bone of rigid cells above the block, its top's nodes carried, and `keys` in
/// its [[rigid_body]].
std::string with_bone(const std::string& keys) {
  return kDynamic + R"(
[[mesh.box]]
name = "bone"
origin = [0, 0, 1]
size = [1, 1, 0.2]
divisions = [1, 1, 1]

[[rigid_body]]
name = "femur"
set = "block.zmax"
blocks = ["bone"]
)" + keys;
}

TEST(CaseReaderDynamic, ARigidBodysDensityVelocitiesAndEulerAnglesAreReadAndWritten) {
  const io::CaseSpec c = io::parse_case(with_bone(R"(density = 2e-9
velocity = [1.0, 0.0, -2.0]
angular_velocity = [0.0, 3.0, 0.0]
euler_angles = { x = { rotation = 0.25 }, z = { rotation = -0.5, curve = "ramp" } }
[curves.ramp]
points = [[0, 0], [1, 1]]
)"),
                                        kMemoryFile);
  for (const io::CaseSpec& spec : {c, io::parse_case(io::case_toml(c), kMemoryFile)}) {
    ASSERT_EQ(spec.rigid_bodies.size(), 1u);
    const io::RigidBodySpec& b = spec.rigid_bodies[0];
    ASSERT_TRUE(b.density.has_value());
    EXPECT_EQ(*b.density, 2e-9);
    EXPECT_EQ(b.velocity, Vec3(1.0, 0.0, -2.0));
    EXPECT_EQ(b.angular_velocity, Vec3(0.0, 3.0, 0.0));
    ASSERT_TRUE(b.euler_angles.has_value());
    EXPECT_EQ((*b.euler_angles)[0].value, 0.25);
    EXPECT_EQ((*b.euler_angles)[1].value, 0.0); // absent: 0
    EXPECT_EQ((*b.euler_angles)[2].value, -0.5);
    EXPECT_EQ((*b.euler_angles)[2].curve, "ramp");
  }
}

/// with_bone's body as a surface body (its set alone, rotating) with `keys`.
std::string with_shells(const std::string& keys) {
  return replaced_in(with_bone("rotation = \"free\"\n" + keys), "blocks = [\"bone\"]\n", "");
}

TEST(CaseReaderDynamic, ARigidBodysShellThicknessIsReadAndWritten) {
  const io::CaseSpec c =
      io::parse_case(with_shells("density = 2e-9\nshell_thickness = 0.25\n"), kMemoryFile);
  for (const io::CaseSpec& spec : {c, io::parse_case(io::case_toml(c), kMemoryFile)}) {
    ASSERT_EQ(spec.rigid_bodies.size(), 1u);
    const io::RigidBodySpec& b = spec.rigid_bodies[0];
    ASSERT_TRUE(b.shell_thickness.has_value());
    EXPECT_EQ(*b.shell_thickness, 0.25);
    EXPECT_EQ(b.density, 2e-9);
  }
}

class CaseReaderDynamicErrors : public ::testing::TestWithParam<BadCase> {};

TEST_P(CaseReaderDynamicErrors, NameTheFileAndTheKey) {
  expect_fails_naming(GetParam());
}

INSTANTIATE_TEST_SUITE_P(
    BadCases, CaseReaderDynamicErrors,
    ::testing::Values(
        BadCase{"missing_density",
                replaced_in(kDynamic, "density = 1.1e-9\n", ""),
                {"materials.soft.density", "missing required key", "dynamic analyses"}},
        BadCase{"missing_density_of_a_dynamic_step",
                replaced_in(kSteps, "density = 1.1e-9\n", ""),
                {"materials.soft.density", "missing required key"}},
        BadCase{"rho_inf_above_one",
                replaced_in(kDynamic, "rho_inf = 0.8", "rho_inf = 1.5"),
                {"dynamic.rho_inf", "1.5", "[0, 1]"}},
        BadCase{"unknown_mass",
                replaced_in(kDynamic, "mass = \"lumped\"", "mass = \"diagonal\""),
                {"dynamic.mass", "diagonal", "consistent", "lumped"}},
        BadCase{"unknown_key",
                replaced_in(kDynamic, "rho_inf = 0.8", "rho_infinity = 0.8"),
                {"dynamic.rho_infinity"}},
        BadCase{"dynamic_table_of_a_quasi_static_case",
                replaced_in(kDynamic, "type = \"dynamic\"", "type = \"quasi-static\""),
                {"dynamic", "only applies to dynamic analyses"}},
        BadCase{"rigid_velocity_of_a_quasi_static_case",
                replaced_in(replaced_in(with_bone("velocity = [1.0, 0.0, 0.0]\n"),
                                        "type = \"dynamic\"", "type = \"quasi-static\""),
                            "[dynamic]\nrho_inf = 0.8\nmass = \"lumped\"\n", ""),
                {"rigid_body[1].velocity", "only applies to dynamic analyses"}},
        BadCase{"density_of_a_body_without_cells",
                replaced_in(with_bone("density = 1e-9\n"), "blocks = [\"bone\"]\n", ""),
                {"rigid_body[1].density", "only a body made of cells"}},
        BadCase{"shell_thickness_of_a_body_of_cells",
                with_bone("density = 1e-9\nshell_thickness = 0.1\n"),
                {"rigid_body[1].shell_thickness", "a body made of cells (blocks) has no shells"}},
        BadCase{"shell_thickness_without_density",
                with_shells("shell_thickness = 0.1\n"),
                {"rigid_body[1].shell_thickness", "no mass without a density"}},
        BadCase{"non_positive_shell_thickness",
                with_shells("density = 1e-9\nshell_thickness = 0.0\n"),
                {"rigid_body[1].shell_thickness"}},
        BadCase{"euler_angles_and_rz",
                with_bone("rz = { rotation = 0.1 }\neuler_angles = { x = { rotation = 0.2 } }\n"),
                {"rigid_body[1].euler_angles", "either by rx, ry, rz or by euler_angles"}},
        BadCase{"a_moment_in_euler_angles",
                with_bone("euler_angles = { x = { moment = 0.2 } }\n"),
                {"rigid_body[1].euler_angles.x.moment"}}),
    [](const auto& info) { return info.param.name; });

} // namespace
