// SPDX-License-Identifier: MIT
// Cases that used to exhaust time or memory (found by the fuzz test, tests/fuzz) are invalid
// input with one clear error line; implausible values (a unit mistake) are warnings on stdout.
#include "cli_harness.hpp"

#include <string>

namespace trifem::cli_test {
namespace {

/// A triphasic cube of 1 x 1 x 1 cells; `time` and `extra` complete it.
std::string cube_case(const std::string& time, const std::string& extra = "") {
  return R"([[mesh.box]]
name = "cube"
size = [1.0, 1.0, 1.0]
divisions = [1, 1, 1]
material = "cartilage"

[materials.cartilage]
type = "triphasic"
phi_s0 = 0.25
permeability = 1.07e-3
fixed_charge = 2.0e-4
d_plus = 5.0e-4
d_minus = 8.0e-4
[materials.cartilage.solid]
type = "saint-venant-kirchhoff"
E = 0.3

[[boundary.fixed]]
set = "cube.zmin"
)" + extra +
         "\n[time]\n" + time + "\n";
}

TEST_F(Cli, TinyOutputIntervalIsInvalidInput) {
  const fs::path file =
      write_file("case.toml", cube_case("end_time = 1.0\ndt = 0.5", "[output]\ninterval = 1e-300"));
  expect_invalid_input(file, {"case.toml: output.interval = 1e-300",
                              "time.end_time / output.interval = 1e+300 output times"});
}

TEST_F(Cli, HugeEndTimeIsInvalidInput) {
  const fs::path file = write_file("case.toml", cube_case("end_time = 1e300\ndt = 0.5"));
  expect_invalid_input(file, {"case.toml: time.end_time = 1e+300", "steps, more than the"});
}

TEST_F(Cli, DenormalTimesAreInvalidInput) {
  const fs::path file = write_file("case.toml", cube_case("end_time = 1e-320\ndt = 1e-320"));
  expect_invalid_input(file, {"case.toml: time.end_time: expected 0 or a number of magnitude at "
                              "least 2.22507e-308 (the smallest normal double), got 1e-320"});
}

TEST_F(Cli, CutbackCloseToOneIsInvalidInput) {
  const fs::path file =
      write_file("case.toml", cube_case("end_time = 1.0\ndt = 1.0\ncutback = 0.999999"));
  expect_invalid_input(file, {"case.toml: time.cutback = 0.999999", "more than the 200 allowed"});
}

TEST_F(Cli, ModelLargerThanTheMachineIsInvalidInput) {
  std::string text = cube_case("end_time = 1.0\ndt = 0.5");
  text.replace(text.find("divisions = [1, 1, 1]"), 21, "divisions = [1000, 1000, 1000]");
  const fs::path file = write_file("case.toml", text);
  expect_invalid_input(file, {"case.toml: mesh.box[1].divisions: the boxes make a model of",
                              "equations, more than the 2147483647 a model can have (line 4)"});
}

// A mesh declaring 2e9 nodes for 12, one with tag 1e9, used to fill a 4 GB table.
TEST_F(Cli, GmshNodeCountAndTagDoNotExhaustMemory) {
  std::string mesh = read_text(fs::path(TRIFEM_SOURCE_DIR) / "tests" / "unit" / "mesh" / "data" /
                               "two_hex_v41.msh");
  mesh.replace(mesh.find("2 12 1 5000000"), 14, "2 2000000000 1 5000000");
  mesh.replace(mesh.find("\n5000000\n"), 9, "\n1000000000\n");
  write_file("part.msh", mesh);
  const fs::path file = write_file("case.toml", R"([[mesh.gmsh]]
file = "part.msh"
materials = { cartilage = "soft" }
[materials.soft]
type = "neo-hookean"
E = 1.0
[time]
end_time = 1.0
dt = 0.5
)");
  expect_invalid_input(file,
                       {"case.toml: ", "part.msh:49: $Nodes declares 2000000000 nodes but its "
                                       "blocks hold 12"});
}

TEST_F(Cli, MolarConcentrationIsAWarningAndTheCaseStaysValid) {
  const fs::path file =
      write_file("case.toml", cube_case("end_time = 1.0\ndt = 0.5",
                                        "[electrochemistry]\nbath_concentration = 0.15"));
  const Result r = trifem({"check", file.string()});
  EXPECT_EQ(r.exit_code, kSuccess) << r;
  EXPECT_TRUE(r.err.empty()) << r;
  EXPECT_EQ(count_of(r.out, "warning: "), 1u) << r;
  EXPECT_TRUE(contains(r.out, "warning: " + file.string() +
                                  ": electrochemistry.bath_concentration = 0.15 mmol/mm^3 is far "
                                  "outside the range of soft tissues (1e-07 to 0.01 mmol/mm^3); "
                                  "if it is in M (mol/L), write 0.00015 (line 21)"))
      << r;
  EXPECT_TRUE(contains(r.out, "check passed")) << r;
}

TEST_F(Cli, ExamplesGiveNoWarning) {
  for (const auto& dir : fs::directory_iterator(fs::path(TRIFEM_SOURCE_DIR) / "examples")) {
    if (!dir.is_directory())
      continue;
    for (const auto& file : fs::directory_iterator(dir.path())) {
      if (file.path().extension() != ".toml")
        continue;
      const Result r = trifem({"check", file.path().string()});
      EXPECT_EQ(r.exit_code, kSuccess) << r;
      EXPECT_FALSE(contains(r.out, "warning")) << r;
    }
  }
}

} // namespace
} // namespace trifem::cli_test
