// SPDX-License-Identifier: MIT
// End-to-end tests of the trifem executable: exit codes, one-line error messages, result files.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <ostream>
#include <regex>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace fs = std::filesystem;

namespace {

const fs::path kExe = TRIFEM_EXE;
const fs::path kData = TRIFEM_TEST_DATA_DIR;

/// Exit codes of trifem (mirrors app::ExitCode, documented in docs/cli.md).
enum ExitCode : int {
  kSuccess = 0,
  kUsage = 1,
  kInvalidInput = 2,
  kAnalysisFailed = 3,
};

/// What one run of the executable produced.
struct Result {
  std::string command; ///< the shell command that was run
  int exit_code = -1;  ///< exit status, or -1 if the process did not exit normally
  std::string out;     ///< everything written to stdout
  std::string err;     ///< everything written to stderr
};

/// Prints a run for failure messages.
std::ostream& operator<<(std::ostream& os, const Result& r) {
  return os << "\n$ " << r.command << "\nexit code " << r.exit_code << "\n--- stdout:\n"
            << r.out << "--- stderr:\n"
            << r.err << "---";
}

/// `text` as one word for /bin/sh (single-quoted, embedded quotes escaped).
std::string shell_quoted(std::string_view text) {
  std::string quoted = "'";
  for (const char c : text) {
    if (c == '\'')
      quoted += "'\\''";
    else
      quoted += c;
  }
  return quoted + "'";
}

/// The whole content of `file` ("" if it cannot be read).
std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// The non-empty lines of `text`.
std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (!line.empty())
      lines.push_back(line);
  return lines;
}

/// The lines of `text` that start with "error:".
std::vector<std::string> error_lines(const std::string& text) {
  std::vector<std::string> found = lines_of(text);
  std::erase_if(found, [](const std::string& line) { return !line.starts_with("error:"); });
  return found;
}

/// True if `text` contains `part`.
bool contains(std::string_view text, std::string_view part) {
  return text.find(part) != std::string_view::npos;
}

/// Number of occurrences of `part` in `text`.
std::size_t count_of(std::string_view text, std::string_view part) {
  std::size_t n = 0;
  for (auto at = text.find(part); at != std::string_view::npos; at = text.find(part, at + 1))
    ++n;
  return n;
}

/// Fixture: every test works in a fresh temporary directory, removed afterwards.
class Cli : public ::testing::Test {
protected:
  void SetUp() override {
    static std::atomic<int> counter{0};
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ =
        fs::temp_directory_path() / ("trifem_test_cli_" + std::string(info->name()) + "_" +
                                     std::to_string(::getpid()) + "_" + std::to_string(counter++));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }

  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

  /// Runs trifem with `args` in the working directory, capturing stdout, stderr and exit code.
  Result trifem(std::initializer_list<std::string> args) const {
    Result r;
    r.command = shell_quoted(kExe.string());
    for (const auto& a : args) {
      r.command += ' ';
      r.command += shell_quoted(a);
    }
    const fs::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
    const std::string line = "cd " + shell_quoted(dir_.string()) + " && " + r.command + " >" +
                             shell_quoted(out.string()) + " 2>" + shell_quoted(err.string());
    const int status = std::system(line.c_str());
    r.exit_code = status != -1 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = read_text(out);
    r.err = read_text(err);
    fs::remove(out);
    fs::remove(err);
    return r;
  }

  /// Writes `bytes` to the file `name` of the working directory and returns its path.
  fs::path write_file(const std::string& name, std::string_view bytes) const {
    const fs::path file = dir_ / name;
    std::ofstream(file, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
    return file;
  }

  /// The output directory passed with -o.
  fs::path output() const { return dir_ / "out"; }

  /// Checks that `check` and `run` both reject `case_file` with exit code 2 and exactly one
  /// stderr line "error: ..." containing every one of `parts`, and that `run` wrote nothing.
  void expect_invalid_input(const fs::path& case_file,
                            std::initializer_list<std::string_view> parts) const {
    for (const std::string command : {"check", "run"}) {
      SCOPED_TRACE("trifem " + command);
      const Result r = command == "check"
                           ? trifem({command, case_file.string()})
                           : trifem({command, case_file.string(), "-o", output().string()});
      EXPECT_EQ(r.exit_code, kInvalidInput) << r;
      const std::vector<std::string> lines = lines_of(r.err);
      ASSERT_EQ(lines.size(), 1u) << "expected one stderr line" << r;
      EXPECT_TRUE(lines[0].starts_with("error: ")) << r;
      for (const std::string_view part : parts)
        EXPECT_TRUE(contains(lines[0], part)) << "'" << part << "' is not named" << r;
      EXPECT_TRUE(error_lines(r.out).empty()) << r;
      EXPECT_FALSE(fs::exists(output())) << "an invalid case must not create its output";
    }
  }

  fs::path dir_;
};

} // namespace

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
