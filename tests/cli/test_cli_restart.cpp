// SPDX-License-Identifier: MIT
// Restart: every quasi-static example run with --write-restart, then continued from its middle
// restart file with --restart, gives the history of the uninterrupted run at every time after
// the restart to 1e-12 of the largest magnitude of the columns of the same unit (steps, Newton
// iterations and time steps identical). Bad restart files and restarts of other cases are input
// errors (exit 2, one error line naming the restart file): files of another case with the same
// number of degrees of freedom (the part of the case that differs is named), damaged files
// (checksum), consistently damaged values (time, time step, array lengths, active step, offsets,
// released reactions) and files of restart format 1. Settings that do not change the state
// (title, output, solver, the end of the run) may differ.
#include "cli_harness.hpp"
#include "restart_file_layout.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace trifem::cli_test {
namespace {

fs::path example_case(const std::string& name) {
  return kExamples / name / (name + ".toml");
}

class CliRestart : public Cli {
protected:
  /// Runs the case `file` whole, writing restart files, then again from the restart file
  /// chosen by `pick` (from the list, in order), and compares the two histories.
  void check_restart(const fs::path& file,
                     const std::function<fs::path(const std::vector<fs::path>&)>& pick) const;
  /// The case of the example `name`; sliding_layers through its first stroke and a quarter of
  /// the way back (39 of its 160 steps: load ramp, sliding and reversal, in a quarter of the
  /// time).
  fs::path case_of(const std::string& name) const;
};

fs::path CliRestart::case_of(const std::string& name) const {
  if (name != "sliding_layers")
    return example_case(name);
  std::string text = read_text(example_case(name));
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"end_time = 0.802", "end_time = 0.152"},
           {"times = [0.002, 0.102, 0.402, 0.452, 0.502, 0.552, 0.602]",
            "times = [0.002, 0.102, 0.152]"},
           {"file = \"", "file = \"" + (kExamples / name).string() + "/"},
           // SparseLU: the same factorization whenever it starts (MUMPS's reuse differs)
           {"linear_solver = \"auto\"", "linear_solver = \"sparselu\""}}) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos)
      text.replace(at, from.size(), to);
  }
  return write_file(name + ".toml", text);
}

class CliRestartExamples : public CliRestart, public testing::WithParamInterface<std::string> {};

TEST_P(CliRestartExamples, ContinuedRunEqualsTheUninterruptedOne) {
  check_restart(case_of(GetParam()),
                [](const auto& files) { return files[(files.size() - 1) / 2]; });
}

/// The swelling example restarted inside its second analysis step (the relative prescribed
/// top displacement keeps the offsets of the step's start, not of the restart state).
TEST_F(CliRestart, ContinuedInsideALaterAnalysisStep) {
  check_restart(case_of("swell_then_compress"),
                [](const auto& files) { return files[files.size() - 2]; });
}

/// A rotating rigid body (its rotation vector is part of the state): the lid of a clamped
/// cube pulled up, twisted by a moment about z and turned about x, continued from the middle.
TEST_F(CliRestart, ContinuedWhileABlockSlidesWithFriction) {
  // the friction test's block dragged over its base: restarted while every node slips (the
  // stick/slip state and the start of the step's slip come from the restart file)
  std::string text = read_text(kData / "friction_block.toml");
  for (const auto& [from, to] :
       {std::pair<std::string, std::string>{"x = { force = 0.03, curve = \"push\" }",
                                            "x = { displacement = 0.5, curve = \"push\" }"},
        {"vtu = false", "vtu = true"}}) {
    ASSERT_NE(text.find(from), std::string::npos) << from;
    text.replace(text.find(from), from.size(), to);
  }
  check_restart(write_file("drag.toml", text),
                [](const auto& files) { return files[3 * (files.size() - 1) / 4]; });
}

TEST_F(CliRestart, ContinuedWhileARigidBodyRotates) {
  const fs::path file = write_file("rotating_lid.toml", R"(
[[mesh.box]]
name = "cube"
size = [1.0, 1.0, 1.0]
divisions = [2, 2, 2]
material = "soft"
[materials.soft]
type = "neo-hookean"
E = 1.0
nu = 0.3
[curves.ramp]
points = [[0.0, 0.0], [1.0, 1.0]]
[[boundary.fixed]]
set = "cube.zmin"
[[rigid_body]]
name = "lid"
set = "cube.zmax"
z = { force = 0.05, curve = "ramp" }
rx = { rotation = 0.3, curve = "ramp" }
rz = { moment = 0.02, curve = "ramp" }
[time]
end_time = 1.0
dt = 0.125
[solver]
linear_solver = "sparselu"
)");
  check_restart(file, [](const auto& files) { return files[(files.size() - 1) / 2]; });
}

/// Biphasic tet10 cells, whose pressure is linear from their corners (the corners' volumes of
/// the last step are part of the state): a column of Kuhn's tets consolidating under a ramped
/// load, continued from the middle.
TEST_F(CliRestart, ContinuedWhileBiphasicTet10CellsConsolidate) {
  const fs::path file = write_file("tet10_column.toml", R"(
[[mesh.box]]
name = "column"
size = [1.0, 1.0, 2.0]
divisions = [1, 1, 4]
cell = "tet10"
material = "tissue"
[materials.tissue]
type = "biphasic"
phi_s0 = 0.2
permeability = 1e-2
[materials.tissue.solid]
type = "neo-hookean"
E = 1.0
nu = 0.3
[curves.ramp]
points = [[0.0, 0.0], [1.0, 1.0]]
[[loads.pressure]]
surface = "column.zmax"
value = 0.1
curve = "ramp"
[[boundary.fixed]]
set = "column.zmin"
[[boundary.fixed]]
set = "column.xmin"
field = "displacement"
components = ["x"]
[[boundary.fixed]]
set = "column.ymin"
field = "displacement"
components = ["y"]
[time]
end_time = 4.0
dt = 0.5
[solver]
linear_solver = "sparselu"
)");
  check_restart(file, [](const auto& files) { return files[(files.size() - 1) / 2]; });
}

TEST_F(CliRestart, ContinuedWhileAJointTurnsABonePastHalfATurn) {
  // a hinge driven through 1.5 turns (the bone's rotation vector is carried below π on the
  // way), a damper and a cable on the bone: the restarted run repeats the history
  const fs::path file = write_file("hinge.toml", R"(
[[mesh.box]]
name = "cube"
size = [1.0, 1.0, 1.0]
divisions = [1, 1, 1]
material = "soft"
[[mesh.box]]
name = "bone"
origin = [0.0, 0.0, 1.0]
size = [1.0, 1.0, 0.3]
divisions = [1, 1, 1]
[materials.soft]
type = "neo-hookean"
E = 1.0
nu = 0.3
[curves.ramp]
points = [[0.0, 0.0], [1.0, 1.0]]
[[rigid_body]]
name = "femur"
set = "cube.zmax"
blocks = ["bone"]
[[connector]]
type = "revolute"
name = "hinge"
body_a = "ground"
body_b = "femur"
origin = [0.5, 0.5, 1.3]
axis = [0.0, 0.0, 1.0]
rotation = { rotation = 9.42477796076938, curve = "ramp" }
[[connector]]
type = "damper"
name = "damper"
body_a = "ground"
body_b = "femur"
point_a = [2.0, 0.5, 1.3]
point_b = [1.0, 0.5, 1.3]
damping = 0.1
[[connector]]
type = "cable"
name = "cable"
body_a = "ground"
body_b = "femur"
point_a = [0.5, 3.0, 1.3]
point_b = [0.5, 1.0, 1.3]
stiffness = 0.5
[time]
end_time = 1.0
dt = 0.1
[solver]
linear_solver = "sparselu"
)");
  check_restart(file, [](const auto& files) { return files[(files.size() - 1) / 2]; });
}

TEST_F(CliRestart, ContinuedWhileARigidWallPressesAndWithdraws) {
  // the wall's contact set (its committed history) and the multipliers of a linear constraint
  // (the state) are carried through the restart, in contact and after the release
  const fs::path file = write_file("wall.toml", R"(
[[mesh.box]]
name = "cube"
size = [1.0, 1.0, 1.0]
divisions = [2, 2, 2]
material = "soft"
[materials.soft]
type = "neo-hookean"
E = 1.0
nu = 0.3
[curves.press]
points = [[0.0, 0.0], [1.0, 1.0], [2.0, -1.0]]
[[boundary.fixed]]
set = "cube.zmin"
components = ["z"]
[[boundary.fixed]]
set = "cube.xmin"
components = ["x"]
[[constraint]]
type = "symmetry-plane"
surface = "cube.ymin"
[[constraint]]
type = "linear"
terms = [{ node = 0, component = "x", coefficient = 1.0 }, { node = 2, component = "x", coefficient = -1.0 }]
[[constraint]]
type = "rigid-wall"
name = "wall"
surface = "cube.zmax"
point = [0.0, 0.0, 1.0]
normal = [0.1, 0.0, -1.0]
offset = 0.15
curve = "press"
[time]
end_time = 2.0
dt = 0.25
[solver]
linear_solver = "sparselu"
)");
  check_restart(file, [](const auto& files) { return files[(files.size() - 1) / 2]; });
}

void CliRestart::check_restart(
    const fs::path& file, const std::function<fs::path(const std::vector<fs::path>&)>& pick) const {
  const fs::path whole = output() / "whole", resumed = output() / "resumed";
  Result r = trifem({"-q", "run", file.string(), "-o", whole.string(), "--write-restart"});
  ASSERT_EQ(r.exit_code, kSuccess) << r;
  const std::vector<fs::path> files = restart_files(whole);
  ASSERT_GE(files.size(), 2u) << "the run wrote no restart file before its end";
  r = trifem(
      {"-q", "run", file.string(), "-o", resumed.string(), "--restart", pick(files).string()});
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
  EXPECT_TRUE(contains(r.err, files.front().string() + ": the restart file was written for "
                                                       "another case (it differs from this "
                                                       "case in its mesh, degrees of freedom"))
      << r;
  r = trifem({"run", example_case("confined_column").string(), "-o", (output() / "end").string(),
              "--restart", files.back().string()});
  EXPECT_EQ(r.exit_code, kInvalidInput) << r;
  EXPECT_TRUE(contains(r.err, "nothing is left to run")) << r;
}

/// The two-step case of the restart tests (its restart files hold offsets and released
/// reactions).
std::string steps_case() {
  return read_text(kData / "restart_steps.toml");
}

/// `text` with its one occurrence of `from` replaced by `to` (the text unchanged, and a test
/// failure, if there is not exactly one).
std::string replaced(std::string_view text, std::string_view from, std::string_view to) {
  std::string out(text);
  const auto at = out.find(from);
  EXPECT_TRUE(at != std::string::npos && out.find(from, at + 1) == std::string::npos)
      << "the case has not exactly one '" << from << "'";
  return at == std::string::npos ? out : out.replace(at, from.size(), to);
}

using test::get;
using test::put;
using test::RestartLayout;

class CliRestartFile : public Cli {
protected:
  void SetUp() override {
    Cli::SetUp();
    steps_case_ = write_file("steps.toml", steps_case());
    const Result r = trifem(
        {"-q", "run", steps_case_.string(), "-o", (dir_ / "ref").string(), "--write-restart"});
    ASSERT_EQ(r.exit_code, kSuccess) << r;
    restart_ = dir_ / "ref" / "restart_0007.bin"; // t = 1.75 s, in the second step
    bytes_ = read_text(restart_);
    ASSERT_FALSE(bytes_.empty()) << restart_;
  }

  /// Runs `case_file` from `restart` into a new output directory.
  Result run_from(const fs::path& case_file, const fs::path& restart) const {
    return trifem(
        {"-q", "run", case_file.string(), "-o", output().string(), "--restart", restart.string()});
  }

  /// A copy of the restart file changed by `edit`, with its header resealed if `reseal`.
  fs::path changed_copy(const std::string& name,
                        const std::function<void(std::string&, const RestartLayout&)>& edit,
                        bool reseal) const {
    std::string bytes = bytes_;
    edit(bytes, test::restart_layout(bytes_));
    if (reseal)
      test::reseal(bytes);
    return write_file(name, bytes);
  }

  /// Exit code 2, one error line that starts with the restart file and holds `part`, and no
  /// output directory.
  void expect_rejected(const Result& r, const fs::path& restart, std::string_view part) const {
    EXPECT_EQ(r.exit_code, kInvalidInput) << r;
    const std::vector<std::string> errors = error_lines(r.err);
    ASSERT_EQ(errors.size(), 1u) << r;
    EXPECT_TRUE(errors[0].starts_with("error: " + restart.string() + ": ")) << r;
    EXPECT_TRUE(contains(errors[0], part)) << "'" << part << "' is not named" << r;
    EXPECT_FALSE(fs::exists(output())) << "an invalid restart must not create the output";
  }

  fs::path steps_case_, restart_;
  std::string bytes_;
};

TEST_F(CliRestartFile, ACaseWithOtherMaterialsOrGeometryNamesTheFileAndThePart) {
  const fs::path stiff = write_file("stiff.toml", replaced(steps_case(), "E = 1.0", "E = 100.0"));
  expect_rejected(run_from(stiff, restart_), restart_,
                  "the restart file was written for another case (it differs from this case in "
                  "its materials): restart with the case that wrote the file");
  const fs::path flat = write_file(
      "flat.toml", replaced(steps_case(), "size = [1.0, 1.0, 1.0]", "size = [3.0, 3.0, 0.5]"));
  expect_rejected(run_from(flat, restart_), restart_,
                  "(it differs from this case in its mesh): restart with the case that wrote the "
                  "file");
}

TEST_F(CliRestartFile, SettingsThatDoNotChangeTheStateMayDiffer) {
  std::string text = replaced(steps_case(), "restart steps case", "another title");
  text = replaced(text, "interval = 0.25", "interval = 0.5");
  text = replaced(text, "end_time = 2.0", "end_time = 3.0");
  text = replaced(text, "[output]", "[solver]\nresidual_tolerance = 1e-10\n\n[output]");
  const Result r = run_from(write_file("longer.toml", text), restart_);
  ASSERT_EQ(r.exit_code, kSuccess) << r;
  const History h = read_history(output() / "history.csv");
  ASSERT_GE(h.columns[0].size(), 2u);
  EXPECT_EQ(h.columns[0].front(), 1.75) << "the first row is the restart state";
  EXPECT_EQ(h.columns[0].back(), 3.0) << "the run goes on to the new end";
}

TEST_F(CliRestartFile, ADamagedFileIsAnInputErrorNamingIt) {
  const fs::path damaged = changed_copy(
      "damaged.bin", [](std::string& b, const RestartLayout&) { b[b.size() / 2] ^= 0x10; }, false);
  expect_rejected(run_from(steps_case_, damaged), damaged,
                  "the restart file is damaged: its checksum does not match its contents");
  const fs::path truncated = write_file("truncated.bin", bytes_.substr(0, bytes_.size() - 8));
  expect_rejected(run_from(steps_case_, truncated), truncated, "is truncated or damaged");
}

/// The header fields of restart_header_fields.sh, damaged as there (the checksum then fails)
/// and consistently (resealed: the checks of the values fail).
TEST_F(CliRestartFile, DamagedHeaderFieldsAreInputErrors) {
  struct Field {
    std::string name;
    std::function<void(std::string&, const RestartLayout&)> edit;
    std::string resealed_message;
  };
  const std::vector<Field> fields = {
      {"time_zero", [](auto& b, auto&) { put(b, RestartLayout::kTime, 0.0); },
       "its time is t = 0 s"},
      {"dt_nan",
       [](auto& b, auto&) { put(b, RestartLayout::kDt, std::numeric_limits<double>::quiet_NaN()); },
       "its next time step is nan s, not a positive number"},
      {"len_2e29",
       [](auto& b, auto&) { put<std::int64_t>(b, RestartLayout::kStateLength, 1 << 29); },
       "the state vector gives 536870912 entries where the"},
  };
  for (const Field& f : fields) {
    SCOPED_TRACE(f.name);
    const fs::path plain = changed_copy(f.name + ".bin", f.edit, false);
    expect_rejected(run_from(steps_case_, plain), plain, "is damaged: its checksum");
    const fs::path resealed = changed_copy(f.name + "_resealed.bin", f.edit, true);
    expect_rejected(run_from(steps_case_, resealed), resealed, f.resealed_message);
  }
}

/// The corruptions of restart_released_dof_segv.sh, restart_offsets_short_silent.sh and
/// restart_active_step_unclear.sh, resealed so that the checks behind the checksum see them.
TEST_F(CliRestartFile, TheCampaignsCorruptionsAreInputErrorsNamingTheFile) {
  const fs::path released = changed_copy(
      "released.bin",
      [](auto& b, auto& l) { put<std::int64_t>(b, l.released_count + 8, 1'000'000'000); }, true);
  expect_rejected(
      run_from(steps_case_, released), released,
      "on degree of freedom 1000000000, not a finite force on a free degree of freedom");
  const fs::path offsets = changed_copy(
      "offsets.bin",
      [](auto& b, auto& l) {
        const auto n = get<std::int64_t>(b, l.offsets[0]);
        put<std::int64_t>(b, l.offsets[0], 0);
        b.erase(l.offsets[0] + 8, 8 * static_cast<std::size_t>(n));
      },
      true);
  expect_rejected(run_from(steps_case_, offsets), offsets,
                  "holds 0 offsets for step[2].boundary.prescribed");
  const fs::path step = changed_copy(
      "step.bin", [](auto& b, auto& l) { put<std::int64_t>(b, l.active_step, 0); }, true);
  expect_rejected(run_from(steps_case_, step), step,
                  "its state at t = 1.75 s is in analysis step 1 'press', which runs from t = 0 "
                  "to 1 s");
}

TEST_F(CliRestartFile, AFileOfRestartFormat1IsAnInputError) {
  std::string v1 = bytes_.substr(0, 64); // format 1 had the same magic, then version 1
  put<std::int64_t>(v1, RestartLayout::kVersion, 1);
  const fs::path old = write_file("format1.bin", v1);
  expect_rejected(run_from(steps_case_, old), old,
                  "the restart file was written by an older trifem (restart format 1); this "
                  "trifem reads format 3");
}

} // namespace
} // namespace trifem::cli_test
