// SPDX-License-Identifier: MIT
// End-to-end tests of the trifem executable: exit codes, one-line error messages, result files.
#include "cli_harness.hpp"

using namespace trifem::cli_test;
namespace fs = std::filesystem;

// ---------------------------------------------------------------------------------------------
// Invalid input: exit code 2, one "error:" line on stderr that names the problem

TEST_F(Cli, MissingCaseFileIsNamed) {
  const fs::path missing = dir_ / "no_such_case.toml";
  expect_invalid_input(missing, {missing.string(), "cannot open the case file"});
}

TEST_F(Cli, EmptyCaseFileIsRejected) {
  expect_invalid_input(write_file("empty.toml", ""), {"empty.toml", "empty"});
}

TEST_F(Cli, CaseFileWithOnlyCommentsIsEmpty) {
  expect_invalid_input(write_file("comments.toml", "# nothing here\n\n   \n"),
                       {"comments.toml", "empty"});
}

TEST_F(Cli, BinaryCaseFileIsNotText) {
  using namespace std::string_view_literals;
  const fs::path file = write_file("binary.toml", "title = 1\n\0\0\x01\x02\xff"sv);
  expect_invalid_input(file, {"binary.toml", "not a text file"});
}

TEST_F(Cli, UnknownKeyIsNamedWithItsTable) {
  expect_invalid_input(kData / "unknown_key.toml", {"time.end_tme", "unknown key", "end_time"});
}

TEST_F(Cli, NegativeModulusIsOutOfRange) {
  expect_invalid_input(kData / "negative_modulus.toml", {"materials.soft.E", "(0, inf)"});
}

/// Node sets are checked when the model is built, which both `check` and `run` do.
TEST_F(Cli, UndefinedNodeSetIsNamed) {
  expect_invalid_input(kData / "undefined_set.toml", {"boundary.fixed[1].set", "nope"});
}

TEST_F(Cli, UndefinedSurfaceIsNamed) {
  expect_invalid_input(kData / "undefined_surface.toml", {"loads.pressure[1].surface", "nowhere"});
}

TEST_F(Cli, MissingGmshFileIsNamed) {
  expect_invalid_input(kData / "missing_gmsh.toml", {"mesh.gmsh[1].file", "does_not_exist.msh"});
}

TEST_F(Cli, UncreatableOutputDirectoryIsInvalidInput) {
  const fs::path file = write_file("a_file", "x");
  const Result r = trifem({"run", (kData / "tiny.toml").string(), "-o", (file / "out").string()});
  EXPECT_EQ(r.exit_code, kInvalidInput) << r;
  const std::vector<std::string> errors = error_lines(r.err);
  ASSERT_EQ(errors.size(), 1u) << r;
  EXPECT_TRUE(contains(errors[0], "cannot create the output directory")) << r;
}

// ---------------------------------------------------------------------------------------------
// Command line

TEST_F(Cli, VersionIsTheProjectVersion) {
  const Result r = trifem({"--version"});
  EXPECT_EQ(r.exit_code, kSuccess) << r;
  EXPECT_EQ(r.out, std::string("trifem ") + TRIFEM_VERSION + "\n") << r;
  std::smatch match;
  EXPECT_TRUE(std::regex_match(r.out, match, std::regex(R"(trifem (\d+\.\d+\.\d+)\n)"))) << r;
  EXPECT_TRUE(r.err.empty()) << r;
}

TEST_F(Cli, MissingSubcommandIsAUsageError) {
  const Result r = trifem({});
  EXPECT_EQ(r.exit_code, kUsage) << r;
  EXPECT_TRUE(contains(r.err, "subcommand")) << r;
}

TEST_F(Cli, UnknownOptionIsAUsageError) {
  const Result r = trifem({"--bogus", "check", (kData / "tiny.toml").string()});
  EXPECT_EQ(r.exit_code, kUsage) << r;
  EXPECT_TRUE(contains(r.err, "--bogus")) << r;
}

TEST_F(Cli, UnknownSubcommandIsAUsageError) {
  const Result r = trifem({"solve", (kData / "tiny.toml").string()});
  EXPECT_EQ(r.exit_code, kUsage) << r;
}

TEST_F(Cli, MissingCaseArgumentIsAUsageError) {
  const Result r = trifem({"run"});
  EXPECT_EQ(r.exit_code, kUsage) << r;
  EXPECT_TRUE(contains(r.err, "case")) << r;
}

/// The global flags belong before the subcommand.
TEST_F(Cli, GlobalFlagAfterSubcommandIsAUsageError) {
  const Result r = trifem({"check", (kData / "tiny.toml").string(), "-q"});
  EXPECT_EQ(r.exit_code, kUsage) << r;
}

/// Usage errors are one "error:" line like every other error, naming the unknown command.
TEST_F(Cli, UsageErrorsAreOneErrorLine) {
  const Result missing = trifem({});
  EXPECT_EQ(missing.exit_code, kUsage) << missing;
  ASSERT_EQ(lines_of(missing.err).size(), 1u) << missing;
  EXPECT_EQ(error_lines(missing.err).size(), 1u) << missing;
  const Result unknown = trifem({"solve", (kData / "tiny.toml").string()});
  EXPECT_EQ(unknown.exit_code, kUsage) << unknown;
  ASSERT_EQ(error_lines(unknown.err).size(), 1u) << unknown;
  EXPECT_TRUE(contains(error_lines(unknown.err)[0], "solve")) << unknown;
}

// ---------------------------------------------------------------------------------------------
// check

TEST_F(Cli, CheckAcceptsAValidCase) {
  const Result r = trifem({"check", (kData / "tiny.toml").string()});
  EXPECT_EQ(r.exit_code, kSuccess) << r;
  EXPECT_TRUE(contains(r.out, "check passed")) << r;
  EXPECT_TRUE(contains(r.out, "8 nodes, 1 hex8 cells")) << r;
  EXPECT_TRUE(r.err.empty()) << r;
  EXPECT_FALSE(fs::exists(dir_ / "results")) << "check must not write results";
}

// ---------------------------------------------------------------------------------------------
// run

TEST_F(Cli, RunWritesAllResultFiles) {
  const Result r = trifem({"run", (kData / "tiny.toml").string(), "-o", output().string()});
  ASSERT_EQ(r.exit_code, kSuccess) << r;
  EXPECT_TRUE(r.err.empty()) << r;
  EXPECT_TRUE(error_lines(r.out).empty()) << r;
  EXPECT_TRUE(contains(r.out, "step    2")) << r;
  for (const char* name : {"results.pvd", "volume_0000.vtu", "volume_0001.vtu", "volume_0002.vtu",
                           "history.csv", "summary.json", "run.log"})
    EXPECT_TRUE(fs::is_regular_file(output() / name)) << name << " is missing";
  EXPECT_FALSE(fs::exists(output() / "volume_0003.vtu"));
  EXPECT_TRUE(contains(read_text(output() / "summary.json"), R"("status": "completed")"));
  EXPECT_TRUE(contains(read_text(output() / "run.log"), "completed: 2 steps"));
}

/// Without output.interval a run of many steps writes about 100 VTU states (the first step at or
/// after each hundredth of the run), with output.interval = 0 every step; history.csv always has
/// every step.
TEST_F(Cli, DefaultOutputWritesAboutAHundredVolumeFiles) {
  std::string text = read_text(kData / "tiny.toml");
  const std::string time = "end_time = 1.0\ndt = 0.5\n";
  ASSERT_TRUE(contains(text, time));
  text.replace(text.find(time), time.size(), "end_time = 1.0\ndt = 0.003\n");
  const auto count_vtu = [&] {
    int n = 0;
    for (const auto& e : fs::directory_iterator(output()))
      n += e.path().extension() == ".vtu";
    return n;
  };
  ASSERT_EQ(
      trifem({"run", write_file("many.toml", text).string(), "-o", output().string()}).exit_code,
      kSuccess);
  EXPECT_EQ(count_vtu(), 101) << "t = 0 and one per hundredth of the run";
  EXPECT_EQ(lines_of(read_text(output() / "history.csv")).size(), 2u + 334u);
  ASSERT_EQ(trifem({"run", write_file("every.toml", text + "[output]\ninterval = 0.0\n").string(),
                    "-o", output().string()})
                .exit_code,
            kSuccess);
  EXPECT_EQ(count_vtu(), 1 + 334) << "interval = 0: every step";
}

TEST_F(Cli, RunHistoryHasOneRowPerState) {
  ASSERT_EQ(trifem({"run", (kData / "tiny.toml").string(), "-o", output().string()}).exit_code,
            kSuccess);
  const std::vector<std::string> rows = lines_of(read_text(output() / "history.csv"));
  ASSERT_EQ(rows.size(), 4u) << "header + t = 0 + two steps";
  EXPECT_EQ(rows[0], "time [s],step,dt [s],iterations,box.zmin.Rx [N],box.zmin.Ry [N],"
                     "box.zmin.Rz [N],top.ux [mm],top.uy [mm],top.uz [mm]");
  EXPECT_TRUE(rows[1].starts_with("0,0,0,0,")) << rows[1];
  EXPECT_TRUE(rows[2].starts_with("0.5,1,0.5,")) << rows[2];
  EXPECT_TRUE(rows[3].starts_with("1,2,0.5,")) << rows[3];
  EXPECT_TRUE(rows[3].ends_with(",0.2")) << "top.uz is the prescribed 0.2 mm: " << rows[3];
}

TEST_F(Cli, RunVolumeFilesHoldTheDocumentedArrays) {
  ASSERT_EQ(trifem({"run", (kData / "tiny.toml").string(), "-o", output().string()}).exit_code,
            kSuccess);
  const std::string pvd = read_text(output() / "results.pvd");
  EXPECT_EQ(count_of(pvd, "<DataSet "), 3u) << pvd;
  EXPECT_TRUE(contains(pvd, R"(timestep="0" group="" part="0" file="volume_0000.vtu")")) << pvd;
  EXPECT_TRUE(contains(pvd, R"(timestep="1" group="" part="0" file="volume_0002.vtu")")) << pvd;
  const std::string vtu = read_text(output() / "volume_0002.vtu");
  for (const char* array : {R"(Name="displacement [mm]" NumberOfComponents="3")",
                            R"(Name="reaction_forces [N]" NumberOfComponents="3")",
                            R"(Name="stress [MPa]" NumberOfComponents="6")",
                            R"(Name="relative_volume" NumberOfComponents="1")"})
    EXPECT_TRUE(contains(vtu, array)) << array << " is missing";
}

TEST_F(Cli, RunWithoutOutputOptionWritesToResultsCaseName) {
  const Result r = trifem({"run", (kData / "tiny.toml").string()});
  ASSERT_EQ(r.exit_code, kSuccess) << r;
  EXPECT_TRUE(fs::is_regular_file(dir_ / "results" / "tiny" / "summary.json")) << r;
}

TEST_F(Cli, QuietRunPrintsNothing) {
  const Result r = trifem({"-q", "run", (kData / "tiny.toml").string(), "-o", output().string()});
  EXPECT_EQ(r.exit_code, kSuccess) << r;
  EXPECT_TRUE(r.out.empty()) << r;
  EXPECT_TRUE(r.err.empty()) << r;
  EXPECT_TRUE(fs::is_regular_file(output() / "summary.json"));
}

TEST_F(Cli, VerboseRunPrintsNewtonIterations) {
  const Result r = trifem({"-v", "run", (kData / "tiny.toml").string(), "-o", output().string()});
  EXPECT_EQ(r.exit_code, kSuccess) << r;
  EXPECT_TRUE(contains(r.out, "iteration  1: residual")) << r;
}

/// A constant prescribed value (no load curve) that inverts the mesh at t = 0 is reported as
/// such before any step, and no result with a NaN is written.
std::string summary_of(const fs::path& dir) {
  return read_text(dir / "summary.json");
}

TEST_F(Cli, InitialStateThatInvertsIsReported) {
  const Result r =
      trifem({"run", (kData / "invert_initial.toml").string(), "-o", output().string()});
  EXPECT_EQ(r.exit_code, kAnalysisFailed) << r;
  const std::vector<std::string> errors = error_lines(r.err);
  ASSERT_EQ(errors.size(), 1u) << r;
  EXPECT_TRUE(contains(errors[0], "initial state")) << r;
  EXPECT_FALSE(fs::exists(output() / "volume_0000.vtu"));
}

/// The top face is pushed through the bottom one in a single step that cannot be cut back.
TEST_F(Cli, RunThatCannotConvergeFailsAndKeepsResults) {
  const Result r = trifem({"run", (kData / "invert.toml").string(), "-o", output().string()});
  EXPECT_EQ(r.exit_code, kAnalysisFailed) << r;
  const std::vector<std::string> errors = error_lines(r.err);
  ASSERT_EQ(errors.size(), 1u) << r;
  EXPECT_TRUE(contains(errors[0], "failed")) << r;
  EXPECT_TRUE(contains(errors[0], "invert")) << r;
  EXPECT_TRUE(contains(summary_of(output()), R"("cutbacks": 0)"));

  const std::string pvd = read_text(output() / "results.pvd");
  EXPECT_EQ(count_of(pvd, "<DataSet "), 1u) << pvd;
  EXPECT_TRUE(contains(pvd, R"(timestep="0" group="" part="0" file="volume_0000.vtu")")) << pvd;
  EXPECT_TRUE(fs::is_regular_file(output() / "volume_0000.vtu"));
  const std::vector<std::string> rows = lines_of(read_text(output() / "history.csv"));
  ASSERT_EQ(rows.size(), 2u) << "header + t = 0";
  EXPECT_EQ(rows[0], "time [s],step,dt [s],iterations");
  EXPECT_EQ(rows[1], "0,0,0,0");
  const std::string summary = read_text(output() / "summary.json");
  EXPECT_TRUE(contains(summary, R"("status": "failed")")) << summary;
  EXPECT_TRUE(contains(summary, R"("steps": 0)")) << summary;
}
