// SPDX-License-Identifier: MIT
// Runs that must end cleanly: every DOF prescribed, an inverted initial state, Ctrl-C, a killed
// run, result files that cannot be written, stale files of an earlier run, a DOF given two
// values, and a strongly graded column whose Newton solves reach the round-off floor.
#include "cli_harness.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

namespace trifem::cli_test {
namespace {

/// A neo-Hookean block of 2 x 2 x 2 cells; `conditions` and `time` complete it.
std::string block_case(const std::string& conditions, const std::string& time) {
  return R"([[mesh.box]]
name = "block"
size = [1.0, 1.0, 1.0]
divisions = [2, 2, 2]
material = "tissue"

[materials.tissue]
type = "neo-hookean"
E = 0.3
nu = 0.2

[curves.ramp]
points = [[0.0, 0.0], [1.0, 1.0]]
)" + conditions +
         "\n[time]\n" + time + "\n";
}

/// The paper's 4.1 confined triphasic column (examples/confined_column) with `mesh` as its
/// [[mesh.box]] lines and `time` as its [time] section.
std::string column_case(const std::string& mesh, const std::string& time,
                        const std::string& output = "") {
  return R"([[mesh.box]]
name = "column"
size = [1.0, 1.0, 1.0]
material = "cartilage"
)" + mesh +
         R"(
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
nu = 0.0

[electrochemistry]
T = 298.0
bath_concentration = 1.5e-4

[curves.ramp]
points = [[0.0, 0.0], [50.0, 1.0]]

[[boundary.fixed]]
set = "column.all"
components = ["x", "y"]
[[boundary.fixed]]
set = "column.all"
field = "fluxes"
components = ["x", "y"]
[[boundary.fixed]]
set = "column.zmin"
components = ["z"]
[[boundary.impermeable]]
set = "column.zmin"
normal = "z"
[[boundary.prescribed]]
set = "column.zmax"
component = "z"
value = -0.05
curve = "ramp"

[time]
)" + time +
         R"(

[output]
)" + output +
         R"(
[[output.reaction]]
set = "column.zmax"
)";
}

nlohmann::json read_summary(const fs::path& dir) {
  return nlohmann::json::parse(read_text(dir / "summary.json"));
}

/// Last value of column `name` in a history.csv.
double last_value(const fs::path& history, const std::string& name) {
  const std::vector<std::string> lines = lines_of(read_text(history));
  std::vector<std::string> header, last;
  auto split = [](const std::string& line) {
    std::vector<std::string> cells;
    std::stringstream in(line);
    for (std::string cell; std::getline(in, cell, ',');)
      cells.push_back(cell);
    return cells;
  };
  header = split(lines.front());
  last = split(lines.back());
  for (std::size_t i = 0; i < header.size(); ++i)
    if (header[i] == name)
      return std::stod(last[i]);
  ADD_FAILURE() << "no column " << name;
  return NAN;
}

} // namespace

TEST_F(Cli, EveryDofPrescribedRunsWithoutEquations) {
  // every node fixed in x and y and moved in z: a rigid translation with nothing to solve
  const auto file = write_file("all_prescribed.toml", block_case(R"(
[[boundary.fixed]]
set = "block.all"
components = ["x", "y"]
[[boundary.prescribed]]
set = "block.all"
component = "z"
value = -0.2
curve = "ramp"
[[output.probe]]
name = "top"
point = [1.0, 1.0, 1.0]
)",
                                                                 "end_time = 1.0\ndt = 0.5"));
  const Result r = trifem({"run", file.string(), "-o", output().string()});
  ASSERT_EQ(r.exit_code, kSuccess) << r;
  EXPECT_TRUE(contains(r.out, "0 equations")) << r;
  EXPECT_EQ(read_summary(output())["status"], "completed");
  EXPECT_EQ(lines_of(read_text(output() / "history.csv")).size(), 4u); // header, t = 0, 2 steps
  EXPECT_EQ(last_value(output() / "history.csv", "top.uz [mm]"), -0.2);
}

TEST_F(Cli, AnInvertedInitialStateFailsWithASummary) {
  const auto file = write_file("inverted.toml", block_case(R"(
[[boundary.fixed]]
set = "block.zmin"
components = ["x", "y", "z"]
[[boundary.prescribed]]
set = "block.zmax"
component = "z"
value = -1.5
)",
                                                           "end_time = 1.0\ndt = 0.5"));
  const Result r = trifem({"run", file.string(), "-o", output().string()});
  EXPECT_EQ(r.exit_code, kAnalysisFailed) << r;
  ASSERT_EQ(error_lines(r.err).size(), 1u) << r;
  EXPECT_TRUE(contains(r.err, "initial state (t = 0) inverts an element")) << r;
  const nlohmann::json s = read_summary(output());
  EXPECT_EQ(s["status"], "failed");
  EXPECT_TRUE(contains(s["failure"].get<std::string>(), "inverts an element"));
}

TEST_F(Cli, ADofGivenTwoValuesByOverlappingSetsIsAnInputError) {
  const auto file = write_file("overlap.toml", block_case(R"(
[[boundary.fixed]]
set = "block.zmin"
components = ["x", "y", "z"]
[[boundary.prescribed]]
set = "block.all"
component = "z"
value = -0.2
curve = "ramp"
)",
                                                          "end_time = 1.0\ndt = 0.5"));
  expect_invalid_input(file, {"overlap.toml", "boundary.fixed[1].set 'block.zmin'",
                              "boundary.prescribed[1].set 'block.all'", "displacement"});
}

TEST_F(Cli, ABodyWithoutSupportIsAnInputErrorNotANewtonFailure) {
  // loaded by a pressure, held in z only: its x and y translations are undetermined
  const auto file = write_file("unsupported.toml", block_case(R"(
[[boundary.fixed]]
set = "block.zmin"
components = ["z"]
[[loads.pressure]]
surface = "block.zmax"
value = 0.01
curve = "ramp"
)",
                                                              "end_time = 1.0\ndt = 0.5"));
  expect_invalid_input(
      file, {"unsupported.toml", "body 'block' is not supported in x", "[[boundary.fixed]]"});
}

TEST_F(Cli, CtrlCEndsTheRunWithAnInterruptedSummaryAndValidResults) {
  const auto file = write_file(
      "long.toml", column_case("divisions = [1, 1, 20]", "end_time = 1e5\ndt = 2.5\ndt_max = 2.5"));
  // start the run, wait for a few history rows, then send SIGINT (as Ctrl-C does)
  const std::string script =
      shell_quoted(kExe.string()) + " -q run " + shell_quoted(file.string()) + " -o " +
      shell_quoted(output().string()) + " 2>" + shell_quoted((dir_ / "err.txt").string()) +
      " & pid=$!; for i in $(seq 600); do n=$(cat " +
      shell_quoted((output() / "history.csv").string()) +
      " 2>/dev/null | wc -l); [ \"$n\" -ge 5 ] && break; sleep 0.05; done; kill -INT $pid; "
      "wait $pid; exit $?";
  const int status = std::system(("sh -c " + shell_quoted(script)).c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);
  const nlohmann::json s = read_summary(output());
  EXPECT_EQ(s["status"], "interrupted");
  EXPECT_GE(s["steps"].get<int>(), 3); // the signal came after 3 history rows of steps
  EXPECT_EQ(lines_of(read_text(output() / "history.csv")).size(), s["steps"].get<size_t>() + 2);
  const std::string pvd = read_text(output() / "results.pvd");
  EXPECT_TRUE(contains(pvd, "</VTKFile>"));
  const std::string err = read_text(dir_ / "err.txt");
  EXPECT_EQ(error_lines(err).size(), 1u) << err;
  EXPECT_TRUE(contains(err, "interrupted")) << err;
}

TEST_F(Cli, AKilledRunLeavesARunningSummaryAndStaleFilesAreCleared) {
  fs::create_directories(output());
  for (const char* stale : {"volume_0099.vtu", "contact1_0003.vtu", "contact2.pvd"})
    write_file(fs::path("out") / stale, "stale");
  write_file("out/notes.txt", "a user's file");
  const auto file = write_file(
      "long.toml", column_case("divisions = [1, 1, 20]", "end_time = 1e5\ndt = 2.5\ndt_max = 2.5"));
  const std::string script = shell_quoted(kExe.string()) + " -q run " +
                             shell_quoted(file.string()) + " -o " +
                             shell_quoted(output().string()) +
                             " >/dev/null 2>&1 & pid=$!; for i in $(seq 600); do n=$(cat " +
                             shell_quoted((output() / "history.csv").string()) +
                             " 2>/dev/null | wc -l); [ \"$n\" -ge 3 ] && break; sleep 0.05; "
                             "done; kill -KILL $pid; wait $pid; exit 0";
  ASSERT_EQ(std::system(("sh -c " + shell_quoted(script)).c_str()), 0);
  EXPECT_EQ(read_summary(output())["status"], "running");
  EXPECT_FALSE(fs::exists(output() / "volume_0099.vtu"));
  EXPECT_FALSE(fs::exists(output() / "contact1_0003.vtu"));
  EXPECT_FALSE(fs::exists(output() / "contact2.pvd"));
  EXPECT_TRUE(fs::exists(output() / "notes.txt")) << "only trifem's own files are removed";
}

TEST_F(Cli, AWriteErrorMidRunFailsWithASummary) {
  // history.csv grows past a file-size limit of 20 KiB after some 80 steps (VTU files are off)
  const auto file =
      write_file("long.toml", column_case("divisions = [1, 1, 20]",
                                          "end_time = 1e5\ndt = 2.5\ndt_max = 2.5", "vtu = false"));
  const std::string script = "trap '' XFSZ; ulimit -f 40; exec " + shell_quoted(kExe.string()) +
                             " -q run " + shell_quoted(file.string()) + " -o " +
                             shell_quoted(output().string()) + " 2>" +
                             shell_quoted((dir_ / "err.txt").string());
  const int status = std::system(("sh -c " + shell_quoted(script)).c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), kAnalysisFailed);
  const std::string err = read_text(dir_ / "err.txt");
  EXPECT_EQ(error_lines(err).size(), 1u) << err;
  EXPECT_TRUE(contains(err, "could not be written")) << err;
  EXPECT_TRUE(contains(err, "history.csv")) << err;
  const nlohmann::json s = read_summary(output());
  EXPECT_EQ(s["status"], "failed");
  EXPECT_GT(s["steps"].get<int>(), 10);
}

TEST_F(Cli, AStronglyGradedColumnReachesTheRoundoffFloorAndCompletes) {
  // 160 cells, each 0.95 of the one below: the top cell is 1.4e-5 mm, 7e4 times the largest
  const std::string graded = "divisions = [1, 1, 160]\ngrading = [1.0, 1.0, 2.8724e-4]";
  const auto file =
      write_file("graded.toml", column_case(graded, "end_time = 150.0\ndt = 2.5\ndt_max = 2.5"));
  const Result r = trifem({"run", file.string(), "-o", output().string()});
  ASSERT_EQ(r.exit_code, kSuccess) << r;
  EXPECT_TRUE(contains(r.out, "round-off floor")) << r;
  EXPECT_TRUE(contains(r.out, "ratio 6.96e+04")) << r; // names the grading
  const nlohmann::json s = read_summary(output());
  EXPECT_GT(s["roundoff_floor_steps"].get<int>(), 0);
  EXPECT_EQ(s["cutbacks"].get<int>(), 0);
  // the same column on a uniform mesh: the platen force agrees to the discretisation error
  const auto uniform =
      write_file("uniform.toml",
                 column_case("divisions = [1, 1, 40]", "end_time = 150.0\ndt = 2.5\ndt_max = 2.5"));
  const fs::path out2 = dir_ / "uniform";
  const Result u = trifem({"-q", "run", uniform.string(), "-o", out2.string()});
  ASSERT_EQ(u.exit_code, kSuccess) << u;
  const double f_graded = last_value(output() / "history.csv", "column.zmax.Rz [N]");
  const double f_uniform = last_value(out2 / "history.csv", "column.zmax.Rz [N]");
  EXPECT_NEAR(f_graded, f_uniform, 5e-3 * std::abs(f_uniform));
}

} // namespace trifem::cli_test

namespace trifem::cli_test {

TEST_F(Cli, ACaseGivesByteIdenticalHistoryOnEveryRunAndThreadCount) {
  // docs/cli.md promises: assembly sums in a fixed (colour) order, so neither a second run nor
  // another thread count changes a bit of the results with SparseLU and UMFPACK; MUMPS (auto's
  // choice for large models) gives the same bits at the same thread count (its BLAS work is
  // split by thread)
  for (const std::string solver : {"sparselu", "umfpack", "mumps"}) {
    const auto file = write_file(
        "column_" + solver + ".toml",
        column_case("divisions = [1, 1, 12]", "end_time = 100.0\ndt = 5.0\ndt_max = 5.0") +
            "\n[solver]\nlinear_solver = \"" + solver + "\"\n");
    std::vector<std::string> histories;
    for (const std::string threads : {"1", "2", "1", "2"}) {
      const fs::path out = dir_ / ("out_" + solver + "_" + std::to_string(histories.size()));
      const std::string command = "OMP_NUM_THREADS=" + threads +
                                  " OPENBLAS_NUM_THREADS=" + threads + " " +
                                  shell_quoted(kExe.string()) + " -q run " +
                                  shell_quoted(file.string()) + " -o " + shell_quoted(out.string());
      ASSERT_EQ(std::system(command.c_str()), 0) << command;
      histories.push_back(read_text(out / "history.csv"));
    }
    ASSERT_GT(lines_of(histories[0]).size(), 20u);
    for (std::size_t i = 1; i < histories.size(); ++i) {
      // the run compared with: the first, or for MUMPS the first with the same thread count
      const std::size_t reference = solver == "mumps" ? i % 2 : 0;
      if (reference != i) {
        EXPECT_EQ(histories[i], histories[reference]) << solver << ", run " << i;
      }
    }
  }
}

} // namespace trifem::cli_test
