// SPDX-License-Identifier: MIT
// End-to-end tests of dynamic-explicit analyses ([analysis] type = "dynamic-explicit"): result
// files, the time step, the keys they reject, and the stop on a non-finite value.
#include "cli_harness.hpp"
#include "restart_file_layout.hpp"

#include <cmath>
#include <cstdlib>

using namespace trifem::cli_test;
namespace fs = std::filesystem;

namespace {

const fs::path kBox = kData / "explicit_box.toml";

/// The value of the JSON number `"key": <number>` in `json` (NaN if absent).
double json_number(const std::string& json, const std::string& key) {
  const std::string tag = "\"" + key + "\": ";
  const auto at = json.find(tag);
  return at == std::string::npos ? std::nan("")
                                 : std::strtod(json.c_str() + at + tag.size(), nullptr);
}

/// The numbers of one history.csv row.
std::vector<double> numbers(const std::string& row) {
  std::vector<double> values;
  std::istringstream in(row);
  for (std::string cell; std::getline(in, cell, ',');)
    values.push_back(std::strtod(cell.c_str(), nullptr));
  return values;
}

/// The index of `column` in the header `row` (-1 if absent).
int column_index(const std::string& row, const std::string& column) {
  std::istringstream in(row);
  int i = 0;
  for (std::string cell; std::getline(in, cell, ','); ++i)
    if (cell == column)
      return i;
  return -1;
}

} // namespace

class CliExplicit : public Cli {
protected:
  /// explicit_box.toml with `from` replaced by `to` (which must occur), as `name`.
  fs::path variant(const std::string& name, const std::string& from, const std::string& to) const {
    std::string text = read_text(kBox);
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << "'" << from << "' is not in " << kBox;
    if (at != std::string::npos)
      text.replace(at, from.size(), to);
    return write_file(name, text);
  }
};

// ---------------------------------------------------------------------------------------------
// A successful run

TEST_F(CliExplicit, RunWritesResultsHistoryAndSummary) {
  const Result r = trifem({"run", kBox.string(), "-o", output().string()});
  ASSERT_EQ(r.exit_code, kSuccess) << r;
  EXPECT_TRUE(r.err.empty()) << r;
  EXPECT_TRUE(contains(r.out, "omega_iso")) << "the stable step estimate is logged" << r;
  for (const char* name : {"results.pvd", "volume_0000.vtu", "volume_0004.vtu", "history.csv",
                           "summary.json", "run.log"})
    EXPECT_TRUE(fs::is_regular_file(output() / name)) << name << " is missing";
  EXPECT_FALSE(fs::exists(output() / "volume_0005.vtu")) << "4 intervals + the initial state";

  const std::string pvd = read_text(output() / "results.pvd");
  EXPECT_EQ(count_of(pvd, "<DataSet "), 5u) << pvd;
  EXPECT_TRUE(contains(pvd, R"(timestep="0.0005)")) << "output times are hit" << pvd;
  const std::string vtu = read_text(output() / "volume_0004.vtu");
  for (const char* array :
       {R"(Name="displacement [mm]" NumberOfComponents="3")",
        R"(Name="velocity [mm/s]" NumberOfComponents="3")", R"(Name="multiplier [MPa]")",
        R"(Name="pressure [MPa]")", R"(Name="Jbar-1")"})
    EXPECT_TRUE(contains(vtu, array)) << array << " is missing";

  const std::vector<std::string> rows = lines_of(read_text(output() / "history.csv"));
  ASSERT_GE(rows.size(), 3u);
  EXPECT_EQ(rows[0], "time [s],step,dt [s],iterations,halvings,constraint_residual,max|Jbar-1|,"
                     "max_gauss|J-1|,kinetic [mJ],strain [mJ],external_work [mJ],"
                     "damping_work [mJ],total_energy [mJ],bar.xmin.Rx [N],bar.xmin.Ry [N],"
                     "bar.xmin.Rz [N],tip.ux [mm],tip.uy [mm],tip.uz [mm]");
  const std::vector<double> last = numbers(rows.back());
  const std::string summary = read_text(output() / "summary.json");
  EXPECT_TRUE(contains(summary, R"("status": "completed")")) << summary;
  EXPECT_TRUE(contains(summary, R"("analysis": "dynamic-explicit")")) << summary;
  EXPECT_FALSE(contains(summary, "newton_iterations")) << summary;
  EXPECT_EQ(json_number(summary, "steps"), double(rows.size() - 2)) << "one row per step + t = 0";
  EXPECT_DOUBLE_EQ(last[0], 1e-3) << "the run ends at time.end_time";
  // The time step is the stability estimate (no time.dt), shortened so that each output
  // interval holds equal steps: 2.5e-4 s in ceil(2.5e-4 / used) steps.
  const double used = json_number(summary, "used");
  EXPECT_EQ(used, json_number(summary, "estimate"));
  EXPECT_GT(used, 0.0);
  const double equal = 2.5e-4 / std::ceil(2.5e-4 / used);
  for (std::size_t i = 1; i + 1 < rows.size(); ++i)
    EXPECT_NEAR(numbers(rows[i + 1])[2], equal, 1e-12 * used) << "step " << i;
  // Undamped from rest: kinetic + strain − external work stays near 0 (0.05 % measured).
  const double external = last[column_index(rows[0], "external_work [mJ]")];
  EXPECT_GT(external, 0.0);
  EXPECT_LT(std::abs(last[column_index(rows[0], "total_energy [mJ]")]), 2e-3 * external);
  EXPECT_LT(last[column_index(rows[0], "tip.uz [mm]")], 0.0) << "the tip moves with the load";
  EXPECT_TRUE(contains(summary, R"("exceeded": false)")) << summary;
  EXPECT_LT(json_number(summary, "max_relative_error"), 0.01) << summary;
  EXPECT_FALSE(contains(r.out, "energy balance")) << r;
  EXPECT_TRUE(contains(read_text(output() / "run.log"), "completed: "));
}

TEST_F(CliExplicit, CheckLogsTheStableStepAndWritesNothing) {
  const Result r = trifem({"check", kBox.string()});
  EXPECT_EQ(r.exit_code, kSuccess) << r;
  EXPECT_TRUE(contains(r.out, "20 nodes, 4 hex8 cells")) << r;
  EXPECT_TRUE(contains(r.out, "stable dt = ")) << r;
  EXPECT_TRUE(contains(r.out, "check passed")) << r;
  EXPECT_TRUE(r.err.empty()) << r;
  EXPECT_FALSE(fs::exists(dir_ / "results"));
}

TEST_F(CliExplicit, RequestedStepAboveTheEstimateIsReducedWithAWarning) {
  const fs::path file = variant("big_dt.toml", "end_time = 1e-3", "end_time = 1e-3\ndt = 1e-3");
  const Result r = trifem({"run", file.string(), "-o", output().string()});
  ASSERT_EQ(r.exit_code, kSuccess) << r;
  EXPECT_TRUE(contains(r.out, "time.dt = 0.001 s is above the stability estimate")) << r;
  const std::string summary = read_text(output() / "summary.json");
  EXPECT_TRUE(contains(summary, R"("reduced": true)")) << summary;
  EXPECT_EQ(json_number(summary, "requested"), 1e-3) << summary;
  EXPECT_LT(json_number(summary, "used"), 1e-4) << summary;
  EXPECT_EQ(json_number(summary, "used"), json_number(summary, "estimate")) << summary;
}

// time.dt = 5e-5 s is 1.34 times the critical step 3.74e-5 s, and stable_step = "none" trusts
// it: the run is unstable, and the energy balance at the output times says so.
TEST_F(CliExplicit, UnstableStepIsFlaggedByTheEnergyBalance) {
  std::string text = read_text(variant("dt.toml", "end_time = 1e-3", "end_time = 1e-3\ndt = 5e-5"));
  text.replace(text.find("penalty = 4000.0"), 16, "penalty = 4000.0\nstable_step = \"none\"");
  const fs::path file = write_file("unstable.toml", text);
  const Result r = trifem({"run", file.string(), "-o", output().string()});
  ASSERT_TRUE(fs::is_regular_file(output() / "summary.json")) << r;
  EXPECT_TRUE(contains(r.out, "the energy balance is off by")) << r;
  EXPECT_TRUE(contains(r.out, "lower explicit.safety_factor")) << r;
  const std::string summary = read_text(output() / "summary.json");
  EXPECT_TRUE(contains(summary, R"("exceeded": true)")) << summary;
  EXPECT_GT(json_number(summary, "max_relative_error"), 0.05) << summary;
}

TEST_F(CliExplicit, IntervalZeroWritesEveryStep) {
  const fs::path file = variant("every.toml", "interval = 2.5e-4", "interval = 0.0");
  ASSERT_EQ(trifem({"run", file.string(), "-o", output().string()}).exit_code, kSuccess);
  const std::size_t rows = lines_of(read_text(output() / "history.csv")).size();
  EXPECT_EQ(count_of(read_text(output() / "results.pvd"), "<DataSet "), rows - 1);
  EXPECT_GT(rows, 30u);
}

// history_interval thins the history rows: the first step at or after each multiple of 2e-4 s,
// the output times and the end, each row the every-step run's row of the same step, bit for bit
// (the integration does not depend on the rows written).
TEST_F(CliExplicit, HistoryIntervalWritesTheEveryStepRowsAtItsMultiples) {
  const fs::path every = output() / "every", thinned = output() / "thinned";
  ASSERT_EQ(trifem({"-q", "run", kBox.string(), "-o", every.string()}).exit_code, kSuccess);
  const fs::path file =
      variant("thinned.toml", "interval = 2.5e-4", "interval = 2.5e-4\nhistory_interval = 2e-4");
  ASSERT_EQ(trifem({"-q", "run", file.string(), "-o", thinned.string()}).exit_code, kSuccess);
  const std::vector<std::string> all = lines_of(read_text(every / "history.csv"));
  const std::vector<std::string> some = lines_of(read_text(thinned / "history.csv"));
  ASSERT_GT(all.size(), 2 * some.size()) << "rows are left out";
  EXPECT_EQ(some.front(), all.front()); // the header
  const int step = column_index(all.front(), "step");
  ASSERT_GE(step, 0);
  std::size_t at = 1;
  double last = -1.0;
  for (std::size_t i = 1; i < some.size(); ++i) {
    while (at < all.size() && numbers(all[at])[step] != numbers(some[i])[step])
      ++at;
    ASSERT_LT(at, all.size()) << "row " << i << " is no step of the every-step run";
    EXPECT_EQ(some[i], all[at]) << "row " << i;
    const double t = numbers(some[i])[0];
    if (i > 1) // no multiple of 2e-4 s passes without a row (the steps are below 3e-5 s)
      EXPECT_LE(t - last, 2e-4 + 3e-5) << "row " << i;
    last = t;
  }
  EXPECT_EQ(some.back(), all.back());
  // only dynamic-explicit steps take it
  const fs::path quasi = write_file("quasi.toml", read_text(kData / "friction_block.toml") +
                                                      "history_interval = 0.5\n");
  const Result r = trifem({"check", quasi.string()});
  EXPECT_EQ(r.exit_code, kInvalidInput) << r;
  EXPECT_TRUE(contains(r.err, "output.history_interval")) << r;
}

TEST_F(CliExplicit, ExactConstraintIsAccepted) {
  const fs::path file = variant("inf.toml", "penalty = 4000.0", "penalty = inf");
  const Result r = trifem({"check", file.string()});
  EXPECT_EQ(r.exit_code, kSuccess) << r;
  EXPECT_TRUE(contains(r.out, "penalty inf MPa")) << r;
}

// ---------------------------------------------------------------------------------------------
// Invalid input: exit code 2, one error line naming the key

TEST_F(CliExplicit, MissingDensityIsNamed) {
  expect_invalid_input(variant("no_density.toml", "density = 1.1e-9", ""),
                       {"materials.rubber.density", "missing required key", "dynamic-explicit"});
}

TEST_F(CliExplicit, ExplicitTableNeedsTheExplicitAnalysis) {
  expect_invalid_input(
      variant("quasi_static.toml", "type = \"dynamic-explicit\"", "type = \"quasi-static\""),
      {"explicit: only applies to dynamic-explicit analyses", "(line "});
}

TEST_F(CliExplicit, UnknownAnalysisTypeIsNamed) {
  expect_invalid_input(variant("typo.toml", "type = \"dynamic-explicit\"", "type = \"explicit\""),
                       {"analysis.type = 'explicit'", "unknown analysis type",
                        "quasi-static, dynamic, dynamic-explicit"});
}

TEST_F(CliExplicit, QuasiStaticTimeKeyIsRejected) {
  expect_invalid_input(variant("growth.toml", "end_time = 1e-3", "end_time = 1e-3\ngrowth = 1.5"),
                       {"time.growth", "quasi-static analyses only"});
}

TEST_F(CliExplicit, SolverTableIsRejected) {
  expect_invalid_input(variant("solver.toml", "[time]", "[solver]\nmax_iterations = 5\n\n[time]"),
                       {"solver: applies to quasi-static analyses only", "[explicit]"});
}

TEST_F(CliExplicit, MixtureMaterialIsRejected) {
  expect_invalid_input(kData / "explicit_mixture.toml",
                       {"materials.gel.type = 'biphasic'", "not supported in dynamic-explicit"});
}

TEST_F(CliExplicit, PrescribedDisplacementMovesTheEnd) {
  // the free end pulled sideways by 0.05 mm over the first half of the run
  const fs::path file =
      variant("prescribed.toml", "[[loads.traction]]",
              "[curves.ramp]\npoints = [[0.0, 0.0], [5e-4, 1.0]]\n\n[[boundary.prescribed]]\n"
              "set = \"bar.xmax\"\ncomponent = \"y\"\nvalue = 0.05\ncurve = \"ramp\"\n\n"
              "[[loads.traction]]");
  const Result r = trifem({"run", file.string(), "-o", output().string()});
  ASSERT_EQ(r.exit_code, kSuccess) << r;
  const std::vector<std::string> rows = lines_of(read_text(output() / "history.csv"));
  const int uy = column_index(rows[0], "tip.uy [mm]");
  // the probe (4, 0.5, 1) lies on the prescribed face: it follows the ramp exactly (the curve's
  // point 0.5 ms is a time the steps land on)
  bool halfway = false;
  for (std::size_t i = 1; i < rows.size(); ++i)
    if (const std::vector<double> row = numbers(rows[i]); std::abs(row[0] - 5e-4) < 1e-15) {
      EXPECT_NEAR(row[uy], 0.05, 1e-12);
      halfway = true;
    }
  EXPECT_TRUE(halfway) << "no step at t = 0.5 ms";
  const std::vector<double> last = numbers(rows.back());
  EXPECT_NEAR(last[uy], 0.05, 1e-12);
  // the energy balance counts the work of the moving support
  const double work = last[column_index(rows[0], "external_work [mJ]")];
  EXPECT_GT(work, 0.0);
  EXPECT_LT(std::abs(last[column_index(rows[0], "total_energy [mJ]")]), 1e-2 * work);
}

TEST_F(CliExplicit, ARunRestartedInsideTheRunContinuesTheUninterruptedOne) {
  // the restart file holds the integrator's state (half-step velocity, multipliers, step
  // sizes, the work done so far and the supports' last step): with a moving support and a
  // factorization serving up to 3 steps (refactorized at every restart point in both runs),
  // the continued run takes the same steps to round-off
  std::string text = read_text(kBox);
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"[[loads.traction]]",
            "[curves.ramp]\npoints = [[0.0, 0.0], [5e-4, 1.0]]\n\n[[boundary.prescribed]]\n"
            "set = \"bar.xmax\"\ncomponent = \"y\"\nvalue = 0.05\ncurve = \"ramp\"\n\n"
            "[[loads.traction]]"},
           {"penalty = 4000.0", "penalty = 4000.0\nfactorization_age = 3"}})
    text.replace(text.find(from), from.size(), to);
  const fs::path file = write_file("restart.toml", text);
  const fs::path whole = output() / "whole", resumed = output() / "resumed";
  Result r = trifem({"-q", "run", file.string(), "-o", whole.string(), "--write-restart"});
  ASSERT_EQ(r.exit_code, kSuccess) << r;
  const std::vector<fs::path> files = restart_files(whole);
  ASSERT_EQ(files.size(), 4u) << "one per output time: 0.25, 0.5, 0.75 and 1 ms";
  r = trifem({"-q", "run", file.string(), "-o", resumed.string(), "--restart", files[1].string()});
  ASSERT_EQ(r.exit_code, kSuccess) << r;
  const History a = read_history(whole / "history.csv");
  const History b = read_history(resumed / "history.csv");
  ASSERT_EQ(a.names, b.names);
  ASSERT_GT(b.columns[0].size(), 10u);
  ASSERT_EQ(a.columns[0].size() - b.columns[0].size() + 1, a.columns[0].size() / 2 + 1)
      << "the continued run starts at 0.5 ms";
  EXPECT_NEAR(b["time [s]"].front(), 5e-4, 1e-15);
  const std::map<std::string, double> scale = unit_scales(a);
  const std::size_t offset = a.columns[0].size() - b.columns[0].size();
  for (std::size_t c = 0; c < a.names.size(); ++c) {
    double column = 1.0; // a unitless column: against its own largest magnitude, at least 1
    for (const double v : a.columns[c])
      column = std::max(column, std::abs(v));
    const std::string unit = unit_of(a.names[c]);
    const double tolerance = 1e-12 * (unit.empty() ? column : scale.at(unit));
    for (std::size_t i = 1; i < b.columns[c].size(); ++i) // row 0: the restart state itself
      ASSERT_LE(std::abs(b.columns[c][i] - a.columns[c][offset + i]), tolerance)
          << a.names[c] << " at t = " << b.columns[0][i];
  }
  const std::string summary = read_text(resumed / "summary.json");
  EXPECT_EQ(json_number(summary, "steps"), json_number(read_text(whole / "summary.json"), "steps"));

  // an integrator state of the right size with an invalid value (as another program could
  // write it, the checksum resealed) is an input error naming the file
  std::string bytes = read_text(files[1]);
  const trifem::test::RestartLayout layout = trifem::test::restart_layout(bytes);
  trifem::test::put<double>(bytes, layout.integrator + 8, -1.0); // the halvings
  trifem::test::reseal(bytes);
  const fs::path damaged = write_file("damaged.bin", bytes);
  r = trifem(
      {"run", file.string(), "-o", (output() / "damaged").string(), "--restart", damaged.string()});
  EXPECT_EQ(r.exit_code, kInvalidInput) << r;
  EXPECT_TRUE(contains(r.err, damaged.string() + ": the dynamic-explicit step's state is invalid "
                                                 "(-1 halvings)"))
      << r;
}

TEST_F(CliExplicit, FluxFieldIsRejected) {
  expect_invalid_input(
      variant("flux.toml", "set = \"bar.xmin\"", "set = \"bar.xmin\"\nfield = \"fluid_flux\""),
      {"boundary.fixed[1].field = 'fluid_flux'", "only the displacement field"});
}

TEST_F(CliExplicit, NegativePenaltyIsOutOfRange) {
  expect_invalid_input(variant("penalty.toml", "penalty = 4000.0", "penalty = -1.0"),
                       {"explicit.penalty = -1", "(0, inf) MPa", "or inf"});
}

TEST_F(CliExplicit, RunOfMoreStepsThanAllowedIsRefusedWithTheStableStep) {
  // 2^31 s at the stability estimate (3e-5 s) would be 7e13 steps: refused at once, before
  // any output, naming the step and the count (it ran until killed)
  expect_invalid_input(
      variant("endless.toml", "end_time = 1e-3\n\n[output]\ninterval = 2.5e-4",
              "end_time = 2147483648.0\n\n[output]\ninterval = 1e6"),
      {"time.end_time = 2.14748e+09 s", "stability estimate", "e+13 steps", "1e+08 allowed"});
}

TEST_F(CliExplicit, UndefinedSurfaceOfALoadIsNamed) {
  expect_invalid_input(variant("surface.toml", "surface = \"bar.xmax\"", "surface = \"bar.top\""),
                       {"loads.traction[1].surface", "bar.top"});
}

// ---------------------------------------------------------------------------------------------
// A non-finite value stops the run: exit code 3, the step, cell and quantity named, the
// results written so far kept

TEST_F(CliExplicit, NonFiniteValueStopsTheRunKeepingTheResults) {
  const Result r =
      trifem({"run", (kData / "explicit_nonfinite.toml").string(), "-o", output().string()});
  EXPECT_EQ(r.exit_code, kAnalysisFailed) << r;
  const std::vector<std::string> errors = error_lines(r.err);
  ASSERT_EQ(errors.size(), 1u) << r;
  ASSERT_EQ(lines_of(r.err).size(), 1u) << r;
  for (const char* part :
       {"explicit_nonfinite.toml", "step 1 (t = 0 s)", "non-finite displacement", "cell 3"})
    EXPECT_TRUE(contains(errors[0], part)) << "'" << part << "' is not named" << r;

  const std::vector<std::string> rows = lines_of(read_text(output() / "history.csv"));
  ASSERT_EQ(rows.size(), 2u) << "header + the initial state";
  EXPECT_TRUE(rows[1].starts_with("0,0,0,")) << rows[1];
  EXPECT_EQ(count_of(read_text(output() / "results.pvd"), "<DataSet "), 1u);
  EXPECT_TRUE(fs::is_regular_file(output() / "volume_0000.vtu"));
  const std::string summary = read_text(output() / "summary.json");
  EXPECT_TRUE(contains(summary, R"("status": "failed")")) << summary;
  EXPECT_EQ(json_number(summary, "steps"), 0.0) << summary;
  EXPECT_TRUE(contains(summary, "non-finite displacement in cell 3")) << summary;
}

class CliExplicitCells : public CliExplicit, public testing::WithParamInterface<const char*> {};

TEST_P(CliExplicitCells, AFreeBarFallsWithTheAccelerationOfItsBodyForce) {
  // the bar of explicit_box.toml without support or traction, under gravity along -z: every
  // node falls as b t² / 2 (central differences integrate a constant acceleration exactly; the
  // lumped masses of quadratic cells and their body forces are lumped alike, so every node has
  // the acceleration b)
  const fs::path file = write_file("falling_bar.toml", std::string(R"(
[analysis]
type = "dynamic-explicit"
[[mesh.box]]
name = "bar"
size = [4.0, 1.0, 1.0]
divisions = [4, 1, 1]
cell = ")") + GetParam() + R"("
material = "rubber"
[materials.rubber]
type = "neo-hookean"
E = 0.8
density = 1.1e-9
[[loads.body_force]]
force = [0.0, 0.0, -9810.0]
[explicit]
penalty = 4000.0
[time]
end_time = 1e-3
[output]
interval = 2.5e-4
[[output.probe]]
name = "tip"
point = [4.0, 0.5, 1.0]
)");
  const Result r = trifem({"-q", "run", file.string(), "-o", output().string()});
  ASSERT_EQ(r.exit_code, kSuccess) << r;
  const History h = read_history(output() / "history.csv");
  const auto& time = h["time [s]"];
  const auto& tip = h["tip.uz [mm]"];
  ASSERT_GE(time.size(), 4u);
  for (std::size_t i = 0; i < time.size(); ++i)
    EXPECT_NEAR(tip[i], -0.5 * 9810.0 * time[i] * time[i], 1e-9 * 0.004905) << time[i];
  EXPECT_NEAR(time.back(), 1e-3, 1e-15);
}

INSTANTIATE_TEST_SUITE_P(Families, CliExplicitCells, testing::Values("hex8", "tet10", "hex20"),
                         [](const auto& info) { return std::string(info.param); });
