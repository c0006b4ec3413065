// SPDX-License-Identifier: MIT
// FEBio's DYNAMIC analysis: solids and biphasic materials map to trifem's implicit dynamic
// analysis with their densities (FEBio's defaults where absent) and the generalized-α spectral
// radius rhoi; what has no counterpart is an error naming the line.
#include "trifem/core/error.hpp"
#include "trifem/feb/feb_reader.hpp"
#include "trifem/model/model.hpp"

#include <gtest/gtest.h>

using namespace trifem;

namespace {

/// A one-hex 4.0 file of `module` with `control` (inside <Control>) and `material`.
std::string model_text(const std::string& module, const std::string& control,
                       const std::string& material) {
  return R"(<?xml version="1.0"?>
<febio_spec version="4.0">
  <Module type=")" +
         module +
         R"("/>
  <Control><time_steps>4</time_steps><step_size>0.001</step_size>)" +
         control + R"(</Control>
  <Material>
)" + material +
         R"(
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
</febio_spec>
)";
}

const std::string kSolid =
    R"(    <material id="1" name="m" type="neo-Hookean"><density>1.2e-9</density><E>1</E><v>0.3</v></material>)";
const std::string kBiphasic = R"(    <material id="1" name="m" type="biphasic">
      <phi0>0.2</phi0>
      <fluid_density>1e-9</fluid_density>
      <solid type="neo-Hookean"><density>1.5e-9</density><E>1</E><v>0</v></solid>
      <permeability type="perm-const-iso"><perm>0.001</perm></permeability>
    </material>)";

std::string error_of(const std::string& text) {
  try {
    feb::parse_feb(text, "dyn.feb");
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no error";
  return "";
}

} // namespace

TEST(FebDynamic, ASolidDynamicAnalysisTakesItsDensity) {
  const io::CaseSpec spec =
      feb::parse_feb(model_text("solid", "<analysis>DYNAMIC</analysis>", kSolid), "dyn.feb");
  EXPECT_EQ(spec.analysis.type, io::AnalysisType::Dynamic);
  ASSERT_TRUE(spec.materials.at("m").density.has_value());
  EXPECT_DOUBLE_EQ(*spec.materials.at("m").density, 1.2e-9);
  EXPECT_EQ(spec.dynamics.rho_inf, 1.0); // FEBio's default: Newmark's trapezoidal rule
  const auto model = model::build_model(spec);
  ASSERT_NE(model->problem->inertia(), nullptr);
}

TEST(FebDynamic, AStaticAnalysisLeavesTheDensityOut) {
  const io::CaseSpec spec =
      feb::parse_feb(model_text("solid", "<analysis>STATIC</analysis>", kSolid), "static.feb");
  EXPECT_EQ(spec.analysis.type, io::AnalysisType::QuasiStatic);
  EXPECT_FALSE(spec.materials.at("m").density.has_value());
  EXPECT_EQ(model::build_model(spec)->problem->inertia(), nullptr);
}

TEST(FebDynamic, ABiphasicDynamicAnalysisMovesTheMixturesMass) {
  const io::CaseSpec spec =
      feb::parse_feb(model_text("biphasic", "<analysis>DYNAMIC</analysis>", kBiphasic), "b.feb");
  EXPECT_EQ(spec.analysis.type, io::AnalysisType::Dynamic);
  // φ0 ρ_s + (1 − φ0) ρ_w = 0.2 x 1.5e-9 + 0.8 x 1e-9
  EXPECT_DOUBLE_EQ(*spec.materials.at("m").density, 1.1e-9);
}

TEST(FebDynamic, DensitiesDefaultToFebios) {
  std::string material = kSolid;
  material.replace(material.find("<density>1.2e-9</density>"), 25, "");
  const io::CaseSpec spec =
      feb::parse_feb(model_text("solid", "<analysis>DYNAMIC</analysis>", material), "d.feb");
  EXPECT_DOUBLE_EQ(*spec.materials.at("m").density, 1.0); // FEBio's default density
}

TEST(FebDynamic, TheSpectralRadiusIsRhoi) {
  const io::CaseSpec spec = feb::parse_feb(
      model_text("solid",
                 "<analysis>DYNAMIC</analysis><solver type=\"solid\"><rhoi>0.6</rhoi></solver>",
                 kSolid),
      "rhoi.feb");
  EXPECT_DOUBLE_EQ(spec.dynamics.rho_inf, 0.6);
}

TEST(FebDynamic, OtherNewmarkParametersAreRefused) {
  const std::string beta = error_of(model_text(
      "solid", "<analysis>DYNAMIC</analysis><solver type=\"solid\"><beta>0.3</beta></solver>",
      kSolid));
  EXPECT_NE(beta.find("dyn.feb:4: "), std::string::npos) << beta;
  EXPECT_NE(beta.find("beta = 0.3 is not supported"), std::string::npos) << beta;
  const std::string rhoi = error_of(model_text(
      "solid", "<analysis>DYNAMIC</analysis><solver type=\"solid\"><rhoi>-1</rhoi></solver>",
      kSolid));
  EXPECT_NE(rhoi.find("rhoi = -1 is not supported"), std::string::npos) << rhoi;
}

namespace {

/// The one-hex model of `control` as a rigid body of density 3 with `rigid` as its <Rigid>.
std::string rigid_cube_text(const std::string& control, const std::string& rigid) {
  std::string text = model_text(
      "solid", control,
      R"(    <material id="1" name="m" type="rigid body"><density>3</density></material>)");
  text.replace(text.find("</febio_spec>"), 13, rigid + "\n</febio_spec>");
  return text;
}

constexpr const char* kInitialVelocity = R"(<Rigid>
  <rigid_ic type="initial_rigid_velocity"><rb>m</rb><value>1,0,0</value></rigid_ic>
  <rigid_ic type="initial_rigid_angular_velocity"><rb>m</rb><value>0,0,2</value></rigid_ic>
</Rigid>)";

} // namespace

TEST(FebDynamic, ARigidBodyTakesItsDensityAndInitialVelocity) {
  const io::CaseSpec spec =
      feb::parse_feb(rigid_cube_text("<analysis>DYNAMIC</analysis>", kInitialVelocity), "spin.feb");
  ASSERT_EQ(spec.rigid_bodies.size(), 1u);
  const io::RigidBodySpec& b = spec.rigid_bodies[0];
  EXPECT_TRUE(b.rotates);
  ASSERT_TRUE(b.density.has_value());
  EXPECT_EQ(*b.density, 3.0);
  EXPECT_EQ(b.velocity, Vec3(1, 0, 0));
  EXPECT_EQ(b.angular_velocity, Vec3(0, 0, 2));
  // the nodes start with v + ω × (X − X_c): node 7 at (1, 1, 1), X_c the cube's center
  const auto model = model::build_model(spec);
  ASSERT_EQ(model->initial_velocity.size(), model->dofs.num_dofs());
  const Vec3 v(model->initial_velocity[model->dofs.dof(model->fields.u, 6, 0)],
               model->initial_velocity[model->dofs.dof(model->fields.u, 6, 1)],
               model->initial_velocity[model->dofs.dof(model->fields.u, 6, 2)]);
  EXPECT_LT((v - Vec3(0, 1, 0)).norm(), 1e-15);
}

TEST(FebDynamic, AStaticAnalysisIgnoresTheInitialVelocityOfARigidBody) {
  const io::CaseSpec spec =
      feb::parse_feb(rigid_cube_text("<analysis>STATIC</analysis>", kInitialVelocity), "still.feb");
  ASSERT_EQ(spec.rigid_bodies.size(), 1u);
  EXPECT_EQ(spec.rigid_bodies[0].velocity, Vec3::Zero());
  EXPECT_EQ(spec.rigid_bodies[0].angular_velocity, Vec3::Zero());
  const std::string unknown = error_of(rigid_cube_text("<analysis>DYNAMIC</analysis>", R"(<Rigid>
  <rigid_ic type="initial_rigid_velocity"><rb>m</rb><value>1,0,0</value><speed>2</speed></rigid_ic>
</Rigid>)"));
  EXPECT_NE(unknown.find("unknown parameter 'speed' of initial_rigid_velocity"), std::string::npos)
      << unknown;
}
