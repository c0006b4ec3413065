// SPDX-License-Identifier: MIT
// End-to-end tests of contact pairs: the contact-surface files (VTU series, .pvd, surface CSV),
// the contact history columns, and the input checks of a pair (surfaces, facing normals,
// initial penetration).
#include "cli_harness.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

using namespace trifem::cli_test;
namespace fs = std::filesystem;

// A named namespace: a unity build includes this file into another one, where GCC warns of
// test classes whose base (the fixture) has internal linkage (-Wsubobject-linkage).
namespace contact_cli {

constexpr double kQ = 0.1;    ///< pressure on the patch [MPa]
constexpr double kEdge = 1.0; ///< the blocks' depth and the scale of their coordinates [mm]

/// A CSV file read back: column names and numeric rows.
struct CsvTable {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;

  /// Position of column `name`; columns.size() if there is none.
  std::size_t index(const std::string& name) const {
    return static_cast<std::size_t>(std::find(columns.begin(), columns.end(), name) -
                                    columns.begin());
  }
  /// All values of column `name` (empty if there is no such column).
  std::vector<double> column(const std::string& name) const {
    std::vector<double> values;
    const std::size_t i = index(name);
    if (i < columns.size())
      for (const auto& row : rows)
        values.push_back(row.at(i));
    return values;
  }
  /// The value of column `name` in the last row (NaN if there is none).
  double last(const std::string& name) const {
    const std::vector<double> values = column(name);
    return values.empty() ? std::nan("") : values.back();
  }
};

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> parts;
  std::istringstream in(line);
  for (std::string part; std::getline(in, part, ',');)
    parts.push_back(part);
  return parts;
}

CsvTable read_csv(const fs::path& file) {
  CsvTable t;
  const std::vector<std::string> lines = lines_of(read_text(file));
  if (lines.empty())
    return t;
  t.columns = split(lines[0]);
  for (std::size_t i = 1; i < lines.size(); ++i) {
    std::vector<double> row;
    for (const std::string& v : split(lines[i]))
      row.push_back(std::stod(v));
    t.rows.push_back(std::move(row));
  }
  return t;
}

/// Largest |v - mean(v)| / max(|mean(v)|, floor) over the values: `floor` is a scale of the
/// quantity that cannot vanish, so a value near zero does not turn round-off into a spread.
double spread(const std::vector<double>& v, double floor) {
  double mean = 0;
  for (double x : v)
    mean += x / static_cast<double>(v.size());
  double worst = 0;
  for (double x : v)
    worst = std::max(worst, std::abs(x - mean) / std::max(std::abs(mean), floor));
  return worst;
}

const std::vector<std::string> kSolidColumns = {"time [s]",
                                                "X [mm]",
                                                "Y [mm]",
                                                "Z [mm]",
                                                "x [mm]",
                                                "y [mm]",
                                                "z [mm]",
                                                "contact_gap [mm]",
                                                "contact_traction [MPa]",
                                                "contact_active",
                                                "contact_projected",
                                                "normal.x",
                                                "normal.y",
                                                "normal.z",
                                                "nodal_area [mm^2]",
                                                "node"};

class ContactCli : public Cli {
protected:
  /// Runs the patch case; returns whether it succeeded.
  bool run_patch() const {
    const Result r =
        trifem({"run", (kData / "contact_patch.toml").string(), "-o", output().string()});
    EXPECT_EQ(r.exit_code, kSuccess) << r;
    return r.exit_code == kSuccess;
  }

  /// A copy of contact_patch.toml with each `from` replaced by `to` (each must occur).
  fs::path patch_variant(const std::string& name,
                         std::initializer_list<std::pair<std::string, std::string>> edits) const {
    return data_variant("contact_patch.toml", name, edits);
  }

  /// A copy of the data file `source` with each `from` replaced by `to` (each must occur).
  fs::path data_variant(const std::string& source, const std::string& name,
                        std::initializer_list<std::pair<std::string, std::string>> edits) const {
    std::string text = read_text(kData / source);
    for (const auto& [from, to] : edits) {
      const auto at = text.find(from);
      EXPECT_NE(at, std::string::npos) << "'" << from << "' is not in " << source;
      if (at != std::string::npos)
        text.replace(at, from.size(), to);
    }
    return write_file(name, text);
  }

  /// Runs `case_file` with -o output().
  Result run(const fs::path& case_file) const {
    return trifem({"run", case_file.string(), "-o", output().string()});
  }
};

} // namespace contact_cli

using namespace contact_cli;

// ---------------------------------------------------------------------------------------------
// Result files

TEST_F(ContactCli, RunWritesTheContactSurfaceSeries) {
  ASSERT_TRUE(run_patch());
  for (const char* name :
       {"contact1.pvd", "contact1_0000.vtu", "contact1_0001.vtu", "contact1_0002.vtu",
        "contact1_surface_0000.csv", "contact1_surface_0001.csv", "contact1_surface_0002.csv"})
    EXPECT_TRUE(fs::is_regular_file(output() / name)) << name << " is missing";
  EXPECT_FALSE(fs::exists(output() / "contact1_0003.vtu"));
  const std::string pvd = read_text(output() / "contact1.pvd");
  EXPECT_EQ(count_of(pvd, "<DataSet "), 3u) << pvd;
  EXPECT_TRUE(contains(pvd, R"(timestep="1" group="" part="0" file="contact1_0002.vtu")")) << pvd;
  const std::string vtu = read_text(output() / "contact1_0002.vtu");
  EXPECT_TRUE(contains(vtu, R"(NumberOfPoints="10" NumberOfCells="4")")) << "4 x 1 slave facets";
  for (const char* array : {R"(Name="contact_gap [mm]" NumberOfComponents="1")",
                            R"(Name="contact_traction [MPa]" NumberOfComponents="1")",
                            R"(Name="contact_active" NumberOfComponents="1")",
                            R"(Name="contact_projected" NumberOfComponents="1")",
                            R"(Name="normal" NumberOfComponents="3")",
                            R"(Name="nodal_area [mm^2]" NumberOfComponents="1")"})
    EXPECT_TRUE(contains(vtu, array)) << array << " is missing";
  EXPECT_FALSE(contains(vtu, "fluid_chemical_potential")) << "a solid model has no potentials";
}

/// The exact patch solution along the interface: t = -q, g = 0, all active, normal +z, and the
/// nodal areas integrate the traction to the interface force of the history.
TEST_F(ContactCli, SurfaceCsvHoldsThePatchSolution) {
  ASSERT_TRUE(run_patch());
  const CsvTable s = read_csv(output() / "contact1_surface_0002.csv");
  const CsvTable h = read_csv(output() / "history.csv");
  EXPECT_EQ(s.columns, kSolidColumns);
  ASSERT_EQ(s.rows.size(), 10u) << "5 x 2 slave nodes";
  const std::vector<double> X = s.column("X [mm]"), t = s.column("contact_traction [MPa]");
  const std::vector<double> g = s.column("contact_gap [mm]"), z = s.column("z [mm]");
  const std::vector<double> nz = s.column("normal.z"), area = s.column("nodal_area [mm^2]");
  double force = 0, total = 0;
  for (std::size_t k = 0; k < s.rows.size(); ++k) {
    if (k > 0) {
      EXPECT_LE(X[k - 1], X[k]) << "rows are ordered along x (the largest extent)";
    }
    EXPECT_NEAR(t[k], -kQ, 1e-10 * kQ) << "row " << k;
    EXPECT_LE(std::abs(g[k]), 1e-12 * kEdge) << "row " << k; // converged gap rows
    EXPECT_EQ(s.rows[k][s.index("contact_active")], 1.0) << "row " << k;
    EXPECT_EQ(s.rows[k][s.index("contact_projected")], 1.0) << "row " << k;
    EXPECT_NEAR(nz[k], 1.0, 1e-14) << "the slave (lower) face points up"; // a unit vector
    EXPECT_NEAR(z[k], z[0], 1e-14 * kEdge) << "a flat interface"; // 45 ulp of the coordinates
    force += t[k] * area[k] * nz[k];
    total += area[k];
  }
  // the same sums in another order: relative to the force q A and to the area A (~1 mm^2)
  EXPECT_NEAR(force, h.last("contact1.Fz [N]"), 1e-12 * kQ * total);
  EXPECT_NEAR(total, h.last("contact1.area [mm^2]"), 1e-13 * total);
}

/// Area = current width (x of the right edge) x depth 1 mm; master and slave forces are equal
/// and opposite (uniform traction); every slave node is active.
TEST_F(ContactCli, HistoryHasTheContactAreaAndBothForces) {
  ASSERT_TRUE(run_patch());
  const CsvTable h = read_csv(output() / "history.csv");
  const auto first = h.index("contact1.Fx [N]");
  ASSERT_LE(first + 8, h.columns.size());
  const std::vector<std::string> expected = {"contact1.Fx [N]",        "contact1.Fy [N]",
                                             "contact1.Fz [N]",        "contact1.master_Fx [N]",
                                             "contact1.master_Fy [N]", "contact1.master_Fz [N]",
                                             "contact1.area [mm^2]",   "contact1.active_nodes"};
  EXPECT_EQ(std::vector<std::string>(h.columns.begin() + static_cast<std::ptrdiff_t>(first),
                                     h.columns.begin() + static_cast<std::ptrdiff_t>(first) + 8),
            expected);
  ASSERT_EQ(h.rows.size(), 3u);
  const double width = h.last("corner.x [mm]"), area = h.last("contact1.area [mm^2]");
  EXPECT_GT(width, 1.01) << "the blocks expand laterally under the pressure";
  EXPECT_NEAR(area, width * kEdge, 1e-13 * area);
  EXPECT_NEAR(h.column("contact1.area [mm^2]").front(), kEdge * kEdge, 1e-14 * kEdge * kEdge)
      << "t = 0: touching";
  EXPECT_NEAR(h.last("contact1.Fz [N]"), -kQ * area, 1e-10 * kQ * area);
  EXPECT_NEAR(h.last("contact1.master_Fz [N]"), -h.last("contact1.Fz [N]"), 1e-12 * kQ * area);
  EXPECT_EQ(h.last("contact1.active_nodes"), 10.0);
}

/// Triphasic interface: potentials in physical units, laterally uniform; the normal water flux
/// into the slave body equals the volume change rate of the lower (master) body, whose only
/// permeable boundary is the interface (backward Euler balance).
TEST_F(ContactCli, TriphasicSurfaceCsvHasPotentialsAndNormalFluxes) {
  const Result r =
      trifem({"run", (kData / "contact_triphasic_column.toml").string(), "-o", output().string()});
  ASSERT_EQ(r.exit_code, kSuccess) << r;
  const CsvTable s1 = read_csv(output() / "contact1_surface_0001.csv");
  const CsvTable s = read_csv(output() / "contact1_surface_0002.csv");
  const CsvTable h = read_csv(output() / "history.csv");
  std::vector<std::string> columns(kSolidColumns.begin(), kSolidColumns.begin() + 9);
  for (const char* c :
       {"fluid_chemical_potential [MPa]", "cation_electrochemical_potential [mJ/mmol]",
        "anion_electrochemical_potential [mJ/mmol]", "normal_fluid_flux [mm/s]",
        "normal_cation_flux [mmol/(mm^2 s)]", "normal_anion_flux [mmol/(mm^2 s)]"})
    columns.emplace_back(c);
  columns.insert(columns.end(), kSolidColumns.begin() + 9, kSolidColumns.end());
  EXPECT_EQ(s.columns, columns);
  ASSERT_EQ(s.rows.size(), 16u) << "4 x 4 slave nodes";
  // floors of the spread, 1e-4 of each quantity's natural scale (the case's E = M = 0.3 MPa,
  // kappa = 1.07e-3 mm^4/(N s), 1 mm columns; RT; c*): the values stay far above them here
  const double RT = 8.314 * 298, c_ref = 1.5e-4, M = 0.3, flux = M * 1.07e-3 / 1.0;
  const std::map<std::string, double> floors = {
      {"contact_traction [MPa]", 1e-4 * M},
      {"fluid_chemical_potential [MPa]", 1e-4 * M},
      {"cation_electrochemical_potential [mJ/mmol]", 1e-4 * RT},
      {"anion_electrochemical_potential [mJ/mmol]", 1e-4 * RT},
      {"normal_fluid_flux [mm/s]", 1e-4 * flux},
      {"normal_cation_flux [mmol/(mm^2 s)]", 1e-4 * c_ref * flux},
      {"normal_anion_flux [mmol/(mm^2 s)]", 1e-4 * c_ref * flux}};
  for (const std::string& c : std::vector<std::string>(columns.begin() + 8, columns.end() - 7))
    EXPECT_LE(spread(s.column(c), floors.at(c)), 1e-8) << c << " is not laterally uniform";
  const double area = h.last("contact1.area [mm^2]");
  const double Rz = h.last("upper.zmax.Rz [N]");
  EXPECT_NEAR(s.last("contact_traction [MPa]") * area, Rz, 4e-9 * std::abs(Rz)); // equilibrium
  for (const char* c : {"cation_electrochemical_potential [mJ/mmol]",
                        "anion_electrochemical_potential [mJ/mmol]"}) {
    const double mu = std::abs(s.last(c));
    EXPECT_TRUE(mu > 1.0 && mu < RT) << c << " = " << mu << ": not in mJ/mmol";
  }
  const double dt = 2.5, w = s.last("normal_fluid_flux [mm/s]");
  const double dV = (s.last("z [mm]") - s1.last("z [mm]")) * area; // lower body, 1 x 1 mm
  EXPECT_LT(w, 0.0) << "water leaves the compressed lower body into the slave";
  EXPECT_NEAR(w, dV / dt, 1e-9 * std::abs(w));
  for (const char* c :
       {"normal_cation_flux [mmol/(mm^2 s)]", "normal_anion_flux [mmol/(mm^2 s)]"}) {
    const double ratio = s.last(c) / w; // ions carried with the water: ~ concentration
    EXPECT_TRUE(ratio > 0.1 * c_ref && ratio < 10 * c_ref) << c << ": j.n / w.n = " << ratio;
  }
}

/// With output.vtu = false the surface CSVs are still written at the output times.
TEST_F(ContactCli, SurfaceCsvIsWrittenWithoutVtu) {
  const fs::path file =
      patch_variant("no_vtu.toml", {{"[time]", "[output]\nvtu = false\n\n[time]"}});
  ASSERT_EQ(trifem({"run", file.string(), "-o", output().string()}).exit_code, kSuccess);
  for (const char* name :
       {"contact1_surface_0000.csv", "contact1_surface_0001.csv", "contact1_surface_0002.csv"})
    EXPECT_TRUE(fs::is_regular_file(output() / name)) << name << " is missing";
  EXPECT_FALSE(fs::exists(output() / "contact1_0000.vtu"));
  EXPECT_EQ(count_of(read_text(output() / "contact1.pvd"), "<DataSet "), 0u);
}

// ---------------------------------------------------------------------------------------------
// Input checks of a pair: exit code 2, one error line naming contact[1]

TEST_F(ContactCli, SurfacesThatDoNotFaceEachOtherAreRejected) {
  expect_invalid_input(
      kData / "contact_reversed_normals.toml",
      {"contact[1]", "'upper.zmax'", "'lower.zmax'", "do not face each other", "9 of the 9"});
}

TEST_F(ContactCli, InitialPenetrationIsRejected) {
  const fs::path file = patch_variant("penetrating.toml",
                                      {{"origin = [0.0, 0.0, 1.0]", "origin = [0.0, 0.0, 0.95]"}});
  expect_invalid_input(file, {"contact[1]", "10 node(s)", "'lower.zmax'", "penetrate",
                              "penetration_tolerance", "gap -0.05 mm"});
}

TEST_F(ContactCli, PenetrationWithinTheToleranceIsAccepted) {
  const fs::path file = patch_variant(
      "tolerated.toml",
      {{"origin = [0.0, 0.0, 1.0]", "origin = [0.0, 0.0, 0.95]"},
       {"slave = \"lower.zmax\"", "slave = \"lower.zmax\"\npenetration_tolerance = 0.06"}});
  const Result r = trifem({"check", file.string()});
  EXPECT_EQ(r.exit_code, kSuccess) << r;
}

TEST_F(ContactCli, NegativePenetrationToleranceIsOutOfRange) {
  const fs::path file =
      patch_variant("negative.toml", {{"slave = \"lower.zmax\"", "slave = \"lower.zmax\"\n"
                                                                 "penetration_tolerance = -0.1"}});
  expect_invalid_input(file, {"contact[1].penetration_tolerance", "[0, inf) mm"});
}

TEST_F(ContactCli, SeparatedSurfacesOnlyWarn) {
  const fs::path file =
      patch_variant("apart.toml", {{"origin = [0.0, 0.0, 1.0]", "origin = [0.0, 0.0, 2.0]"}});
  const Result r = trifem({"check", file.string()});
  EXPECT_EQ(r.exit_code, kSuccess) << r;
  EXPECT_TRUE(r.err.empty()) << r;
  EXPECT_TRUE(contains(r.out, "warning: contact[1]")) << r;
  EXPECT_TRUE(contains(r.out, "not in contact yet")) << r;
}

TEST_F(ContactCli, UnknownMasterSurfaceIsNamed) {
  const fs::path file =
      patch_variant("master.toml", {{"master = \"upper.zmin\"", "master = \"up\""}});
  expect_invalid_input(file, {"contact[1].master", "undefined surface 'up'"});
}

TEST_F(ContactCli, UnknownSlaveSurfaceIsNamed) {
  const fs::path file = patch_variant("slave.toml", {{"slave = \"lower.zmax\"", "slave = \"lo\""}});
  expect_invalid_input(file, {"contact[1].slave", "undefined surface 'lo'"});
}

TEST_F(ContactCli, SameMasterAndSlaveSurfaceIsRejected) {
  const fs::path file =
      patch_variant("same.toml", {{"slave = \"lower.zmax\"", "slave = \"upper.zmin\""}});
  expect_invalid_input(file, {"contact[1].slave", "'upper.zmin' is also the master surface"});
}

TEST_F(ContactCli, ADuplicatedPairIsRejected) {
  // it passed `check` and failed in the first step as "contact status did not settle"
  const fs::path file = patch_variant(
      "duplicate.toml",
      {{"[[contact]]",
        "[[contact]]\nmaster = \"lower.zmax\"\nslave = \"upper.zmin\"\n\n[[contact]]"}});
  expect_invalid_input(file, {"contact[2]", "'upper.zmin' and 'lower.zmax'",
                              "already a pair in contact[1]", "remove the duplicate"});
}

TEST_F(ContactCli, SurfacesOfOneBodyAreRejected) {
  const fs::path file =
      patch_variant("one_body.toml", {{"slave = \"lower.zmax\"", "slave = \"upper.xmax\""}});
  expect_invalid_input(
      file, {"contact[1]", "'upper.zmin'", "'upper.xmax'", "share 2 node(s)", "different bodies"});
}

// ---------------------------------------------------------------------------------------------
// Hard steps: tunnelling, unloading and separation of triphasic layers

namespace {

/// The largest value of the JSON numbers `"key": <number>` in `json` (NaN if there is none).
double largest_json_number(const std::string& json, const std::string& key) {
  const std::string tag = "\"" + key + "\": ";
  double largest = std::nan("");
  for (auto at = json.find(tag); at != std::string::npos; at = json.find(tag, at + 1)) {
    const double v = std::strtod(json.c_str() + at + tag.size(), nullptr);
    largest = std::isnan(largest) ? v : std::max(largest, v);
  }
  return largest;
}

/// Largest relative water/ion balance error of summary.json (whole model and per body).
double largest_balance_error(const fs::path& summary) {
  const std::string json = read_text(summary);
  double worst = 0;
  for (const char* species : {"water", "cation", "anion"})
    worst = std::max(worst, largest_json_number(json, species));
  return worst;
}

} // namespace

/// A step that would carry the upper layer through the lower one (platen 1 mm down in one step,
/// column 1 mm high) converges to a state without contact force; it must be rejected, and at
/// the minimum step size the run fails naming the node and what to change.
TEST_F(ContactCli, TunnellingStepFailsWithTheCrossingNode) {
  const Result r = run(kData / "contact_tunnelling.toml");
  EXPECT_EQ(r.exit_code, kAnalysisFailed) << r;
  const std::vector<std::string> errors = error_lines(r.err);
  ASSERT_EQ(errors.size(), 1u) << r;
  for (const char* part : {"slave node", "crossed the master surface", "search distance",
                           "reduce the step", "search_distance"})
    EXPECT_TRUE(contains(errors[0], part)) << "'" << part << "' is missing" << r;
  const CsvTable h = read_csv(output() / "history.csv");
  EXPECT_EQ(h.rows.size(), 1u) << "no step may be accepted";
}

/// With room to cut back, the rejected steps are retried: every accepted state keeps the layers
/// in contact and carries a platen force far above the initial (Donnan) one, never 0.
TEST_F(ContactCli, TunnellingStepIsCutBackToStatesWithContact) {
  const Result r = run(data_variant("contact_tunnelling.toml", "cut_back.toml",
                                    {{"dt_min = 2.5", "dt_min = 0.05"}}));
  EXPECT_TRUE(r.exit_code == kSuccess || r.exit_code == kAnalysisFailed) << r;
  EXPECT_TRUE(contains(read_text(output() / "run.log"), "crossed the master surface")) << r;
  const CsvTable h = read_csv(output() / "history.csv");
  ASSERT_GE(h.rows.size(), 2u) << "some step must be accepted" << r;
  const std::vector<double> R = h.column("upper.zmax.Rz [N]");
  const std::vector<double> F = h.column("contact1.Fz [N]");
  const std::vector<double> active = h.column("contact1.active_nodes");
  for (std::size_t i = 1; i < h.rows.size(); ++i) {
    EXPECT_LT(R[i], 100 * R[0]) << "row " << i << ": the crushed column pushes back";
    EXPECT_NEAR(F[i], -R[i], 1e-10 * std::abs(R[i])) << "row " << i;
    EXPECT_EQ(active[i], 16.0) << "row " << i;
  }
}

/// Compressed by 0.05 mm, then the platen returns to the reference height and holds: the
/// interface unloads to zero traction everywhere at once and goes tensile while the layers
/// still swell into each other. The run completes and ends in the initial Donnan state.
TEST_F(ContactCli, UnloadedLayersReturnToTheirDonnanState) {
  const Result r = run(
      data_variant("contact_separation.toml", "back.toml", {{"[100.0, -10.0]", "[100.0, 0.0]"}}));
  ASSERT_EQ(r.exit_code, kSuccess) << r;
  const CsvTable h = read_csv(output() / "history.csv");
  const std::vector<double> R = h.column("upper.zmax.Rz [N]");
  const double peak = std::abs(*std::min_element(R.begin(), R.end()));
  EXPECT_GT(peak, 2 * std::abs(R.front())) << "the column was compressed";
  EXPECT_NEAR(R.back(), R.front(), 1e-8 * peak) << "initial platen force";
  EXPECT_NEAR(h.last("contact1.Fz [N]"), -R.back(), 1e-10 * peak);
  for (const char* column : {"water_volume [mm^3]", "cation_moles [mmol]", "anion_moles [mmol]",
                             "lower.water_volume [mm^3]", "upper.water_volume [mm^3]"})
    EXPECT_NEAR(h.last(column), h.column(column).front(), 1e-8 * h.column(column).front())
        << column;
  EXPECT_LT(largest_balance_error(output() / "summary.json"), 1e-12);
}

/// Two loading cycles, the second from the rested initial state: the interface goes sealed ->
/// wetted when the platen returns to the reference height, and must seal again when it is
/// pressed the second time, so that the second cycle repeats the first. Before wetted nodes
/// re-sealed, the interface stayed free-draining and the second cycle's peak platen force was
/// 47 % below the first's.
TEST_F(ContactCli, PressedAgainTheWettedInterfaceSealsAndTheCycleRepeats) {
  const Result r = run(kData / "contact_cycles.toml");
  ASSERT_EQ(r.exit_code, kSuccess) << r;
  const CsvTable h = read_csv(output() / "history.csv");
  const std::vector<double> t = h.column("time [s]"), R = h.column("upper.zmax.Rz [N]");
  std::map<double, double> force;
  for (std::size_t i = 0; i < t.size(); ++i)
    force[t[i]] = R[i];
  double peak = 0.0;
  for (const auto& [time, value] : force)
    if (time <= 100.0)
      peak = std::max(peak, std::abs(value));
  ASSERT_GT(peak, 0.0);
  int compared = 0;
  for (const auto& [time, value] : force) {
    if (time > 100.0)
      break;
    const auto again = force.find(time + 50000.0);
    ASSERT_NE(again, force.end()) << "no row at t = " << time + 50000.0;
    EXPECT_NEAR(again->second, value, 1e-8 * peak) << "t = " << time << " and 50000 s later";
    ++compared;
  }
  EXPECT_EQ(compared, 41) << "the rows of a cycle (t = 0, 2.5, ..., 100)";
}

/// Compressed, then the platen is lifted 0.5 mm and held: the layers separate, the interface
/// carries no force, and each layer swells to the same free-swelling equilibrium (a confined
/// layer of the same height: the upper one hangs from the porous platen, the lower one stands
/// on the impermeable base, with different meshes).
TEST_F(ContactCli, LiftedLayersSeparateAndSwellAlike) {
  const Result r = run(kData / "contact_separation.toml");
  ASSERT_EQ(r.exit_code, kSuccess) << r;
  const CsvTable h = read_csv(output() / "history.csv");
  const std::vector<double> R = h.column("upper.zmax.Rz [N]");
  const double peak = std::abs(*std::min_element(R.begin(), R.end()));
  EXPECT_LT(std::abs(R.back()), 1e-10 * peak);
  EXPECT_LT(std::abs(h.last("contact1.Fz [N]")), 1e-10 * peak);
  EXPECT_EQ(h.last("contact1.active_nodes"), 0.0);
  const double lower = h.last("lower.water_volume [mm^3]");
  const double upper = h.last("upper.water_volume [mm^3]");
  EXPECT_GT(lower, 1.2 * h.column("lower.water_volume [mm^3]").front()) << "swollen";
  EXPECT_NEAR(upper, lower, 1e-8 * lower);
  EXPECT_LT(largest_balance_error(output() / "summary.json"), 1e-12);
}

/// A flat block pressed by a rigid plate and slid 1.5 mm along a flat base: master nodes cross
/// the loaded free edges of the slave surface (their multiplier switches between 0 and the edge
/// pressure, docs/theory/contact.md §8 item 7). Every step converges without cutbacks, and the
/// contact force on the block balances the plate load at every step. The master force differs
/// (both-surface integration) and jumps as nodes cross; it is only bounded here.
TEST_F(ContactCli, FlatBlockSlidesWithLoadedEdges) {
  const Result r = run(kData / "contact_flat_slide.toml");
  ASSERT_EQ(r.exit_code, kSuccess) << r;
  EXPECT_FALSE(contains(read_text(output() / "run.log"), "cutting the step back")) << r;
  const CsvTable h = read_csv(output() / "history.csv");
  ASSERT_EQ(h.rows.size(), 61u);
  EXPECT_NEAR(h.last("plate.ux [mm]"), 1.5, 1e-12);
  const std::vector<double> load = h.column("plate.Fz [N]");
  const std::vector<double> slave = h.column("contact1.Fz [N]");
  const std::vector<double> master = h.column("contact1.master_Fz [N]");
  const std::vector<double> iterations = h.column("iterations");
  const double peak = std::abs(load.back());
  for (std::size_t i = 1; i < h.rows.size(); ++i) {
    EXPECT_NEAR(slave[i], -load[i], 1e-10 * peak) << "row " << i;
    EXPECT_LT(std::abs(master[i] + slave[i]), 0.5 * std::abs(slave[i])) << "row " << i;
    EXPECT_LE(iterations[i], 8.0) << "row " << i;
  }
}

/// The contact surface CSV of the last output of the run.
fs::path last_surface_file(const fs::path& dir) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().starts_with("contact1_surface_"))
      files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files.empty() ? dir / "contact1_surface_missing.csv" : files.back();
}

/// Coulomb friction (friction = 0.3) between a block pressed by a rigid plate (0.4 N) and a
/// fixed base: a tangential force below the friction limit μ F_n is carried with every slave
/// node sticking (the block's bottom does not move); dragged by 0.5 mm, every node slips and the
/// friction force is μ times the normal force, with quadratic Newton convergence while sliding.
TEST_F(ContactCli, FrictionHoldsABlockBelowTheLimitAndDragsItAtTheLimit) {
  constexpr double kMu = 0.3, kLoad = 0.4, kPush = 0.03;
  Result r = run(kData / "friction_block.toml");
  ASSERT_EQ(r.exit_code, kSuccess) << r;
  CsvTable h = read_csv(output() / "history.csv");
  ASSERT_EQ(h.rows.size(), 21u);
  const std::vector<double> time = h.column("time [s]");
  const std::vector<double> fx = h.column("contact1.Fx [N]");
  const std::vector<double> fz = h.column("contact1.Fz [N]");
  const std::vector<double> friction_x = h.column("contact1.friction_Fx [N]");
  const std::vector<double> friction_z = h.column("contact1.friction_Fz [N]");
  const std::vector<double> slipping_nodes = h.column("contact1.slipping_nodes");
  ASSERT_EQ(friction_x.size(), time.size());
  for (std::size_t i = 0; i < time.size(); ++i) {
    EXPECT_NEAR(fx[i], -kPush * std::max(0.0, time[i] - 1.0), 1e-10 * kLoad) << "row " << i;
    EXPECT_NEAR(fz[i], kLoad * std::min(1.0, time[i]), 1e-10 * kLoad) << "row " << i;
    EXPECT_NEAR(friction_x[i], fx[i], 1e-10 * kLoad) << "row " << i; // the interface is flat
    EXPECT_NEAR(friction_z[i], 0.0, 1e-10 * kLoad) << "row " << i;
    EXPECT_EQ(slipping_nodes[i], 0.0) << "row " << i;
    EXPECT_LE(std::abs(h.column("contact1.friction_dissipation [mJ]")[i]), 1e-12 * kLoad * kEdge)
        << "row " << i;
  }
  const CsvTable stuck = read_csv(last_surface_file(output()));
  ASSERT_EQ(stuck.rows.size(), 15u);
  const std::vector<double> X = stuck.column("X [mm]"), x = stuck.column("x [mm]");
  const std::vector<double> slipping = stuck.column("contact_slipping");
  const std::vector<double> active = stuck.column("contact_active");
  const std::vector<double> tx = stuck.column("friction_traction.x [MPa]");
  const std::vector<double> p = stuck.column("contact_traction [MPa]");
  for (std::size_t k = 0; k < X.size(); ++k) {
    EXPECT_EQ(active[k], 1.0) << "slave node " << k;
    EXPECT_EQ(slipping[k], 0.0) << "slave node " << k;
    EXPECT_NEAR(x[k], X[k], 1e-10 * kEdge) << "slave node " << k << " slid";
    EXPECT_LT(std::abs(tx[k]), kMu * std::abs(p[k])) << "slave node " << k;
  }

  const fs::path drag = data_variant(
      "friction_block.toml", "friction_drag.toml",
      {{"x = { force = 0.03, curve = \"push\" }", "x = { displacement = 0.5, curve = \"push\" }"}});
  r = run(drag);
  ASSERT_EQ(r.exit_code, kSuccess) << r;
  h = read_csv(output() / "history.csv");
  const std::vector<double> t2 = h.column("time [s]"), fx2 = h.column("contact1.Fx [N]");
  const std::vector<double> fz2 = h.column("contact1.Fz [N]"), plate = h.column("plate.Fx [N]");
  const std::vector<double> iterations = h.column("iterations");
  std::size_t sliding = 0;
  for (std::size_t i = 0; i < t2.size(); ++i) {
    if (t2[i] < 1.2)
      continue; // pressed, then dragged until every node slips
    ++sliding;
    EXPECT_NEAR(fx2[i], -kMu * fz2[i], 1e-10 * kLoad) << "row " << i;
    EXPECT_NEAR(plate[i], kMu * kLoad, 1e-10 * kLoad) << "row " << i;
    EXPECT_LE(iterations[i], 3.0) << "row " << i;
  }
  EXPECT_GE(sliding, 8u);
  EXPECT_EQ(h.last("contact1.slipping_nodes"), 15.0);
  EXPECT_NEAR(h.last("contact1.friction_Fx [N]"), -kMu * kLoad, 1e-10 * kLoad);
  const CsvTable slid = read_csv(last_surface_file(output()));
  for (const double s : slid.column("contact_slipping"))
    EXPECT_EQ(s, 1.0);
  EXPECT_NEAR(h.last("plate.ux [mm]"), 0.5, 1e-12);
  // friction's work: while every node slides with the plate, each step dissipates μ F_n times
  // the plate's travel; every slave node's accumulated slip is its travel over the fixed base
  const std::vector<double> dissipation = h.column("contact1.friction_dissipation [mJ]");
  const std::vector<double> ux = h.column("plate.ux [mm]");
  for (std::size_t i = 1; i < t2.size(); ++i) {
    EXPECT_GE(dissipation[i], dissipation[i - 1] - 1e-15) << "row " << i;
    if (t2[i - 1] >= 1.2)
      EXPECT_NEAR(dissipation[i] - dissipation[i - 1], kMu * kLoad * (ux[i] - ux[i - 1]),
                  1e-8 * kMu * kLoad * (ux[i] - ux[i - 1]))
          << "row " << i;
  }
  const std::vector<double> X2 = slid.column("X [mm]"), x2 = slid.column("x [mm]");
  const std::vector<double> slip = slid.column("accumulated_slip [mm]");
  for (std::size_t k = 0; k < X2.size(); ++k)
    EXPECT_NEAR(slip[k], x2[k] - X2[k], 1e-10 * kEdge) << "slave node " << k;
}

TEST_F(ContactCli, FrictionBetweenMixturesIsRefusedNamingThePair) {
  const fs::path file =
      data_variant("contact_triphasic_column.toml", "friction_mixture.toml",
                   {{"slave = \"upper.zmin\"\n", "slave = \"upper.zmin\"\nfriction = 0.2\n"}});
  const Result r = trifem({"check", file.string()});
  EXPECT_EQ(r.exit_code, kInvalidInput) << r;
  EXPECT_TRUE(contains(r.err, "contact[1]")) << r;
  EXPECT_TRUE(contains(r.err, "friction between mixtures is not implemented yet")) << r;
}
