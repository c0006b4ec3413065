// SPDX-License-Identifier: MIT
// The dynamic-explicit analysis keeps its numbers while it moves onto the shared model (issue
// 35): short explicit runs through the reader and the application, every history column (every
// step: time, dt, iterations, energies, constraint residuals, reactions, probes) against the
// history that the analysis gave before the move (tests/data/explicit_reference/, written by
// this test with TRIFEM_WRITE_EXPLICIT_REFERENCE=1), to 1e-12 of a scale of the column that
// cannot vanish (column_scale), the constraint residual below its tolerance. The cases cover both
// readings, both constraints, a finite and no multiplier, damping, both stable-step estimates and
// their re-estimation, reused factorizations, follower pressures and dead tractions, and a
// quasi-static step followed by an explicit one.
#include "edited_text.hpp"
#include "history_csv.hpp"
#include "trifem/analysis/run.hpp"
#include "trifem/io/case_reader.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace {

namespace fs = std::filesystem;
using namespace trifem;
using test::edited;

const fs::path kSource = TRIFEM_SOURCE_DIR;
const fs::path kReference = kSource / "tests" / "data" / "explicit_reference";

std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The default [explicit] constraint_tolerance (no case here changes it).
constexpr double kConstraintTolerance = 1e-11;

/// The scale a column is compared at, one that cannot vanish: J − 1 against J (1); energies,
/// reactions and displacements against the largest of their kind (every column with the same
/// unit), so a component that stays at round-off (a reaction across the load, the total energy)
/// is not compared to itself; other columns against their own largest magnitude.
double column_scale(const test::History& h, const std::string& name) {
  if (name.ends_with("-1|")) // max|Jbar-1|, max_gauss|J-1|
    return 1.0;
  const auto largest = [&](const auto& in_scale) {
    double scale = 0.0;
    for (std::size_t k = 0; k < h.names.size(); ++k)
      if (in_scale(h.names[k]))
        for (const double v : h.columns[k])
          scale = std::max(scale, std::abs(v));
    return scale;
  };
  for (const std::string unit : {"[mJ]", "[N]", "[mm]"})
    if (name.ends_with(unit))
      return largest([&](const std::string& other) { return other.ends_with(unit); });
  return largest([&](const std::string& other) { return other == name; });
}

/// One explicit case: its name (that of its reference file), its text and the history file its
/// run writes (history_step<k>.csv for an explicit step after quasi-static ones).
struct ExplicitCase {
  std::string name;
  std::string text;
  std::string history = "history.csv";
};

std::vector<ExplicitCase> cases() {
  // The probes sit on the nodes the references took (the node nearest to the probe point, before
  // probes were interpolated in their cell as in every other analysis).
  const std::string cantilever = edited(
      read_text(kSource / "examples" / "explicit_cantilever" / "explicit_cantilever.toml"),
      {{"point = [10.0, 0.5, 0.5]", "point = [10.0, 0.6666666666666666, 0.6666666666666666]"}});
  const std::string bar =
      edited(read_text(kSource / "tests" / "cli" / "data" / "explicit_box.toml"),
             {{"point = [4.0, 0.5, 1.0]", "point = [4.0, 0.0, 1.0]"}});
  const std::string pressure_on_top = "\n[[loads.pressure]]\nsurface = \"bar.zmax\"\n"
                                      "value = 1.0e-3\ncurve = \"step\"\n";
  std::vector<ExplicitCase> all;
  // reading B, J - 1, finite penalty, power iteration, follower pressure: the first tenth of the
  // example (its first bending swing)
  all.push_back({"cantilever_B", edited(cantilever, {{"end_time = 0.04 ", "end_time = 0.004 "},
                                                     {"interval = 5e-4 ", "interval = 1e-3 "}})});
  // reading B, dead traction, the defaults
  all.push_back({"bar_B", bar});
  // reading A, ln J, damping, the element bound re-estimated every 5 steps, a follower
  // pressure beside the traction
  all.push_back({"bar_A_lnJ_damped",
                 edited(bar, {{"penalty = 4000.0", "penalty = 4000.0\nreading = \"A\"\n"
                                                   "constraint = \"lnJ\"\ndamping = 500.0\n"
                                                   "stable_step = \"element-bound\"\n"
                                                   "stable_step_interval = 5"}}) +
                     pressure_on_top});
  // reading B, a factorization serving 3 steps, power iteration re-estimated every 10 steps,
  // damping
  all.push_back({"bar_B_reused",
                 edited(bar, {{"penalty = 4000.0", "penalty = 4000.0\nfactorization_age = 3\n"
                                                   "stable_step_interval = 10\ndamping = 200.0"},
                              {"end_time = 1e-3", "end_time = 2e-3"}}) +
                     pressure_on_top});
  // no multiplier (the law's own bulk response): a bar stretched quasi-statically, then
  // released (tests/verification/app/qs_then_explicit_test.cpp, a quarter of its duration)
  all.push_back({"bar_quasi_static_then_explicit", R"(
[[mesh.box]]
name = "bar"
size = [10.0, 1.0, 1.0]
divisions = [20, 1, 1]
material = "rubber"

[materials.rubber]
type = "neo-hookean"
E = 1.0
nu = 0.3
density = 1e-9

[curves.ramp]
points = [[0.0, 0.0], [1.0, 1.0]]

[[boundary.fixed]]
set = "bar.xmin"
components = ["x"]
[[boundary.fixed]]
set = "bar.ymin"
components = ["y"]
[[boundary.fixed]]
set = "bar.zmin"
components = ["z"]

[explicit]
multiplier = false

[[step]]
name = "stretch"
end_time = 1.0
dt = 0.25
[[step.boundary.prescribed]]
set = "bar.xmax"
component = "x"
value = 0.1
curve = "ramp"

[[step]]
name = "release"
analysis = "dynamic-explicit"
duration = 5e-4

[[output.probe]]
name = "tip"
point = [10.0, 0.0, 0.0]
[[output.probe]]
name = "corner"
point = [10.0, 1.0, 1.0]
)",
                 "history_step2.csv"});
  return all;
}

class ExplicitReferenceHistory : public ::testing::TestWithParam<ExplicitCase> {
protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("trifem_explicit_reference_" + GetParam().name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  fs::path dir_;
};

TEST_P(ExplicitReferenceHistory, EveryColumnOfEveryStepIsTheReferenceOne) {
  const ExplicitCase& c = GetParam();
  const fs::path file = dir_ / (c.name + ".toml");
  std::ofstream(file) << c.text;
  ASSERT_EQ(analysis::run_case(io::read_case(file), dir_ / "out"), 0);
  const fs::path produced = dir_ / "out" / c.history;
  const fs::path reference = kReference / (c.name + ".csv");
  if (const char* write = std::getenv("TRIFEM_WRITE_EXPLICIT_REFERENCE");
      write != nullptr && std::string(write) == "1") {
    fs::create_directories(kReference);
    fs::copy_file(produced, reference, fs::copy_options::overwrite_existing);
    GTEST_SKIP() << "wrote " << reference;
  }
  const test::History expected = test::read_history(reference);
  const test::History actual = test::read_history(produced);
  ASSERT_GT(expected.names.size(), 10u) << reference;
  ASSERT_GT(expected.columns.front().size(), 5u) << "steps of " << reference;
  for (std::size_t k = 0; k < expected.names.size(); ++k) {
    const std::string& name = expected.names[k];
    SCOPED_TRACE(name);
    const std::vector<double>& want = expected.columns[k];
    const std::vector<double>& got = actual[name];
    ASSERT_EQ(got.size(), want.size()) << "rows";
    if (name == "constraint_residual") { // round-off of a converged iteration: below its tolerance
      for (std::size_t row = 0; row < got.size(); ++row)
        EXPECT_LE(got[row], kConstraintTolerance) << "row " << row + 1;
      continue;
    }
    const double scale = column_scale(expected, name);
    for (std::size_t row = 0; row < want.size(); ++row)
      ASSERT_LE(std::abs(got[row] - want[row]), 1e-12 * scale) << "row " << row + 1;
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, ExplicitReferenceHistory, ::testing::ValuesIn(cases()),
                         [](const auto& info) { return info.param.name; });

} // namespace
