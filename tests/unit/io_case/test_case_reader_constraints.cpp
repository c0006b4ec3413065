// SPDX-License-Identifier: MIT
// [[constraint]] tables: each kind read into its ConstraintSpec, the errors of bad constraints
// (naming the key and the line), and the TOML writer's round trip.
#include "bad_input.hpp"
#include "trifem/io/case_writer.hpp"

#include <gtest/gtest.h>

#include <cmath>

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
density = 1e-9

[curves.ramp]
points = [[0, 0], [1, 1]]

[time]
end_time = 1.0
dt = 0.1
)";

const std::string kSymmetry = R"(
[[constraint]]
type = "symmetry-plane"
name = "x0_plane"
surface = "block.xmin"
)";

const std::string kNormal = R"(
[[constraint]]
type = "normal-displacement"
surface = "block.ymin"
)";

const std::string kLinear = R"(
[[constraint]]
type = "linear"
name = "tie"
terms = [ { node = 4, component = "z", coefficient = 1.0 },
          { node = 8, component = "x", coefficient = -0.5 } ]
value = 0.25
curve = "ramp"
)";

const std::string kWall = R"(
[[constraint]]
type = "rigid-wall"
name = "floor"
surface = "block.zmin"
point = [0.0, 0.0, -0.1]
normal = [0.0, 3.0, 4.0]
offset = 0.5
curve = "ramp"
)";

const std::string kAll = kBlock + kSymmetry + kNormal + kLinear + kWall;

TEST(CaseReaderConstraints, ReadsEveryKind) {
  const io::CaseSpec c = io::parse_case(kAll, kMemoryFile);
  ASSERT_EQ(c.constraints.size(), 4u);

  const io::ConstraintSpec& plane = c.constraints[0];
  EXPECT_EQ(plane.key, "constraint[1]");
  EXPECT_EQ(plane.name, "x0_plane");
  EXPECT_EQ(plane.kind, io::ConstraintKind::SymmetryPlane);
  EXPECT_EQ(plane.surface, "block.xmin");
  EXPECT_TRUE(plane.entries.empty());
  EXPECT_TRUE(plane.curve.empty());

  const io::ConstraintSpec& normal = c.constraints[1];
  EXPECT_EQ(normal.key, "constraint[2]");
  EXPECT_EQ(normal.name, "constraint_2") << "the default name counts from 1";
  EXPECT_EQ(normal.kind, io::ConstraintKind::NormalDisplacement);
  EXPECT_EQ(normal.surface, "block.ymin");

  const io::ConstraintSpec& tie = c.constraints[2];
  EXPECT_EQ(tie.kind, io::ConstraintKind::Linear);
  EXPECT_TRUE(tie.surface.empty());
  ASSERT_EQ(tie.entries.size(), 2u);
  EXPECT_EQ(tie.entries[0].node, 4);
  EXPECT_EQ(tie.entries[0].component, 2);
  EXPECT_EQ(tie.entries[0].coefficient, 1.0);
  EXPECT_EQ(tie.entries[1].node, 8);
  EXPECT_EQ(tie.entries[1].component, 0);
  EXPECT_EQ(tie.entries[1].coefficient, -0.5);
  EXPECT_EQ(tie.value, 0.25);
  EXPECT_EQ(tie.curve, "ramp");

  const io::ConstraintSpec& wall = c.constraints[3];
  EXPECT_EQ(wall.kind, io::ConstraintKind::RigidWall);
  EXPECT_EQ(wall.surface, "block.zmin");
  EXPECT_EQ(wall.point, Vec3(0.0, 0.0, -0.1));
  EXPECT_DOUBLE_EQ(wall.normal[0], 0.0);
  EXPECT_DOUBLE_EQ(wall.normal[1], 0.6) << "stored normalised";
  EXPECT_DOUBLE_EQ(wall.normal[2], 0.8);
  EXPECT_EQ(wall.value, 0.5) << "the offset";
  EXPECT_EQ(wall.curve, "ramp");
}

TEST(CaseReaderConstraints, DefaultsOfARigidWallAndALinearConstraint) {
  const io::CaseSpec c = io::parse_case(kBlock + R"(
[[constraint]]
type = "rigid-wall"
surface = "block.zmin"
normal = [0, 0, 2]
[[constraint]]
type = "linear"
terms = [ { node = 0, component = "y", coefficient = 2 } ]
)",
                                        kMemoryFile);
  ASSERT_EQ(c.constraints.size(), 2u);
  EXPECT_EQ(c.constraints[0].name, "constraint_1");
  EXPECT_EQ(c.constraints[0].point, Vec3::Zero());
  EXPECT_EQ(c.constraints[0].normal, Vec3::UnitZ());
  EXPECT_EQ(c.constraints[0].value, 0.0);
  EXPECT_TRUE(c.constraints[0].curve.empty());
  EXPECT_EQ(c.constraints[1].name, "constraint_2");
  EXPECT_EQ(c.constraints[1].value, 0.0);
  EXPECT_TRUE(c.constraints[1].curve.empty());
  ASSERT_EQ(c.constraints[1].entries.size(), 1u);
  EXPECT_EQ(c.constraints[1].entries[0].coefficient, 2.0);
}

TEST(CaseReaderConstraints, TheWriterKeepsEveryConstraint) {
  const io::CaseSpec c = io::parse_case(kAll, kMemoryFile);
  const io::CaseSpec again = io::parse_case(io::case_toml(c), kMemoryFile);
  ASSERT_EQ(again.constraints.size(), c.constraints.size());
  for (std::size_t k = 0; k < c.constraints.size(); ++k) {
    const io::ConstraintSpec& a = c.constraints[k];
    const io::ConstraintSpec& b = again.constraints[k];
    EXPECT_EQ(b.key, a.key);
    EXPECT_EQ(b.name, a.name);
    EXPECT_EQ(b.kind, a.kind);
    EXPECT_EQ(b.surface, a.surface);
    ASSERT_EQ(b.entries.size(), a.entries.size());
    for (std::size_t i = 0; i < a.entries.size(); ++i) {
      EXPECT_EQ(b.entries[i].node, a.entries[i].node);
      EXPECT_EQ(b.entries[i].component, a.entries[i].component);
      EXPECT_EQ(b.entries[i].coefficient, a.entries[i].coefficient);
    }
    EXPECT_EQ(b.value, a.value);
    EXPECT_EQ(b.curve, a.curve);
    EXPECT_EQ(b.point, a.point);
    EXPECT_EQ(b.normal, a.normal) << "a unit normal reads back bitwise";
  }
}

class CaseReaderConstraintErrors : public ::testing::TestWithParam<BadCase> {};

TEST_P(CaseReaderConstraintErrors, NameTheFileTheKeyAndTheLine) {
  expect_fails_naming(GetParam());
}

INSTANTIATE_TEST_SUITE_P(
    BadCases, CaseReaderConstraintErrors,
    ::testing::Values(
        BadCase{
            "unknown_type",
            kBlock + replaced_in(kSymmetry, "symmetry-plane", "symmetry"),
            {"constraint[1].type = 'symmetry'", "unknown constraint type", "rigid-wall", "line"}},
        BadCase{"offset_of_a_symmetry_plane",
                kBlock + replaced_in(kSymmetry, "surface", "offset = 0.5\nsurface"),
                {"constraint[1].offset", "only a rigid-wall has an offset", "'symmetry-plane'",
                 "(line 23)"}},
        BadCase{"surface_of_a_linear_constraint",
                kBlock + replaced_in(kLinear, "value", "surface = \"block.xmin\"\nvalue"),
                {"constraint[1].surface", "'linear'", "line"}},
        BadCase{"unknown_key",
                kBlock + replaced_in(kWall, "offset", "ofset"),
                {"constraint[1].ofset", "unknown key", "did you mean 'offset'?", "line"}},
        BadCase{"missing_surface",
                kBlock + replaced_in(kNormal, "surface = \"block.ymin\"\n", ""),
                {"constraint[1].surface", "missing required key", "line"}},
        BadCase{"zero_normal",
                kBlock + replaced_in(kWall, "[0.0, 3.0, 4.0]", "[0, 0, 0]"),
                {"constraint[1].normal", "not the zero vector", "(line 25)"}},
        BadCase{"missing_normal",
                kBlock + replaced_in(kWall, "normal = [0.0, 3.0, 4.0]\n", ""),
                {"constraint[1].normal", "missing required key"}},
        BadCase{"undefined_curve",
                kBlock + replaced_in(kWall, "curve = \"ramp\"", "curve = \"rmap\""),
                {"constraint[1].curve = 'rmap'", "undefined curve", "did you mean 'ramp'?"}},
        BadCase{"no_terms",
                kBlock + replaced_in(kLinear,
                                     R"([ { node = 4, component = "z", coefficient = 1.0 },
          { node = 8, component = "x", coefficient = -0.5 } ])",
                                     "[]"),
                {"constraint[1].terms", "at least one term", "line"}},
        BadCase{"negative_node",
                kBlock + replaced_in(kLinear, "node = 8", "node = -1"),
                {"constraint[1].terms[2].node = -1", "expected an integer >= 0", "(line 24)"}},
        BadCase{"unknown_component",
                kBlock + replaced_in(kLinear, "\"x\"", "\"w\""),
                {"constraint[1].terms[2].component = 'w'", "expected one of: x, y, z"}},
        BadCase{"zero_coefficient",
                kBlock + replaced_in(kLinear, "-0.5", "0.0"),
                {"constraint[1].terms[2].coefficient = 0", "non-zero coefficient"}},
        BadCase{"repeated_component",
                kBlock + replaced_in(kLinear, "node = 8, component = \"x\"",
                                     "node = 4, component = \"z\""),
                {"constraint[1].terms[2]",
                 "node 4 component 'z' is already in constraint[1].terms[1]", "(line 24)"}},
        BadCase{"duplicate_name",
                kBlock + kLinear + kLinear,
                {"constraint[2].name = 'tie'", "duplicate constraint name", "constraint[1]"}},
        BadCase{"name_with_a_space",
                kBlock + replaced_in(kSymmetry, "x0_plane", "x0 plane"),
                {"constraint[1].name = 'x0 plane'", "invalid name"}},
        BadCase{"in_a_dynamic_explicit_analysis",
                kBlock + "[analysis]\ntype = \"dynamic-explicit\"\n" + kSymmetry,
                {"constraint[1]", "not supported in dynamic-explicit analyses", "implicit solver"}},
        BadCase{"before_a_dynamic_explicit_step",
                replaced_in(kBlock, "[time]\nend_time = 1.0\ndt = 0.1\n", "") + kSymmetry + R"(
[[step]]
end_time = 1.0
dt = 0.1
[[step]]
analysis = "dynamic-explicit"
duration = 0.01
)",
                {"step[2].analysis = 'dynamic-explicit'", "[[constraint]]"}},
        BadCase{"in_a_step",
                replaced_in(kBlock, "[time]\nend_time = 1.0\ndt = 0.1\n", "") + R"(
[[step]]
end_time = 1.0
dt = 0.1
[[step.constraint]]
type = "symmetry-plane"
surface = "block.xmin"
)",
                {"step[1].constraint", "unknown key"}}),
    bad_case_name);

} // namespace
