// SPDX-License-Identifier: MIT
// Tests of the TOML case reader: a complete case, defaults, and one test per kind of bad input.
#include "trifem/core/error.hpp"
#include "trifem/io/case_reader.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using trifem::InputError;
using trifem::Real;
using trifem::dofs::Interpolation;
using trifem::io::CaseSpec;
using trifem::io::parse_case;
using trifem::io::read_case;

namespace {

const fs::path kData = TRIFEM_TEST_DATA_DIR;
/// Name under which in-memory cases are parsed.
const fs::path kMemoryFile = "memory/case.toml";

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

/// kBase with the first occurrence of `from` replaced by `to` (which must exist).
std::string replaced(const std::string& from, const std::string& to) {
  std::string text = kBase;
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "'" << from << "' is not in the base case";
  if (at != std::string::npos)
    text.replace(at, from.size(), to);
  return text;
}

/// The message of the InputError that reading `text` throws ("" if none).
std::string error_of(const std::string& text, const fs::path& file = kMemoryFile) {
  try {
    parse_case(text, file);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
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
  EXPECT_EQ(c.solver.linear_solver, "sparselu");

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
  EXPECT_EQ(c.solver.linear_solver, "umfpack");
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

TEST(CaseReader, WindowsLineEndingsAndByteOrderMarkAreAccepted) {
  std::string text = "\xEF\xBB\xBF";
  for (char ch : kBase)
    text += ch == '\n' ? std::string("\r\n") : std::string(1, ch);
  EXPECT_EQ(parse_case(text, kMemoryFile).boxes.size(), 1u);
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

struct BadCase {
  std::string name;
  std::string text;
  std::vector<std::string> fragments;
};

void PrintTo(const BadCase& c, std::ostream* os) {
  *os << c.name;
}

class BadInput : public testing::TestWithParam<BadCase> {};

TEST_P(BadInput, FailsNamingFileAndKey) {
  const BadCase& c = GetParam();
  const std::string m = error_of(c.text);
  ASSERT_FALSE(m.empty()) << "no InputError for " << c.name;
  EXPECT_EQ(m.rfind(kMemoryFile.string() + ": ", 0), 0u) << m;
  for (const auto& fragment : c.fragments)
    EXPECT_NE(m.find(fragment), std::string::npos) << "'" << fragment << "' not in: " << m;
}

const std::vector<BadCase> kBadCases = {
    {"unknown_top_level_key",
     kBase + "\n[Solver]\nmax_iterations = 3\n",
     {"Solver: unknown key (expected one of: title, mesh,", "did you mean 'solver'?", "(line 19)"}},
    {"unknown_nested_key",
     kBase + "\n[[mesh.box]]\nname = \"b\"\nsizes = [1, 1, 1]\ndivisions = [1, 1, 1]\n",
     {"mesh.box[2].sizes: unknown key (expected one of: name, origin, size, divisions, grading, "
      "material); did you mean 'size'?"}},
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
     kBase + "[[output.probe]]\nname = \"tip\"\nquantity = \"stress\"\npoint = [1, 1, 1]\n",
     {"output.probe[1].quantity = 'stress': unknown quantity (expected one of: displacement, "
      "position)"}},
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
     kBase + "[solver]\nlinear_solver = \"mumps\"\n",
     {"solver.linear_solver = 'mumps': unknown value (expected one of: umfpack, sparselu)"}},
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

INSTANTIATE_TEST_SUITE_P(CaseReader, BadInput, testing::ValuesIn(kBadCases),
                         [](const testing::TestParamInfo<BadCase>& info) {
                           return info.param.name;
                         });

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

TEST(CaseReader, DocumentedExampleParses) {
  const fs::path doc = fs::path(TRIFEM_SOURCE_DIR) / "docs" / "input.md";
  std::ifstream in(doc);
  ASSERT_TRUE(in) << doc;
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string fence = "## Complete annotated example\n\n```toml\n";
  const auto begin = text.find(fence);
  ASSERT_NE(begin, std::string::npos);
  const auto body = begin + fence.size();
  const auto end = text.find("```", body);
  ASSERT_NE(end, std::string::npos);
  const CaseSpec c = parse_case(text.substr(body, end - body), doc);
  EXPECT_EQ(c.boxes.size(), 1u);
  EXPECT_EQ(c.materials.size(), 2u);
  EXPECT_EQ(c.fixed.size(), 2u);
  EXPECT_EQ(c.prescribed.size(), 1u);
  EXPECT_EQ(c.output.probes.size(), 1u);
  EXPECT_DOUBLE_EQ(c.time.dt_min, 1e-7);
}
