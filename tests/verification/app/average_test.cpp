// SPDX-License-Identifier: MIT
// [[output.average]]: block averages of any quantity.
// - Two separate boxes under homogeneous deformations (triaxial stretch of a neo-Hookean block,
//   confined compression of a Saint Venant-Kirchhoff block): each block's average stress is the
//   law's Cauchy stress at the exact F, its average J the stretch product, its average
//   displacement and position those of its centroid, in the model and in history.csv.
// - The Terzaghi creep column (examples/biphasic_creep) during consolidation: the averages of
//   fluid_pressure and stress are the current-volume-weighted means of the cell values, J the
//   current over the reference volume, displacement the reference-volume mean and fluid_flux the
//   current-volume mean of the nodal field, all recomputed here from the node positions (the
//   cells stay boxes); a restarted run gives the same averages.
// - Blocks that the mesh lacks and quantities a block's material lacks are input errors.
#include "case_runner.hpp"
#include "history_csv.hpp"
#include "trifem/analysis/averages.hpp"
#include "trifem/analysis/run.hpp"
#include "trifem/core/error.hpp"
#include "trifem/tensor/kinematics.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <unistd.h>

using namespace trifem;
using test::History;
using test::read_history;
namespace fs = std::filesystem;

namespace {

// ---------------------------------------------------------------------------------------------
// Homogeneous deformations of two boxes

const char* kTwoBoxes = R"(
[[mesh.box]]
name = "soft"
size = [1.0, 1.0, 1.0]
divisions = [2, 2, 2]
material = "rubber"

[[mesh.box]]
name = "stiff"
origin = [2.0, 0.0, 0.0]
size = [1.0, 2.0, 1.0]
divisions = [2, 3, 2]
material = "plastic"

[materials.rubber]
type = "neo-hookean"
E = 1.0
nu = 0.3

[materials.plastic]
type = "saint-venant-kirchhoff"
E = 3.0
nu = 0.2

[curves.ramp]
points = [[0.0, 0.0], [1.0, 1.0]]

# soft: stretched to 1.1, 0.95, 0.8 (every face moves along its normal only)
[[boundary.fixed]]
set = "soft.xmin"
components = ["x"]
[[boundary.fixed]]
set = "soft.ymin"
components = ["y"]
[[boundary.fixed]]
set = "soft.zmin"
components = ["z"]
[[boundary.prescribed]]
set = "soft.xmax"
component = "x"
value = 0.1
curve = "ramp"
[[boundary.prescribed]]
set = "soft.ymax"
component = "y"
value = -0.05
curve = "ramp"
[[boundary.prescribed]]
set = "soft.zmax"
component = "z"
value = -0.2
curve = "ramp"

# stiff: confined compression to 0.9
[[boundary.fixed]]
set = "stiff.all"
components = ["x", "y"]
[[boundary.fixed]]
set = "stiff.zmin"
components = ["z"]
[[boundary.prescribed]]
set = "stiff.zmax"
component = "z"
value = -0.1
curve = "ramp"

[time]
end_time = 1.0
dt = 0.25

[[output.average]]
name = "soft_stress"
quantity = "stress"
block = "soft"
[[output.average]]
name = "soft_J"
quantity = "relative_volume"
block = "soft"
[[output.average]]
name = "soft_u"
quantity = "displacement"
block = "soft"
[[output.average]]
name = "soft_x"
quantity = "position"
block = "soft"
[[output.average]]
name = "stiff_stress"
quantity = "stress"
block = "stiff"
[[output.average]]
name = "stiff_J"
quantity = "relative_volume"
block = "stiff"
)";

/// The exact deformation gradient of a box at time t (the ramp is linear from 0 to 1).
Mat3 exact_F(const std::string& block, Real t) {
  const Vec3 stretch = block == "soft" ? Vec3(1.0 + 0.1 * t, 1.0 - 0.05 * t, 1.0 - 0.2 * t)
                                       : Vec3(1.0, 1.0, 1.0 - 0.1 * t);
  return stretch.asDiagonal();
}

/// The reference centroid of a box.
Vec3 centroid(const std::string& block) {
  return block == "soft" ? Vec3(0.5, 0.5, 0.5) : Vec3(2.5, 1.0, 0.5);
}

/// The Cauchy stress of the law of the block's first cell at F, as history columns (xx yy zz
/// xy yz xz).
std::vector<double> exact_stress(const model::Model& m, const std::string& block, const Mat3& F) {
  const material::ElasticLaw& law = *m.materials[m.mesh.cell_block(block).front()].solid;
  const Vec6 s = voigt::stress(kinematics::cauchy_from_pk2(F, law.stress(F.transpose() * F)));
  return {s.begin(), s.end()};
}

const model::Average& average(const model::Model& m, const std::string& name) {
  for (const model::Average& a : m.averages)
    if (a.name == name)
      return a;
  throw std::runtime_error("no average " + name);
}

std::vector<double> average_values(const model::Model& m, const std::string& name) {
  std::vector<double> row;
  analysis::append_average_values(m, analysis::CellEvaluator(m), average(m, name),
                                  m.problem->state(), row);
  return row;
}

/// Largest |a_k - b_k| over the components.
Real max_difference(const std::vector<double>& a, const std::vector<double>& b) {
  EXPECT_EQ(a.size(), b.size());
  Real d = 0.0;
  for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k)
    d = std::max(d, std::abs(a[k] - b[k]));
  return d;
}

/// Largest |a_k|.
Real max_abs(const std::vector<double>& a) {
  Real m = 0.0;
  for (double v : a)
    m = std::max(m, std::abs(v));
  return m;
}

std::vector<double> as_row(const Vec3& v) {
  return {v.x(), v.y(), v.z()};
}

TEST(Averages, EachBoxAveragesItsOwnHomogeneousState) {
  int checked = 0;
  Real worst_stress = 0.0, worst_J = 0.0, worst_u = 0.0;
  const auto run = test::run_case_text(
      kTwoBoxes, "two_boxes.toml", [&](const test::CaseRun& r, const solver::StepInfo& info) {
        const model::Model& m = *r.model;
        for (const std::string block : {"soft", "stiff"}) {
          const Mat3 F = exact_F(block, info.time);
          const std::vector<double> sigma = exact_stress(m, block, F);
          const Real scale = max_abs(sigma); // > 0 after the first step
          const Real ds = max_difference(average_values(m, block + "_stress"), sigma) / scale;
          EXPECT_LE(ds, 1e-10) << block << " at t = " << info.time;
          const std::vector<double> J = average_values(m, block + "_J");
          ASSERT_EQ(J.size(), 1u);
          EXPECT_NEAR(J[0], F.determinant(), 1e-12) << block << " at t = " << info.time;
          worst_stress = std::max(worst_stress, ds);
          worst_J = std::max(worst_J, std::abs(J[0] - F.determinant()));
        }
        // the soft box's centroid moves with the homogeneous map x = F X (its origin is fixed)
        const Mat3 F = exact_F("soft", info.time);
        const Vec3 X = centroid("soft");
        const Real du =
            max_difference(average_values(m, "soft_u"), as_row((F - Mat3::Identity()) * X));
        EXPECT_LE(du, 1e-12) << "t = " << info.time; // length scale 1 mm
        EXPECT_LE(max_difference(average_values(m, "soft_x"), as_row(F * X)), 1e-12);
        worst_u = std::max(worst_u, du);
        ++checked;
      });
  ASSERT_TRUE(run.report.success) << run.report.failure;
  EXPECT_EQ(checked, 4);
  std::cout << "homogeneous boxes: max relative stress error " << worst_stress
            << ", max |J - J_exact| " << worst_J << ", max displacement error " << worst_u
            << " mm\n";
}

TEST(Averages, ColumnsAreNamedLikeTheProbesOfTheQuantity) {
  const auto m = model::build_model(io::parse_case(kTwoBoxes, "two_boxes.toml"));
  const auto stress = analysis::average_columns(average(*m, "soft_stress"));
  ASSERT_EQ(stress.size(), 6u);
  EXPECT_EQ(stress[0], "soft_stress.stress_xx [MPa]");
  EXPECT_EQ(stress[5], "soft_stress.stress_xz [MPa]");
  EXPECT_EQ(analysis::average_columns(average(*m, "soft_J")),
            std::vector<std::string>{"soft_J.relative_volume"});
  EXPECT_EQ(analysis::average_columns(average(*m, "soft_u")),
            (std::vector<std::string>{"soft_u.ux [mm]", "soft_u.uy [mm]", "soft_u.uz [mm]"}));
  EXPECT_EQ(analysis::average_columns(average(*m, "soft_x")),
            (std::vector<std::string>{"soft_x.x [mm]", "soft_x.y [mm]", "soft_x.z [mm]"}));
  EXPECT_EQ(average(*m, "stiff_J").cells.size(), 12u); // the block's cells only
}

/// A fresh directory for the results of one test.
fs::path output_directory(const std::string& name) {
  const fs::path dir = fs::path(testing::TempDir()) /
                       fmt::format("trifem_average_{}_{}", name, static_cast<long>(getpid()));
  fs::remove_all(dir);
  return dir;
}

TEST(Averages, HistoryHoldsTheAveragesOfEveryStep) {
  const io::CaseSpec spec = io::parse_case(kTwoBoxes, "two_boxes.toml");
  const auto m = model::build_model(spec);
  const fs::path dir = output_directory("history");
  ASSERT_EQ(analysis::run_case(spec, dir), analysis::kSuccess);
  const History h = read_history(dir / "history.csv");
  const std::vector<double>& time = h["time [s]"];
  ASSERT_EQ(time.size(), 5u); // t = 0 and four steps
  const char* components[] = {"xx", "yy", "zz", "xy", "yz", "xz"};
  for (std::size_t i = 1; i < time.size(); ++i)
    for (const std::string block : {"soft", "stiff"}) {
      const Mat3 F = exact_F(block, time[i]);
      const std::vector<double> sigma = exact_stress(*m, block, F);
      for (int k = 0; k < 6; ++k)
        EXPECT_NEAR(h[fmt::format("{}_stress.stress_{} [MPa]", block, components[k])][i], sigma[k],
                    1e-10 * max_abs(sigma))
            << block << " " << components[k] << " at t = " << time[i];
      EXPECT_NEAR(h[block + "_J.relative_volume"][i], F.determinant(), 1e-12);
    }
  EXPECT_EQ(h["soft_J.relative_volume"][0], 1.0); // the undeformed initial state
  fs::remove_all(dir);
}

// ---------------------------------------------------------------------------------------------
// The consolidating creep column

const fs::path kCreep = fs::path(TRIFEM_EXAMPLES_DIR) / "biphasic_creep" / "biphasic_creep.toml";
constexpr Real kSigma0 = 1e-4; ///< the example's load [MPa]

const char* kColumnAverages = R"(
[[output.average]]
name = "p"
quantity = "fluid_pressure"
block = "layer"
[[output.average]]
name = "s"
quantity = "stress"
block = "layer"
[[output.average]]
name = "J"
quantity = "relative_volume"
block = "layer"
[[output.average]]
name = "u"
quantity = "displacement"
block = "layer"
[[output.average]]
name = "w"
quantity = "fluid_flux"
block = "layer"
)";

/// The creep example ending at `end` (largest step 10 s) with the column averages and `output`
/// replacing its [output] interval.
std::string creep_case(Real end, const std::string& output = "interval = 500.0") {
  std::ifstream in(kCreep);
  std::stringstream s;
  s << in.rdbuf();
  std::string text = s.str();
  for (const auto& [from, to] :
       std::map<std::string, std::string>{{"end_time = 6000.0", fmt::format("end_time = {}", end)},
                                          {"dt_max = 50.0", "dt_max = 10.0"},
                                          {"interval = 500.0", output}}) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
  }
  return text + kColumnAverages;
}

/// What the column's averages must be, recomputed from the state: the cells are boxes whose
/// current volume is the product of their edge lengths; a trilinear field over a box (the
/// current map of each cell is affine) has the mean of its eight nodal values as its mean.
struct ColumnMeans {
  Real p_current = 0.0;   ///< Σ p_c v_c / Σ v_c
  Real p_reference = 0.0; ///< Σ p_c V_c / Σ V_c (the weighting not chosen)
  Real szz = 0.0;         ///< Σ σzz_c v_c / Σ v_c
  Real J = 0.0;           ///< Σ v_c / Σ V_c
  Real uz = 0.0;          ///< Σ mean(u_z) V_c / Σ V_c
  Real wz = 0.0;          ///< Σ mean(w_z) v_c / Σ v_c
  Real w_scale = 0.0;     ///< largest nodal |w_z|
};

/// The volume of the axis-aligned box spanned by eight points.
Real box_volume(const std::array<Vec3, 8>& points) {
  Vec3 lo = points[0], hi = points[0];
  for (const Vec3& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).prod();
}

ColumnMeans column_means(const model::Model& m) {
  const Vector& x = m.problem->state();
  const analysis::CellEvaluator cells(m);
  ColumnMeans r;
  Real v_total = 0.0, V_total = 0.0;
  for (Index c : m.mesh.cell_block("layer")) {
    std::array<Vec3, 8> X, current;
    Real uz = 0.0, wz = 0.0;
    for (int a = 0; a < 8; ++a) {
      const Index n = m.mesh.cell(c)[a];
      X[a] = m.mesh.node(n);
      for (int k = 0; k < 3; ++k)
        current[a][k] = X[a][k] + x[m.dofs.dof(m.fields.u, n, k)];
      uz += x[m.dofs.dof(m.fields.u, n, 2)] / 8.0;
      wz += x[m.dofs.dof(m.fields.w, n, 2)] / 8.0;
      r.w_scale = std::max(r.w_scale, std::abs(x[m.dofs.dof(m.fields.w, n, 2)]));
    }
    const Real V = box_volume(X), v = box_volume(current);
    const Real p = x[m.dofs.dof(m.fields.p, c, 0)]; // the cell's pressure unknown (VTU value)
    r.p_current += p * v;
    r.p_reference += p * V;
    r.szz += cells.values(c, x).stress(2, 2) * v;
    r.uz += uz * V;
    r.wz += wz * v;
    v_total += v;
    V_total += V;
  }
  r.p_current /= v_total;
  r.p_reference /= V_total;
  r.szz /= v_total;
  r.J = v_total / V_total;
  r.uz /= V_total;
  r.wz /= v_total;
  return r;
}

TEST(Averages, CreepColumnAveragesWeightTheCellsByTheirVolumes) {
  int checked = 0;
  Real worst_p = 0.0, worst_s = 0.0, worst_J = 0.0, worst_u = 0.0, worst_w = 0.0;
  Real weighting = 0.0; // largest difference between the current and reference weightings
  const auto run = test::run_case_text(
      creep_case(600.0), kCreep, [&](const test::CaseRun& r, const solver::StepInfo& info) {
        const model::Model& m = *r.model;
        const ColumnMeans e = column_means(m);
        const std::vector<double> p = average_values(m, "p"), s = average_values(m, "s"),
                                  J = average_values(m, "J"), u = average_values(m, "u"),
                                  w = average_values(m, "w");
        ASSERT_EQ(p.size(), 1u);
        ASSERT_EQ(s.size(), 6u);
        const Real h = 1.0; // the column's height [mm]
        worst_p = std::max(worst_p, std::abs(p[0] - e.p_current) / kSigma0);
        worst_s = std::max(worst_s, std::abs(s[2] - e.szz) / kSigma0);
        worst_J = std::max(worst_J, std::abs(J[0] - e.J));
        worst_u = std::max(worst_u, std::abs(u[2] - e.uz) / h);
        worst_w = std::max(worst_w, std::abs(w[2] - e.wz) / e.w_scale);
        EXPECT_NEAR(p[0], e.p_current, 1e-12 * kSigma0) << "t = " << info.time;
        EXPECT_NEAR(s[2], e.szz, 1e-12 * kSigma0) << "t = " << info.time;
        EXPECT_NEAR(s[2], -kSigma0, 1e-8 * kSigma0) << "equilibrium at t = " << info.time;
        EXPECT_NEAR(J[0], e.J, 1e-13) << "t = " << info.time;
        EXPECT_NEAR(u[2], e.uz, 1e-13 * h) << "t = " << info.time;
        EXPECT_NEAR(u[0], 0.0, 1e-13 * h);
        EXPECT_NEAR(w[2], e.wz, 1e-12 * e.w_scale) << "t = " << info.time;
        weighting = std::max(weighting, std::abs(e.p_current - e.p_reference));
        ++checked;
      });
  ASSERT_TRUE(run.report.success) << run.report.failure;
  EXPECT_GT(checked, 20);
  // the tolerances above tell the weightings apart by far
  EXPECT_GT(weighting, 1e-6 * kSigma0);
  std::cout << "creep column: |p - mean| / sigma0 " << worst_p << ", |szz - mean| / sigma0 "
            << worst_s << ", |J - v/V| " << worst_J << ", |uz - mean| / h " << worst_u
            << ", |wz - mean| / max|w| " << worst_w
            << "; current vs reference weighting of p differ by " << weighting / kSigma0
            << " sigma0\n";
}

TEST(Averages, ARestartedRunGivesTheSameAverages) {
  const io::CaseSpec spec =
      io::parse_case(creep_case(300.0, "interval = 100.0\nrestart = true"), kCreep);
  const fs::path whole = output_directory("whole"), resumed = output_directory("resumed");
  ASSERT_EQ(analysis::run_case(spec, whole), analysis::kSuccess);
  ASSERT_TRUE(fs::exists(whole / "restart_0002.bin")); // t = 200 s
  ASSERT_EQ(analysis::run_case(spec, resumed, {.restart_file = whole / "restart_0002.bin"}),
            analysis::kSuccess);
  const History a = read_history(whole / "history.csv"), b = read_history(resumed / "history.csv");
  ASSERT_EQ(a.names, b.names);
  const std::vector<double>&ta = a["time [s]"], &tb = b["time [s]"];
  ASSERT_GE(tb.size(), 2u);
  EXPECT_EQ(tb.front(), 200.0);
  EXPECT_EQ(tb.back(), ta.back());
  std::size_t compared = 0;
  for (std::size_t i = 0; i < tb.size(); ++i) {
    const auto at = std::find(ta.begin(), ta.end(), tb[i]);
    ASSERT_NE(at, ta.end()) << "t = " << tb[i];
    const auto j = static_cast<std::size_t>(at - ta.begin());
    for (const char* column : {"p.fluid_pressure [MPa]", "s.stress_zz [MPa]"})
      EXPECT_NEAR(b[column][i], a[column][j], 1e-12 * kSigma0) << column << " at t = " << tb[i];
    EXPECT_NEAR(b["J.relative_volume"][i], a["J.relative_volume"][j], 1e-12);
    EXPECT_NEAR(b["u.uz [mm]"][i], a["u.uz [mm]"][j], 1e-12);
    ++compared;
  }
  EXPECT_GE(compared, 2u);
  fs::remove_all(whole);
  fs::remove_all(resumed);
}

// ---------------------------------------------------------------------------------------------
// Input errors of the model

/// The InputError message of building the model of `spec` ("" if none).
std::string build_error(const io::CaseSpec& spec) {
  try {
    model::build_model(spec);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Averages, APhysicalVolumeTheMeshLacksIsAnInputError) {
  const std::string text =
      fmt::format(R"(
[[mesh.gmsh]]
file = "{}"
materials = {{ lower = "rubber", upper = "rubber" }}

[materials.rubber]
type = "neo-hookean"
E = 1.0

[[boundary.fixed]]
set = "lower"
[[boundary.fixed]]
set = "upper"

[time]
end_time = 1.0
dt = 0.5

[[output.average]]
name = "mid"
quantity = "stress"
block = "middle"
)",
                  (fs::path(TRIFEM_EXAMPLES_DIR) / "sliding_layers" / "sliding_layers_coarse.msh")
                      .generic_string());
  const std::string m = build_error(io::parse_case(text, "gmsh.toml"));
  EXPECT_NE(m.find("output.average[1].block: undefined cell block 'middle' (available: lower, "
                   "upper)"),
            std::string::npos)
      << m;
}

TEST(Averages, ACellWithoutTheQuantityIsAnInputErrorOfTheModel) {
  // the reader rejects this for the blocks it knows; the model checks every cell (a Gmsh
  // physical volume may span several materials)
  io::CaseSpec spec = io::parse_case(kTwoBoxes, "two_boxes.toml");
  spec.output.averages.push_back({"p", "fluid_pressure", "stiff"});
  const std::string m = build_error(spec);
  EXPECT_NE(m.find("output.average[7].quantity = 'fluid_pressure': the material of cell "),
            std::string::npos)
      << m;
  EXPECT_NE(m.find("of the cell block 'stiff' has no fluid_pressure (it needs a biphasic or "
                   "triphasic material)"),
            std::string::npos)
      << m;
}

} // namespace
