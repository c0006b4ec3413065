// SPDX-License-Identifier: MIT
// The FEBio reader refuses what it cannot map with one error line: file, line, XML path, what.
#include "box_assembly.hpp"
#include "feb_errors.hpp"
#include "trifem/core/error.hpp"
#include "trifem/feb/feb_reader.hpp"
#include "trifem/model/model.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <numbers>
#include <sstream>
#include <tuple>

using namespace trifem;

namespace {

/// A valid single-hex 4.0 file; `material`, `elements` and `boundary` replace its sections.
std::string solid_model_text(const std::string& material, const std::string& elements,
                             const std::string& boundary) {
  return R"(<?xml version="1.0"?>
<febio_spec version="4.0">
  <Module type="solid"/>
  <Control><analysis>STATIC</analysis><time_steps>2</time_steps><step_size>0.5</step_size></Control>
  <Material>
)" + material +
         R"(
  </Material>
  <Mesh>
    <Nodes name="all">
      <node id="1">0,0,0</node><node id="2">1,0,0</node><node id="3">1,1,0</node><node id="4">0,1,0</node>
      <node id="5">0,0,1</node><node id="6">1,0,1</node><node id="7">1,1,1</node><node id="8">0,1,1</node>
    </Nodes>
)" + elements +
         R"(
    <NodeSet name="bottom">1, 2, 3, 4</NodeSet>
  </Mesh>
  <MeshDomains><SolidDomain name="P" mat="m"/></MeshDomains>
  <Boundary>
)" + boundary +
         R"(
  </Boundary>
</febio_spec>
)";
}

const std::string kMaterial =
    R"(    <material id="1" name="m" type="neo-Hookean"><E>1</E><v>0.3</v></material>)";
const std::string kHex =
    R"(    <Elements type="hex8" name="P"><elem id="1">1,2,3,4,5,6,7,8</elem></Elements>)";
const std::string kFixed =
    R"(    <bc name="fix" node_set="bottom" type="zero displacement"><x_dof>1</x_dof><y_dof>1</y_dof><z_dof>1</z_dof></bc>)";

/// The message of the InputError parse_feb throws for `text` (fails the test if none).
std::string feb_error(const std::string& text, const std::string& file = "bad.feb") {
  try {
    feb::parse_feb(text, file);
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.find('\n'), std::string::npos) << "one line: " << what;
    return what;
  }
  ADD_FAILURE() << "no error for " << file;
  return "";
}

using test::expect_contains;

} // namespace

TEST(FebErrors, TheValidBaseFileReads) {
  EXPECT_NO_THROW(feb::parse_feb(solid_model_text(kMaterial, kHex, kFixed), "good.feb"));
}

TEST(FebErrors, Tet15Mesh) {
  const std::string tet =
      R"(    <Elements type="tet15" name="P"><elem id="1">1,2,3,5,6,7,8,4,1,2,3,5,6,7,8</elem></Elements>)";
  expect_contains(feb_error(solid_model_text(kMaterial, tet, kFixed)),
                  {"bad.feb:13: febio_spec/Mesh/Elements[@type='tet15'][@name='P']: ",
                   "element type 'tet15' is not supported (trifem has hex8, tet4, tet10, penta6 "
                   "and hex20 solids, and quad4 and tri3 shells as rigid bodies)"});
}

// A tet4 and a wedge whose corners are in the inverted order; a tet10 with too few nodes.
TEST(FebErrors, InvertedOrIncompleteCellsOfTheOtherFamilies) {
  const std::string tet =
      R"(    <Elements type="tet4" name="P"><elem id="1">1,3,2,5</elem></Elements>)";
  expect_contains(feb_error(solid_model_text(kMaterial, tet, kFixed)),
                  {"bad.feb:13: febio_spec/Mesh/Elements[@type='tet4'][@name='P']/elem[@id='1']: ",
                   "the tet4 element has negative volume (inverted node order; expected nodes "
                   "0-2 counter-clockwise seen from node 3)"});
  const std::string wedge =
      R"(    <Elements type="penta6" name="P"><elem id="1">1,4,2,5,8,6</elem></Elements>)";
  expect_contains(feb_error(solid_model_text(kMaterial, wedge, kFixed)),
                  {"febio_spec/Mesh/Elements[@type='penta6'][@name='P']/elem[@id='1']: ",
                   "the penta6 element has negative volume"});
  const std::string tet10 =
      R"(    <Elements type="tet10" name="P"><elem id="1">1,2,4,5,6,7,8,3</elem></Elements>)";
  expect_contains(feb_error(solid_model_text(kMaterial, tet10, kFixed)),
                  {"febio_spec/Mesh/Elements[@type='tet10'][@name='P']/elem[@id='1']: ",
                   "a tet10 has 10 nodes, got 8"});
}

// A biphasic material on tet4 elements stops the model build naming the first such element by its
// id in the file, not by trifem's cell index.
TEST(FebErrors, AMixtureOnTet4ElementsIsRefusedNamingTheElementId) {
  const std::string biphasic = R"(    <material id="1" name="m" type="biphasic">
      <phi0>0.2</phi0>
      <solid type="neo-Hookean"><E>1</E><v>0</v></solid>
      <permeability type="perm-const-iso"><perm>0.001</perm></permeability>
    </material>)";
  const std::string tets = R"(    <Elements type="tet4" name="P">
      <elem id="7">1,2,3,5</elem><elem id="9">1,3,4,8</elem>
    </Elements>)";
  const io::CaseSpec spec = feb::parse_feb(solid_model_text(biphasic, tets, kFixed), "tets.feb");
  try {
    (void)model::build_model(spec);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    expect_contains(e.what(), {"tet4 cells cannot carry it", "element 7 of 'tets.feb'"});
  }
}

// One hex beside eight of half its size: the fine cells' nodes hang on its face.
TEST(FebErrors, ElementsMeetingWithHangingNodes) {
  test::BoxAssembly a;
  a.add_box(mesh::CellType::Hex8, Vec3::Zero(), Vec3::Ones(), {1, 1, 1});
  a.add_box(mesh::CellType::Hex8, Vec3(1.0, 0.0, 0.0), Vec3::Ones(), {2, 2, 2});
  const mesh::Mesh& m = a.mesh();
  std::string text = R"(<?xml version="1.0"?>
<febio_spec version="4.0">
  <Module type="solid"/>
  <Control><analysis>STATIC</analysis><time_steps>2</time_steps><step_size>0.5</step_size></Control>
  <Material>
)" + kMaterial + R"(
  </Material>
  <Mesh>
    <Nodes name="all">
)";
  for (Index n = 0; n < m.num_nodes(); ++n)
    text += fmt::format("      <node id=\"{}\">{},{},{}</node>\n", n + 1, m.node(n).x(),
                        m.node(n).y(), m.node(n).z());
  text += "    </Nodes>\n    <Elements type=\"hex8\" name=\"P\">\n";
  for (Index c = 0; c < m.num_cells(); ++c) {
    text += fmt::format("      <elem id=\"{}\">", c + 1);
    for (const Index n : m.cell_nodes(c))
      text += fmt::format("{}{}", n == m.cell_nodes(c).front() ? "" : ",", n + 1);
    text += "</elem>\n";
  }
  text += R"(    </Elements>
  </Mesh>
  <MeshDomains><SolidDomain name="P" mat="m"/></MeshDomains>
</febio_spec>
)";
  expect_contains(feb_error(text),
                  {"febio_spec/Mesh/Elements[@type='hex8'][@name='P']/elem[@id='1']: ",
                   "elements 1 (hex8) and 2 (hex8) meet on a quad4 face and a "
                   "quad4 face that overlap",
                   "nodes of one hang on the other", "trifem needs a conforming mesh"});
}

TEST(FebErrors, UnknownMaterialType) {
  const std::string m =
      R"(    <material id="1" name="m" type="Fung orthotropic"><E1>1</E1></material>)";
  expect_contains(feb_error(solid_model_text(m, kHex, kFixed)),
                  {"bad.feb:6: febio_spec/Material/material[@type='Fung orthotropic'][@name='m']"
                   "/@type: ",
                   "material type 'Fung orthotropic' is not supported", "neo-Hookean"});
}

TEST(FebErrors, UnknownMaterialParameter) {
  const std::string m =
      R"(    <material id="1" name="m" type="neo-Hookean"><E>1</E><nu>0.3</nu></material>)";
  expect_contains(feb_error(solid_model_text(m, kHex, kFixed)),
                  {"bad.feb:6: febio_spec/Material/material[@type='neo-Hookean'][@name='m']/nu: ",
                   "unknown parameter 'nu' of material type 'neo-Hookean'", "E, v"});
}

TEST(FebErrors, OutOfRangeMaterialParameter) {
  const std::string m =
      R"(    <material id="1" name="m" type="neo-Hookean"><E>-1</E><v>0.3</v></material>)";
  expect_contains(feb_error(solid_model_text(m, kHex, kFixed)),
                  {"bad.feb:6: ", "E = -1: out of range"});
}

TEST(FebErrors, MissingNodeSet) {
  const std::string bc =
      R"(    <bc name="fix" node_set="botom" type="zero displacement"><z_dof>1</z_dof></bc>)";
  expect_contains(feb_error(solid_model_text(kMaterial, kHex, bc)),
                  {"bad.feb:18: febio_spec/Boundary/bc[@type='zero displacement'][@name='fix']"
                   "/@node_set: ",
                   "node set 'botom' is not defined (defined: bottom)"});
}

TEST(FebErrors, UndefinedNodeInAnElement) {
  const std::string hex =
      R"(    <Elements type="hex8" name="P"><elem id="1">1,2,3,4,5,6,7,9</elem></Elements>)";
  expect_contains(feb_error(solid_model_text(kMaterial, hex, kFixed)),
                  {"bad.feb:13: ", "elem[@id='1']: node id 9 is not defined"});
}

TEST(FebErrors, BrokenXmlGivesTheLine) {
  std::string text = solid_model_text(kMaterial, kHex, kFixed);
  text.replace(text.find("</Material>"), 11, "</Materal>");
  expect_contains(feb_error(text), {"bad.feb:7: XML syntax error: ", "not well-formed"});
}

TEST(FebErrors, OldFormatVersions) {
  for (const char* v : {"2.0", "2.5", "1.2"}) {
    std::string text = solid_model_text(kMaterial, kHex, kFixed);
    text.replace(text.find("\"4.0\""), 5, fmt::format("\"{}\"", v));
    expect_contains(feb_error(text), {"bad.feb:2: febio_spec/@version: ",
                                      fmt::format("FEBio format version '{}' is "
                                                  "not supported",
                                                  v),
                                      "trifem reads 4.0 and 3.0"});
  }
}

TEST(FebErrors, UnsupportedBoundaryAndSections) {
  const std::string rigid =
      R"(    <bc name="r" node_set="bottom" type="zero rotation"><x_dof>1</x_dof></bc>)";
  expect_contains(feb_error(solid_model_text(kMaterial, kHex, rigid)),
                  {"bad.feb:18: ", "boundary condition type 'zero rotation' is not supported"});
  std::string discrete = solid_model_text(kMaterial, kHex, kFixed);
  discrete.replace(discrete.find("</febio_spec>"), 13, "  <Discrete/>\n</febio_spec>");
  expect_contains(feb_error(discrete),
                  {"bad.feb:20: febio_spec/Discrete: ", "the section <Discrete> is not supported"});
}

TEST(FebErrors, SteadyStateBiphasicAndStepCurves) {
  std::string text = solid_model_text(kMaterial, kHex, kFixed);
  text.replace(text.find("\"solid\""), 7, "\"biphasic\"");
  expect_contains(feb_error(text), {"bad.feb:4: febio_spec/Control/analysis: ",
                                    "a static analysis of a mixture is not supported"});
  // FEBio's splines are not mapped (its SMOOTH is: FebCurves.SmoothIsFebiosQuadraticBlend)
  text = solid_model_text(kMaterial, kHex, kFixed);
  text.replace(
      text.find("</febio_spec>"), 13,
      R"(<LoadData><load_controller id="1" type="loadcurve"><interpolate>CSPLINE</interpolate>
<points><pt>0,0</pt><pt>1,1</pt><pt>2,0</pt></points></load_controller></LoadData></febio_spec>)");
  expect_contains(feb_error(text),
                  {"bad.feb:20: ", "/interpolate: interpolation 'CSPLINE' is not supported"});
}

TEST(FebErrors, MissingFile) {
  try {
    feb::read_feb("no/such/model.feb");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no/such/model.feb: cannot open the FEBio file"),
              std::string::npos)
        << e.what();
  }
}

TEST(FebErrors, UnsupportedSurfaceLoads) {
  const std::string loads =
      R"(<Loads><surface_load surface="top" type="{}">{}</surface_load></Loads>
</febio_spec>)";
  const auto with_load = [&](const std::string& type, const std::string& body) {
    std::string text = solid_model_text(kMaterial, kHex, kFixed);
    text.replace(text.find("<NodeSet"), 0,
                 "<Surface name=\"top\"><quad4 id=\"1\">5,6,7,8</quad4></Surface>\n    ");
    std::string l = loads;
    l.replace(l.find("{}"), 2, type);
    l.replace(l.find("{}"), 2, body);
    text.replace(text.find("</febio_spec>"), 13, l);
    return text;
  };
  expect_contains(feb_error(with_load("traction", "<scale>1</scale><trac>0,0,1</trac>")),
                  {"bad.feb:21: ", "/trac: unknown parameter 'trac' of a traction load"});
  expect_contains(
      feb_error(with_load("traction", "<scale>1</scale>")),
      {"bad.feb:21: ", "surface_load[@type='traction']: the element <traction> is required"});
  expect_contains(feb_error(with_load("heat flux", "<flux>1</flux>")),
                  {"bad.feb:21: ", "only <surface_load> of type pressure, traction, force, "
                                   "normal_traction and fluidflux are supported"});
  expect_contains(feb_error(with_load("fluidflux", "<flux>1</flux>")),
                  {"bad.feb:21: ", "a fluid flux needs the biphasic or multiphasic module"});
  expect_contains(
      feb_error(with_load("normal_traction", "<traction>1</traction><linear>1</linear>")),
      {"bad.feb:21: ", "/linear: a linear (non-follower) load is not supported"});
}

namespace {

/// The stacked-blocks contact file with each `from` replaced by its `to` (which must occur).
std::string stacked_with(const std::vector<std::pair<std::string, std::string>>& edits) {
  std::ifstream in(std::string(TRIFEM_FEB_DATA_DIR) + "/stacked_blocks_contact.feb");
  std::stringstream text;
  text << in.rdbuf();
  std::string s = text.str();
  for (const auto& [from, to] : edits) {
    const auto at = s.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos)
      s.replace(at, from.size(), to);
  }
  return s;
}

std::string stacked_with(const std::string& from, const std::string& to) {
  return stacked_with({{from, to}});
}

} // namespace

TEST(FebContact, TheFrictionPenaltyOfAFrictionlessInterfaceIsIgnored) {
  EXPECT_NO_THROW(feb::parse_feb(
      stacked_with("<fric_coeff>0</fric_coeff>",
                   "<fric_coeff>0</fric_coeff><fric_penalty>10</fric_penalty><ktmult>1</ktmult>"),
      "good.feb"));
}

TEST(FebContact, TheFrictionCoefficientOfASolidInterfaceIsItsCoulombFriction) {
  const io::CaseSpec spec = feb::parse_feb(
      stacked_with("<fric_coeff>0</fric_coeff>", "<fric_coeff>0.3</fric_coeff>"), "good.feb");
  ASSERT_EQ(spec.contacts.size(), 1u);
  EXPECT_EQ(spec.contacts[0].friction, 0.3);
}

TEST(FebErrors, UnsupportedContact) {
  expect_contains(
      feb_error(stacked_with("<fric_coeff>0</fric_coeff>", "<fric_coeff>-0.3</fric_coeff>")),
      {"bad.feb:", "contact[@type='sliding-elastic'][@name='Stack']/fric_coeff",
       "'fric_coeff' must be >= 0, not -0.3"});
  expect_contains(feb_error(stacked_with("type=\"sliding-elastic\"", "type=\"tied-elastic\"")),
                  {"@type: contact type 'tied-elastic' is not supported (trifem has no tied "
                   "contact"});
  expect_contains(feb_error(stacked_with("surface_pair=\"Interface\"", "surface_pair=\"Gap\"")),
                  {"@surface_pair: surface pair 'Gap' is not defined in <Mesh>"});
  expect_contains(
      feb_error(stacked_with("<primary>UpperBottom</primary>", "<primary>UpperBotom</primary>")),
      {"SurfacePair[@name='Interface']/primary: surface 'UpperBotom' is not defined"});
  expect_contains(
      feb_error(stacked_with("<search_tol>", "<friction_angle>1</friction_angle><search_tol>")),
      {"friction_angle: contact parameter 'friction_angle' is not supported"});
  // a biphasic model needs the contact that couples the fluid
  const std::string biphasic =
      stacked_with({{"<Module type=\"solid\"/>", "<Module type=\"biphasic\"/>"},
                    {"<analysis>STATIC</analysis>", "<analysis>TRANSIENT</analysis>"}});
  expect_contains(feb_error(biphasic),
                  {"'sliding-elastic' in a biphasic model", "use "
                                                            "'sliding-biphasic'"});
  expect_contains(feb_error(stacked_with("type=\"sliding-elastic\"", "type=\"sliding-biphasic\"")),
                  {"'sliding-biphasic' needs the biphasic module"});
}

namespace {

/// The base file with a rigid body "plate" attached to the bottom nodes and `rigid` as its
/// <Rigid> section.
std::string with_rigid_body(const std::string& rigid) {
  const std::string materials = kMaterial + R"(
    <material id="2" name="plate" type="rigid body"><density>1</density><center_of_mass>0,0,0</center_of_mass></material>)";
  std::string text = solid_model_text(
      materials, kHex, R"(    <bc name="glue" node_set="bottom" type="rigid"><rb>plate</rb></bc>)");
  text.replace(text.find("</febio_spec>"), 13, rigid + "\n</febio_spec>");
  return text;
}

} // namespace

TEST(FebRigid, AttachedBodyWithFixedRotationsTranslates) {
  const io::CaseSpec spec = feb::parse_feb(with_rigid_body(R"(<Rigid>
  <rigid_bc type="rigid_fixed"><rb>plate</rb><Rx_dof>1</Rx_dof><Ry_dof>1</Ry_dof><Ru_dof>1</Ru_dof><Rv_dof>1</Rv_dof><Rw_dof>1</Rw_dof></rigid_bc>
  <rigid_load type="rigid_force"><rb>plate</rb><dof>Rz</dof><value>-0.5</value><load_type>LOAD</load_type></rigid_load>
</Rigid>)"),
                                           "good.feb");
  ASSERT_EQ(spec.rigid_bodies.size(), 1u);
  const io::RigidBodySpec& b = spec.rigid_bodies[0];
  EXPECT_EQ(b.set, "bottom");
  EXPECT_EQ(b.components, (std::vector<io::Component>{0, 1, 2}));
  EXPECT_EQ(b.drives[0].drive, io::RigidDrive::Displacement); // fixed: held at 0
  EXPECT_EQ(b.drives[0].value, 0.0);
  EXPECT_EQ(b.drives[2].drive, io::RigidDrive::Force);
  EXPECT_EQ(b.drives[2].value, -0.5);
  EXPECT_FALSE(spec.materials.contains("plate")); // no elements: not a material of the mesh
}

TEST(FebRigid, AnAttachedBodyWhoseRotationIsNotHeldRotates) {
  const io::CaseSpec spec = feb::parse_feb(with_rigid_body(R"(<Rigid>
  <rigid_bc type="rigid_fixed"><rb>plate</rb><Rx_dof>1</Rx_dof></rigid_bc>
  <rigid_load type="rigid_moment"><rb>plate</rb><dof>Rv</dof><value>0.25</value></rigid_load>
</Rigid>)"),
                                           "good.feb");
  ASSERT_EQ(spec.rigid_bodies.size(), 1u);
  const io::RigidBodySpec& b = spec.rigid_bodies[0];
  EXPECT_TRUE(b.rotates);
  EXPECT_EQ(b.set, "bottom");
  ASSERT_TRUE(b.center.has_value()); // center_of_mass
  EXPECT_EQ(*b.center, Vec3::Zero());
  EXPECT_EQ(b.drives[0].drive, io::RigidDrive::Displacement); // Rx fixed: held at 0
  EXPECT_EQ(b.drives[1].drive, io::RigidDrive::Free);
  EXPECT_EQ(b.rotation_drives[0].drive, io::RigidDrive::Free);
  EXPECT_EQ(b.rotation_drives[1].drive, io::RigidDrive::Force); // the moment about v
  EXPECT_EQ(b.rotation_drives[1].value, 0.25);
}

TEST(FebRigid, RefusesUnknownConditionsAndBodies) {
  expect_contains(
      feb_error(with_rigid_body(R"(<Rigid>
  <rigid_bc type="rigid_follower_force"><rb>plate</rb></rigid_bc>
</Rigid>)")),
      {"febio_spec/Rigid/rigid_bc[@type='rigid_follower_force']/@type: ", "is not supported"});
  expect_contains(feb_error(with_rigid_body(R"(<Rigid>
  <rigid_bc type="rigid_rotation"><rb>plate</rb><dof>x</dof><value>1</value></rigid_bc>
</Rigid>)")),
                  {"/dof: ", "dof 'x' is not a rotation (Ru, Rv, Rw)"});
  expect_contains(feb_error(with_rigid_body(R"(<Rigid>
  <rigid_load type="rigid_force"><rb>bone</rb><dof>Rz</dof><value>1</value></rigid_load>
</Rigid>)")),
                  {"/rb: ", "'bone' is not a material of type 'rigid body'"});
}

TEST(FebGlobals, AnAmbientPressureOfZeroIsAcceptedAndOtherValuesRefused) {
  const auto with_p = [](const std::string& p) {
    std::string text = solid_model_text(kMaterial, kHex, kFixed);
    text.replace(text.find("<Control>"), 9,
                 "<Globals><Constants><T>0</T><P>" + p + "</P></Constants></Globals>\n  <Control>");
    return text;
  };
  EXPECT_NO_THROW(feb::parse_feb(with_p("0"), "good.feb"));
  expect_contains(feb_error(with_p("101325")),
                  {"Globals/Constants/P: ", "an ambient pressure P other than 0"});
}

TEST(FebRigid, ASphericalJointToTheGroundDrivesTheBodysRotation) {
  // the plate joined to "lid", a ground (no elements, all six fixed)
  const auto joint = [](const std::string& bodies, const std::string& drive) {
    std::string text = with_rigid_body(R"(<Rigid>
  <rigid_bc type="rigid_fixed"><rb>lid</rb><Rx_dof>1</Rx_dof><Ry_dof>1</Ry_dof><Rz_dof>1</Rz_dof><Ru_dof>1</Ru_dof><Rv_dof>1</Rv_dof><Rw_dof>1</Rw_dof></rigid_bc>
  <rigid_connector type="rigid spherical joint">)" +
                                       bodies + "<joint_origin>0,0,0</joint_origin>" + drive +
                                       "</rigid_connector>\n</Rigid>");
    const std::string plate = R"(<material id="2" name="plate" type="rigid body">)";
    text.replace(text.find(plate), 0,
                 R"(<material id="3" name="lid" type="rigid body"><density>1</density></material>
    )");
    return feb::parse_feb(text, "joint.feb");
  };
  const auto plate = [](const io::CaseSpec& spec) {
    for (const io::RigidBodySpec& b : spec.rigid_bodies)
      if (b.name == "plate")
        return b;
    ADD_FAILURE() << "no plate";
    return io::RigidBodySpec{};
  };
  // the rotation of b relative to a: the plate's rotation vector (z absent: held at 0)
  const io::RigidBodySpec turned =
      plate(joint("<body_a>lid</body_a><body_b>plate</body_b>",
                  "<prescribed_rotation>1</prescribed_rotation><rotation_x>0.5</rotation_x>"
                  "<rotation_y>-0.25</rotation_y>"));
  for (int k = 0; k < 3; ++k)
    EXPECT_EQ(turned.rotation_drives[k].drive, io::RigidDrive::Displacement) << k;
  EXPECT_EQ(turned.rotation_drives[0].value, 0.5);
  EXPECT_EQ(turned.rotation_drives[1].value, -0.25);
  EXPECT_EQ(turned.rotation_drives[2].value, 0.0);
  // the plate as body a: R_a = exp(−a)
  EXPECT_EQ(plate(joint("<body_a>plate</body_a><body_b>lid</body_b>",
                        "<prescribed_rotation>1</prescribed_rotation><rotation_x>0.5</rotation_x>"))
                .rotation_drives[0]
                .value,
            -0.5);
  // moments: FEBio applies M to body a and −M to body b
  const io::RigidBodySpec loaded =
      plate(joint("<body_a>lid</body_a><body_b>plate</body_b>", "<moment_z>2</moment_z>"));
  EXPECT_EQ(loaded.rotation_drives[0].drive, io::RigidDrive::Free);
  EXPECT_EQ(loaded.rotation_drives[2].drive, io::RigidDrive::Force);
  EXPECT_EQ(loaded.rotation_drives[2].value, -2.0);
  EXPECT_EQ(plate(joint("<body_a>plate</body_a><body_b>lid</body_b>", "<moment_z>2</moment_z>"))
                .rotation_drives[2]
                .value,
            2.0);
}

TEST(FebRigid, ConnectorsTrifemCannotBuildAreRefusedByName) {
  // the plate attached to the bottom nodes; a second body "lid" of no elements
  const auto connector = [](const std::string& body) {
    std::string text = with_rigid_body("<Rigid>\n" + body + "\n</Rigid>");
    const std::string plate = R"(<material id="2" name="plate" type="rigid body">)";
    text.replace(text.find(plate), 0,
                 R"(<material id="3" name="lid" type="rigid body"><density>1</density></material>
    )");
    return text;
  };
  expect_contains(
      feb_error(connector(
          R"(<rigid_connector type="rigid angular damper"><body_a>plate</body_a><body_b>lid</body_b></rigid_connector>)")),
      {"rigid_connector[@type='rigid angular damper']/@type: ", "is not supported",
       "rigid revolute joint"});
  expect_contains(
      feb_error(connector(
          R"(<rigid_connector type="rigid revolute joint"><body_a>plate</body_a><body_b>lid</body_b><joint_origin>0,0,0</joint_origin><force_damping>2</force_damping></rigid_connector>)")),
      {"/force_damping: ", "no damping"});
  expect_contains(
      feb_error(connector(
          R"(<rigid_connector type="rigid spring"><body_a>plate</body_a><body_b>plate</body_b><k>1</k><insertion_a>0,0,0</insertion_a><insertion_b>0,0,1</insertion_b></rigid_connector>)")),
      {"/body_b: ", "joins a body to itself"});
  expect_contains(
      feb_error(connector(
          R"(<rigid_connector type="rigid spring"><body_a>plate</body_a><body_b>lid</body_b><k>1</k><insertion_a>0,0,0</insertion_a><insertion_b>0,0,1</insertion_b><stiffness>2</stiffness></rigid_connector>)")),
      {"/stiffness: ", "unknown parameter 'stiffness' of a rigid spring"});
  // "lid" has no elements and no nodes: the ground, if held
  expect_contains(
      feb_error(connector(
          R"(<rigid_connector type="rigid spring"><body_a>plate</body_a><body_b>lid</body_b><k>1</k><insertion_a>0,0,0</insertion_a><insertion_b>0,0,1</insertion_b></rigid_connector>)")),
      {"material[@type='rigid body'][@name='lid']", "as the ground only", "rigid_fixed"});
}

TEST(FebCurves, SmoothIsFebiosQuadraticBlend) {
  std::string text = solid_model_text(kMaterial, kHex, kFixed);
  text.replace(
      text.find("</febio_spec>"), 13,
      R"(<LoadData><load_controller id="1" name="wave" type="loadcurve"><interpolate>SMOOTH</interpolate>
<points><pt>0,0</pt><pt>1,1</pt><pt>2,0</pt><pt>3,1</pt></points></load_controller></LoadData></febio_spec>)");
  const io::CaseSpec spec = feb::parse_feb(text, "smooth.feb");
  const io::CurveSpec& wave = spec.curves.at("wave");
  EXPECT_EQ(wave.interpolation, dofs::Interpolation::QuadraticBlend);
  EXPECT_DOUBLE_EQ(dofs::LoadCurve(wave.points, wave.interpolation)(1.5), 0.5); // FEBio's value
}

/// The base file with one LINEAR curve "gait" through (0, 0), (0.5, 1), (1, 0.5) and the given
/// <extend> (period 1, v_n - v_0 = 0.5).
std::string with_extended_curve(const std::string& extend) {
  std::string text = solid_model_text(kMaterial, kHex, kFixed);
  text.replace(text.find("</febio_spec>"), 13,
               R"(<LoadData><load_controller id="1" name="gait" type="loadcurve"><extend>)" +
                   extend + R"(</extend>
<points><pt>0,0</pt><pt>0.5,1</pt><pt>1,0.5</pt></points></load_controller></LoadData></febio_spec>)");
  return text;
}

TEST(FebCurves, RepeatAndRepeatOffsetAreMapped) {
  // FEBio at t = 1.25: REPEAT 0.25 -> 0.5; REPEAT OFFSET 0.5 + 1 x (0.5 - 0)
  for (const auto& [extend, extension, value] :
       {std::tuple{"REPEAT", dofs::Extension::Repeat, 0.5},
        std::tuple{"REPEAT OFFSET", dofs::Extension::RepeatOffset, 1.0},
        std::tuple{"repeat offset", dofs::Extension::RepeatOffset, 1.0},
        std::tuple{"CONSTANT", dofs::Extension::Constant, 0.5}}) {
    const io::CaseSpec spec = feb::parse_feb(with_extended_curve(extend), "repeat.feb");
    const io::CurveSpec& gait = spec.curves.at("gait");
    EXPECT_EQ(gait.extension, extension) << extend;
    EXPECT_EQ(gait.interpolation, dofs::Interpolation::Linear) << extend;
    EXPECT_EQ(gait.points, (std::vector<std::pair<Real, Real>>{{0, 0}, {0.5, 1}, {1, 0.5}}));
    EXPECT_DOUBLE_EQ(dofs::LoadCurve(gait.points, gait.interpolation, "gait", gait.extension)(1.25),
                     value)
        << extend;
  }
  expect_contains(feb_error(with_extended_curve("MIRROR")),
                  {"bad.feb:20: ", "/extend: extend 'MIRROR' is not supported (expected CONSTANT, "
                                   "REPEAT, REPEAT OFFSET, or EXTRAPOLATE inside the points)"});
}

TEST(FebRigid, ARotationVectorPrescribesTheThreeRotations) {
  const io::CaseSpec spec = feb::parse_feb(with_rigid_body(R"(<Rigid>
  <rigid_bc type="rigid_rotation_vector"><rb>plate</rb><vx>0.5</vx><vz>-0.25</vz></rigid_bc>
</Rigid>)"),
                                           "good.feb");
  ASSERT_EQ(spec.rigid_bodies.size(), 1u);
  const io::RigidBodySpec& b = spec.rigid_bodies[0];
  EXPECT_TRUE(b.rotates);
  for (int k = 0; k < 3; ++k)
    EXPECT_EQ(b.rotation_drives[k].drive, io::RigidDrive::Displacement) << k;
  EXPECT_EQ(b.rotation_drives[0].value, 0.5);
  EXPECT_EQ(b.rotation_drives[1].value, 0.0); // absent: held
  EXPECT_EQ(b.rotation_drives[2].value, -0.25);
  expect_contains(feb_error(with_rigid_body(R"(<Rigid>
  <rigid_bc type="rigid_rotation_vector"><rb>plate</rb><vx>0.5</vx></rigid_bc>
  <rigid_bc type="rigid_rotation"><rb>plate</rb><dof>Ru</dof><value>1</value></rigid_bc>
</Rigid>)")),
                  {"rigid_rotation", "a second motion or load on the same component"});
}

namespace {

/// Two rigid bodies "a" (id 2) and "b" (id 3) of one hex each, stacked so that they share four
/// nodes, with `rigid` as the <Rigid> section and b's density `density`.
std::string touching_bodies(const std::string& rigid, const std::string& density = "1") {
  return R"(<?xml version="1.0"?>
<febio_spec version="4.0">
  <Module type="solid"/>
  <Control><analysis>STATIC</analysis><time_steps>2</time_steps><step_size>0.5</step_size></Control>
  <Material>
    <material id="2" name="a" type="rigid body"><density>1</density></material>
    <material id="3" name="b" type="rigid body"><density>)" +
         density + R"(</density></material>
  </Material>
  <Mesh>
    <Nodes name="all">
      <node id="1">0,0,0</node><node id="2">1,0,0</node><node id="3">1,1,0</node><node id="4">0,1,0</node>
      <node id="5">0,0,1</node><node id="6">1,0,1</node><node id="7">1,1,1</node><node id="8">0,1,1</node>
      <node id="9">0,0,2</node><node id="10">1,0,2</node><node id="11">1,1,2</node><node id="12">0,1,2</node>
    </Nodes>
    <Elements type="hex8" name="PB"><elem id="2">5,6,7,8,9,10,11,12</elem></Elements>
    <Elements type="hex8" name="PA"><elem id="1">1,2,3,4,5,6,7,8</elem></Elements>
  </Mesh>
  <MeshDomains><SolidDomain name="PB" mat="b"/><SolidDomain name="PA" mat="a"/></MeshDomains>
)" + rigid +
         R"(
</febio_spec>
)";
}

} // namespace

TEST(FebRigid, BodiesWhoseElementsShareNodesMoveAsOneAndLaterConditionsWin) {
  // as FEBio: one body, named after the lower material id; a condition replaces an earlier one
  // on the same component, within a body and across the merged ones
  const io::CaseSpec spec = feb::parse_feb(touching_bodies(R"(<Rigid>
  <rigid_bc type="rigid_displacement"><rb>a</rb><dof>x</dof><value>0.5</value></rigid_bc>
  <rigid_bc type="rigid_fixed"><rb>b</rb><Rx_dof>1</Rx_dof><Ry_dof>1</Ry_dof><Rz_dof>1</Rz_dof><Ru_dof>1</Ru_dof><Rv_dof>1</Rv_dof></rigid_bc>
  <rigid_bc type="rigid_rotation"><rb>b</rb><dof>Rw</dof><value>0.25</value></rigid_bc>
  <rigid_bc type="rigid_displacement"><rb>b</rb><dof>y</dof><value>-1</value></rigid_bc>
</Rigid>)"),
                                           "merged.feb");
  ASSERT_EQ(spec.rigid_bodies.size(), 1u);
  const io::RigidBodySpec& body = spec.rigid_bodies[0];
  EXPECT_EQ(body.name, "a");
  EXPECT_EQ(body.blocks.size(), 2u);
  EXPECT_EQ(body.drives[0].drive, io::RigidDrive::Displacement);
  EXPECT_EQ(body.drives[0].value, 0.0);  // b's later rigid_fixed
  EXPECT_EQ(body.drives[1].value, -1.0); // b's later drive replaces its fixed y
  EXPECT_EQ(body.rotation_drives[2].drive, io::RigidDrive::Displacement);
  EXPECT_EQ(body.rotation_drives[2].value, 0.25);
  const auto model = model::build_model(spec);
  EXPECT_EQ(model->rigid_bodies.size(), 1u);
  expect_contains(
      feb_error(touching_bodies("", "2")),
      {"bad.feb:7: ", "share nodes, so they move as one body", "their densities differ (1 and 2)"});
}

TEST(FebRigid, EulerAnglesInDegreesPrescribeTheRotation) {
  const io::CaseSpec spec = feb::parse_feb(with_rigid_body(R"(<Rigid>
  <rigid_bc type="rigid_euler_angles"><rb>plate</rb><Ex>60</Ex><Ez>-90</Ez></rigid_bc>
</Rigid>)"),
                                           "euler.feb");
  ASSERT_EQ(spec.rigid_bodies.size(), 1u);
  const io::RigidBodySpec& b = spec.rigid_bodies[0];
  EXPECT_TRUE(b.rotates);
  ASSERT_TRUE(b.euler_angles.has_value());
  EXPECT_DOUBLE_EQ((*b.euler_angles)[0].value, std::numbers::pi / 3);
  EXPECT_EQ((*b.euler_angles)[1].value, 0.0);
  EXPECT_DOUBLE_EQ((*b.euler_angles)[2].value, -std::numbers::pi / 2);
  for (int k = 0; k < 3; ++k)
    EXPECT_EQ(b.rotation_drives[k].drive, io::RigidDrive::Free) << k;
  expect_contains(feb_error(with_rigid_body(R"(<Rigid>
  <rigid_bc type="rigid_euler_angles"><rb>plate</rb><Ex>60</Ex></rigid_bc>
  <rigid_bc type="rigid_rotation"><rb>plate</rb><dof>Ru</dof><value>1</value></rigid_bc>
</Rigid>)")),
                  {"rigid_euler_angles", "also fixed or driven by another rigid condition"});
  expect_contains(feb_error(with_rigid_body(R"(<Rigid>
  <rigid_bc type="rigid_euler_angles"><rb>plate</rb><Ex>60</Ex><convention>XYZ</convention></rigid_bc>
</Rigid>)")),
                  {"/convention: ", "convention 'XYZ' is not supported"});
}

TEST(FebInitial, AnInitialVelocityOfANodeSetIsTheCasesInitialVelocity) {
  std::string text = solid_model_text(kMaterial, kHex, kFixed);
  const std::string end = "</febio_spec>";
  text.insert(
      text.find(end),
      R"(  <Initial><ic name="v0" node_set="bottom" type="velocity"><value>-1,0,2.5</value></ic></Initial>
)");
  const io::CaseSpec spec = feb::parse_feb(text, "good.feb");
  ASSERT_EQ(spec.initial_velocities.size(), 1u);
  EXPECT_EQ(spec.initial_velocities[0].set, "bottom");
  EXPECT_EQ(spec.initial_velocities[0].value, Vec3(-1.0, 0.0, 2.5));
  std::string varying = text;
  varying.replace(varying.find("<value>"), 7, R"(<value lc="1">)");
  expect_contains(feb_error(varying), {"an initial velocity must be a constant vector"});
}
