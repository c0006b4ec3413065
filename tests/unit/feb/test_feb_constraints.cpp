// SPDX-License-Identifier: MIT
// The FEBio reader's constraints: <Constraints> (rigid wall, symmetry plane, fixed normal
// displacement, linear constraint sets) and the boundary condition "linear constraint" as
// [[constraint]]s, and the refusal of the other constraint types.
#include "feb_errors.hpp"
#include "trifem/core/error.hpp"
#include "trifem/feb/feb_reader.hpp"

#include <gtest/gtest.h>

#include <algorithm>

using namespace trifem;

namespace {

/// One hex8 of FEBio node ids 101-108 (mesh nodes 0-7) with the surfaces "bottom" (z = 0) and
/// "x0" (x = 0), the load controller 1 ("ramp") and `boundary` and `constraints` as sections.
std::string constrained_hex(const std::string& boundary, const std::string& constraints) {
  return R"(<?xml version="1.0"?>
<febio_spec version="4.0">
  <Module type="solid"/>
  <Control><analysis>STATIC</analysis><time_steps>2</time_steps><step_size>0.5</step_size></Control>
  <Material><material id="1" name="m" type="neo-Hookean"><E>1</E><v>0.3</v></material></Material>
  <Mesh>
    <Nodes name="all">
      <node id="101">0,0,0</node><node id="102">1,0,0</node><node id="103">1,1,0</node><node id="104">0,1,0</node>
      <node id="105">0,0,1</node><node id="106">1,0,1</node><node id="107">1,1,1</node><node id="108">0,1,1</node>
    </Nodes>
    <Elements type="hex8" name="P"><elem id="1">101,102,103,104,105,106,107,108</elem></Elements>
    <Surface name="bottom"><quad4 id="1">101,104,103,102</quad4></Surface>
    <Surface name="x0"><quad4 id="1">101,105,108,104</quad4></Surface>
  </Mesh>
  <MeshDomains><SolidDomain name="P" mat="m"/></MeshDomains>
  <LoadData>
    <load_controller id="1" name="ramp" type="loadcurve">
      <interpolate>LINEAR</interpolate>
      <points><pt>0,0</pt><pt>1,1</pt></points>
    </load_controller>
  </LoadData>
  <Boundary>
)" + boundary +
         R"(
  </Boundary>
  <Constraints>
)" + constraints +
         R"(
  </Constraints>
</febio_spec>
)";
}

// FEBio: u_x(105) = 0.5 u_x(108) - 2 u_z(106) + 0.2 ramp(t)
const std::string kConstraintBc = R"(    <bc name="tie" type="linear constraint">
      <dof>x</dof><node>105</node><offset lc="1">0.2</offset>
      <child_dof><dof>x</dof><node>108</node><value>0.5</value></child_dof>
      <child_dof><dof>z</dof><node>106</node><value>-2</value></child_dof>
    </bc>)";

const std::string kConstraintWall =
    R"(    <constraint type="rigid_wall" name="floor wall" surface="bottom">
      <laugon>0</laugon><tolerance>0.1</tolerance><penalty lc="7">100</penalty>
      <plane>0,0,2,-0.5</plane>
      <offset lc="1">0.3</offset>
    </constraint>)";

const std::string kConstraintSymmetry =
    R"(    <constraint type="symmetry plane" name="sym" surface="x0">
      <laugon>1</laugon><tol>0.1</tol><penalty>1</penalty><rhs>0</rhs><minaug>0</minaug><maxaug>10</maxaug>
    </constraint>)";

const std::string kConstraintSet = R"(    <constraint type="linear constraint" name="sym">
      <laugon>1</laugon><tol>0.1</tol><penalty>1</penalty><rhs>0.1</rhs>
      <linear_constraint><node id="102" bc="x">1</node><node id="103" bc="y">-1</node></linear_constraint>
      <linear_constraint><node id="107" bc="z">2.5</node></linear_constraint>
    </constraint>)";

const std::string kConstraintNormal =
    R"(    <constraint type="fixed normal displacement" surface="bottom">
      <penalty>1</penalty><rhs>0</rhs><shell_bottom>0</shell_bottom>
    </constraint>)";

/// The message of the InputError parse_feb throws for `text` (fails the test if none).
std::string constraint_error(const std::string& text) {
  try {
    feb::parse_feb(text, "bad.feb");
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no error";
  return "";
}

void expect_constraint_entry(const io::LinearConstraintEntry& e, Index node, io::Component k,
                             Real c) {
  EXPECT_EQ(e.node, node);
  EXPECT_EQ(e.component, k);
  EXPECT_DOUBLE_EQ(e.coefficient, c);
}

} // namespace

TEST(FebConstraints, MapsConstraintsAndTheLinearConstraintBoundaryCondition) {
  const io::CaseSpec spec = feb::parse_feb(
      constrained_hex(kConstraintBc, kConstraintWall + "\n" + kConstraintSymmetry + "\n" +
                                         kConstraintSet + "\n" + kConstraintNormal),
      "constraints.feb");
  ASSERT_EQ(spec.constraints.size(), 6u);

  // the bc: u_x(105) - 0.5 u_x(108) + 2 u_z(106) = 0.2 ramp(t); FEBio id 101 is mesh node 0
  const io::ConstraintSpec& tie = spec.constraints[0];
  EXPECT_EQ(tie.kind, io::ConstraintKind::Linear);
  EXPECT_EQ(tie.name, "tie");
  ASSERT_EQ(tie.entries.size(), 3u);
  expect_constraint_entry(tie.entries[0], 4, 0, 1.0);
  expect_constraint_entry(tie.entries[1], 7, 0, -0.5);
  expect_constraint_entry(tie.entries[2], 5, 2, 2.0);
  EXPECT_DOUBLE_EQ(tie.value, 0.2);
  EXPECT_EQ(tie.curve, "ramp");
  EXPECT_TRUE(spec.curves.contains(tie.curve));

  // the plane 2 z = -0.5: unit normal +z through (0, 0, -0.25), moved by 0.3 ramp(t)
  const io::ConstraintSpec& wall = spec.constraints[1];
  EXPECT_EQ(wall.kind, io::ConstraintKind::RigidWall);
  EXPECT_EQ(wall.name, "floor_wall");
  EXPECT_EQ(wall.surface, "bottom");
  EXPECT_DOUBLE_EQ(wall.normal[0], 0.0);
  EXPECT_DOUBLE_EQ(wall.normal[1], 0.0);
  EXPECT_DOUBLE_EQ(wall.normal[2], 1.0);
  EXPECT_DOUBLE_EQ(wall.point[0], 0.0);
  EXPECT_DOUBLE_EQ(wall.point[1], 0.0);
  EXPECT_DOUBLE_EQ(wall.point[2], -0.25);
  EXPECT_DOUBLE_EQ(wall.value, 0.3);
  EXPECT_EQ(wall.curve, "ramp");
  EXPECT_TRUE(std::any_of(spec.warnings.begin(), spec.warnings.end(), [](const std::string& w) {
    return w.find("FEBio by offset / 4") != std::string::npos;
  })) << "FEBio moves a wall of a non-unit (a, b, c) differently";

  const io::ConstraintSpec& plane = spec.constraints[2];
  EXPECT_EQ(plane.kind, io::ConstraintKind::SymmetryPlane);
  EXPECT_EQ(plane.name, "sym");
  EXPECT_EQ(plane.surface, "x0");
  EXPECT_TRUE(plane.entries.empty());

  // one constraint per <linear_constraint>, each equal to the set's rhs; the taken name gets
  // the constraint's number
  const io::ConstraintSpec& first = spec.constraints[3];
  EXPECT_EQ(first.kind, io::ConstraintKind::Linear);
  EXPECT_EQ(first.name, "sym_4");
  ASSERT_EQ(first.entries.size(), 2u);
  expect_constraint_entry(first.entries[0], 1, 0, 1.0);
  expect_constraint_entry(first.entries[1], 2, 1, -1.0);
  EXPECT_DOUBLE_EQ(first.value, 0.1);
  EXPECT_TRUE(first.curve.empty());
  const io::ConstraintSpec& second = spec.constraints[4];
  EXPECT_EQ(second.name, "sym_5");
  ASSERT_EQ(second.entries.size(), 1u);
  expect_constraint_entry(second.entries[0], 6, 2, 2.5);
  EXPECT_DOUBLE_EQ(second.value, 0.1);

  const io::ConstraintSpec& normal = spec.constraints[5];
  EXPECT_EQ(normal.kind, io::ConstraintKind::NormalDisplacement);
  EXPECT_EQ(normal.name, "constraint_6");
  EXPECT_EQ(normal.surface, "bottom");
}

TEST(FebConstraints, RefusesOtherConstraintTypes) {
  const std::string tied = R"(    <constraint type="tied-line" name="t" surface="bottom"/>)";
  test::expect_contains(
      constraint_error(constrained_hex("", tied)),
      {"bad.feb:26: febio_spec/Constraints/constraint[@type='tied-line'][@name='t']/@type: ",
       "constraint type 'tied-line' is not supported (supported: rigid_wall, symmetry plane, "
       "fixed normal displacement, linear constraint)"});
}

TEST(FebConstraints, RefusesANonZeroRhsOfASymmetryPlane) {
  const std::string plane = R"(    <constraint type="symmetry plane" name="sym" surface="x0">
      <rhs>0.1</rhs>
    </constraint>)";
  test::expect_contains(constraint_error(constrained_hex("", plane)),
                        {"bad.feb:27: febio_spec/Constraints/constraint[@type='symmetry plane']"
                         "[@name='sym']/rhs: ",
                         "rhs = 0.1 is not supported", "must be 0"});
}

TEST(FebConstraints, RefusesAFluidDofInALinearConstraint) {
  const std::string bc = R"(    <bc type="linear constraint">
      <dof>p</dof><node>105</node>
    </bc>)";
  test::expect_contains(constraint_error(constrained_hex(bc, "")),
                        {"bad.feb:24: ", "/dof: ", "dof 'p' is not supported", "x, y or z"});
}
