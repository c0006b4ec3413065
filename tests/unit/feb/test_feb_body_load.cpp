// SPDX-License-Identifier: MIT
// FEBio's <body_load> of type "const" (x, y, z, each with its own load controller) and "body
// force" (<force>) map to [[loads.body_force]] with the sign flipped (FEBio applies its body
// force b as the external force −ρ b), one per curve; the materials then get their densities
// in a static analysis too. <nodal_load type="nodal_force"> maps to [[loads.nodal_force]]. What
// has no counterpart is an error naming the line.
#include "feb_errors.hpp"
#include "trifem/core/error.hpp"
#include "trifem/feb/feb_reader.hpp"
#include "trifem/model/model.hpp"

#include <gtest/gtest.h>

#include <algorithm>

using namespace trifem;

namespace {

/// A one-hex 4.0 solid file (static, material density 1.2e-9, fixed bottom) with `loads` in its
/// <Loads> section (and `step` after it, if any) and the load controllers 1 to 3.
std::string body_load_text(const std::string& loads, const std::string& step = "") {
  return R"(<?xml version="1.0"?>
<febio_spec version="4.0">
  <Module type="solid"/>
  <Control><analysis>STATIC</analysis><time_steps>4</time_steps><step_size>0.25</step_size></Control>
  <Material>
    <material id="1" name="m" type="neo-Hookean"><density>1.2e-9</density><E>1</E><v>0.3</v></material>
  </Material>
  <Mesh>
    <Nodes name="all">
      <node id="1">0,0,0</node><node id="2">1,0,0</node><node id="3">1,1,0</node><node id="4">0,1,0</node>
      <node id="5">0,0,1</node><node id="6">1,0,1</node><node id="7">1,1,1</node><node id="8">0,1,1</node>
    </Nodes>
    <Elements type="hex8" name="P"><elem id="1">1,2,3,4,5,6,7,8</elem></Elements>
    <NodeSet name="bottom">1, 2, 3, 4</NodeSet>
  </Mesh>
  <MeshDomains><SolidDomain name="P" mat="m"/></MeshDomains>
  <Boundary>
    <bc name="fix" node_set="bottom" type="zero displacement"><x_dof>1</x_dof><y_dof>1</y_dof><z_dof>1</z_dof></bc>
  </Boundary>
  <Loads>
)" + loads +
         R"(
  </Loads>
  <LoadData>
    <load_controller id="1" name="LC1" type="loadcurve"><interpolate>LINEAR</interpolate>
      <points><point>0,0</point><point>1,1</point></points></load_controller>
    <load_controller id="2" name="LC2" type="loadcurve"><interpolate>LINEAR</interpolate>
      <points><point>0,0</point><point>1,2</point></points></load_controller>
    <load_controller id="3" name="LC3" type="loadcurve"><interpolate>LINEAR</interpolate>
      <points><point>0,1</point><point>1,1</point></points></load_controller>
  </LoadData>
)" + step +
         R"(
</febio_spec>
)";
}

std::string body_load_error(const std::string& text) {
  try {
    feb::parse_feb(text, "bf.feb");
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no error";
  return "";
}

} // namespace

TEST(FebBodyLoad, AConstLoadIsOneBodyForcePerCurveWithTheSignFlipped) {
  const io::CaseSpec spec = feb::parse_feb(body_load_text(R"(
    <body_load type="const">
      <x lc="1">0</x>
      <y lc="2">1</y>
      <z lc="3">-9810</z>
    </body_load>)"),
                                           "const.feb");
  ASSERT_EQ(spec.body_forces.size(), 2u); // x is zero: dropped
  EXPECT_EQ(spec.body_forces[0].force, Vec3(0, -1, 0));
  EXPECT_EQ(spec.body_forces[0].curve, "LC2");
  EXPECT_EQ(spec.body_forces[1].force, Vec3(0, 0, 9810));
  EXPECT_EQ(spec.body_forces[1].curve, "LC3");
  for (const io::BodyForceSpec& b : spec.body_forces) {
    EXPECT_TRUE(b.blocks.empty()); // every cell
    EXPECT_NE(b.key.find("(line 22)"), std::string::npos) << b.key;
  }
  // the material's density, although the analysis is static
  ASSERT_TRUE(spec.materials.at("m").density.has_value());
  EXPECT_DOUBLE_EQ(*spec.materials.at("m").density, 1.2e-9);
}

TEST(FebBodyLoad, ComponentsOfOneCurveMakeOneBodyForce) {
  const io::CaseSpec spec = feb::parse_feb(body_load_text(R"(
    <body_load type="const"><x lc="1">1</x><y>0</y><z lc="1">2</z></body_load>
    <body_load type="const"><z>-3</z></body_load>)"),
                                           "one.feb");
  ASSERT_EQ(spec.body_forces.size(), 2u);
  EXPECT_EQ(spec.body_forces[0].force, Vec3(-1, 0, -2));
  EXPECT_EQ(spec.body_forces[0].curve, "LC1");
  EXPECT_EQ(spec.body_forces[1].force, Vec3(0, 0, 3));
  EXPECT_EQ(spec.body_forces[1].curve, "");
}

TEST(FebBodyLoad, ABodyForceLoadIsGravityAgainstItsForce) {
  const io::CaseSpec spec = feb::parse_feb(body_load_text(R"(
    <body_load type="body force">
      <force>0,0,9.81</force>
    </body_load>)"),
                                           "gravity.feb");
  ASSERT_EQ(spec.body_forces.size(), 1u);
  EXPECT_EQ(spec.body_forces[0].force, Vec3(0, 0, -9.81)); // FEBio's z = 9.81 pulls along −z
  EXPECT_TRUE(spec.body_forces[0].curve.empty());
  EXPECT_TRUE(spec.body_forces[0].blocks.empty());
  const auto model = model::build_model(spec);
  EXPECT_TRUE(std::any_of(model->loads.begin(), model->loads.end(),
                          [](const physics::Term* t) { return t->name() == "body force"; }));
}

TEST(FebBodyLoad, ABodyForceWithACurveOnAnElementSet) {
  const io::CaseSpec spec = feb::parse_feb(body_load_text(R"(
    <body_load type="body force" elem_set="P"><force lc="2">0,1,0</force></body_load>)"),
                                           "set.feb");
  ASSERT_EQ(spec.body_forces.size(), 1u);
  EXPECT_EQ(spec.body_forces[0].force, Vec3(0, -1, 0));
  EXPECT_EQ(spec.body_forces[0].curve, "LC2");
  EXPECT_EQ(spec.body_forces[0].blocks, std::vector<std::string>{"P"});
}

TEST(FebBodyLoad, AZeroLoadIsIgnoredWithAWarning) {
  const io::CaseSpec spec = feb::parse_feb(
      body_load_text(R"(<body_load type="const"><x lc="1">0</x><y>0</y><z>0</z></body_load>)"),
      "zero.feb");
  EXPECT_TRUE(spec.body_forces.empty());
  ASSERT_EQ(spec.warnings.size(), 1u);
  EXPECT_NE(spec.warnings[0].find("a body load that is zero at every time is ignored"),
            std::string::npos);
}

TEST(FebBodyLoad, WhatHasNoCounterpartIsAnErrorNamingTheLine) {
  test::expect_contains(
      body_load_error(body_load_text(R"(<body_load type="const"><w>1</w></body_load>)")),
      {"bf.feb:21: ", "unknown parameter 'w' of a const body load (expected one of: "
                      "x, y, z)"});
  test::expect_contains(
      body_load_error(body_load_text(R"(<body_load type="body force"><x>1</x></body_load>)")),
      {"bf.feb:21: ", "unknown parameter 'x' of a body force load"});
  test::expect_contains(
      body_load_error(body_load_text(R"(<body_load type="body force"></body_load>)")),
      {"bf.feb:21: ", "force"});
  test::expect_contains(
      body_load_error(body_load_text(R"(<body_load type="non-const"><x>1</x></body_load>)")),
      {"bf.feb:21: ", "body_load of type 'non-const' is not supported (supported: "
                      "const, body force)"});
  test::expect_contains(
      body_load_error(
          body_load_text(R"(<body_load type="const"><x type="math">-0.1*X</x></body_load>)")),
      {"bf.feb:21: ", "a body force that varies in space (math or map) is not supported"});
  test::expect_contains(body_load_error(body_load_text(
                            R"(<body_load type="const" elem_set="Q"><x>1</x></body_load>)")),
                        {"bf.feb:21: ", "@elem_set: element set 'Q' is not defined (defined: P)"});
  test::expect_contains(
      body_load_error(body_load_text(R"(<body_load type="const" lc="1"><x>1</x></body_load>)")),
      {"bf.feb:21: ", "/@lc: a load controller on <body_load> itself is not supported"});
  test::expect_contains(
      body_load_error(body_load_text(R"(<body_load type="const"><x lc="7">1</x></body_load>)")),
      {"bf.feb:21: ", "load controller 7 is not defined"});
  test::expect_contains(body_load_error(body_load_text("", R"(
  <Step><step id="1" name="s">
    <Control><time_steps>2</time_steps><step_size>0.5</step_size></Control>
    <Loads><body_load type="const"><z>1</z></body_load></Loads>
  </step></Step>)")),
                        {"a body load inside a <step> is not supported"});
  test::expect_contains(body_load_error(body_load_text(R"(<edge_load type="force"/>)")),
                        {"bf.feb:21: ",
                         "are supported in <Loads>, <body_load> of type const and body force, and "
                         "<nodal_load> of type nodal_force"});
}

// <nodal_load type="nodal_force">: its <value> (with an lc) on every node of the set, as
// [[loads.nodal_force]] (the run: FebNodalLoad in test_feb_verification.cpp).
TEST(FebNodalLoad, ANodalForceIsANodalForceOnItsSet) {
  const std::string top = R"(<NodeSet name="top">5, 6, 7, 8</NodeSet>
  </Mesh>)";
  std::string text = body_load_text(R"(<nodal_load name="F" node_set="top" type="nodal_force">
      <relative>0</relative><value lc="1">0,0,0.1</value><shell_bottom>0</shell_bottom>
    </nodal_load>)");
  text.replace(text.find("</Mesh>"), 7, top);
  const io::CaseSpec spec = feb::parse_feb(text, "nf.feb");
  ASSERT_EQ(spec.nodal_forces.size(), 1u);
  EXPECT_EQ(spec.nodal_forces[0].set, "top");
  EXPECT_EQ(spec.nodal_forces[0].value, Vec3(0, 0, 0.1));
  EXPECT_EQ(spec.nodal_forces[0].curve, "LC1");
}

TEST(FebNodalLoad, WhatHasNoCounterpartIsAnErrorNamingTheLine) {
  const auto with_top = [](std::string text) {
    text.replace(text.find("</Mesh>"), 7, R"(<NodeSet name="top">5, 6, 7, 8</NodeSet></Mesh>)");
    return text;
  };
  test::expect_contains(
      body_load_error(with_top(body_load_text(
          R"(<nodal_load node_set="top" type="nodal fluidflux"><value>1</value></nodal_load>)"))),
      {"bf.feb:21: ", "nodal_load of type 'nodal fluidflux' is not supported "
                      "(supported: nodal_force)"});
  test::expect_contains(
      body_load_error(with_top(body_load_text(
          R"(<nodal_load node_set="top" type="nodal_force"><relative>1</relative><value>0,0,1</value></nodal_load>)"))),
      {"/relative: a relative nodal force", "is not supported"});
  test::expect_contains(
      body_load_error(with_top(body_load_text(
          R"(<nodal_load node_set="top" type="nodal_force"><scale>1</scale></nodal_load>)"))),
      {"unknown parameter 'scale' of a nodal_force load (expected one of: "
       "value, relative, shell_bottom)"});
  test::expect_contains(body_load_error(with_top(body_load_text(
                            R"(<nodal_load node_set="top" type="nodal_force"></nodal_load>)"))),
                        {"bf.feb:21: ", "value"});
  test::expect_contains(
      body_load_error(with_top(body_load_text(
          R"(<nodal_load node_set="topp" type="nodal_force"><value>0,0,1</value></nodal_load>)"))),
      {"bf.feb:21: ", "topp"});
  test::expect_contains(body_load_error(with_top(body_load_text("", R"(
  <Step><step id="1" name="s">
    <Control><time_steps>2</time_steps><step_size>0.5</step_size></Control>
    <Loads><nodal_load node_set="top" type="nodal_force"><value>0,0,1</value></nodal_load></Loads>
  </step></Step>)"))),
                        {"a nodal load inside a <step> is not supported"});
}
