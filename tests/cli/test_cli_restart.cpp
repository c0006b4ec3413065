// SPDX-License-Identifier: MIT
// Restart: every quasi-static example run with --write-restart, then continued from its middle
// restart file with --restart, gives the history of the uninterrupted run at every time after
// the restart to 1e-12 of the largest magnitude of the columns of the same unit (steps, Newton
// iterations and time steps identical). Bad restart files and restarts of other cases are input
// errors.
#include "cli_harness.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>

namespace trifem::cli_test {
namespace {

const fs::path kExamples = fs::path(TRIFEM_SOURCE_DIR) / "examples";

fs::path example_case(const std::string& name) {
  return kExamples / name / (name + ".toml");
}

/// The restart files of a run directory, in order.
std::vector<fs::path> restart_files(const fs::path& dir) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().starts_with("restart_"))
      files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

class CliRestart : public Cli {
protected:
  /// Runs the example `name` whole, writing restart files, then again from the restart file
  /// chosen by `pick` (from the list, in order), and compares the two histories.
  void check_restart(const std::string& name,
                     const std::function<fs::path(const std::vector<fs::path>&)>& pick) const;
};

class CliRestartExamples : public CliRestart, public testing::WithParamInterface<std::string> {};

TEST_P(CliRestartExamples, ContinuedRunEqualsTheUninterruptedOne) {
  check_restart(GetParam(), [](const auto& files) { return files[(files.size() - 1) / 2]; });
}

/// The swelling example restarted inside its second analysis step (the relative prescribed
/// top displacement keeps the offsets of the step's start, not of the restart state).
TEST_F(CliRestart, ContinuedInsideALaterAnalysisStep) {
  check_restart("swell_then_compress", [](const auto& files) { return files[files.size() - 2]; });
}

void CliRestart::check_restart(
    const std::string& name,
    const std::function<fs::path(const std::vector<fs::path>&)>& pick) const {
  const fs::path whole = output() / "whole", resumed = output() / "resumed";
  Result r =
      trifem({"-q", "run", example_case(name).string(), "-o", whole.string(), "--write-restart"});
  ASSERT_EQ(r.exit_code, kSuccess) << r;
  const std::vector<fs::path> files = restart_files(whole);
  ASSERT_GE(files.size(), 2u) << "the run wrote no restart file before its end";
  r = trifem({"-q", "run", example_case(name).string(), "-o", resumed.string(), "--restart",
              pick(files).string()});
  ASSERT_EQ(r.exit_code, kSuccess) << r;

  const History a = read_history(whole / "history.csv");
  const History b = read_history(resumed / "history.csv");
  ASSERT_EQ(a.names, b.names);
  ASSERT_GE(b.columns[0].size(), 2u) << "the restarted run took no step";
  // rows of the uninterrupted run by time
  std::map<double, std::size_t> row_at;
  for (std::size_t i = 0; i < a.columns[0].size(); ++i)
    row_at[a.columns[0][i]] = i;
  const std::map<std::string, double> scale = unit_scales(a); // a zero column: its unit's
  std::size_t compared = 0;
  for (std::size_t i = 0; i < b.columns[0].size(); ++i) {
    const auto it = row_at.find(b.columns[0][i]);
    ASSERT_NE(it, row_at.end()) << "t = " << b.columns[0][i] << " is not a time of the whole run";
    for (std::size_t c = 1; c < a.names.size(); ++c) {
      if (i == 0 && (a.names[c] == "dt [s]" || a.names[c] == "iterations"))
        continue; // the first row is the restart state itself (no step taken)
      EXPECT_LE(std::abs(b.columns[c][i] - a.columns[c][it->second]),
                1e-12 * scale.at(unit_of(a.names[c])))
          << a.names[c] << " at t = " << b.columns[0][i];
    }
    ++compared;
  }
  EXPECT_EQ(a.columns[0].back(), b.columns[0].back()) << "both runs end at the end time";
  EXPECT_GE(compared, 2u);
}

INSTANTIATE_TEST_SUITE_P(Examples, CliRestartExamples,
                         testing::Values("biphasic_creep", "cantilever", "confined_column",
                                         "contact_column", "contact_patch", "free_swelling",
                                         "sliding_layers", "swell_then_compress"));

TEST_F(Cli, RestartFromAFileThatIsNotOneIsAnInputError) {
  const fs::path bad = write_file("bad.bin", "not a restart file at all, just text");
  const Result r = trifem({"run", example_case("biphasic_creep").string(), "-o", output().string(),
                           "--restart", bad.string()});
  EXPECT_EQ(r.exit_code, kInvalidInput) << r;
  EXPECT_TRUE(contains(r.err, "bad.bin: not a trifem restart file")) << r;
  EXPECT_FALSE(fs::exists(output())) << "an invalid restart must not create the output";
}

TEST_F(Cli, RestartOfAnotherCaseOrAtTheEndIsAnInputError) {
  const fs::path first = output() / "first";
  ASSERT_EQ(trifem({"-q", "run", example_case("confined_column").string(), "-o", first.string(),
                    "--write-restart"})
                .exit_code,
            kSuccess);
  const std::vector<fs::path> files = restart_files(first);
  ASSERT_FALSE(files.empty());
  Result r = trifem({"run", example_case("biphasic_creep").string(), "-o",
                     (output() / "other").string(), "--restart", files.front().string()});
  EXPECT_EQ(r.exit_code, kInvalidInput) << r;
  EXPECT_TRUE(contains(r.err, "degrees of freedom")) << r;
  r = trifem({"run", example_case("confined_column").string(), "-o", (output() / "end").string(),
              "--restart", files.back().string()});
  EXPECT_EQ(r.exit_code, kInvalidInput) << r;
  EXPECT_TRUE(contains(r.err, "nothing is left to run")) << r;
  r = trifem({"run", example_case("explicit_cantilever").string(), "-o",
              (output() / "explicit").string(), "--write-restart"});
  EXPECT_EQ(r.exit_code, kInvalidInput) << r;
  EXPECT_TRUE(contains(r.err, "quasi-static analyses only")) << r;
}

} // namespace
} // namespace trifem::cli_test
