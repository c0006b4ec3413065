// SPDX-License-Identifier: MIT
// A mixed run ([[step]] analysis = "dynamic-explicit" after a quasi-static step) through
// `trifem run`'s analysis: a neo-Hookean bar (nu = 0, lateral faces free) is stretched by 1 %
// quasi-statically (step 1), then its end is released in a dynamic-explicit step (step 2) and the
// bar vibrates freely. Checks, against quantities computed independently of the run:
// - the explicit step starts from the quasi-static end state (same displacements, same time);
// - its initial strain energy equals the closed-form strain energy of the homogeneous uniaxial
//   state, V (mu/2 (s^2 - 1) - mu ln s) (nu = 0: no lateral contraction);
// - the energy balance: kinetic + strain stays at that initial energy (no loads, no damping) up
//   to the time-discretisation error of central differences, which is of second order (halving
//   the step divides it by 4: it is not a bias of the initial state);
// - the free end oscillates about the undeformed length with the period 4 L / c, c = sqrt(E/rho),
//   of the fixed-free bar (linear theory, an error of order of the strain squared).
#include "history_csv.hpp"
#include "restart_file_layout.hpp"
#include "trifem/analysis/run.hpp"
#include "trifem/io/case_reader.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

using namespace trifem;

namespace {

constexpr Real kLength = 10.0;   // mm
constexpr Real kE = 1.0;         // MPa
constexpr Real kDensity = 1e-9;  // t/mm^3
constexpr Real kStretch = 1.01;  // of step 1
constexpr Real kQsEnd = 1.0;     // s, end of step 1
constexpr Real kDuration = 2e-3; // s, of step 2 (about 1.6 periods)

const std::string kCase = R"(
title = "bar stretched quasi-statically, then released dynamically"

[[mesh.box]]
name = "bar"
size = [10.0, 1.0, 1.0]
divisions = [20, 1, 1]
material = "rubber"

[materials.rubber]
type = "neo-hookean"
E = 1.0
nu = 0.0
density = 1e-9

[curves.ramp]
points = [[0.0, 0.0], [1.0, 1.0]]

[[boundary.fixed]]            # symmetry planes: the lateral faces stay free
set = "bar.xmin"
components = ["x"]
[[boundary.fixed]]
set = "bar.ymin"
components = ["y"]
[[boundary.fixed]]
set = "bar.zmin"
components = ["z"]

[explicit]
multiplier = false            # the law's own bulk response, as in the quasi-static step

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
name = "release"              # bar.xmax is released at once
analysis = "dynamic-explicit"
duration = 2e-3

[[output.probe]]
name = "tip"
point = [10.0, 0.0, 0.0]
[[output.probe]]
name = "corner"
point = [10.0, 1.0, 1.0]
[[output.probe]]
name = "middle"
point = [5.0, 1.0, 0.0]
)";

/// Closed-form strain energy of the bar at axial stretch s: nu = 0 gives lambda = 0, no lateral
/// contraction (S_yy = mu (1 - 1/t^2) = 0 at t = 1), W = mu/2 (s^2 - 1) - mu ln s.
Real uniaxial_energy(Real s) {
  const Real mu = kE / 2.0, volume = kLength * 1.0 * 1.0;
  return volume * (0.5 * mu * (s * s - 1.0) - mu * std::log(s));
}

/// The energy balance error max |kinetic + strain - W0| / W0 over the rows of `h`.
Real energy_error(const test::History& h, Real W0) {
  const auto& kinetic = h["kinetic [mJ]"];
  const auto& strain = h["strain [mJ]"];
  Real worst = 0.0;
  for (std::size_t i = 0; i < kinetic.size(); ++i)
    worst = std::max(worst, std::abs(kinetic[i] + strain[i] - W0) / W0);
  return worst;
}

/// Runs `text` as case `name` in `dir` with `options`; the exit code.
int run_text(const std::filesystem::path& dir, const std::string& name, const std::string& text,
             const analysis::RunOptions& options = {}) {
  const auto file = dir / (name + ".toml");
  std::ofstream(file) << text;
  return analysis::run_case(io::read_case(file), dir / name, options);
}

/// Times at which `u` crosses zero (linear interpolation between rows).
std::vector<Real> zero_crossings(const std::vector<double>& t, const std::vector<double>& u) {
  std::vector<Real> out;
  for (std::size_t i = 1; i < u.size(); ++i)
    if ((u[i - 1] > 0.0) != (u[i] > 0.0))
      out.push_back(t[i - 1] + (t[i] - t[i - 1]) * u[i - 1] / (u[i - 1] - u[i]));
  return out;
}

class QuasiStaticThenExplicit : public ::testing::Test {
protected:
  static void SetUpTestSuite() {
    // one directory per process: ctest runs each test of this suite in its own process
    dir_ = std::filesystem::temp_directory_path() /
           fmt::format("trifem_qs_then_explicit_{}", static_cast<long>(getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    exit_code_ = run_text(dir_, "results", kCase);
    qs_ = test::read_history(dir_ / "results" / "history.csv");
    ex_ = test::read_history(dir_ / "results" / "history_step2.csv");
    std::ifstream summary(dir_ / "results" / "summary.json");
    summary_ = nlohmann::json::parse(summary);
    // the same run with half the explicit step (the steps of the run above are equal)
    if (ex_.names.empty() || ex_["dt [s]"].size() < 2)
      return;
    step_ = ex_["dt [s]"][1];
    std::string halved = kCase;
    const std::string duration = "duration = 2e-3";
    halved.replace(halved.find(duration), duration.size(),
                   fmt::format("{}\ndt = {:.17g}", duration, 0.5 * step_));
    half_exit_code_ = run_text(dir_, "halved", halved);
    half_ = test::read_history(dir_ / "halved" / "history_step2.csv");
  }
  static void TearDownTestSuite() { std::filesystem::remove_all(dir_); }
  static inline std::filesystem::path dir_;
  static inline int exit_code_ = -1;
  static inline int half_exit_code_ = -1;
  static inline Real step_ = 0.0; ///< explicit step of the first run [s]
  static inline test::History qs_, ex_, half_;
  static inline nlohmann::json summary_;
};

TEST_F(QuasiStaticThenExplicit, CompletesWithOneSummaryOfBothSteps) {
  ASSERT_EQ(exit_code_, analysis::kSuccess);
  EXPECT_EQ(summary_["status"], "completed");
  EXPECT_NEAR(summary_["end_time_s"].get<double>(), kQsEnd + kDuration, 1e-12);
  ASSERT_EQ(summary_["analysis_steps"].size(), 2u);
  EXPECT_EQ(summary_["analysis_steps"][0]["analysis"], "quasi-static");
  EXPECT_EQ(summary_["analysis_steps"][1]["analysis"], "dynamic-explicit");
  EXPECT_EQ(summary_["analysis_steps"][1]["history"], "history_step2.csv");
  EXPECT_FALSE(summary_["dynamic_explicit"]["energy_balance"]["exceeded"].get<bool>());
}

TEST_F(QuasiStaticThenExplicit, OneCollectionWithIncreasingTimes) {
  std::ifstream in(dir_ / "results" / "results.pvd");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<Real> times;
  for (std::size_t at = text.find("timestep=\""); at != std::string::npos;
       at = text.find("timestep=\"", at + 1))
    times.push_back(std::stod(text.substr(at + 10)));
  ASSERT_GT(times.size(), 50u); // the quasi-static states and about 100 explicit ones
  EXPECT_TRUE(std::is_sorted(times.begin(), times.end()));
  EXPECT_EQ(std::adjacent_find(times.begin(), times.end()), times.end()); // t0 written once
  EXPECT_DOUBLE_EQ(times.front(), 0.0);
  EXPECT_NEAR(times.back(), kQsEnd + kDuration, 1e-12);
  EXPECT_TRUE(std::filesystem::exists(dir_ / "results" /
                                      fmt::format("volume_{:04d}.vtu", times.size() - 1)));
}

TEST_F(QuasiStaticThenExplicit, StartsFromTheQuasiStaticState) {
  ASSERT_FALSE(qs_.names.empty());
  ASSERT_FALSE(ex_.names.empty());
  EXPECT_EQ(qs_["time [s]"].back(), kQsEnd);
  EXPECT_EQ(ex_["time [s]"].front(), kQsEnd); // the time continues
  EXPECT_NEAR(qs_["tip.ux [mm]"].back(), (kStretch - 1.0) * kLength, 1e-12 * kLength);
  for (const char* probe : {"tip", "corner", "middle"})
    for (const char* axis : {"x", "y", "z"}) {
      const std::string column = fmt::format("{}.u{} [mm]", probe, axis);
      EXPECT_NEAR(ex_[column].front(), qs_[column].back(), 1e-12 * kLength) << column;
    }
  EXPECT_EQ(ex_["kinetic [mJ]"].front(), 0.0); // at rest
}

TEST_F(QuasiStaticThenExplicit, InitialEnergyIsTheUniaxialStrainEnergy) {
  const Real W0 = uniaxial_energy(kStretch);
  const Real initial = ex_["strain [mJ]"].front();
  std::printf("initial strain energy %.10g mJ, closed form %.10g mJ, relative error %.2e\n",
              initial, W0, std::abs(initial - W0) / W0);
  EXPECT_NEAR(initial, W0, 1e-9 * W0);
  EXPECT_NEAR(summary_["dynamic_explicit"]["energies_mJ"]["initial"].get<double>(), W0, 1e-9 * W0);
}

TEST_F(QuasiStaticThenExplicit, EnergyBalanceHoldsToSecondOrderInTheStep) {
  const Real W0 = uniaxial_energy(kStretch);
  const auto& kinetic = ex_["kinetic [mJ]"];
  const auto& strain = ex_["strain [mJ]"];
  const auto& total = ex_["total_energy [mJ]"];
  Real largest_kinetic = 0.0;
  for (std::size_t i = 0; i < total.size(); ++i) {
    EXPECT_NEAR(total[i], kinetic[i] + strain[i], 1e-14 * W0); // no loads, no damping
    largest_kinetic = std::max(largest_kinetic, kinetic[i]);
  }
  ASSERT_EQ(half_exit_code_, analysis::kSuccess);
  const Real error = energy_error(ex_, W0), half = energy_error(half_, W0);
  std::printf("energy balance: max |kinetic + strain - W0| / W0 = %.3e with dt = %.4g s (%zu "
              "steps), %.3e with dt/2 (ratio %.2f); largest kinetic energy %.4f W0\n",
              error, step_, total.size() - 1, half, error / half, largest_kinetic / W0);
  EXPECT_GT(largest_kinetic, 0.9 * W0); // the energy really changes form
  // The sudden release excites the mesh's highest modes, whose energy central differences
  // measure to O((omega dt)^2): well within the 5 % alarm at the default step...
  EXPECT_LT(error, 1e-2);
  EXPECT_NEAR(summary_["dynamic_explicit"]["energy_balance"]["max_relative_error"].get<double>(),
              error, 0.05 * error); // the run's own check measures the same
  // ...and a time-discretisation error of second order, not a misplaced initial energy
  EXPECT_NEAR(error / half, 4.0, 0.5);
}

TEST_F(QuasiStaticThenExplicit, FreeEndOscillatesWithTheFirstAxialPeriod) {
  const Real period = 4.0 * kLength / std::sqrt(kE / kDensity);
  const Real amplitude = (kStretch - 1.0) * kLength;
  const auto& t = ex_["time [s]"];
  const auto& u = ex_["tip.ux [mm]"];
  const std::vector<Real> crossings = zero_crossings(t, u);
  ASSERT_GE(crossings.size(), 3u);
  // the end displacement is a triangle wave: zero at T/4, 3T/4, 5T/4 after the release
  const Real measured = crossings[2] - crossings[0];
  const Real first = crossings[0] - kQsEnd;
  const Real lowest = *std::min_element(u.begin(), u.end());
  std::printf("period %.6e s, 4L/c = %.6e s (%.2f %%); first zero crossing at %.4f T; lowest "
              "end displacement %.5f of -amplitude\n",
              measured, period, 100.0 * (measured / period - 1.0), first / period,
              -lowest / amplitude);
  EXPECT_NEAR(measured, period, 0.02 * period);
  EXPECT_NEAR(first, 0.25 * period, 0.02 * period);
  EXPECT_NEAR(lowest, -amplitude, 0.05 * amplitude); // about the undeformed length
}

TEST_F(QuasiStaticThenExplicit, QuasiStaticStepAfterTheReleaseReturnsToTheStretchedState) {
  // stretch, release (the bar vibrates), stretch again to the same prescribed end: the third
  // step starts from the vibrating explicit state on the same mesh and ends at the equilibrium
  // of the first
  const std::string text = kCase + R"(
[[step]]
name = "restretch"
duration = 1.0
dt = 0.25
[[step.boundary.prescribed]]
set = "bar.xmax"
component = "x"
value = 0.1
)";
  ASSERT_EQ(run_text(dir_, "three_steps", text), 0);
  const test::History qs = test::read_history(dir_ / "three_steps" / "history.csv");
  const test::History ex = test::read_history(dir_ / "three_steps" / "history_step2.csv");
  const auto& t = qs["time [s]"];
  ASSERT_NEAR(t.back(), kQsEnd + kDuration + 1.0, 1e-12) << "the third step ends the run";
  const auto first_end = std::find(t.begin(), t.end(), kQsEnd);
  ASSERT_NE(first_end, t.end());
  const std::size_t i = static_cast<std::size_t>(first_end - t.begin()), last = t.size() - 1;
  ASSERT_GT(last, i) << "the rows of the third step follow those of the first";
  EXPECT_GT(std::abs(ex["tip.ux [mm]"].back() - qs["tip.ux [mm]"][i]), 1e-3)
      << "the release moved the free end";
  for (const char* column : {"tip.ux [mm]", "corner.ux [mm]", "corner.uy [mm]", "middle.ux [mm]"})
    EXPECT_NEAR(qs[column][last], qs[column][i], 1e-9 * kLength) << column;
  const nlohmann::json summary =
      nlohmann::json::parse(std::ifstream(dir_ / "three_steps" / "summary.json"));
  EXPECT_EQ(summary["status"], "completed");
  EXPECT_EQ(summary["analysis_steps"][2]["history"], "history.csv");
}

/// kCase with a release of 1e-3 s at dt = 1e-5 s (its output times are multiples of the step)
/// and `more` appended.
std::string released_with_fixed_step(const std::string& more) {
  std::string text = kCase;
  const std::string duration = "duration = 2e-3";
  text.replace(text.find(duration), duration.size(), "duration = 1e-3\ndt = 1e-5");
  return text + more;
}

/// The released end at the end of the run, one explicit release of 2e-3 s against a release of
/// 1e-3 s followed by a step `analysis` of 1e-3 s: a step after a dynamic one starts with its
/// velocity (at rest the free end would stop mid-stroke).
class MotionAcrossSteps : public QuasiStaticThenExplicit {
protected:
  /// Runs the split case with a release of `release` and a third step of `analysis`; the
  /// history of the third step.
  test::History split_run(const std::string& name, const std::string& release,
                          const std::string& analysis) {
    const bool implicit = release == "dynamic" || analysis == "dynamic";
    const char* kLumped = "[dynamic]\nmass = \"lumped\"  # as the explicit steps'\n";
    std::string text = released_with_fixed_step(fmt::format(R"(
[[step]]
name = "continue"
analysis = "{}"
duration = 1e-3
dt = 1e-5
{})",
                                                            analysis, implicit ? kLumped : ""));
    const std::string explicit_release = "analysis = \"dynamic-explicit\"";
    text.replace(text.find(explicit_release), explicit_release.size(),
                 fmt::format("analysis = \"{}\"", release));
    EXPECT_EQ(run_text(dir_, name, text), 0) << name;
    return test::read_history(
        dir_ / name / (analysis == "dynamic-explicit" ? "history_step3.csv" : "history.csv"));
  }
  /// The one-step release over the same 2e-3 s at the same step.
  test::History whole_run() {
    std::string text = released_with_fixed_step("");
    text.replace(text.find("duration = 1e-3"), 15, "duration = 2e-3");
    EXPECT_EQ(run_text(dir_, "whole", text), 0);
    return test::read_history(dir_ / "whole" / "history_step2.csv");
  }
};

TEST_F(MotionAcrossSteps, AnExplicitStepAfterAnExplicitStepContinuesItsMotion) {
  const test::History whole = whole_run();
  const test::History split = split_run("explicit_twice", "dynamic-explicit", "dynamic-explicit");
  const test::History first = test::read_history(dir_ / "explicit_twice" / "history_step2.csv");
  ASSERT_FALSE(whole.names.empty());
  ASSERT_FALSE(split.names.empty());
  ASSERT_FALSE(first.names.empty());
  const Real amplitude = (kStretch - 1.0) * kLength;
  EXPECT_NEAR(split["time [s]"].back(), whole["time [s]"].back(), 1e-12);
  // the second explicit step starts with the kinetic energy the first one ended with
  EXPECT_GT(first["kinetic [mJ]"].back(), 0.1 * uniaxial_energy(kStretch));
  EXPECT_NEAR(split["kinetic [mJ]"].front(), first["kinetic [mJ]"].back(),
              1e-9 * uniaxial_energy(kStretch));
  // central differences continue where they stopped: the same steps as one release
  for (const char* column : {"tip.ux [mm]", "corner.ux [mm]", "middle.ux [mm]"})
    EXPECT_NEAR(split[column].back(), whole[column].back(), 1e-9 * amplitude) << column;
  EXPECT_NEAR(split["kinetic [mJ]"].back(), whole["kinetic [mJ]"].back(),
              1e-9 * uniaxial_energy(kStretch));
}

/// The released end at the end of the run: `split` against one explicit release.
void expect_close_to_the_explicit_release(const test::History& split, const test::History& whole) {
  ASSERT_FALSE(whole.names.empty());
  ASSERT_FALSE(split.names.empty());
  const Real amplitude = (kStretch - 1.0) * kLength;
  const Real tip = split["tip.ux [mm]"].back(), reference = whole["tip.ux [mm]"].back();
  std::printf("tip at t = %.6g s: %.6f mm, explicit release %.6f mm (%.2e of the amplitude)\n",
              split["time [s]"].back(), tip, reference, std::abs(tip - reference) / amplitude);
  // two second-order integrators at the same step: their difference is the time-discretisation
  // error of the sudden release's fastest modes, far below the amplitude (a step started at
  // rest instead misses by 0.8 of it)
  EXPECT_NEAR(tip, reference, 0.05 * amplitude);
}

TEST_F(MotionAcrossSteps, AnImplicitDynamicStepAfterAnExplicitStepContinuesItsMotion) {
  expect_close_to_the_explicit_release(
      split_run("explicit_then_implicit", "dynamic-explicit", "dynamic"), whole_run());
}

TEST_F(MotionAcrossSteps, AnExplicitStepAfterAnImplicitDynamicStepContinuesItsMotion) {
  expect_close_to_the_explicit_release(
      split_run("implicit_then_explicit", "dynamic", "dynamic-explicit"), whole_run());
}

/// The restart files of a run directory by their time.
std::map<double, std::filesystem::path> restart_files(const std::filesystem::path& dir) {
  std::map<double, std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().filename().string().starts_with("restart_")) {
      std::ifstream in(e.path(), std::ios::binary);
      const std::string bytes((std::istreambuf_iterator<char>(in)), {});
      files[test::get<double>(bytes, test::RestartLayout::kTime)] = e.path();
    }
  return files;
}

/// Every row of `resumed` after its first (the restart state) is the row of `whole` at the
/// same time, each column to 1e-12 of its largest magnitude (at least 1 for unitless ones).
void expect_the_rows_of(const test::History& whole, const test::History& resumed) {
  ASSERT_EQ(whole.names, resumed.names);
  const auto& t = whole["time [s]"];
  ASSERT_GT(resumed["time [s]"].size(), 1u);
  const auto first = std::find(t.begin(), t.end(), resumed["time [s]"][1]);
  ASSERT_NE(first, t.end()) << "the continued run takes other steps";
  const auto offset = static_cast<std::size_t>(first - t.begin()) - 1;
  ASSERT_EQ(t.size() - offset, resumed["time [s]"].size());
  for (std::size_t c = 0; c < whole.names.size(); ++c) {
    double scale = whole.names[c].find('[') == std::string::npos ? 1.0 : 0.0;
    for (const double v : whole.columns[c])
      scale = std::max(scale, std::abs(v));
    for (std::size_t i = 1; i < resumed.columns[c].size(); ++i)
      ASSERT_NEAR(resumed.columns[c][i], whole.columns[c][offset + i], 1e-12 * scale)
          << whole.names[c] << " at t = " << resumed.columns[0][i];
  }
}

TEST_F(MotionAcrossSteps, RestartsInsideAndAtTheEndOfTheExplicitStepContinueTheRun) {
  // quasi-static stretch, explicit release, implicit dynamic continuation; restarted inside the
  // explicit step (the file holds the integrator's state) and at its end (the file holds the
  // velocity the implicit step starts with)
  std::string text = released_with_fixed_step(R"(
[[step]]
name = "continue"
analysis = "dynamic"
duration = 1e-3
dt = 1e-5

[dynamic]
mass = "lumped"
)");
  analysis::RunOptions write;
  write.write_restart = true;
  ASSERT_EQ(run_text(dir_, "restarts", text, write), 0);
  const std::map<double, std::filesystem::path> files = restart_files(dir_ / "restarts");
  const auto inside = files.lower_bound(kQsEnd + 4.9e-4), end = files.lower_bound(kQsEnd + 1e-3);
  ASSERT_NE(inside, files.end());
  ASSERT_NE(end, files.end());
  ASSERT_NEAR(inside->first, kQsEnd + 5e-4, 1e-12);
  ASSERT_NEAR(end->first, kQsEnd + 1e-3, 1e-12);
  const test::History explicit_whole = test::read_history(dir_ / "restarts" / "history_step2.csv");
  const test::History implicit_whole = test::read_history(dir_ / "restarts" / "history.csv");
  for (const auto& [name, file] :
       {std::pair{"from_inside", inside->second}, std::pair{"from_the_end", end->second}}) {
    SCOPED_TRACE(name);
    analysis::RunOptions resume;
    resume.restart_file = file;
    ASSERT_EQ(run_text(dir_, name, text, resume), 0);
    if (std::string(name) == "from_inside")
      expect_the_rows_of(explicit_whole, test::read_history(dir_ / name / "history_step2.csv"));
    expect_the_rows_of(implicit_whole, test::read_history(dir_ / name / "history.csv"));
  }
}

} // namespace
