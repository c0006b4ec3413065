// SPDX-License-Identifier: MIT
// Rigid bodies in dynamic-explicit analyses (docs/theory/explicit.md §7), through `trifem run`'s
// analysis, against answers computed independently of the run:
// - a rigid arm released from horizontal swings about a fixed hinge under gravity with the exact
//   period of the physical pendulum of its lumped point masses, 4 sqrt(I/(m g d)) K(sin² 45°),
//   converging at second order;
// - a free body spinning about a principal axis while it drifts turns through exactly ω t and
//   travels exactly v t;
// - a bar fixed at one end carrying a heavy free block at the other oscillates as the implicit
//   generalized-α run of the same lumped-mass model, with and without the volume multiplier;
// - a tissue cube carried by a bone turned through a prescribed angle ends where the
//   quasi-static run puts it.
#include "case_runner.hpp"
#include "history_csv.hpp"
#include "trifem/analysis/run.hpp"
#include "trifem/core/error.hpp"
#include "trifem/explicit/explicit_view.hpp"
#include "trifem/io/case_reader.hpp"
#include "trifem/parallel/communicator.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

using namespace trifem;

namespace {

/// A per-process directory for the runs of this file.
std::filesystem::path work_dir() {
  const auto dir =
      std::filesystem::temp_directory_path() /
      fmt::format("trifem_explicit_rigid_{}_{}", static_cast<long>(getpid()), parallel::rank());
  std::filesystem::create_directories(dir);
  return dir;
}

/// Runs the case `text` as `name` in the work directory; its history `history` (empty if the
/// run failed).
test::History run(const std::string& name, const std::string& text,
                  const std::string& history = "history.csv") {
  const auto dir = work_dir();
  const auto file = dir / (name + ".toml");
  std::ofstream(file) << text;
  const int code = analysis::run_case(io::read_case(file), dir / name, {});
  EXPECT_EQ(code, analysis::kSuccess) << name;
  return test::read_history(dir / name / history);
}

/// The times at which `value` crosses `level` (linear interpolation between rows).
std::vector<Real> crossings(const test::History& h, const std::string& column, Real level) {
  const auto& t = h["time [s]"];
  const auto& v = h[column];
  std::vector<Real> out;
  for (std::size_t i = 1; i < v.size(); ++i)
    if ((v[i - 1] > level) != (v[i] > level))
      out.push_back(t[i - 1] + (t[i] - t[i - 1]) * (v[i - 1] - level) / (v[i - 1] - v[i]));
  return out;
}

/// max |column| over the rows.
Real largest(const test::History& h, const std::string& column) {
  Real m = 0.0;
  for (Real v : h[column])
    m = std::max(m, std::abs(v));
  return m;
}

/// K(m), the complete elliptic integral of the first kind of parameter m = k², by the
/// arithmetic-geometric mean.
Real elliptic_k(Real m) {
  Real a = 1.0, b = std::sqrt(1.0 - m);
  for (int i = 0; i < 40; ++i) {
    const Real next = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = next;
  }
  return std::numbers::pi / (2.0 * a);
}

// ---------------------------------------------------------------------------------------------
// The pendulum: a 2 x 1 x 0.5 mm arm of two cells, hinged about z at P = (-0.5, 0.5, 0.25),
// released from horizontal with gravity along -y.

constexpr Real kArmDensity = 2e-9; // t/mm³
constexpr Real kGravity = 9810.0;  // mm/s²

std::string pendulum_case(Real dt) {
  return fmt::format(R"(
[[mesh.box]]
name = "arm"
size = [2.0, 1.0, 0.5]
divisions = [2, 1, 1]
[[rigid_body]]
name = "arm"
blocks = ["arm"]
density = {}
center = [-0.5, 0.5, 0.25]
x = {{ displacement = 0.0 }}
y = {{ displacement = 0.0 }}
z = {{ displacement = 0.0 }}
rx = {{ rotation = 0.0 }}
ry = {{ rotation = 0.0 }}
[[loads.body_force]]
force = [0.0, {}, 0.0]
[analysis]
type = "dynamic-explicit"
[explicit]
multiplier = false
[time]
end_time = 0.12
dt = {:.17g}
[output]
vtu = false
interval = 0.01    # the steps of dt land on it
)",
                     kArmDensity, -kGravity, dt);
}

/// The period of the arm's point masses (the row sums of its cells' mass, ρ V_cell / 8 per
/// cell at each node) swinging through 90° on either side: T = 4 sqrt(I_P/(m g d)) K(1/2).
Real pendulum_period() {
  const Real node_mass = kArmDensity * 0.5 / 8.0; // per cell and node
  Real mass = 0.0, inertia = 0.0, moment = 0.0;   // about P, in the xy plane
  for (int i = 0; i <= 2; ++i)                    // x = 0, 1, 2: the middle nodes are in both cells
    for (int j = 0; j <= 1; ++j) {                // y = 0, 1; two nodes (z = 0, 0.5) at each (x, y)
      const Real m = 2.0 * node_mass * (i == 1 ? 2.0 : 1.0);
      const Real dx = i + 0.5, dy = j - 0.5;
      mass += m;
      inertia += m * (dx * dx + dy * dy);
      moment += m * dx;
    }
  const Real d = moment / mass; // the center of mass from the hinge
  return 4.0 * std::sqrt(inertia / (mass * kGravity * d)) * elliptic_k(0.5);
}

/// The largest error of the times the arm hangs vertically (rz = −π/2: T/4, 3T/4), relative to
/// the period; the hinge holds the arm's center and the other rotations.
Real pendulum_error(Real dt) {
  const test::History h = run(fmt::format("pendulum_{}", dt), pendulum_case(dt));
  if (h.names.empty())
    return 1.0;
  const Real period = pendulum_period();
  const std::vector<Real> down = crossings(h, "arm.rz [rad]", -0.5 * std::numbers::pi);
  EXPECT_GE(down.size(), 2u);
  if (down.size() < 2)
    return 1.0;
  for (const char* c : {"arm.ux [mm]", "arm.uy [mm]", "arm.uz [mm]"})
    EXPECT_LT(largest(h, c), 1e-12) << c;
  for (const char* c : {"arm.rx [rad]", "arm.ry [rad]"})
    EXPECT_LT(largest(h, c), 1e-12) << c;
  // energy: the kinetic energy is the work of gravity (m g d at the bottom) up to O(dt²)
  const Real mgd = kArmDensity * kGravity * 1.5;          // mass 2e-9 t (the block's), d = 1.5 mm
  EXPECT_LT(largest(h, "total_energy [mJ]"), 2e-3 * mgd); // measured 1e-4
  return std::max(std::abs(down[0] - 0.25 * period), std::abs(down[1] - 0.75 * period)) / period;
}

TEST(ExplicitRigid, AHingedArmSwingsWithTheExactPendulumPeriodAtSecondOrder) {
  const Real coarse = pendulum_error(1e-3), fine = pendulum_error(5e-4);
  std::cout << "pendulum: period error " << coarse << " (about 106 steps per period), " << fine
            << " (212); ratio " << coarse / fine << "\n";
  EXPECT_LT(coarse, 3e-4); // measured 1.0e-4
  EXPECT_GT(coarse / fine, 3.5);
}

/// The pendulum with its hinge shaken along x (1 mm out and back, smooth) and free to turn
/// about every axis: the largest error of the energy balance (kinetic energy = the work of
/// gravity and of the hinge), relative to the largest kinetic energy.
Real shaken_pendulum_balance(Real dt) {
  std::string text = pendulum_case(dt);
  for (const std::string line : {"rx = { rotation = 0.0 }\n", "ry = { rotation = 0.0 }\n"})
    text.erase(text.find(line), line.size());
  const std::string held = "x = { displacement = 0.0 }";
  text.replace(text.find(held), held.size(), "x = { displacement = 1.0, curve = \"shake\" }");
  text += R"(
[curves.shake]
interpolation = "smooth"
points = [[0.0, 0.0], [0.05, 1.0], [0.1, 0.0]]
)";
  const test::History h = run(fmt::format("shaken_{}", dt), text);
  if (h.names.empty())
    return 1.0;
  EXPECT_GT(largest(h, "arm.rz [rad]"), 1.0);
  return largest(h, "total_energy [mJ]") / largest(h, "kinetic [mJ]");
}

TEST(ExplicitRigid, TheEnergyBalanceOfAPendulumOnAShakenHingeConvergesAtSecondOrder) {
  const Real coarse = shaken_pendulum_balance(1e-3), fine = shaken_pendulum_balance(5e-4);
  std::cout << "shaken pendulum: balance error " << coarse << ", " << fine << " (dt/2)\n";
  EXPECT_LT(coarse, 5e-3); // measured 1.4e-3
  EXPECT_GT(coarse / fine, 3.5);
}

// ---------------------------------------------------------------------------------------------
// A free body spinning about a principal axis.

TEST(ExplicitRigid, AFreeBodySpinningAboutAPrincipalAxisTurnsThroughExactlyOmegaT) {
  constexpr Real kOmega = 300.0, kSpeed = 20.0; // rad/s, mm/s
  const test::History h = run("spin", fmt::format(R"(
[[mesh.box]]
name = "block"
size = [3.0, 2.0, 1.0]
divisions = [3, 2, 1]
[[rigid_body]]
name = "block"
blocks = ["block"]
density = 1e-9
velocity = [{}, 0.0, 0.0]
angular_velocity = [0.0, 0.0, {}]
[analysis]
type = "dynamic-explicit"
[explicit]
multiplier = false
[time]
end_time = 0.05
dt = 1e-3
[output]
vtu = false
)",
                                                  kSpeed, kOmega));
  ASSERT_FALSE(h.names.empty());
  const auto& t = h["time [s]"];
  for (std::size_t i = 0; i < t.size(); ++i) {
    const Real angle = kOmega * t[i]; // the rotation vector's angle is taken below π
    EXPECT_NEAR(std::cos(h["block.rz [rad]"][i]), std::cos(angle), 1e-12) << t[i];
    EXPECT_NEAR(std::sin(h["block.rz [rad]"][i]), std::sin(angle), 1e-12) << t[i];
    EXPECT_NEAR(h["block.ux [mm]"][i], kSpeed * t[i], 1e-12) << t[i];
  }
  EXPECT_LT(largest(h, "block.rx [rad]") + largest(h, "block.ry [rad]"), 1e-12);
  const Real kinetic = h["kinetic [mJ]"].front();
  EXPECT_GT(kinetic, 0.0);
  EXPECT_NEAR(h["kinetic [mJ]"].back(), kinetic, 1e-12 * kinetic);
}

// A moment about z on a free block of one cell (its point masses m/8 at the corners:
// J_zz = m (a² + b²)/4) turns it through ½ (M/J) t²: central differences are exact for a
// constant acceleration.
TEST(ExplicitRigid, AMomentTurnsAFreeBlockThroughHalfAlphaTSquared) {
  constexpr Real kMoment = 1e-4, kMass = 1e-9 * 6.0; // N mm, t
  constexpr Real kAlpha = kMoment / (kMass * (9.0 + 4.0) / 4.0);
  const test::History h = run("moment", fmt::format(R"(
[[mesh.box]]
name = "block"
size = [3.0, 2.0, 1.0]
divisions = [1, 1, 1]
[[rigid_body]]
name = "block"
blocks = ["block"]
density = 1e-9
rz = {{ moment = {} }}
[analysis]
type = "dynamic-explicit"
[explicit]
multiplier = false
[time]
end_time = 0.02
dt = 1e-3
[output]
vtu = false
interval = 1e-3
)",
                                                    kMoment));
  ASSERT_FALSE(h.names.empty());
  const auto& t = h["time [s]"];
  ASSERT_EQ(t.size(), 21u);
  for (std::size_t i = 0; i < t.size(); ++i)
    EXPECT_NEAR(h["block.rz [rad]"][i], 0.5 * kAlpha * t[i] * t[i], 1e-12) << t[i];
  EXPECT_GT(h["block.rz [rad]"].back(), 1.0);
  EXPECT_LT(largest(h, "block.ux [mm]") + largest(h, "block.uy [mm]"), 1e-12);
  // the moment's work is the kinetic energy ½ J (α t)² = M θ (both exact for this motion)
  const Real energy = 0.5 * kMass * 13.0 / 4.0 * std::pow(kAlpha * t.back(), 2);
  EXPECT_NEAR(h["kinetic [mJ]"].back(), energy, 1e-12 * energy);
  EXPECT_NEAR(h["external_work [mJ]"].back(), energy, 1e-12 * energy);
}

// ---------------------------------------------------------------------------------------------
// A bar carrying a heavy block.

/// The drift of the energy balance over the rows, relative to its start.
Real energy_drift(const test::History& h) {
  const Real energy = h["total_energy [mJ]"].front();
  Real drift = 0.0;
  for (Real e : h["total_energy [mJ]"])
    drift = std::max(drift, std::abs(e - energy));
  return drift / energy;
}

/// The half period of a fixed-free bar of mass 1e-8 t, length 10 mm, unit section and Young's
/// modulus E carrying a tip mass of 1e-7 t: β L tan β L = m_bar / M, ω = β c [s].
Real tip_mass_half_period(Real E) {
  Real lo = 0.0, hi = 0.5 * std::numbers::pi - 1e-12;
  for (int i = 0; i < 200; ++i) {
    const Real mid = 0.5 * (lo + hi);
    (mid * std::tan(mid) < 0.1 ? lo : hi) = mid;
  }
  return std::numbers::pi / (lo / 10.0 * std::sqrt(E / 1e-9));
}

/// A 10 x 1 x 1 mm bar (E = 1 MPa, ν = 0) fixed at x = 0 carries a free block of 1e-7 t (100
/// times its own mass) that starts at 100 mm/s along the bar; dynamic-explicit or implicit
/// dynamic with the lumped mass and ρ∞ = 1 (trapezoidal); the multiplier makes the bar
/// incompressible.
std::string bar_case(bool implicit, bool multiplier) {
  const std::string analysis =
      implicit ? "[analysis]\ntype = \"dynamic\"\n[dynamic]\nmass = \"lumped\"\nrho_inf = 1.0\n"
               : fmt::format("[analysis]\ntype = \"dynamic-explicit\"\n[explicit]\nmultiplier = "
                             "{}\n",
                             multiplier ? "true" : "false");
  return R"(
[[mesh.box]]
name = "bar"
size = [10.0, 1.0, 1.0]
divisions = [10, 1, 1]
material = "rubber"
[[mesh.box]]
name = "weight"
origin = [10.0, 0.0, 0.0]
size = [1.0, 1.0, 1.0]
divisions = [1, 1, 1]
[materials.rubber]
type = "neo-hookean"
E = 1.0
nu = 0.0
density = 1e-9
[[boundary.fixed]]
set = "bar.xmin"
[[rigid_body]]
name = "weight"
set = "bar.xmax"
blocks = ["weight"]
density = 1e-7
velocity = [100.0, 0.0, 0.0]
[time]
end_time = 0.01
dt = 2.5e-5
[output]
vtu = false
)" + analysis;
}

TEST(ExplicitRigid, ABarCarryingAFreeBlockOscillatesAsTheImplicitRunOfTheSameModel) {
  const test::History ex = run("bar_explicit", bar_case(false, false));
  const test::History im = run("bar_implicit", bar_case(true, false));
  ASSERT_FALSE(ex.names.empty());
  ASSERT_FALSE(im.names.empty());
  const auto& u = ex["weight.ux [mm]"];
  const auto& v = im["weight.ux [mm]"];
  ASSERT_EQ(u.size(), v.size());
  Real difference = 0.0;
  for (std::size_t i = 0; i < u.size(); ++i) {
    EXPECT_NEAR(ex["time [s]"][i], im["time [s]"][i], 1e-15);
    difference = std::max(difference, std::abs(u[i] - v[i]));
  }
  const Real amplitude = largest(ex, "weight.ux [mm]");
  std::cout << "bar and block: explicit - implicit " << difference << " mm of " << amplitude
            << " mm\n";
  EXPECT_GT(amplitude, 0.09);              // v0/ω = 0.10 mm
  EXPECT_LT(difference, 5e-3 * amplitude); // measured 2.3e-3 (opposite period errors)
  for (const char* c : {"weight.rx [rad]", "weight.ry [rad]", "weight.rz [rad]", "weight.uy [mm]"})
    EXPECT_LT(largest(ex, c), 1e-12) << c;
  EXPECT_LT(energy_drift(ex), 5e-3); // measured 1.6e-3
  const std::vector<Real> zero = crossings(ex, "weight.ux [mm]", 0.0);
  ASSERT_GE(zero.size(), 2u); // the bar's modes shift the crossings a little
  EXPECT_NEAR(zero[1] - zero[0], tip_mass_half_period(1.0), 0.01 * tip_mass_half_period(1.0));
}

TEST(ExplicitRigid, TheMultiplierKeepsTheVolumeOfABarCarryingAFreeBlock) {
  const test::History h = run("bar_multiplier", bar_case(false, true));
  ASSERT_FALSE(h.names.empty());
  EXPECT_LT(largest(h, "max|Jbar-1|"), 1e-10);
  EXPECT_LT(energy_drift(h), 5e-3); // measured 2.5e-3
  Real iterations = 0.0;
  for (Real k : h["iterations"])
    iterations += k;
  EXPECT_LT(iterations / static_cast<Real>(h["iterations"].size()), 8.0); // measured 5.0
  // incompressible: at least as stiff as the bar of E = 3μ = 1.5 MPa free to contract (its ends
  // are held wide here, which stiffens it: measured 2.5 % shorter)
  const std::vector<Real> zero = crossings(h, "weight.ux [mm]", 0.0);
  ASSERT_GE(zero.size(), 2u);
  EXPECT_LT(zero[1] - zero[0], tip_mass_half_period(1.5));
  EXPECT_GT(zero[1] - zero[0], 0.9 * tip_mass_half_period(1.5));
}

// Reading A iterates all forces at t_{n+1} (dissipative: about 1 % of the amplitude per
// period here, as without bodies): the body moves with each iterate's forces and the volume
// constraint converges; the block crosses zero when reading B's does.
TEST(ExplicitRigid, ReadingAMovesTheBodyAsReadingB) {
  std::string text = bar_case(false, true);
  text.replace(text.find("[explicit]\n"), 11, "[explicit]\nreading = \"A\"\n");
  const test::History a = run("bar_reading_a", text);
  const test::History b = run("bar_multiplier_b", bar_case(false, true));
  ASSERT_FALSE(a.names.empty());
  ASSERT_FALSE(b.names.empty());
  EXPECT_LT(largest(a, "max|Jbar-1|"), 1e-10);
  std::vector<Real> zero_a = crossings(a, "weight.ux [mm]", 0.0);
  std::vector<Real> zero_b = crossings(b, "weight.ux [mm]", 0.0);
  for (std::vector<Real>* zero : {&zero_a, &zero_b}) // not the start at u = 0
    std::erase_if(*zero, [](Real t) { return t < 1e-4; });
  ASSERT_EQ(zero_a.size(), 3u);
  ASSERT_EQ(zero_b.size(), 3u);
  const Real half_period = zero_b[1] - zero_b[0];
  for (std::size_t i = 0; i < 3; ++i)
    EXPECT_NEAR(zero_a[i], zero_b[i], 5e-3 * half_period) << i; // measured 5e-4
  const Real amplitude = largest(b, "weight.ux [mm]");
  EXPECT_NEAR(largest(a, "weight.ux [mm]"), amplitude, 0.05 * amplitude); // measured 0.7 %
}

/// The bar and its block (multiplier off) in three steps: the block pulled by a force of
/// 0.01 N quasi-statically, released dynamically-explicitly (the force falls to 0 in 1 ms, 10 ms
/// in all), then brought to rest quasi-statically; one mesh, one state.
std::string pulled_block_steps() {
  std::string text = bar_case(false, false);
  const std::string velocity = "velocity = [100.0, 0.0, 0.0]";
  text.replace(text.find(velocity), velocity.size(), "x = { force = 0.01, curve = \"pull\" }");
  text.erase(text.find("[time]"), text.find("[output]") - text.find("[time]"));
  text.erase(text.find("[analysis]"), text.find("[explicit]") - text.find("[analysis]"));
  return text + R"(
[curves.pull]
points = [[0.0, 0.0], [1.0, 1.0], [1.001, 0.0]]
[[step]]
name = "pull"
end_time = 1.0
dt = 0.25
[[step]]
name = "release"
analysis = "dynamic-explicit"
duration = 0.01
dt = 2.5e-5
[[step]]
name = "settle"
duration = 1.0
dt = 0.25
)";
}

TEST(ExplicitRigid, AForceDrivenBlockPulledThenReleasedOscillatesAndComesToRestInLaterSteps) {
  const test::History steps = run("pulled", pulled_block_steps());
  const test::History release = test::read_history(work_dir() / "pulled" / "history_step2.csv");
  ASSERT_FALSE(steps.names.empty());
  ASSERT_FALSE(release.names.empty());
  const auto& t = steps["time [s]"];
  const auto& u = steps["weight.ux [mm]"];
  ASSERT_EQ(t.size(), 9u);      // 4 + 4 quasi-static steps and the start
  EXPECT_NEAR(u[4], 0.1, 0.01); // F L / (E A) = 0.1 mm
  EXPECT_NEAR(release["weight.ux [mm]"].front(), u[4], 1e-15); // the explicit step starts there
  EXPECT_LT(*std::min_element(release["weight.ux [mm]"].begin(), release["weight.ux [mm]"].end()),
            -0.09);                       // it swings through
  EXPECT_LT(energy_drift(release), 1e-3); // the force's work included; measured 1.4e-4
  EXPECT_LT(release["external_work [mJ]"].back(), -1e-5); // the force resists the first swing
  EXPECT_LT(std::abs(u.back()), 1e-9);                    // the last step ends at rest, unloaded
}

// The stable step is estimated on the mesh with the bodies' nodes free (their rigidity only
// lowers the frequencies): the estimate of a bar whose end face is a body is that of the bar.
TEST(ExplicitRigid, TheStableStepOfABarCarryingABodyIsThatOfTheFreeBar) {
  std::string with_body = bar_case(false, false);
  const std::size_t weight = with_body.find("[[mesh.box]]\nname = \"weight\"");
  with_body.erase(weight, with_body.find("[materials.rubber]") - weight);
  with_body.replace(with_body.find("blocks = [\"weight\"]"), 19, "");
  with_body.replace(with_body.find("density = 1e-7"), 14, "");
  with_body.replace(with_body.find("dt = 2.5e-5"), 11, ""); // the estimate
  const std::size_t body = with_body.find("[[rigid_body]]");
  std::string without_body = with_body;
  without_body.erase(body, without_body.find("[time]") - body);
  const auto omega = [](const std::string& name, const std::string& text) {
    run(name, text);
    std::ifstream in(work_dir() / name / "summary.json");
    return nlohmann::json::parse(in)["time_step_s"]["omega_iso_per_s"].get<double>();
  };
  const Real bar = omega("free_bar", without_body), carried = omega("bar_with_body", with_body);
  EXPECT_GT(bar, 1e4); // 2 c / h = 6.3e4 1/s
  EXPECT_NEAR(carried, bar, 1e-12 * bar);
}

// ---------------------------------------------------------------------------------------------
// A body whose motion is prescribed: its nodes are moving supports.

/// A 2x2x2 tissue cube (light: 1e-12 t/mm³) fixed at its base, its top face carried by a bone
/// turned 0.8 rad about z in 10 ms, then held for 2 ms; dynamic-explicit or quasi-static.
std::string turned_cube_case(bool dynamic) {
  return fmt::format(R"(
[[mesh.box]]
name = "cube"
size = [1.0, 1.0, 1.0]
divisions = [2, 2, 2]
material = "tissue"
[[mesh.box]]
name = "bone"
origin = [0.0, 0.0, 1.0]
size = [1.0, 1.0, 0.3]
divisions = [1, 1, 1]
[materials.tissue]
type = "neo-hookean"
E = 1.0
nu = 0.3
density = 1e-12
[curves.ramp]
points = [[0.0, 0.0], [0.01, 1.0]]
[[boundary.fixed]]
set = "cube.zmin"
[[rigid_body]]
name = "femur"
set = "cube.zmax"
blocks = ["bone"]
density = 2e-9
center = [0.5, 0.5, 1.15]
x = {{ displacement = 0.0 }}
y = {{ displacement = 0.0 }}
z = {{ displacement = 0.0 }}
rx = {{ rotation = 0.0 }}
ry = {{ rotation = 0.0 }}
rz = {{ rotation = 0.8, curve = "ramp" }}
[time]
end_time = 0.012
{}
[output]
vtu = false
)",
                     dynamic ? "[analysis]\ntype = \"dynamic-explicit\"\n[explicit]\nmultiplier = "
                               "false"
                             : "dt = 0.001");
}

TEST(ExplicitRigid, ATissueCubeTurnedByADrivenBoneEndsAtTheQuasiStaticAnswer) {
  const test::History ex = run("turned_explicit", turned_cube_case(true));
  const test::History qs = run("turned_static", turned_cube_case(false));
  ASSERT_FALSE(ex.names.empty());
  ASSERT_FALSE(qs.names.empty());
  EXPECT_NEAR(ex["femur.rz [rad]"].back(), 0.8, 1e-15);
  // the light tissue follows at once: the end forces are the static ones (measured 1e-4)
  for (const char* c : {"femur.Fz [N]", "femur.Mz [N mm]"}) {
    const Real expected = qs[c].back();
    EXPECT_GT(std::abs(expected), 1e-2) << c;
    EXPECT_NEAR(ex[c].back(), expected, 1e-3 * std::abs(expected)) << c;
  }
  // the balance of a run from rest: the drive's work is the strain energy (measured 1e-9)
  EXPECT_LT(largest(ex, "total_energy [mJ]"), 1e-6 * ex["strain [mJ]"].back());
}

// The cube tilted about an x axis 1 mm beside it (0.8 rad in 10 ms) is sheared and squeezed
// until its stiffest mode outgrows the stable step estimated at the start: the run stops with
// the way out, and takes it when the estimate follows the deformation.
TEST(ExplicitRigid, ACellStiffenedPastTheStartsStableStepStopsTheRunWithTheWayOut) {
  std::string text = turned_cube_case(true);
  for (const auto& [from, to] :
       {std::pair<std::string, std::string>{"center = [0.5, 0.5, 1.15]",
                                            "center = [0.5, 1.5, 1.15]"},
        {"rx = { rotation = 0.0 }", "rx = { rotation = 0.8, curve = \"ramp\" }"},
        {"rz = { rotation = 0.8, curve = \"ramp\" }", "rz = { rotation = 0.0 }"}})
    text.replace(text.find(from), from.size(), to);
  const auto dir = work_dir();
  std::ofstream(dir / "stiffened.toml") << text;
  EXPECT_EQ(analysis::run_case(io::read_case(dir / "stiffened.toml"), dir / "stiffened", {}),
            analysis::kAnalysisFailed);
  std::ifstream in(dir / "stiffened" / "summary.json");
  const std::string failure = nlohmann::json::parse(in)["failure"].get<std::string>();
  EXPECT_NE(failure.find("explicit.stable_step_interval"), std::string::npos) << failure;
  text.replace(text.find("multiplier = false"), 18,
               "multiplier = false\nstable_step_interval = 50");
  const test::History h = run("followed", text);
  ASSERT_FALSE(h.names.empty());
  EXPECT_NEAR(h["time [s]"].back(), 0.012, 1e-12);
}

// ---------------------------------------------------------------------------------------------
// Drives the explicit integrator does not take.

/// The InputError message of the explicit view of the model of `text` ("" if none).
std::string explicit_model_error(const std::string& text) {
  const auto model = model::build_model(io::parse_case(text, work_dir() / "bad.toml"));
  try {
    explicit_dynamics::ExplicitView view(*model);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ExplicitRigid, ARotationHeldInOneComponentOnlyIsAnInputErrorNamingTheBody) {
  std::string text = pendulum_case(1e-3);
  const std::string held = "ry = { rotation = 0.0 }\n";
  text.erase(text.find(held), held.size()); // rx held, ry and rz free
  const std::string message = explicit_model_error(text);
  EXPECT_NE(message.find("rigid body 'arm'"), std::string::npos) << message;
  EXPECT_NE(message.find("free about one axis"), std::string::npos) << message;
}

TEST(ExplicitRigid, ABodyWithoutMassIsAnInputErrorNamingTheBody) {
  std::string text = pendulum_case(1e-3);
  const std::string density = fmt::format("density = {}\n", kArmDensity);
  text.erase(text.find(density), density.size());
  const std::size_t gravity = text.find("[[loads.body_force]]"); // (no mass to act on)
  text.erase(gravity, text.find("[analysis]") - gravity);
  const std::string message = explicit_model_error(text);
  EXPECT_NE(message.find("rigid body 'arm' has no mass"), std::string::npos) << message;
}

} // namespace
