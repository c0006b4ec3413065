// SPDX-License-Identifier: MIT
// The FEBio reader: the CaseSpec and the model built from the test problems of tests/data/feb.
#include "trifem/feb/feb_reader.hpp"
#include "trifem/material/mixture.hpp"
#include "trifem/model/model.hpp"

#include <gtest/gtest.h>

#include <algorithm>

using namespace trifem;

namespace {

const std::filesystem::path kData = TRIFEM_FEB_DATA_DIR;

const io::InlineMeshSpec& only_mesh(const io::CaseSpec& spec) {
  EXPECT_EQ(spec.meshes.size(), 1u);
  return spec.meshes.front();
}

} // namespace

TEST(FebReader, ConfinedCompressionCase) {
  const io::CaseSpec spec = feb::read_feb(kData / "confined_biphasic_ramp.feb");
  const mesh::Mesh& m = only_mesh(spec).mesh;
  EXPECT_EQ(m.num_nodes(), 44);
  EXPECT_EQ(m.num_cells(), 10);
  EXPECT_EQ(m.node_set("All").size(), 44u);
  EXPECT_EQ(m.node_set("Top").size(), 4u);
  EXPECT_EQ(m.cell_block("BottomLayer").size(), 1u);
  EXPECT_EQ(only_mesh(spec).materials.at("Layers"), "Cartilage");

  const io::MaterialSpec& mat = spec.materials.at("Cartilage");
  EXPECT_EQ(mat.type, "biphasic");
  EXPECT_DOUBLE_EQ(mat.parameters.at("phi_s0"), 0.2);
  EXPECT_DOUBLE_EQ(mat.parameters.at("permeability"), 1e-3);
  ASSERT_TRUE(mat.solid.has_value());
  EXPECT_EQ(mat.solid->type, "neo-hookean");
  EXPECT_DOUBLE_EQ(mat.solid->parameters.at("E"), 1.0);
  EXPECT_DOUBLE_EQ(mat.solid->parameters.at("nu"), 0.0);

  // z on the bottom, x and y everywhere, then FEBio's undrained faces (below)
  ASSERT_EQ(spec.fixed.size(), 7u);
  EXPECT_EQ(spec.fixed[0].set, "Bottom");
  EXPECT_EQ(spec.fixed[0].components, std::vector<io::Component>{2});
  EXPECT_EQ(spec.fixed[1].set, "All");
  EXPECT_EQ(spec.fixed[1].components, (std::vector<io::Component>{0, 1}));
  ASSERT_EQ(spec.prescribed.size(), 1u);
  EXPECT_EQ(spec.prescribed[0].set, "Top");
  EXPECT_EQ(spec.prescribed[0].component, 2);
  EXPECT_DOUBLE_EQ(spec.prescribed[0].value, 1.0);
  EXPECT_EQ(spec.prescribed[0].curve, "Ramp");
  const io::CurveSpec& lc = spec.curves.at("Ramp");
  ASSERT_EQ(lc.points.size(), 2u);
  EXPECT_DOUBLE_EQ(lc.points[1].first, 100.0);
  EXPECT_DOUBLE_EQ(lc.points[1].second, -0.1);

  EXPECT_DOUBLE_EQ(spec.time.end_time, 1000.0);
  EXPECT_DOUBLE_EQ(spec.time.dt, 2.5);
  EXPECT_DOUBLE_EQ(spec.time.dt_max, 2.5); // no time stepper: FEBio's fixed steps
  EXPECT_TRUE(spec.steps.empty());

  // FEBio's undrained faces: the bottom and the four sides (five patches), not the top; each
  // is a plane normal to an axis, so its normal flux component is fixed
  EXPECT_TRUE(spec.impermeable_surfaces.empty());
  std::size_t facets = 0;
  std::vector<io::Component> normals;
  for (std::size_t k = 2; k < spec.fixed.size(); ++k) {
    EXPECT_EQ(spec.fixed[k].fields, std::vector<io::FieldKind>{io::FieldKind::FluidFlux});
    ASSERT_EQ(spec.fixed[k].components.size(), 1u);
    normals.push_back(spec.fixed[k].components[0]);
    facets += m.surface(spec.fixed[k].set).facets.size();
  }
  EXPECT_EQ(facets, 41u); // 1 bottom + 4 x 10 sides
  std::sort(normals.begin(), normals.end());
  EXPECT_EQ(normals, (std::vector<io::Component>{0, 0, 1, 1, 2}));
}

TEST(FebReader, ConfinedCompressionBuildsTheModel) {
  const io::CaseSpec spec = feb::read_feb(kData / "confined_biphasic_ramp.feb");
  const auto model = model::build_model(spec);
  EXPECT_EQ(model->mesh.num_cells(), 10);
  ASSERT_NE(model->mixture, nullptr);
  EXPECT_EQ(model->solid, nullptr);
  EXPECT_TRUE(model->fields.w.valid());
  EXPECT_FALSE(model->fields.j_plus.valid());
  EXPECT_DOUBLE_EQ(model->materials[0].mixture->phi_s0, 0.2);
  EXPECT_DOUBLE_EQ(model->materials[0].mixture->permeability, 1e-3);
}

TEST(FebReader, SolidProblemsMapLawsLoadsAndOutputs) {
  const io::CaseSpec nh = feb::read_feb(kData / "uniaxial_neo_hookean.feb");
  EXPECT_EQ(nh.materials.at("Rubber").type, "neo-hookean");
  EXPECT_DOUBLE_EQ(nh.materials.at("Rubber").parameters.at("nu"), 0.3);
  ASSERT_EQ(nh.prescribed.size(), 1u);
  EXPECT_EQ(nh.prescribed[0].set, "Top"); // @surface:Top
  EXPECT_DOUBLE_EQ(nh.time.dt_min, 0.01);
  EXPECT_DOUBLE_EQ(nh.time.dt_max, 0.1);
  EXPECT_EQ(nh.time.target_iterations, 10);
  ASSERT_EQ(nh.output.reactions.size(), 1u);
  EXPECT_EQ(nh.output.reactions[0].set, "Top");
  ASSERT_EQ(nh.output.probes.size(), 2u);
  EXPECT_EQ(nh.output.probes[0].name, "node7_displacement");
  EXPECT_EQ(nh.output.probes[1].quantity, "stress");
  EXPECT_TRUE(nh.output.probes[1].point.isApprox(Vec3(0.5, 0.5, 0.5)));
  ASSERT_EQ(nh.warnings.size(), 1u); // rigid_body_data
  EXPECT_NE(nh.warnings[0].find("uniaxial_neo_hookean.feb:94: "), std::string::npos)
      << nh.warnings[0];
  EXPECT_TRUE(nh.impermeable_surfaces.empty());

  const io::CaseSpec mr = feb::read_feb(kData / "uniaxial_mooney_rivlin_pressure.feb");
  const io::MaterialSpec& law = mr.materials.at("MR");
  EXPECT_EQ(law.type, "mooney-rivlin");
  EXPECT_DOUBLE_EQ(law.parameters.at("c2"), 0.05);
  EXPECT_DOUBLE_EQ(law.parameters.at("k"), 20.0);
  ASSERT_EQ(mr.pressures.size(), 1u);
  EXPECT_EQ(mr.pressures[0].surface, "Top");
  EXPECT_DOUBLE_EQ(mr.pressures[0].value, 0.1);
  EXPECT_EQ(mr.curves.at("ramp").interpolation, dofs::Interpolation::Linear); // SMOOTH, 2 points
  EXPECT_DOUBLE_EQ(mr.time.dt_max, 0.1);   // the largest value of the dtmax curve
  EXPECT_TRUE(mr.curves.contains("must")); // its points are must points
  EXPECT_EQ(mr.output.probes.size(), 4u);  // uz of the four top nodes

  const io::CaseSpec og = feb::read_feb(kData / "ogden_two_steps.feb");
  const io::MaterialSpec& ogden = og.materials.at("Ogden");
  EXPECT_EQ(ogden.type, "ogden");
  EXPECT_DOUBLE_EQ(ogden.parameters.at("m2"), -2.0);
  EXPECT_FALSE(ogden.parameters.contains("c4"));
  ASSERT_EQ(og.steps.size(), 2u);
  EXPECT_EQ(og.steps[0].name, "Stretch");
  EXPECT_DOUBLE_EQ(og.steps[0].time.end_time, 1.0);
  EXPECT_DOUBLE_EQ(og.steps[1].time.end_time, 2.0);
  EXPECT_DOUBLE_EQ(og.steps[1].time.dt, 0.25);
  EXPECT_DOUBLE_EQ(og.time.end_time, 2.0);
  ASSERT_EQ(og.steps[1].prescribed.size(), 1u);
  EXPECT_EQ(og.steps[1].prescribed[0].curve, "back");
  EXPECT_EQ(og.fixed.size(), 3u);
  for (const char* f :
       {"uniaxial_neo_hookean.feb", "uniaxial_mooney_rivlin_pressure.feb", "ogden_two_steps.feb"})
    EXPECT_NO_THROW(model::build_model(feb::read_feb(kData / f))) << f;
}

TEST(FebReader, ReadsFormat30) {
  const std::string text = R"(<?xml version="1.0"?>
<febio_spec version="3.0">
  <Module type="solid"/>
  <Control><analysis>STATIC</analysis><time_steps>4</time_steps><step_size>0.25</step_size></Control>
  <Material><material id="1" name="m" type="isotropic elastic"><E>2</E><v>0.25</v></material></Material>
  <Mesh>
    <Nodes name="all">
      <node id="1">0,0,0</node><node id="2">1,0,0</node><node id="3">1,1,0</node><node id="4">0,1,0</node>
      <node id="5">0,0,1</node><node id="6">1,0,1</node><node id="7">1,1,1</node><node id="8">0,1,1</node>
    </Nodes>
    <Elements type="hex8" name="P"><elem id="1">1,2,3,4,5,6,7,8</elem></Elements>
    <NodeSet name="bottom"><node id="1"/><node id="2"/><node id="3"/><node id="4"/></NodeSet>
    <NodeSet name="top"><node id="5"/><node id="6"/><node id="7"/><node id="8"/></NodeSet>
  </Mesh>
  <MeshDomains><SolidDomain name="P" mat="m"/></MeshDomains>
  <Boundary>
    <bc type="fix" node_set="bottom"><dofs>x,y,z</dofs></bc>
    <bc type="prescribe" node_set="top"><dof>z</dof><scale lc="1">0.1</scale><relative>0</relative></bc>
  </Boundary>
  <LoadData>
    <load_controller id="1" type="loadcurve"><interpolate>LINEAR</interpolate>
      <points><point>0,0</point><point>1,1</point></points></load_controller>
  </LoadData>
</febio_spec>
)";
  const io::CaseSpec spec = feb::parse_feb(text, "v3.feb");
  EXPECT_EQ(spec.materials.at("m").type, "saint-venant-kirchhoff");
  ASSERT_EQ(spec.fixed.size(), 1u);
  EXPECT_EQ(spec.fixed[0].components, (std::vector<io::Component>{0, 1, 2}));
  ASSERT_EQ(spec.prescribed.size(), 1u);
  EXPECT_DOUBLE_EQ(spec.prescribed[0].value, 0.1);
  EXPECT_EQ(spec.prescribed[0].curve, "lc1");
  EXPECT_DOUBLE_EQ(spec.time.end_time, 1.0);
  EXPECT_NO_THROW(model::build_model(spec));
}

TEST(FebReader, DispatchesOnTheExtension) {
  EXPECT_TRUE(feb::is_feb_file("a/b/model.feb"));
  EXPECT_TRUE(feb::is_feb_file("MODEL.FEB"));
  EXPECT_FALSE(feb::is_feb_file("case.toml"));
  EXPECT_FALSE(feb::is_feb_file("feb"));
}
