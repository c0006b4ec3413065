// SPDX-License-Identifier: MIT
// `trifem convert`: each .feb test file converted to a TOML case and its Gmsh mesh, the
// converted case read back and run; its history.csv must equal that of the .feb run.
#include "history_csv.hpp"
#include "trifem/analysis/case_file.hpp"
#include "trifem/analysis/run.hpp"
#include "trifem/core/error.hpp"
#include "trifem/feb/feb_reader.hpp"
#include "trifem/io/case_writer.hpp"
#include "trifem/linalg/linear_solver.hpp"
#include "trifem/model/model.hpp"
#include "trifem/solver/time_loop.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <ostream>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

using namespace trifem;

namespace {

namespace fs = std::filesystem;

const fs::path kData = TRIFEM_FEB_DATA_DIR;

/// A fresh directory of the test's temporary directory, unique per process and name.
fs::path fresh_dir(const std::string& name) {
  const fs::path dir =
      fs::path(testing::TempDir()) / ("feb_convert_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

/// Runs `spec` (without VTU files) into `dir` and returns its history.
test::History run(io::CaseSpec spec, const fs::path& dir) {
  spec.output.vtu = false;
  EXPECT_EQ(analysis::run_case(spec, dir), analysis::kSuccess);
  return test::read_history(dir / "history.csv");
}

/// Expects equal histories (1e-12 of each column's largest magnitude) and prints the largest
/// relative difference.
void expect_same_history(const std::string& name, const test::History& expected,
                         const test::History& got) {
  ASSERT_FALSE(expected.names.empty());
  ASSERT_EQ(expected.names, got.names);
  Real largest = 0.0; // relative difference over all columns
  for (std::size_t c = 0; c < expected.names.size(); ++c) {
    ASSERT_EQ(expected.columns[c].size(), got.columns[c].size()) << expected.names[c];
    Real scale = 0.0;
    for (Real v : expected.columns[c])
      scale = std::max(scale, std::abs(v));
    for (std::size_t i = 0; i < expected.columns[c].size(); ++i) {
      const Real diff = std::abs(expected.columns[c][i] - got.columns[c][i]);
      EXPECT_LE(diff, 1e-12 * scale) << expected.names[c] << " row " << i;
      if (scale > 0.0)
        largest = std::max(largest, diff / scale);
    }
  }
  std::cout << name << ": " << expected.names.size() << " columns, " << expected.columns[0].size()
            << " rows, largest relative difference " << largest << '\n';
}

/// Ends a case of one time span at `end_time` (0: not), with its output times.
void end_at(io::CaseSpec& spec, Real end_time) {
  if (end_time <= 0.0)
    return;
  ASSERT_TRUE(spec.steps.empty()) << "a case of one time span";
  ASSERT_LT(end_time, spec.time.end_time);
  spec.time.end_time = end_time;
  std::erase_if(spec.output.times, [&](Real t) { return t > end_time; });
}

/// A test file of tests/data/feb, its runs ended at `end_time` (0: its own).
struct FebFile {
  std::string name;
  Real end_time = 0.0; ///< s
};

void PrintTo(const FebFile& file, std::ostream* out) {
  *out << file.name;
}

class FebConvert : public testing::TestWithParam<FebFile> {};

TEST_P(FebConvert, ConvertedCaseGivesTheSameHistory) {
  const FebFile& file = GetParam();
  const std::string& name = file.name;
  const fs::path dir = fresh_dir(name);
  const fs::path feb = kData / (name + ".feb");
  const auto written = analysis::convert_case(feb, dir / "case.toml");
  ASSERT_EQ(written.size(), 2u);
  EXPECT_EQ(written[0], dir / "case.toml");
  EXPECT_EQ(written[1], dir / "case.msh");
  ASSERT_TRUE(fs::exists(dir / "case.msh"));
  io::CaseSpec original = analysis::read_case_file(feb);
  io::CaseSpec converted = analysis::read_case_file(dir / "case.toml");
  end_at(original, file.end_time);
  end_at(converted, file.end_time);
  expect_same_history(name, run(original, dir / "feb"), run(converted, dir / "toml"));
  fs::remove_all(dir);
}

// A TOML case converted to TOML: the writer's paths the .feb files do not reach (boxes,
// triphasic materials, baths, bonded faces, [electrochemistry], analysis steps, rigid bodies).
// The examples of one time span end early (their first steps test the writer as well as the
// whole run): the case as read, ended at `end_time` (0: not), is written, read back and run.
struct TomlExample {
  std::string name;
  Real end_time = 0.0; ///< s; 0: the example's own
};

void PrintTo(const TomlExample& example, std::ostream* out) {
  *out << example.name;
}

class TomlConvert : public testing::TestWithParam<TomlExample> {};

TEST_P(TomlConvert, ConvertedExampleGivesTheSameHistory) {
  const TomlExample& example = GetParam();
  const fs::path dir = fresh_dir("toml_" + example.name);
  const fs::path source =
      fs::path(TRIFEM_SOURCE_DIR) / "examples" / example.name / (example.name + ".toml");
  io::CaseSpec spec = analysis::read_case_file(source);
  end_at(spec, example.end_time);
  // Newton to round-off: at the examples' own tolerances a residual that lands on the tolerance
  // may take one iteration more in one run than in the other (round-off of vectorized sums
  // follows the alignment of the heap), and the histories then differ by the tolerance
  spec.solver.residual_tolerance = spec.solver.increment_tolerance = 1e-12;
  io::write_case(spec, dir / "case.toml");
  expect_same_history(example.name, run(spec, dir / "original"),
                      run(analysis::read_case_file(dir / "case.toml"), dir / "converted"));
  fs::remove_all(dir);
}

// the columns under their platen's ramp (the confined one through the whole 50 s ramp, 20 of
// its 400 steps; the contact one through half of it, 10 of 80 steps), the first 200 s of the
// creep's 6000 and the swelling's 12 doubling steps to 4095 s (of 22 to 50 000 s)
INSTANTIATE_TEST_SUITE_P(
    Examples, TomlConvert,
    testing::Values(TomlExample{"biphasic_creep", 200.0}, TomlExample{"free_swelling", 4095.0},
                    TomlExample{"swell_then_compress"}, TomlExample{"confined_column", 50.0},
                    TomlExample{"contact_patch"}, TomlExample{"contact_column", 25.0}),
    [](const auto& info) { return info.param.name; });

// Rigid bodies are written as [[rigid_body]] tables that read back to the same description
// (the runs of examples/sliding_layers and indentation take minutes, so the round trip of the
// case description is compared here).
TEST(TomlConvertRigid, RigidBodiesReadBackAsWritten) {
  io::CaseSpec spec = analysis::read_case_file(kData / "uniaxial_neo_hookean.feb");
  io::RigidBodySpec body;
  body.key = "rigid body 'plate'";
  body.name = "plate";
  body.set = "z0";
  body.components = {0, 2};
  body.drives[0] = {io::RigidDrive::Displacement, 0.0, ""};
  body.drives[2] = {io::RigidDrive::Force, -0.25, spec.curves.begin()->first};
  spec.fixed.erase(std::remove_if(spec.fixed.begin(), spec.fixed.end(),
                                  [](const io::FixedSpec& f) { return f.set == "z0"; }),
                   spec.fixed.end());
  spec.rigid_bodies = {body};
  const fs::path dir = fresh_dir("rigid");
  io::write_case(spec, dir / "case.toml");
  const io::CaseSpec back = analysis::read_case_file(dir / "case.toml");
  ASSERT_EQ(back.rigid_bodies.size(), 1u);
  const io::RigidBodySpec& b = back.rigid_bodies[0];
  EXPECT_EQ(b.name, "plate");
  EXPECT_EQ(b.set, "z0");
  EXPECT_EQ(b.components, body.components);
  EXPECT_EQ(b.drives[0].drive, io::RigidDrive::Displacement);
  EXPECT_EQ(b.drives[0].value, 0.0);
  EXPECT_EQ(b.drives[1].drive, io::RigidDrive::Free);
  EXPECT_EQ(b.drives[2].drive, io::RigidDrive::Force);
  EXPECT_EQ(b.drives[2].value, -0.25);
  EXPECT_EQ(b.drives[2].curve, body.drives[2].curve);
  fs::remove_all(dir);
}

// The Krylov backend's preconditioner is written and reads back (the default is not written).
TEST(TomlConvertSolver, KrylovPreconditionerReadsBackAsWritten) {
  io::CaseSpec spec = analysis::read_case_file(kData / "uniaxial_neo_hookean.feb");
  spec.solver.linear_solver.kind = LinearSolverKind::krylov;
  const fs::path dir = fresh_dir("krylov_amg");
  io::write_case(spec, dir / "case.toml");
  std::ifstream written(dir / "case.toml");
  const std::string text{std::istreambuf_iterator<char>(written), {}};
  EXPECT_NE(text.find("linear_solver = \"krylov\""), std::string::npos) << text;
  EXPECT_EQ(text.find("preconditioner"), std::string::npos) << text;
  spec.solver.linear_solver.preconditioner = KrylovPreconditioner::amg;
  io::write_case(spec, dir / "case.toml");
  const io::CaseSpec back = analysis::read_case_file(dir / "case.toml");
  EXPECT_EQ(back.solver.linear_solver.kind, LinearSolverKind::krylov);
  EXPECT_EQ(back.solver.linear_solver.preconditioner, KrylovPreconditioner::amg);
  fs::remove_all(dir);
}

TEST(TomlConvertAnalysis, LumpedFluxMassReadsBackAsWritten) {
  io::CaseSpec spec = analysis::read_case_file(kData / "confined_biphasic_ramp.feb");
  const fs::path dir = fresh_dir("flux_mass");
  io::write_case(spec, dir / "case.toml");
  EXPECT_EQ(analysis::read_case_file(dir / "case.toml").analysis.flux_mass,
            io::FluxMass::Consistent);
  spec.analysis.flux_mass = io::FluxMass::Lumped;
  io::write_case(spec, dir / "case.toml");
  EXPECT_EQ(analysis::read_case_file(dir / "case.toml").analysis.flux_mass, io::FluxMass::Lumped);
  fs::remove_all(dir);
}

TEST(TomlConvertSolver, FactorizationPrecisionReadsBackAsWritten) {
  io::CaseSpec spec = analysis::read_case_file(kData / "uniaxial_neo_hookean.feb");
  spec.solver.linear_solver.kind = LinearSolverKind::mumps;
  spec.solver.linear_solver.reuse_factorization = true;
  const fs::path dir = fresh_dir("factorization_precision");
  io::write_case(spec, dir / "case.toml");
  EXPECT_EQ(analysis::read_case_file(dir / "case.toml").solver.linear_solver.precision,
            FactorPrecision::single);
  spec.solver.linear_solver.precision = FactorPrecision::full;
  io::write_case(spec, dir / "case.toml");
  const io::CaseSpec back = analysis::read_case_file(dir / "case.toml");
  EXPECT_TRUE(back.solver.linear_solver.reuse_factorization);
  EXPECT_EQ(back.solver.linear_solver.precision, FactorPrecision::full);
  fs::remove_all(dir);
}

TEST(TomlConvertSolver, SchurApproximationReadsBackAsWritten) {
  io::CaseSpec spec = analysis::read_case_file(kData / "uniaxial_neo_hookean.feb");
  spec.solver.linear_solver.kind = LinearSolverKind::krylov;
  const fs::path dir = fresh_dir("schur_approximation");
  io::write_case(spec, dir / "case.toml");
  EXPECT_EQ(analysis::read_case_file(dir / "case.toml").solver.linear_solver.schur,
            SchurApproximation::selfp);
  spec.solver.linear_solver.schur = SchurApproximation::drained;
  io::write_case(spec, dir / "case.toml");
  EXPECT_EQ(analysis::read_case_file(dir / "case.toml").solver.linear_solver.schur,
            SchurApproximation::drained);
  fs::remove_all(dir);
}

// A refined case is written with its [mesh] refine and reads back to the same refined model.
TEST(TomlConvertRefined, MeshRefinementReadsBackAsWritten) {
  io::CaseSpec spec = analysis::read_case_file(kData / "uniaxial_neo_hookean.feb");
  std::map<std::string, std::string> blocks;
  const Index cells = model::build_mesh(spec, blocks).num_cells();
  analysis::refine_case(spec, {.mesh_levels = 1});
  const fs::path dir = fresh_dir("refined");
  io::write_case(spec, dir / "case.toml");
  const io::CaseSpec back = analysis::read_case_file(dir / "case.toml");
  EXPECT_EQ(back.mesh_refinement, 1);
  EXPECT_EQ(model::build_mesh(back, blocks).num_cells(), 8 * cells);
  fs::remove_all(dir);
}

// the biphasic column through its 100 s ramp and the first 100 s of its relaxation (80 of 400
// steps)
INSTANTIATE_TEST_SUITE_P(
    TestFiles, FebConvert,
    testing::Values(FebFile{"confined_biphasic_ramp", 200.0}, FebFile{"uniaxial_neo_hookean"},
                    FebFile{"uniaxial_mooney_rivlin_pressure"}, FebFile{"ogden_two_steps"},
                    FebFile{"stacked_blocks_contact"}, FebFile{"triphasic_swelling_column"}),
    [](const auto& info) { return info.param.name; });

TEST(FebConvertErrors, RefusesToOverwriteTheInput) {
  const fs::path dir = fresh_dir("self");
  const fs::path feb = dir / "model.feb";
  fs::copy_file(kData / "uniaxial_neo_hookean.feb", feb);
  EXPECT_THROW(analysis::convert_case(feb, feb), InputError);
  fs::remove_all(dir);
}

TEST(FebConvertErrors, RefusesWhatTheWriterCannotExpress) {
  io::CaseSpec spec = analysis::read_case_file(kData / "uniaxial_neo_hookean.feb");
  spec.analysis.type = io::AnalysisType::DynamicExplicit;
  const fs::path dir = fresh_dir("explicit");
  try {
    io::write_case(spec, dir / "case.toml");
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("dynamic-explicit analyses"), std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(fs::exists(dir / "case.toml"));
  EXPECT_FALSE(fs::exists(dir / "case.msh"));
  fs::remove_all(dir);
}

} // namespace

// A model of rigid bodies only, joined by connectors: the TOML case reads back with the same
// connectors and runs (its mesh volumes have no material: the cells of rigid bodies).
TEST(TomlConvertRigid, ConnectorsOfAnAllRigidModelReadBackAsWritten) {
  const char* feb = R"(<?xml version="1.0"?>
<febio_spec version="4.0">
  <Module type="solid"/>
  <Control><analysis>STATIC</analysis><time_steps>4</time_steps><step_size>0.25</step_size></Control>
  <Material>
    <material id="1" name="bone" type="rigid body"><density>1</density></material>
    <material id="2" name="Ground" type="rigid body"><density>1</density></material>
  </Material>
  <Mesh>
    <Nodes name="all">
      <node id="1">0,0,0</node><node id="2">1,0,0</node><node id="3">1,1,0</node><node id="4">0,1,0</node>
      <node id="5">0,0,1</node><node id="6">1,0,1</node><node id="7">1,1,1</node><node id="8">0,1,1</node>
    </Nodes>
    <Elements type="hex8" name="Bone"><elem id="1">1,2,3,4,5,6,7,8</elem></Elements>
  </Mesh>
  <MeshDomains><SolidDomain name="Bone" mat="bone"/></MeshDomains>
  <Rigid>
    <rigid_bc type="rigid_fixed"><rb>Ground</rb><Rx_dof>1</Rx_dof><Ry_dof>1</Ry_dof><Rz_dof>1</Rz_dof><Ru_dof>1</Ru_dof><Rv_dof>1</Rv_dof><Rw_dof>1</Rw_dof></rigid_bc>
    <rigid_connector name="hinge" type="rigid revolute joint">
      <body_a>Ground</body_a><body_b>bone</body_b><joint_origin>0,0,0</joint_origin>
      <rotation_axis>0,0,1</rotation_axis><transverse_axis>1,0,0</transverse_axis>
      <prescribed_rotation>1</prescribed_rotation><rotation lc="1">0.5</rotation>
    </rigid_connector>
  </Rigid>
  <LoadData>
    <load_controller id="1" type="loadcurve"><interpolate>LINEAR</interpolate>
      <points><pt>0,0</pt><pt>1,1</pt></points></load_controller>
  </LoadData>
</febio_spec>
)";
  const io::CaseSpec spec = feb::parse_feb(feb, "hinge.feb");
  const fs::path dir = fresh_dir("connectors");
  io::write_case(spec, dir / "case.toml");
  const io::CaseSpec back = analysis::read_case_file(dir / "case.toml");
  ASSERT_EQ(back.connectors.size(), 1u);
  const io::ConnectorSpec& c = back.connectors[0];
  EXPECT_EQ(c.kind, io::ConnectorKind::Revolute);
  EXPECT_EQ(c.body_a, "ground");
  EXPECT_EQ(c.body_b, "bone");
  EXPECT_EQ(c.axis, Vec3::UnitZ());
  EXPECT_EQ(c.rotation.drive, io::RigidDrive::Displacement);
  EXPECT_EQ(c.rotation.value, 0.5);
  EXPECT_EQ(c.rotation.curve, spec.connectors[0].rotation.curve);
  auto model = model::build_model(back);
  solver::NewtonSolver newton(analysis::newton_settings(back.solver),
                              linalg::make_linear_solver(back.solver.linear_solver));
  solver::StepController controller(analysis::step_settings(back));
  ASSERT_TRUE(
      solver::run_time_loop(*model->problem, newton, controller, [](const auto&) {}).success);
  const Vector& x = model->problem->state();
  const auto& body = model->problem->rigid_map().bodies().at(0);
  EXPECT_NEAR(x[body.rotation[2]], 0.5, 1e-12);
  fs::remove_all(dir);
}
