// SPDX-License-Identifier: MIT
// Tests of the TOML case reader: a complete case, defaults, and one test per kind of bad input.
#include "bad_input.hpp"
#include "trifem/core/error.hpp"
#include "trifem/io/case_reader.hpp"
#include "trifem/io/case_writer.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using trifem::InputError;
using trifem::Real;
using trifem::dofs::Extension;
using trifem::dofs::Interpolation;
using trifem::io::CaseSpec;
using trifem::io::FieldKind;
using trifem::io::InitialStateKind;
using trifem::io::MaterialSpec;
using trifem::io::parse_case;
using trifem::io::read_case;

using namespace trifem::test;

namespace {

const fs::path kData = TRIFEM_TEST_DATA_DIR;
const fs::path kInputDoc = fs::path(TRIFEM_SOURCE_DIR) / "docs" / "input.md";

/// A small valid case that the bad-input tests modify.
const std::string kBase = R"(
[[mesh.box]]
name = "block"
size = [1, 1, 1]
divisions = [2, 2, 2]
material = "soft"

[materials.soft]
type = "neo-hookean"
E = 1.0

[curves.ramp]
points = [[0, 0], [1, 1]]

[time]
end_time = 1.0
dt = 0.1
)";

/// A triphasic material (appended to kBase by the mixture tests).
const std::string kCartilage = R"(
[materials.cart]
type = "triphasic"
phi_s0 = 0.2
permeability = 1e-3
fixed_charge = 2e-4
d_plus = 5e-4
d_minus = 8e-4

[materials.cart.solid]
type = "neo-hookean"
E = 1.0
)";

/// A biphasic material (appended to kBase by the mixture tests).
const std::string kGel = R"(
[materials.gel]
type = "biphasic"
phi_s0 = 0.2
permeability = 1e-3

[materials.gel.solid]
type = "neo-hookean"
E = 1.0
)";

/// kBase with the first occurrence of `from` replaced by `to` (which must exist).
std::string replaced(const std::string& from, const std::string& to) {
  return replaced_in(kBase, from, to);
}

/// Writes `bytes` to a fresh file in the temporary directory and returns its path.
fs::path temp_file(const std::string& name, const std::string& bytes) {
  const fs::path dir = fs::temp_directory_path() / "trifem_test_case_reader";
  fs::create_directories(dir);
  const fs::path file = dir / name;
  std::ofstream(file, std::ios::binary) << bytes;
  return file;
}

} // namespace

// ---------------------------------------------------------------------------------------------
// Valid input

TEST(CaseReader, CompleteCaseParsesIntoExpectedValues) {
  const CaseSpec c = read_case(kData / "complete.toml");
  EXPECT_EQ(c.file, kData / "complete.toml");
  EXPECT_EQ(c.title, "Cube under pressure");

  ASSERT_EQ(c.boxes.size(), 2u);
  EXPECT_EQ(c.boxes[0].box.name, "block");
  EXPECT_EQ(c.boxes[0].material, "cartilage");
  EXPECT_EQ(c.boxes[0].box.size, trifem::Vec3(1.0, 2.0, 0.5));
  EXPECT_EQ(c.boxes[0].box.divisions, (std::array<int, 3>{4, 8, 2}));
  EXPECT_EQ(c.boxes[0].box.grading, trifem::Vec3(1.0, 1.0, 2.0));
  EXPECT_EQ(c.boxes[1].box.origin, trifem::Vec3(0.0, 0.0, 0.5));
  EXPECT_EQ(c.boxes[1].box.grading, trifem::Vec3::Ones()); // default

  ASSERT_EQ(c.gmsh.size(), 1u);
  EXPECT_EQ(c.gmsh[0].file, fs::absolute(kData / "part.msh").lexically_normal()); // resolved
  EXPECT_EQ(c.gmsh[0].materials.at("cartilage_volume"), "cartilage");

  ASSERT_EQ(c.materials.size(), 2u);
  EXPECT_EQ(c.materials.at("cartilage").type, "neo-hookean");
  EXPECT_DOUBLE_EQ(c.materials.at("cartilage").parameters.at("nu"), 0.1);
  EXPECT_DOUBLE_EQ(c.materials.at("bone").parameters.at("E"), 1000.0); // integer accepted
  EXPECT_DOUBLE_EQ(c.materials.at("bone").parameters.at("nu"), 0.0);   // schema default

  ASSERT_EQ(c.curves.size(), 2u);
  EXPECT_EQ(c.curves.at("ramp").interpolation, Interpolation::Smooth);
  EXPECT_EQ(c.curves.at("hold").interpolation, Interpolation::Linear); // default
  ASSERT_EQ(c.curves.at("hold").points.size(), 3u);
  EXPECT_EQ(c.curves.at("hold").points[1], (std::pair<Real, Real>{0.5, 1.0}));
}

TEST(CaseReader, CompleteCaseBoundaryLoadsAndSettings) {
  const CaseSpec c = read_case(kData / "complete.toml");
  ASSERT_EQ(c.fixed.size(), 3u);
  EXPECT_EQ(c.fixed[0].components, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(c.fixed[1].components, (std::vector<int>{0}));
  EXPECT_EQ(c.fixed[2].components, (std::vector<int>{0, 1, 2})); // default: all
  ASSERT_EQ(c.prescribed.size(), 1u);
  EXPECT_EQ(c.prescribed[0].set, "cap.zmax");
  EXPECT_EQ(c.prescribed[0].component, 2);
  EXPECT_DOUBLE_EQ(c.prescribed[0].value, -0.1);
  EXPECT_EQ(c.prescribed[0].curve, "ramp");
  ASSERT_EQ(c.pressures.size(), 1u);
  EXPECT_DOUBLE_EQ(c.pressures[0].value, 0.01);
  EXPECT_EQ(c.pressures[0].curve, "hold");
  ASSERT_EQ(c.tractions.size(), 1u);
  EXPECT_EQ(c.tractions[0].value, trifem::Vec3(0.01, 0.0, -0.02));
  EXPECT_EQ(c.tractions[0].curve, ""); // constant

  EXPECT_DOUBLE_EQ(c.time.end_time, 2.0);
  EXPECT_DOUBLE_EQ(c.time.dt_min, 0.1 * 1e-6); // default dt * 1e-6
  EXPECT_DOUBLE_EQ(c.time.dt_max, 0.2);
  EXPECT_EQ(c.time.target_iterations, 5);
  EXPECT_DOUBLE_EQ(c.time.growth, 2.0);
  EXPECT_DOUBLE_EQ(c.time.cutback, 0.25);
  EXPECT_EQ(c.solver.max_iterations, 30);
  EXPECT_DOUBLE_EQ(c.solver.residual_tolerance, 1e-9);
  EXPECT_DOUBLE_EQ(c.solver.increment_tolerance, 1e-7);
  EXPECT_FALSE(c.solver.line_search);
  EXPECT_EQ(c.solver.linear_solver.kind, trifem::LinearSolverKind::sparselu);

  EXPECT_DOUBLE_EQ(c.output.interval, 0.5);
  EXPECT_EQ(c.output.times, (std::vector<Real>{0.25, 1.5})); // sorted, duplicates dropped
  EXPECT_FALSE(c.output.vtu);
  ASSERT_EQ(c.output.reactions.size(), 2u);
  EXPECT_EQ(c.output.reactions[1].set, "cap.zmax");
  ASSERT_EQ(c.output.probes.size(), 2u);
  EXPECT_EQ(c.output.probes[0].quantity, "position");
  EXPECT_EQ(c.output.probes[1].quantity, "displacement"); // default
  EXPECT_EQ(c.output.probes[1].point, trifem::Vec3(1.0, 2.0, 0.0));
}

TEST(CaseReader, MinimalCaseGetsDefaults) {
  const CaseSpec c = parse_case(kBase, kMemoryFile);
  EXPECT_EQ(c.title, "");
  EXPECT_EQ(c.boxes[0].box.origin, trifem::Vec3::Zero());
  EXPECT_DOUBLE_EQ(c.materials.at("soft").parameters.at("nu"), 0.0);
  EXPECT_DOUBLE_EQ(c.time.dt_min, 1e-7);
  EXPECT_DOUBLE_EQ(c.time.dt_max, 0.1);
  EXPECT_EQ(c.time.target_iterations, 6);
  EXPECT_DOUBLE_EQ(c.time.growth, 1.5);
  EXPECT_DOUBLE_EQ(c.time.cutback, 0.5);
  EXPECT_EQ(c.solver.max_iterations, 20);
  EXPECT_TRUE(c.solver.line_search);
  EXPECT_EQ(c.solver.linear_solver.kind, trifem::LinearSolverKind::automatic);
  EXPECT_DOUBLE_EQ(c.output.interval, 0.0);
  EXPECT_TRUE(c.output.vtu);
  EXPECT_TRUE(c.fixed.empty());
  EXPECT_TRUE(c.output.probes.empty());
}

TEST(CaseReader, IntegersAcceptedWhereNumbersExpected) {
  const CaseSpec c =
      parse_case(replaced("end_time = 1.0\ndt = 0.1", "end_time = 2\ndt = 1"), kMemoryFile);
  EXPECT_DOUBLE_EQ(c.time.end_time, 2.0);
  EXPECT_DOUBLE_EQ(c.time.dt, 1.0);
}

TEST(CaseReader, CurvesRepeatAndTheWriterKeepsIt) {
  EXPECT_EQ(parse_case(kBase, kMemoryFile).curves.at("ramp").extension,
            Extension::Constant); // default
  const std::string text =
      replaced("[[0, 0], [1, 1]]", "[[0, 0], [1, 1]]\nextend = \"repeat-offset\"") +
      "[curves.cycle]\ninterpolation = \"next\"\npoints = [[0, 0], [0.5, 1], [1, 0]]\n"
      "extend = \"repeat\"\n[curves.hold]\npoints = [[0, 1]]\nextend = \"constant\"\n";
  const CaseSpec c = parse_case(text, kMemoryFile);
  EXPECT_EQ(c.curves.at("ramp").extension, Extension::RepeatOffset);
  EXPECT_EQ(c.curves.at("cycle").extension, Extension::Repeat);
  EXPECT_EQ(c.curves.at("cycle").interpolation, Interpolation::Next);
  EXPECT_EQ(c.curves.at("hold").extension, Extension::Constant);

  const std::string written = trifem::io::case_toml(c);
  EXPECT_NE(written.find("extend = \"repeat-offset\""), std::string::npos) << written;
  EXPECT_EQ(written.find("extend = \"constant\""), std::string::npos) << written; // default
  const CaseSpec again = parse_case(written, kMemoryFile);
  ASSERT_EQ(again.curves.size(), c.curves.size());
  for (const auto& [name, curve] : c.curves) {
    EXPECT_EQ(again.curves.at(name).extension, curve.extension) << name;
    EXPECT_EQ(again.curves.at(name).interpolation, curve.interpolation) << name;
    EXPECT_EQ(again.curves.at(name).points, curve.points) << name;
  }
}

TEST(CaseReader, WindowsLineEndingsAndByteOrderMarkAreAccepted) {
  std::string text = "\xEF\xBB\xBF";
  for (char ch : kBase)
    text += ch == '\n' ? std::string("\r\n") : std::string(1, ch);
  EXPECT_EQ(parse_case(text, kMemoryFile).boxes.size(), 1u);
}

// ---------------------------------------------------------------------------------------------
// Valid mixture input

TEST(CaseReader, TriphasicCaseMaterialsAndOptions) {
  const CaseSpec c = read_case(kData / "triphasic.toml");
  ASSERT_EQ(c.materials.size(), 2u);
  const MaterialSpec& cart = c.materials.at("cartilage");
  EXPECT_EQ(cart.type, "triphasic");
  EXPECT_TRUE(cart.is_mixture());
  ASSERT_TRUE(cart.solid.has_value());
  EXPECT_EQ(cart.solid->type, "saint-venant-kirchhoff");
  EXPECT_DOUBLE_EQ(cart.solid->parameters.at("E"), 0.3);
  EXPECT_DOUBLE_EQ(cart.solid->parameters.at("nu"), 0.0);
  EXPECT_EQ(cart.parameters.size(), 11u); // every key of the triphasic schema, defaults filled in
  EXPECT_DOUBLE_EQ(cart.parameters.at("phi_s0"), 0.25);
  EXPECT_DOUBLE_EQ(cart.parameters.at("permeability"), 1.07e-3);
  EXPECT_DOUBLE_EQ(cart.parameters.at("fixed_charge"), 2.0e-4);
  EXPECT_DOUBLE_EQ(cart.parameters.at("fixed_charge_basis"), 1.0); // "tissue"
  EXPECT_DOUBLE_EQ(cart.parameters.at("d_plus"), 5.0e-4);
  EXPECT_DOUBLE_EQ(cart.parameters.at("d_minus"), 8.0e-4);
  EXPECT_DOUBLE_EQ(cart.parameters.at("free_d_plus"), 0.0); // d0 = d: the paper's ions
  EXPECT_DOUBLE_EQ(cart.parameters.at("gamma_plus"), 0.9);
  EXPECT_DOUBLE_EQ(cart.parameters.at("gamma_minus"), 1.0); // default
  EXPECT_DOUBLE_EQ(cart.parameters.at("osmotic"), 0.95);

  const MaterialSpec& gel = c.materials.at("gel");
  EXPECT_EQ(gel.type, "biphasic");
  EXPECT_EQ(gel.parameters.size(), 2u); // phi_s0, permeability
  EXPECT_DOUBLE_EQ(gel.parameters.at("permeability"), 1e-2);
  ASSERT_TRUE(gel.solid.has_value());
  EXPECT_EQ(gel.solid->type, "neo-hookean");
  EXPECT_DOUBLE_EQ(gel.solid->parameters.at("nu"), 0.2);

  EXPECT_EQ(c.analysis.initial_state, InitialStateKind::DonnanPrestressed);
  EXPECT_EQ(c.analysis.fixed_charge_curve, "ramp");
  EXPECT_DOUBLE_EQ(c.electrochemistry.R, 8.3145);
  EXPECT_DOUBLE_EQ(c.electrochemistry.T, 310.0); // integer accepted
  EXPECT_DOUBLE_EQ(c.electrochemistry.faraday, 96.4853);
  EXPECT_DOUBLE_EQ(c.electrochemistry.bath_concentration, 1.0e-4);
  EXPECT_DOUBLE_EQ(c.electrochemistry.bath_activity, 0.8);
  EXPECT_DOUBLE_EQ(c.electrochemistry.bath_osmotic, 0.93);
}

TEST(CaseReader, TriphasicCaseBoundaryConditions) {
  const CaseSpec c = read_case(kData / "triphasic.toml");
  const std::vector<FieldKind> fluxes = {FieldKind::FluidFlux, FieldKind::CationFlux,
                                         FieldKind::AnionFlux};
  ASSERT_EQ(c.fixed.size(), 5u); // [[fixed]] x3, then [[impermeable]], then [[bonded]]
  EXPECT_EQ(c.fixed[0].fields, std::vector<FieldKind>{FieldKind::Displacement}); // default
  EXPECT_EQ(c.fixed[0].components, (std::vector<int>{0}));
  EXPECT_EQ(c.fixed[1].fields, fluxes); // "fluxes"
  EXPECT_EQ(c.fixed[1].components, (std::vector<int>{1}));
  EXPECT_EQ(c.fixed[2].fields, std::vector<FieldKind>{FieldKind::CationFlux});
  EXPECT_EQ(c.fixed[2].components, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(c.fixed[3].set, "block.xmin"); // impermeable, normal = "x"
  EXPECT_EQ(c.fixed[3].components, (std::vector<int>{0}));
  EXPECT_EQ(c.fixed[3].fields, fluxes);
  EXPECT_EQ(c.fixed[4].set, "block.zmin"); // bonded
  EXPECT_EQ(c.fixed[4].components, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(c.fixed[4].fields,
            (std::vector<FieldKind>{FieldKind::Displacement, FieldKind::FluidFlux,
                                    FieldKind::CationFlux, FieldKind::AnionFlux}));

  ASSERT_EQ(c.prescribed.size(), 3u);
  EXPECT_EQ(c.prescribed[0].field, FieldKind::Displacement); // default
  EXPECT_EQ(c.prescribed[0].curve, "ramp");
  EXPECT_EQ(c.prescribed[1].field, FieldKind::FluidFlux); // same set and component: no conflict
  EXPECT_EQ(c.prescribed[1].set, c.prescribed[0].set);
  EXPECT_EQ(c.prescribed[1].component, 2);
  EXPECT_DOUBLE_EQ(c.prescribed[1].value, 1e-4);
  EXPECT_EQ(c.prescribed[2].field, FieldKind::AnionFlux);
  EXPECT_EQ(c.prescribed[2].component, 1);
  EXPECT_DOUBLE_EQ(c.prescribed[2].value, -2e-6);
}

TEST(CaseReader, BathSurfaceIsRead) {
  const CaseSpec c = parse_case(kBase + kCartilage +
                                    "\n[[boundary.bath]]\nsurface = \"block.xmax\"\nconcentration "
                                    "= 1.5e-5\ncurve = \"ramp\"\n",
                                kMemoryFile);
  ASSERT_EQ(c.baths.size(), 1u);
  EXPECT_EQ(c.baths[0].surface, "block.xmax");
  EXPECT_DOUBLE_EQ(c.baths[0].concentration, 1.5e-5);
  EXPECT_EQ(c.baths[0].curve, "ramp");
}

TEST(CaseReader, ImpermeableSurfaceOfAnyOrientation) {
  const CaseSpec c = parse_case(
      kBase + kCartilage + "\n[[boundary.impermeable]]\nsurface = \"block.xmax\"\n", kMemoryFile);
  ASSERT_EQ(c.impermeable_surfaces.size(), 1u);
  EXPECT_EQ(c.impermeable_surfaces[0].surface, "block.xmax");
  EXPECT_EQ(c.impermeable_surfaces[0].key, "boundary.impermeable[1]");
}

TEST(CaseReader, ContactPairIsRead) {
  const CaseSpec c = parse_case(kBase + "\n[[contact]]\nmaster = \"a\"\nslave = \"b\"\n"
                                        "integration = \"slave-nodes\"\n",
                                kMemoryFile);
  ASSERT_EQ(c.contacts.size(), 1u);
  EXPECT_EQ(c.contacts[0].master, "a");
  EXPECT_EQ(c.contacts[0].slave, "b");
  EXPECT_FALSE(c.contacts[0].both_surfaces);
  EXPECT_EQ(c.contacts[0].key, "contact[1]");
}

TEST(CaseReader, ContactPairNeedsTwoSurfaces) {
  const std::string same = error_of(kBase + "\n[[contact]]\nmaster = \"a\"\nslave = \"a\"\n");
  EXPECT_NE(same.find("contact[1].slave"), std::string::npos) << same;
}

TEST(CaseReader, MixtureDefaults) {
  const CaseSpec c = parse_case(kBase + kCartilage, kMemoryFile);
  const MaterialSpec& cart = c.materials.at("cart");
  EXPECT_DOUBLE_EQ(cart.parameters.at("fixed_charge_basis"), 0.0); // "water"
  EXPECT_DOUBLE_EQ(cart.parameters.at("osmotic"), 1.0);
  EXPECT_FALSE(c.materials.at("soft").solid.has_value());
  EXPECT_FALSE(c.materials.at("soft").is_mixture());
  EXPECT_EQ(c.analysis.initial_state, InitialStateKind::Donnan);
  EXPECT_EQ(c.analysis.fixed_charge_curve, "");
  EXPECT_DOUBLE_EQ(c.electrochemistry.R, 8.314);
  EXPECT_DOUBLE_EQ(c.electrochemistry.T, 298.0);
  EXPECT_DOUBLE_EQ(c.electrochemistry.faraday, 96.485);
  EXPECT_DOUBLE_EQ(c.electrochemistry.bath_concentration, 1.5e-4);
  EXPECT_DOUBLE_EQ(c.electrochemistry.bath_activity, 1.0);
  EXPECT_DOUBLE_EQ(c.electrochemistry.bath_osmotic, 1.0);
}

TEST(CaseReader, WaterBasisAndEmptyOptionTables) {
  const std::string text = replaced_in(kBase + kCartilage, "phi_s0 = 0.2",
                                       "phi_s0 = 0.2\nfixed_charge_basis = \"water\"") +
                           "[analysis]\n[electrochemistry]\n";
  const CaseSpec c = parse_case(text, kMemoryFile);
  EXPECT_DOUBLE_EQ(c.materials.at("cart").parameters.at("fixed_charge_basis"), 0.0);
  EXPECT_EQ(c.analysis.initial_state, InitialStateKind::Donnan);
  EXPECT_DOUBLE_EQ(c.electrochemistry.T, 298.0);
}

TEST(CaseReader, FluxesOnABiphasicModelAndBondedOnASolidModel) {
  const CaseSpec bi = parse_case(
      kBase + kGel + "[[boundary.fixed]]\nset = \"block.zmin\"\nfield = \"fluxes\"\n", kMemoryFile);
  ASSERT_EQ(bi.fixed.size(), 1u);
  EXPECT_EQ(bi.fixed[0].fields.front(), FieldKind::FluidFlux); // ion fields: skipped by the model
  const CaseSpec solid =
      parse_case(kBase + "[[boundary.bonded]]\nset = \"block.zmin\"\n", kMemoryFile);
  ASSERT_EQ(solid.fixed.size(), 1u);
  EXPECT_EQ(solid.fixed[0].components, (std::vector<int>{0, 1, 2}));
}

TEST(CaseReader, PrescribedFluxOnAFixedDisplacementSetIsNoConflict) {
  const CaseSpec c = parse_case(kBase + kCartilage +
                                    "[[boundary.fixed]]\nset = \"block.zmax\"\n"
                                    "[[boundary.prescribed]]\nset = \"block.zmax\"\n"
                                    "field = \"fluid_flux\"\ncomponent = \"z\"\nvalue = 1e-3\n",
                                kMemoryFile);
  ASSERT_EQ(c.prescribed.size(), 1u);
  EXPECT_EQ(c.prescribed[0].field, FieldKind::FluidFlux);
}

// ---------------------------------------------------------------------------------------------
// Files that cannot be read as a case

TEST(CaseReader, MissingFile) {
  const fs::path file = kData / "no_such_case.toml";
  try {
    read_case(file);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind(file.string() + ": ", 0), 0u) << m;
    EXPECT_NE(m.find("cannot open the case file (No such file or directory)"), std::string::npos)
        << m;
  }
}

TEST(CaseReader, DirectoryInsteadOfFile) {
  try {
    read_case(kData);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("it is a directory"), std::string::npos) << e.what();
  }
}

TEST(CaseReader, EmptyFile) {
  const fs::path file = kData / "empty.toml";
  try {
    read_case(file);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), file.string() + ": the case file is empty");
  }
}

TEST(CaseReader, CommentsOnlyFileIsEmpty) {
  const fs::path file = kData / "comments_only.toml";
  try {
    read_case(file);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind(file.string() + ": the case file is empty", 0), 0u) << m;
  }
}

TEST(CaseReader, BinaryFileWithNulBytes) {
  const fs::path file = temp_file("nul.toml", std::string("title = \"x\"\n\0\0\x01\x02", 16));
  try {
    read_case(file);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              file.string() + ": not a text file (binary data found at byte 12); expected a "
                              "TOML case file");
  }
  fs::remove(file);
}

TEST(CaseReader, BinaryFileWithInvalidUtf8) {
  const fs::path file = temp_file("latin1.toml", "title = \"caf\xE9\"\n");
  try {
    read_case(file);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind(file.string() + ": not a text file (binary data found at byte 12)", 0), 0u)
        << m;
  }
  fs::remove(file);
}

// ---------------------------------------------------------------------------------------------
// Bad input: each case must fail with a message that starts with the file name and contains
// every listed fragment (the key path, the offending value, what was expected).

class BadInput : public testing::TestWithParam<BadCase> {};

TEST_P(BadInput, FailsNamingFileAndKey) {
  expect_fails_naming(GetParam());
}

const std::vector<BadCase> kBadCases = {
    {"unknown_top_level_key",
     kBase + "\n[Solver]\nmax_iterations = 3\n",
     {"Solver: unknown key (expected one of: title, mesh,", "did you mean 'solver'?", "(line 19)"}},
    {"unknown_nested_key",
     kBase + "\n[[mesh.box]]\nname = \"b\"\nsizes = [1, 1, 1]\ndivisions = [1, 1, 1]\n",
     {"mesh.box[2].sizes: unknown key (expected one of: name, origin, size, divisions, grading, "
      "cell, material); did you mean 'size'?"}},
    {"wrong_type",
     replaced("dt = 0.1", "dt = \"0.1\""),
     {"time.dt: expected a number, got a string (line 17)"}},
    {"negative_modulus",
     replaced("E = 1.0", "E = -1"),
     {"materials.soft.E = -1: out of range, expected a value in (0, inf) MPa (line 10)"}},
    {"unknown_material_type",
     replaced("neo-hookean", "neo-hooke"),
     {"materials.soft.type = 'neo-hooke': unknown material type", "did you mean 'neo-hookean'?"}},
    {"unknown_material_parameter",
     replaced("E = 1.0", "E = 1.0\nnu2 = 0.3"),
     {"materials.soft.nu2: unknown key (expected one of: type, E, nu)"}},
    {"material_parameter_not_a_number",
     replaced("E = 1.0", "E = \"stiff\""),
     {"materials.soft.E: expected a number, got a string"}},
    {"missing_material_parameter",
     replaced("E = 1.0", "nu = 0.3"),
     {"materials.soft.E: missing required parameter"}},
    {"undefined_curve",
     kBase + "[[boundary.prescribed]]\nset = \"block.zmax\"\ncomponent = \"z\"\nvalue = -0.1\n"
             "curve = \"rmap\"\n",
     {"boundary.prescribed[1].curve = 'rmap': undefined curve (defined: ramp)",
      "did you mean 'ramp'?"}},
    {"undefined_material",
     replaced("material = \"soft\"", "material = \"cartilage\""),
     {"mesh.box[1].material = 'cartilage': undefined material (defined: soft)"}},
    {"bad_component",
     kBase + "[[boundary.fixed]]\nset = \"block.zmin\"\ncomponents = [\"x\", \"w\"]\n",
     {"boundary.fixed[1].components[2] = 'w': unknown component (expected one of: x, y, z)"}},
    {"duplicate_component",
     kBase + "[[boundary.fixed]]\nset = \"block.zmin\"\ncomponents = [\"x\", \"x\"]\n",
     {"boundary.fixed[1].components[2] = 'x': duplicate component"}},
    {"empty_components",
     kBase + "[[boundary.fixed]]\nset = \"block.zmin\"\ncomponents = []\n",
     {"boundary.fixed[1].components: expected at least one of"}},
    {"dt_exceeds_end_time",
     replaced("dt = 0.1", "dt = 2.0"),
     {"time.dt = 2: out of range, expected a value in (0, 1] s (at most time.end_time)"}},
    {"non_increasing_curve_times",
     replaced("[[0, 0], [1, 1]]", "[[0, 0], [1, 1], [1, 2]]"),
     {"curves.ramp.points: times must increase strictly"}},
    {"curve_point_not_a_pair",
     replaced("[[0, 0], [1, 1]]", "[[0, 0], [1, 1, 2]]"),
     {"curves.ramp.points[2]: expected a [t, value] pair of numbers, got an array of 3"}},
    {"unknown_curve_extension",
     replaced("[[0, 0], [1, 1]]", "[[0, 0], [1, 1]]\nextend = \"periodic\""),
     {"curves.ramp.extend = 'periodic': unknown value (expected one of: constant, repeat, "
      "repeat-offset)",
      "(line 14)"}},
    {"syntax_error",
     replaced("dt = 0.1", "dt = = 0.1"),
     {"line 17, column", "TOML syntax error", "dt = = 0.1"}},
    {"duplicate_toml_key",
     replaced("dt = 0.1", "dt = 0.1\ndt = 0.2"),
     {"line 18, column", "TOML syntax error"}},
    {"duplicate_probe_name",
     kBase + "[[output.probe]]\nname = \"tip\"\npoint = [1, 1, 1]\n"
             "[[output.probe]]\nname = \"tip\"\npoint = [0, 0, 0]\n",
     {"output.probe[2].name = 'tip': duplicate probe name (already used by output.probe[1])"}},
    {"invalid_probe_name",
     kBase + "[[output.probe]]\nname = \"tip point\"\npoint = [1, 1, 1]\n",
     {"output.probe[1].name = 'tip point': invalid name"}},
    {"bad_probe_quantity",
     kBase + "[[output.probe]]\nname = \"tip\"\nquantity = \"pressure\"\npoint = [1, 1, 1]\n",
     {"output.probe[1].quantity = 'pressure': unknown quantity (expected one of: displacement, "
      "position, fluid_flux,",
      "fluid_pressure,", "current_density)"}},
    {"missing_required_key",
     replaced("size = [1, 1, 1]\n", ""),
     {"mesh.box[1].size: missing required key (expected an array of 3 numbers) (line 2)"}},
    {"non_positive_size",
     replaced("size = [1, 1, 1]", "size = [1, 0, 1]"),
     {"mesh.box[1].size[2] = 0: out of range, expected a value in (0, inf) mm"}},
    {"vector_of_wrong_length",
     replaced("size = [1, 1, 1]", "size = [1, 1]"),
     {"mesh.box[1].size: expected an array of 3 numbers, got an array of 2 element(s)"}},
    {"fractional_divisions",
     replaced("divisions = [2, 2, 2]", "divisions = [2, 2.5, 2]"),
     {"mesh.box[1].divisions[2]: expected an integer, got a floating-point number"}},
    {"zero_divisions",
     replaced("divisions = [2, 2, 2]", "divisions = [2, 0, 2]"),
     {"mesh.box[1].divisions[2] = 0: out of range, expected an integer >= 1"}},
    {"non_positive_grading",
     kBase + "[[mesh.box]]\nname = \"b\"\nsize = [1, 1, 1]\n"
             "divisions = [1, 1, 1]\ngrading = [1, -2, 1]\nmaterial = \"soft\"\n",
     {"mesh.box[2].grading[2] = -2: out of range"}},
    {"too_many_cells",
     replaced("divisions = [2, 2, 2]", "divisions = [2000, 2000, 2147483647]"),
     {"mesh.box[1].divisions: 2000 x 2000 x 2147483647 cells need", "more than the 2147483647"}},
    {"integer_out_of_range",
     replaced("divisions = [2, 2, 2]", "divisions = [2, 2, 3000000000]"),
     {"mesh.box[1].divisions[3]: 3000000000 is out of range for an integer"}},
    {"first_unknown_key_in_file_order",
     kBase + "[solver]\nzzz = 1\naaa = 2\n",
     {"solver.zzz: unknown key", "(line 19)"}},
    {"duplicate_box_name",
     kBase + "[[mesh.box]]\nname = \"block\"\nsize = [1, 1, 1]\ndivisions = [1, 1, 1]\n"
             "material = \"soft\"\n",
     {"mesh.box[2].name = 'block': duplicate box name (already used by mesh.box[1])"}},
    {"box_as_single_table",
     replaced("[[mesh.box]]", "[mesh.box]"),
     {"mesh.box: expected an array of tables (one [[mesh.box]] per entry), got a table"}},
    {"no_mesh",
     replaced("[[mesh.box]]\nname = \"block\"\nsize = [1, 1, 1]\ndivisions = [2, 2, 2]\n"
              "material = \"soft\"\n",
              ""),
     {"mesh: no mesh defined"}},
    {"missing_time_table",
     replaced("[time]\nend_time = 1.0\ndt = 0.1\n", ""),
     {"time: missing required table [time]"}},
    {"missing_gmsh_file",
     kBase + "[[mesh.gmsh]]\nfile = \"nowhere.msh\"\nmaterials = { v = \"soft\" }\n",
     {"mesh.gmsh[1].file = 'nowhere.msh': file not found (looked for '", "memory/nowhere.msh')"}},
    {"conflicting_constraints",
     kBase + "[[boundary.fixed]]\nset = \"block.zmax\"\n[[boundary.prescribed]]\nset = "
             "\"block.zmax\"\ncomponent = \"z\"\nvalue = 1\n",
     {"boundary.prescribed[1]: component z of node set 'block.zmax' is already constrained by "
      "boundary.fixed[1]"}},
    {"output_time_after_end",
     kBase + "[output]\ntimes = [0.5, 3.0]\n",
     {"output.times[2] = 3: out of range, expected a value in [0, 1] s"}},
    {"bad_linear_solver",
     kBase + "[solver]\nlinear_solver = \"pardiso\"\n",
     {"solver.linear_solver = 'pardiso': unknown value (expected one of: auto, umfpack, sparselu, "
      "mumps, krylov)"}},
    {"reuse_without_mumps",
     kBase + "[solver]\nlinear_solver = \"umfpack\"\nreuse_factorization = true\n",
     {"solver.reuse_factorization", "applies to linear_solver = \"mumps\"", "umfpack"}},
    {"preconditioner_without_krylov",
     kBase + "[solver]\nlinear_solver = \"mumps\"\npreconditioner = \"amg\"\n",
     {"solver.preconditioner", "applies to linear_solver = \"krylov\"", "mumps"}},
    {"precision_without_reuse",
     kBase + "[solver]\nlinear_solver = \"umfpack\"\nfactorization_precision = \"double\"\n",
     {"solver.factorization_precision", "applies to reused factorizations"}},
    {"unknown_precision",
     kBase + "[solver]\nfactorization_precision = \"half\"\n",
     {"solver.factorization_precision = 'half': unknown value (expected one of: single, "
      "double)"}},
    {"schur_without_krylov",
     kBase + "[solver]\nlinear_solver = \"mumps\"\nschur_approximation = \"drained\"\n",
     {"solver.schur_approximation", "applies to linear_solver = \"krylov\"", "mumps"}},
    {"unknown_schur_approximation",
     kBase + "[solver]\nlinear_solver = \"krylov\"\nschur_approximation = \"lsc\"\n",
     {"solver.schur_approximation = 'lsc': unknown value (expected one of: selfp, drained)"}},
    {"unknown_preconditioner",
     kBase + "[solver]\nlinear_solver = \"krylov\"\npreconditioner = \"ilu\"\n",
     {"solver.preconditioner = 'ilu': unknown value (expected one of: lu, amg)"}},
    {"tolerance_out_of_range",
     kBase + "[solver]\nresidual_tolerance = 1.5\n",
     {"solver.residual_tolerance = 1.5: out of range, expected a value in (0, 1)"}},
    {"zero_max_iterations",
     kBase + "[solver]\nmax_iterations = 0\n",
     {"solver.max_iterations = 0: out of range, expected an integer >= 1"}},
    {"boolean_expected",
     kBase + "[output]\nvtu = \"yes\"\n",
     {"output.vtu: expected a boolean (true or false), got a string"}},
    {"cutback_out_of_range",
     replaced("dt = 0.1", "dt = 0.1\ncutback = 1"),
     {"time.cutback = 1: out of range, expected a value in (0, 1)"}},
    {"dt_min_above_dt",
     replaced("dt = 0.1", "dt = 0.1\ndt_min = 0.5"),
     {"time.dt_min = 0.5: out of range"}},
    {"empty_set_name",
     kBase + "[[boundary.fixed]]\nset = \"\"\n",
     {"boundary.fixed[1].set: expected a non-empty string"}},
    {"not_finite",
     replaced("E = 1.0", "E = nan"),
     {"materials.soft.E: expected a finite number, got nan"}},
    {"section_not_a_table",
     "curves = 5\n" + replaced("[curves.ramp]\npoints = [[0, 0], [1, 1]]\n", ""),
     {"curves: expected a table [curves], got an integer (line 1)"}},
    {"material_entry_not_a_table",
     replaced("[materials.soft]", "[materials]\nhard = 3\n[materials.soft]"),
     {"materials.hard: expected a table [materials.hard], got an integer"}},
};

INSTANTIATE_TEST_SUITE_P(CaseReader, BadInput, testing::ValuesIn(kBadCases), bad_case_name);

/// kBase + kCartilage with `from` replaced by `to`.
std::string cartilage_with(const std::string& from, const std::string& to) {
  return replaced_in(kBase + kCartilage, from, to);
}

/// kBase + kGel with `from` replaced by `to`.
std::string gel_with(const std::string& from, const std::string& to) {
  return replaced_in(kBase + kGel, from, to);
}

const std::string kSolidTable = "\n[materials.cart.solid]\ntype = \"neo-hookean\"\nE = 1.0\n";

const std::vector<BadCase> kMixtureBadCases = {
    {"bath_without_ions",
     kBase + kGel + "\n[[boundary.bath]]\nsurface = \"block.xmax\"\nconcentration = 1e-5\n",
     {"boundary.bath[1].concentration", "a bath concentration needs a triphasic material"}},
    {"bath_zero_concentration",
     kBase + kCartilage + "\n[[boundary.bath]]\nsurface = \"block.xmax\"\nconcentration = 0.0\n",
     {"boundary.bath[1].concentration = 0", "out of range"}},
    {"mixture_without_solid",
     cartilage_with(kSolidTable, ""),
     {"materials.cart.solid: missing required table [materials.cart.solid]",
      "solid matrix of a triphasic material", "(line 19)"}},
    {"solid_table_on_solid_law",
     kBase + "[materials.soft.solid]\ntype = \"neo-hookean\"\nE = 1\n",
     {"materials.soft.solid: only biphasic and triphasic materials have a [solid] sub-table",
      "materials.soft.type = 'neo-hookean' is a solid law", "(line 18)"}},
    {"solid_table_not_a_table",
     cartilage_with(kSolidTable, "solid = \"neo-hookean\"\n"),
     {"materials.cart.solid: expected a table [materials.cart.solid], got a string (line 26)"}},
    {"unknown_mixture_key",
     cartilage_with("phi_s0 = 0.2", "phi_s0 = 0.2\nporosity = 0.8"),
     {"materials.cart.porosity: unknown key (expected one of: type, solid, phi_s0, permeability, "
      "fixed_charge, fixed_charge_basis, d_plus, d_minus, free_d_plus, free_d_minus, gamma_plus, "
      "gamma_minus, osmotic, axes, density) (line 22)"}},
    {"misspelt_mixture_key",
     cartilage_with("permeability", "permeabilty"),
     {"materials.cart.permeabilty: unknown key", "did you mean 'permeability'?"}},
    {"triphasic_key_on_biphasic",
     gel_with("phi_s0 = 0.2", "phi_s0 = 0.2\nd_plus = 5e-4"),
     {"materials.gel.d_plus: only applies to triphasic materials (materials.gel.type = "
      "'biphasic' has no fixed charge and no ions) (line 22)"}},
    {"unknown_fixed_charge_basis",
     cartilage_with("phi_s0 = 0.2", "phi_s0 = 0.2\nfixed_charge_basis = \"tisue\""),
     {"materials.cart.fixed_charge_basis = 'tisue': unknown basis (expected one of: water, "
      "tissue); did you mean 'tissue'? (line 22)"}},
    {"numeric_fixed_charge_basis",
     cartilage_with("phi_s0 = 0.2", "phi_s0 = 0.2\nfixed_charge_basis = 1"),
     {"materials.cart.fixed_charge_basis: expected a string, got an integer"}},
    {"volume_fraction_out_of_range",
     cartilage_with("phi_s0 = 0.2", "phi_s0 = 1.2"),
     {"materials.cart.phi_s0 = 1.2: out of range, expected a value in [0, 1) (line 21)"}},
    {"negative_fixed_charge",
     cartilage_with("fixed_charge = 2e-4", "fixed_charge = -2e-4"),
     {"materials.cart.fixed_charge = -0.0002: out of range, expected a value in [0, 1] "
      "mEq/mm^3"}},
    {"missing_mixture_parameter",
     cartilage_with("d_plus = 5e-4\n", ""),
     {"materials.cart.d_plus: missing required parameter (cation (Na+) diffusivity, mm^2/s)"}},
    {"unknown_permeability_law",
     cartilage_with("permeability = 1e-3", "permeability = { type = \"holmes_mow\", k0 = 1e-3 }"),
     {"materials.cart.permeability.type = 'holmes_mow': unknown permeability law (expected one "
      "of: constant, holmes-mow, exponential); did you mean 'holmes-mow'? (line 22)"}},
    {"unknown_diffusivity_law",
     cartilage_with("d_plus = 5e-4", "d_plus = { type = \"mackie\", d0 = 1.33e-3 }"),
     {"materials.cart.d_plus.type = 'mackie': unknown diffusivity law (expected one of: "
      "constant, mackie-meares)"}},
    {"unknown_permeability_law_key",
     cartilage_with("permeability = 1e-3",
                    "permeability = { type = \"holmes-mow\", k0 = 1e-3, beta = 2 }"),
     {"materials.cart.permeability.beta: unknown key (expected one of: type, k0, M, alpha) "
      "(line 22)"}},
    {"law_without_type",
     cartilage_with("d_plus = 5e-4", "d_plus = { d0 = 1.33e-3 }"),
     {"materials.cart.d_plus.type: missing required key (expected one of: constant, "
      "mackie-meares)"}},
    {"law_without_required_parameter",
     cartilage_with("d_minus = 8e-4", "d_minus = { type = \"mackie-meares\" }"),
     {"materials.cart.d_minus.d0: missing required parameter (diffusivity in free solution, "
      "mm^2/s)"}},
    {"law_parameter_out_of_range",
     cartilage_with("permeability = 1e-3\n", "") +
         "\n[materials.cart.permeability]\ntype = \"exponential\"\nk0 = 1e-3\nM = -1\n",
     {"materials.cart.permeability.M = -1: out of range, expected a value in [0, inf) (line 33)"}},
    {"law_given_as_string",
     cartilage_with("permeability = 1e-3", "permeability = \"holmes-mow\""),
     {"materials.cart.permeability: expected a number in (0, inf) mm^4/(N s) (constant) or a "
      "table with a type (a law of the deformation), got a string (line 22)"}},
    {"law_on_a_key_without_laws",
     cartilage_with("phi_s0 = 0.2", "phi_s0 = { type = \"constant\", d = 0.2 }"),
     {"materials.cart.phi_s0: expected a number, got a table"}},
    {"diffusivity_law_on_biphasic",
     gel_with("phi_s0 = 0.2", "phi_s0 = 0.2\nd_plus = { type = \"mackie-meares\", d0 = 1e-3 }"),
     {"materials.gel.d_plus: only applies to triphasic materials"}},
    {"mixture_as_solid_law",
     cartilage_with(kSolidTable, replaced_in(kSolidTable, "neo-hookean", "biphasic")),
     {"materials.cart.solid.type = 'biphasic': unknown solid law (expected one of:", "(line 28)"}},
    {"unknown_solid_parameter",
     cartilage_with(kSolidTable, kSolidTable + "mu = 0.3\n"),
     {"materials.cart.solid.mu: unknown key (expected one of: type, E, nu)"}},
    {"missing_solid_parameter",
     cartilage_with(kSolidTable, replaced_in(kSolidTable, "E = 1.0", "nu = 0.3")),
     {"materials.cart.solid.E: missing required parameter"}},
    {"ion_field_without_triphasic",
     kBase + kGel +
         "[[boundary.fixed]]\nset = \"a\"\n[[boundary.fixed]]\nset = \"b\"\n"
         "field = \"cation_flux\"\n",
     {"boundary.fixed[2].field = 'cation_flux': the model has no ion fields (no triphasic "
      "material) (line 31)"}},
    {"fluid_flux_without_mixture",
     kBase + "[[boundary.fixed]]\nset = \"b\"\nfield = \"fluid_flux\"\n",
     {"boundary.fixed[1].field = 'fluid_flux': the model has no flux fields (no biphasic or "
      "triphasic material) (line 20)"}},
    {"fluxes_without_mixture",
     kBase + "[[boundary.fixed]]\nset = \"b\"\nfield = \"fluxes\"\n",
     {"boundary.fixed[1].field = 'fluxes': the model has no flux fields"}},
    {"prescribed_ion_flux_without_triphasic",
     kBase + kGel +
         "[[boundary.prescribed]]\nset = \"b\"\nfield = \"anion_flux\"\n"
         "component = \"x\"\nvalue = 1\n",
     {"boundary.prescribed[1].field = 'anion_flux': the model has no ion fields"}},
    {"fluxes_cannot_be_prescribed",
     kBase + kCartilage +
         "[[boundary.prescribed]]\nset = \"b\"\nfield = \"fluxes\"\n"
         "component = \"x\"\nvalue = 1\n",
     {"boundary.prescribed[1].field = 'fluxes': unknown field (expected one of: displacement, "
      "fluid_flux, cation_flux, anion_flux)"}},
    {"unknown_field",
     kBase + kCartilage + "[[boundary.fixed]]\nset = \"b\"\nfield = \"fluid-flux\"\n",
     {"boundary.fixed[1].field = 'fluid-flux': unknown field (expected one of: displacement, "
      "fluid_flux, cation_flux, anion_flux, fluxes); did you mean 'fluid_flux'?"}},
    {"impermeable_without_mixture",
     kBase + "[[boundary.impermeable]]\nset = \"block.zmin\"\nnormal = \"z\"\n",
     {"boundary.impermeable[1]: the model has no flux fields (no biphasic or triphasic material) "
      "(line 18)"}},
    {"impermeable_without_normal",
     kBase + kCartilage + "[[boundary.impermeable]]\nset = \"block.zmin\"\n",
     {"boundary.impermeable[1].normal: missing required key (expected one of: x, y, z)"}},
    {"impermeable_bad_normal",
     kBase + kCartilage + "[[boundary.impermeable]]\nset = \"block.zmin\"\nnormal = \"n\"\n",
     {"boundary.impermeable[1].normal = 'n': unknown axis (expected one of: x, y, z)"}},
    {"impermeable_with_components",
     kBase + kCartilage +
         "[[boundary.impermeable]]\nset = \"s\"\nnormal = \"z\"\n"
         "components = [\"z\"]\n",
     {"boundary.impermeable[1].components: unknown key (expected one of: set, normal)"}},
    {"bonded_with_field",
     kBase + kCartilage + "[[boundary.bonded]]\nset = \"s\"\nfield = \"fluxes\"\n",
     {"boundary.bonded[1].field: unknown key (expected one of: set)"}},
    {"prescribed_flux_on_bonded_set",
     kBase + kCartilage +
         "[[boundary.bonded]]\nset = \"s\"\n[[boundary.prescribed]]\n"
         "set = \"s\"\nfield = \"anion_flux\"\ncomponent = \"y\"\nvalue = 1\n",
     {"boundary.prescribed[1]: anion_flux component y of node set 's' is already constrained by "
      "boundary.bonded[1]"}},
    {"prescribed_flux_on_impermeable_face",
     kBase + kCartilage +
         "[[boundary.fixed]]\nset = \"a\"\n[[boundary.impermeable]]\n"
         "set = \"s\"\nnormal = \"y\"\n[[boundary.prescribed]]\nset = \"s\"\n"
         "field = \"fluid_flux\"\ncomponent = \"y\"\nvalue = 1\n",
     {"boundary.prescribed[1]: fluid_flux component y of node set 's' is already constrained by "
      "boundary.impermeable[1]"}},
    {"prescribed_flux_on_fixed_fluxes",
     kBase + kCartilage +
         "[[boundary.fixed]]\nset = \"s\"\nfield = \"fluxes\"\n"
         "[[boundary.prescribed]]\nset = \"s\"\nfield = \"cation_flux\"\n"
         "component = \"x\"\nvalue = 1\n",
     {"boundary.prescribed[1]: cation_flux component x of node set 's' is already constrained by "
      "boundary.fixed[1]"}},
    {"flux_prescribed_twice",
     kBase + kCartilage +
         "[[boundary.prescribed]]\nset = \"s\"\nfield = \"fluid_flux\"\n"
         "component = \"x\"\nvalue = 1\n[[boundary.prescribed]]\nset = \"s\"\n"
         "field = \"fluid_flux\"\ncomponent = \"x\"\nvalue = 2\n",
     {"boundary.prescribed[2]: fluid_flux component x of node set 's' is already constrained by "
      "boundary.prescribed[1]"}},
    {"analysis_without_mixture",
     kBase + "[analysis]\ninitial_state = \"donnan\"\n",
     {"analysis: only applies to biphasic/triphasic materials", "(line 18)"}},
    {"electrochemistry_without_mixture",
     kBase + "[electrochemistry]\nT = 300\n",
     {"electrochemistry: only applies to biphasic/triphasic materials", "(line 18)"}},
    {"unknown_initial_state",
     kBase + kCartilage + "[analysis]\ninitial_state = \"donan\"\n",
     {"analysis.initial_state = 'donan': unknown initial state (expected one of: donnan, "
      "donnan-prestressed); did you mean 'donnan'? (line 31)"}},
    {"unknown_flux_mass",
     kBase + kCartilage + "[analysis]\nflux_mass = \"lump\"\n",
     {"analysis.flux_mass = 'lump': unknown flux mass (expected one of: consistent, lumped); did "
      "you mean 'lumped'? (line 31)"}},
    {"undefined_fixed_charge_curve",
     kBase + kCartilage + "[analysis]\nfixed_charge_curve = \"rmp\"\n",
     {"analysis.fixed_charge_curve = 'rmp': undefined curve (defined: ramp); did you mean "
      "'ramp'?"}},
    {"fixed_charge_curve_without_triphasic",
     kBase + kGel + "[analysis]\nfixed_charge_curve = \"ramp\"\n",
     {"analysis.fixed_charge_curve = 'ramp': only applies to triphasic materials"}},
    {"unknown_analysis_key",
     kBase + kCartilage + "[analysis]\ninitial = \"donnan\"\n",
     {"analysis.initial: unknown key (expected one of: initial_state, fixed_charge_curve, "
      "flux_mass)"}},
    {"non_positive_temperature",
     kBase + kCartilage + "[electrochemistry]\nT = -1\n",
     {"electrochemistry.T = -1: out of range, expected a value in (0, inf) K (line 31)"}},
    {"zero_bath_concentration",
     kBase + kCartilage + "[electrochemistry]\nbath_concentration = 0\n",
     {"electrochemistry.bath_concentration = 0: out of range, expected a value in (0, inf) "
      "mmol/mm^3"}},
    {"unknown_electrochemistry_key",
     kBase + kCartilage + "[electrochemistry]\ntemperature = 300\n",
     {"electrochemistry.temperature: unknown key (expected one of: R, T, faraday, "
      "bath_concentration, bath_activity, bath_osmotic)"}},
};

INSTANTIATE_TEST_SUITE_P(Mixture, BadInput, testing::ValuesIn(kMixtureBadCases), bad_case_name);

/// Strain-dependent laws: permeability as a sub-table, d_plus as an inline table (defaults of
/// the laws filled in), d_minus as a number (constant law).
TEST(CaseReader, TransportLawsAsTables) {
  const std::string text =
      cartilage_with("permeability = 1e-3\nfixed_charge = 2e-4\nd_plus = 5e-4",
                     "fixed_charge = 2e-4\nd_plus = { type = \"mackie-meares\", d0 = 1.33e-3 }") +
      "\n[materials.cart.permeability]\ntype = \"holmes-mow\"\nk0 = 1e-3\nM = 4.6\n";
  const CaseSpec c = parse_case(text, kMemoryFile);
  const MaterialSpec& cart = c.materials.at("cart");
  EXPECT_EQ(cart.parameters.count("permeability"), 0u);
  EXPECT_EQ(cart.parameters.count("d_plus"), 0u);
  EXPECT_DOUBLE_EQ(cart.parameters.at("permeability.holmes-mow.k0"), 1e-3);
  EXPECT_DOUBLE_EQ(cart.parameters.at("permeability.holmes-mow.M"), 4.6);
  EXPECT_DOUBLE_EQ(cart.parameters.at("permeability.holmes-mow.alpha"), 0.0); // default
  EXPECT_DOUBLE_EQ(cart.parameters.at("d_plus.mackie-meares.d0"), 1.33e-3);
  EXPECT_DOUBLE_EQ(cart.parameters.at("d_minus"), 8e-4);
  EXPECT_TRUE(c.warnings.empty());
  const CaseSpec gel = parse_case(
      gel_with("permeability = 1e-3", "permeability = { type = \"exponential\", k0 = 2e-3 }"),
      kMemoryFile);
  EXPECT_DOUBLE_EQ(gel.materials.at("gel").parameters.at("permeability.exponential.M"), 0.0);
}

TEST(CaseReader, SyntaxErrorQuotesTheLineWithACaret) {
  const std::string m = error_of("title = \"x\"\n[time]\nend_time = 1.0\ndt = \n");
  EXPECT_NE(m.find("memory/case.toml: line 4, column"), std::string::npos) << m;
  EXPECT_NE(m.find("     4 | dt = \n"), std::string::npos) << m;
  EXPECT_NE(m.find("^"), std::string::npos) << m;
}

TEST(CaseReader, GmshPathIsResolvedAgainstTheCaseDirectory) {
  const std::string text =
      replaced("[[mesh.box]]", "[[mesh.gmsh]]\nfile = \"part.msh\"\nmaterials = { v = \"soft\" }\n"
                               "[[mesh.box]]");
  const CaseSpec c = parse_case(text, kData / "virtual.toml");
  ASSERT_EQ(c.gmsh.size(), 1u);
  EXPECT_EQ(c.gmsh[0].file, fs::absolute(kData / "part.msh").lexically_normal());
  EXPECT_EQ(c.gmsh[0].materials.at("v"), "soft");
}

/// The TOML block that follows the heading `## <heading>` in docs/input.md ("" if none).
std::string documented_example(const std::string& heading) {
  std::ifstream in(kInputDoc);
  EXPECT_TRUE(in) << kInputDoc;
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string fence = "## " + heading + "\n\n";
  const auto begin = text.find(fence);
  const auto body = text.find("```toml\n", begin);
  EXPECT_NE(begin, std::string::npos) << heading;
  if (begin == std::string::npos || body == std::string::npos)
    return "";
  const auto end = text.find("```", body + 8);
  EXPECT_NE(end, std::string::npos);
  return text.substr(body + 8, end - body - 8);
}

TEST(CaseReader, DocumentedExampleParses) {
  const CaseSpec c = parse_case(documented_example("Complete annotated example"), kInputDoc);
  EXPECT_EQ(c.boxes.size(), 1u);
  EXPECT_EQ(c.materials.size(), 2u);
  EXPECT_EQ(c.fixed.size(), 2u);
  EXPECT_EQ(c.prescribed.size(), 1u);
  EXPECT_EQ(c.output.probes.size(), 1u);
  EXPECT_DOUBLE_EQ(c.time.dt_min, 1e-7);
}

TEST(CaseReader, DocumentedTriphasicExampleParses) {
  const CaseSpec c = parse_case(documented_example("Complete triphasic example"), kInputDoc);
  ASSERT_EQ(c.materials.size(), 1u);
  EXPECT_EQ(c.materials.at("cartilage").type, "triphasic");
  EXPECT_EQ(c.materials.at("cartilage").solid->type, "saint-venant-kirchhoff");
  EXPECT_EQ(c.analysis.fixed_charge_curve, "charge");
  EXPECT_DOUBLE_EQ(c.electrochemistry.bath_concentration, 1.5e-4);
  EXPECT_EQ(c.fixed.size(), 9u); // 6 fixed + 2 impermeable + 1 bonded
  EXPECT_EQ(c.prescribed.size(), 1u);
}

// ---------------------------------------------------------------------------------------------
// Limits on the work a case implies (steps, output times, model size), denormal numbers

const std::vector<BadCase> kLimitCases = {
    {"output_interval_too_small",
     kBase + "[output]\ninterval = 1e-300\n",
     {"output.interval = 1e-300: time.end_time / output.interval = 1e+300 output times, more "
      "than the 1e+06 allowed",
      "(line 19)"}},
    {"end_time_too_long_for_the_interval",
     replaced("end_time = 1.0\ndt = 0.1", "end_time = 1e7\ndt = 0.1\ndt_max = 1e6") +
         "[output]\ninterval = 1.0\n",
     {"output.interval = 1: time.end_time / output.interval = 1e+07 output times"}},
    {"denormal_end_time_and_dt",
     replaced("end_time = 1.0\ndt = 0.1", "end_time = 1e-320\ndt = 1e-320"),
     {"time.end_time: expected 0 or a number of magnitude at least 2.22507e-308 (the smallest "
      "normal double), got 1e-320 (line 16)"}},
    {"denormal_modulus",
     replaced("E = 1.0", "E = 4.9e-324"),
     {"materials.soft.E: expected 0 or a number of magnitude at least"}},
    {"end_time_below_the_time_resolution",
     replaced("end_time = 1.0\ndt = 0.1", "end_time = 1e-11\ndt = 1e-11"),
     {"time.end_time = 1e-11: out of range, expected a value in [1e-08, inf) s (the step control "
      "resolves times to 1e-10 s)"}},
    {"too_many_steps",
     replaced("dt = 0.1", "dt = 1e-301"),
     {"time.end_time = 1: with time.dt = 1e-301 s the run needs at least 1e+301 steps, more than "
      "the 1e+08 allowed"}},
    {"too_many_steps_with_slow_growth",
     replaced("dt = 0.1", "dt = 1e-300\ndt_max = 1.0\ngrowth = 1.0000001"),
     {"time.end_time = 1: with time.dt = 1e-300 s, time.dt_max = 1 s the run needs at least",
      "steps, more than the 1e+08 allowed"}},
    {"repeating_curve_with_too_many_periods",
     replaced("[[0, 0], [1, 1]]", "[[0, 0], [1e-7, 1]]\nextend = \"repeat\""),
     {"times the steps must land on", "in every period of a repeating one", "1e+06 allowed"}},
    {"too_many_cutbacks",
     replaced("dt = 0.1", "dt = 0.1\ncutback = 0.999999"),
     {"time.cutback = 0.999999: a failed step would be cut back 1.38e+07 times",
      "more than the 200 allowed"}},
    {"too_many_newton_iterations",
     kBase + "[solver]\nmax_iterations = 2147483647\n",
     {"solver.max_iterations = 2147483647: out of range, expected an integer >= 1 and <= 1000"}},
    {"too_many_equations",
     replaced("divisions = [2, 2, 2]", "divisions = [1000, 1000, 1000]"),
     {"mesh.box[1].divisions: the boxes make a model of 1.003e+09 nodes and 1e+09 cells, about "
      "3.009e+09 equations, more than the 2147483647 a model can have (line 5)"}},
    {"model_larger_than_the_memory",
     replaced("divisions = [2, 2, 2]", "divisions = [600, 600, 600]"),
     {"mesh.box[1].divisions: the boxes make a model of 2.171e+08 nodes", "a run needs at least",
      "GB of memory", "of this machine (line 5)"}},
    {"triphasic_model_larger_than_the_memory",
     replaced_in(kBase + kCartilage, "divisions = [2, 2, 2]\nmaterial = \"soft\"",
                 "divisions = [300, 300, 300]\nmaterial = \"cart\""),
     {"2.727e+07 nodes and 2.7e+07 cells, about 3.813e+08 equations; a run needs at least"}},
};

INSTANTIATE_TEST_SUITE_P(Limits, BadInput, testing::ValuesIn(kLimitCases), bad_case_name);

TEST(CaseReader, LongRunsWithinTheLimitsAreAccepted) {
  const CaseSpec c =
      parse_case(replaced("end_time = 1.0\ndt = 0.1", "end_time = 1e6\ndt = 1e-6\ndt_max = 100.0") +
                     "[output]\ninterval = 10.0\n",
                 kMemoryFile);
  EXPECT_DOUBLE_EQ(c.time.end_time, 1e6);
  EXPECT_DOUBLE_EQ(c.output.interval, 10.0);
  const CaseSpec zero = parse_case(replaced("E = 1.0", "E = 1.0\nnu = 0"), kMemoryFile);
  EXPECT_EQ(zero.materials.at("soft").parameters.at("nu"), 0.0); // 0 is not a denormal
}

// ---------------------------------------------------------------------------------------------
// Implausible values: a warning naming the key, its unit and the value probably meant

/// The warnings of reading `text` (which must be valid).
std::vector<std::string> warnings_of(const std::string& text) {
  return parse_case(text, kMemoryFile).warnings;
}

/// Expects exactly one warning, containing every fragment.
void expect_one_warning(const std::string& text, const std::vector<std::string>& fragments) {
  const std::vector<std::string> w = warnings_of(text);
  ASSERT_EQ(w.size(), 1u) << testing::PrintToString(w);
  for (const auto& fragment : fragments)
    EXPECT_NE(w[0].find(fragment), std::string::npos) << "'" << fragment << "' not in: " << w[0];
}

TEST(CaseReaderWarnings, MolarBathConcentration) {
  expect_one_warning(kBase + kCartilage + "[electrochemistry]\nbath_concentration = 0.15\n",
                     {"electrochemistry.bath_concentration = 0.15 mmol/mm^3 is far outside the "
                      "range of soft tissues (1e-07 to 0.01 mmol/mm^3); if it is in M (mol/L), "
                      "write 0.00015 (line 31)"});
}

TEST(CaseReaderWarnings, MillimolarBathOfASurface) {
  expect_one_warning(
      kBase + kCartilage + "[[boundary.bath]]\nsurface = \"block.xmax\"\nconcentration = 150\n",
      {"boundary.bath[1].concentration = 150 mmol/mm^3", "if it is in mM (mmol/L), write "
                                                         "0.00015"});
}

TEST(CaseReaderWarnings, MixtureParametersInOtherUnits) {
  expect_one_warning(cartilage_with("fixed_charge = 2e-4", "fixed_charge = 0.2"),
                     {"materials.cart.fixed_charge = 0.2 mEq/mm^3", "in mEq/mL, write 0.0002"});
  expect_one_warning(
      cartilage_with("permeability = 1e-3", "permeability = 1e-15"),
      {"materials.cart.permeability = 1e-15 mm^4/(N s)", "in m^4/(N s), write 0.001"});
  expect_one_warning(cartilage_with("d_plus = 5e-4", "d_plus = 5e-10"),
                     {"materials.cart.d_plus = 5e-10 mm^2/s", "in m^2/s, write 0.0005"});
  expect_one_warning(
      cartilage_with("permeability = 1e-3", "permeability = { type = \"holmes-mow\", k0 = 1e-15 }"),
      {"materials.cart.permeability.k0 = 1e-15 mm^4/(N s)", "in m^4/(N s), write 0.001"});
  expect_one_warning(cartilage_with("d_minus = 8e-4", "d_minus = { type = \"mackie-meares\", "
                                                      "d0 = 2e-9 }"),
                     {"materials.cart.d_minus.d0 = 2e-09 mm^2/s", "in m^2/s, write 0.002"});
}

TEST(CaseReaderWarnings, ModulusInPascalAndSizeInMetres) {
  expect_one_warning(replaced("E = 1.0", "E = 300000"),
                     {"materials.soft.E = 300000 MPa", "if it is in Pa, write 0.3 (line 10)"});
  expect_one_warning(cartilage_with("[materials.cart.solid]\ntype = \"neo-hookean\"\nE = 1.0",
                                    "[materials.cart.solid]\ntype = \"neo-hookean\"\nE = 1e-7"),
                     {"materials.cart.solid.E = 1e-07 MPa"});
  expect_one_warning(replaced("size = [1, 1, 1]", "size = [1, 2e5, 1]"),
                     {"mesh.box[1].size[2] = 200000 mm is far outside the range of soft tissues "
                      "(0.0001 to 10000 mm) (line 4)"});
}

TEST(CaseReaderWarnings, PlausibleValuesGiveNoWarning) {
  EXPECT_TRUE(warnings_of(kBase + kCartilage + kGel).empty());
  EXPECT_TRUE(warnings_of(cartilage_with("fixed_charge = 2e-4", "fixed_charge = 0")).empty());
  for (const auto& dir : fs::directory_iterator(fs::path(TRIFEM_SOURCE_DIR) / "examples")) {
    if (!dir.is_directory())
      continue;
    for (const auto& file : fs::directory_iterator(dir.path())) {
      if (file.path().extension() == ".toml") {
        EXPECT_TRUE(read_case(file.path()).warnings.empty()) << file.path();
      }
    }
  }
  EXPECT_TRUE(
      parse_case(documented_example("Complete annotated example"), kInputDoc).warnings.empty());
  EXPECT_TRUE(
      parse_case(documented_example("Complete triphasic example"), kInputDoc).warnings.empty());
}
