// SPDX-License-Identifier: MIT
// End-to-end tests of implicit dynamic analyses ([analysis] type = "dynamic"): the suddenly
// loaded cantilever of examples/explicit_cantilever against its dynamic-explicit answer, a
// quasi-static step followed by a dynamic one on the same mesh (restarted inside the dynamic
// step, and followed by a quasi-static one again), a biphasic layer whose inertia is
// negligible against its quasi-static creep, and a swinging rigid body restarted mid-swing.
#include "cli_harness.hpp"
#include "edited_text.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <vector>

using namespace trifem::cli_test;
using trifem::test::edited;
namespace fs = std::filesystem;

namespace {

const fs::path kCantilever =
    fs::path(TRIFEM_SOURCE_DIR) / "examples" / "explicit_cantilever" / "explicit_cantilever.toml";

/// The first minimum of `values` (index), where the series turns up again.
std::size_t first_minimum(const std::vector<double>& values) {
  std::size_t k = 0;
  while (k + 1 < values.size() && values[k + 1] <= values[k])
    ++k;
  return k;
}

/// A block pressed slowly (a quasi-static step of 4 steps), then released at once (a dynamic
/// step of 150 steps): it springs back and oscillates about its free length.
std::string press_release_case(const std::string& output_lines = "vtu = false") {
  return R"(
[[mesh.box]]
name = "block"
size = [1, 1, 4]
divisions = [1, 1, 4]
material = "soft"

[materials.soft]
type = "neo-hookean"
E = 1.0
nu = 0.3
density = 1e-9

[curves.ramp]
points = [[0, 0], [1, 1]]

[[boundary.fixed]]
set = "block.zmin"

[[output.reaction]]
set = "block.zmin"

[[output.probe]]
name = "top"
point = [0.5, 0.5, 4.0]

[output]
)" + output_lines +
         R"(

[[step]]
name = "press"
end_time = 1.0
dt = 0.25
[[step.loads.traction]]
surface = "block.zmax"
value = [0, 0, -0.01]
curve = "ramp"

[[step]]
name = "spring_back"
analysis = "dynamic"
duration = 3e-4
dt = 2e-6
)";
}

} // namespace

class CliDynamic : public Cli {};

TEST_F(CliDynamic, SuddenlyLoadedCantileverFollowsTheExplicitAnswer) {
  // the first half period (peak at about 9.2 ms) of the explicit example, and the same beam as
  // an implicit dynamic case: the same shear modulus (0.4 MPa) with the explicit penalty as the
  // bulk modulus (4000 MPa: nu = 0.49995, mean-dilatation cells), 100 steps of 0.1 ms
  const std::string text = read_text(kCantilever);
  const fs::path explicit_case =
      write_file("explicit.toml", edited(text, {{"end_time = 0.04", "end_time = 0.0105"},
                                                {"interval = 5e-4", "interval = 1.5e-3"}}));
  const std::string implicit_text = edited(
      text, {{"type = \"dynamic-explicit\"", "type = \"dynamic\""},
             {"E = 0.8                           # MPa: mu = 0.4 MPa; nu = 0, the bulk response "
              "is the multiplier's",
              "E = 1.19996\nnu = 0.49995"},
             {"end_time = 0.04", "end_time = 0.0105\ndt = 1e-4"},
             {"interval = 5e-4", "interval = 1.5e-3"}});
  const auto explicit_table = implicit_text.find("[explicit]");
  ASSERT_NE(explicit_table, std::string::npos);
  const fs::path implicit_case =
      write_file("implicit.toml", implicit_text.substr(0, explicit_table) +
                                      implicit_text.substr(implicit_text.find("[time]")));
  const Result e = trifem({"-q", "run", explicit_case.string(), "-o", (output() / "e").string()});
  ASSERT_EQ(e.exit_code, kSuccess) << e;
  const Result i = trifem({"-q", "run", implicit_case.string(), "-o", (output() / "i").string()});
  ASSERT_EQ(i.exit_code, kSuccess) << i;
  const History he = read_history(output() / "e" / "history.csv");
  const History hi = read_history(output() / "i" / "history.csv");
  const auto& ze = he["tip.uz [mm]"];
  const auto& zi = hi["tip.uz [mm]"];
  const std::size_t pe = first_minimum(ze), pi = first_minimum(zi);
  ASSERT_LT(pi + 1, zi.size()) << "the implicit tip turns within the run";
  // explicit: -3.730 mm at 9.23 ms (examples/explicit_cantilever/README.md). At the same point
  // the two incompressible formulations differ by 1.1 %: the implicit peak is converged in its
  // step (-3.7706, -3.7731, -3.7730 mm at dt = 1e-4, 5e-5, 2.5e-5 s; measured), and so is the
  // difference at a node of the tip face (-3.7942 against -3.7533 mm).
  EXPECT_NEAR(ze[pe], -3.730, 0.005);
  EXPECT_NEAR(zi[pi] / ze[pe], 1.0, 0.015) << "implicit peak " << zi[pi] << " mm";
  EXPECT_NEAR(hi["time [s]"][pi] / he["time [s]"][pe], 1.0, 0.02);
  EXPECT_GT(hi["iterations"][1], 1.0); // Newton iterates the nonlinear step
  std::cout << "first peak: explicit " << ze[pe] << " mm at " << he["time [s]"][pe]
            << " s, implicit " << zi[pi] << " mm at " << hi["time [s]"][pi] << " s\n";
}

TEST_F(CliDynamic, AQuasiStaticStepThenADynamicOneRunOnOneMesh) {
  // a block pressed slowly, then released at once: it springs back and oscillates about its
  // free length (the clamp's reaction changes sign), starting from rest
  const fs::path file = write_file("press_release.toml", press_release_case());
  const Result r = trifem({"run", file.string(), "-o", output().string()});
  ASSERT_EQ(r.exit_code, kSuccess) << r;
  EXPECT_TRUE(contains(r.out, "'spring_back' (dynamic)")) << r;
  const History h = read_history(output() / "history.csv");
  const auto& time = h["time [s]"];
  const auto& top = h["top.uz [mm]"];
  const auto& reaction = h["block.zmin.Rz [N]"];
  std::size_t press_end = 0;
  while (press_end < time.size() && time[press_end] < 1.0 - 1e-12)
    ++press_end;
  ASSERT_LT(press_end + 10, time.size());
  EXPECT_LT(top[press_end], -0.03); // pressed (about 0.04 mm)
  // released: the top swings up past its free position (a linear spring would reach +|u_0|)
  const double highest = *std::max_element(top.begin() + press_end, top.end());
  EXPECT_GT(highest, 0.5 * std::abs(top[press_end]));
  // the clamp pulls while the block is stretched, pushes while it is compressed
  EXPECT_GT(*std::max_element(reaction.begin() + press_end, reaction.end()), 0.0);
  EXPECT_LT(*std::min_element(reaction.begin() + press_end, reaction.end()), 0.0);
}

TEST_F(CliDynamic, BiphasicCreepWithNegligibleInertiaIsTheQuasiStaticCreep) {
  // Terzaghi's creep (examples/biphasic_creep) with the tissue's mass: the layer's elastic
  // waves (period ~1e-4 s) are far below the steps (1.25 to 50 s), so with rho_inf = 0 (their
  // numerical annihilation) the dynamic history is the quasi-static one
  const fs::path example =
      fs::path(TRIFEM_SOURCE_DIR) / "examples" / "biphasic_creep" / "biphasic_creep.toml";
  const std::string text = read_text(example);
  const auto dynamic_case = [&](const std::string& density) {
    return write_file(
        "dynamic_" + density + ".toml",
        edited(text, {{"nu = 0.0", "nu = 0.0\n[analysis]\ntype = \"dynamic\"\n"
                                   "[dynamic]\nrho_inf = 0.0"},
                      {"permeability = 1.07e-3", "permeability = 1.07e-3\ndensity = " + density}}));
  };
  const Result q = trifem({"-q", "run", example.string(), "-o", (output() / "q").string()});
  ASSERT_EQ(q.exit_code, kSuccess) << q;
  const History hq = read_history(output() / "q" / "history.csv");
  const auto& uq = hq["top.uz [mm]"];
  // largest difference of the top's settlement from the quasi-static one, relative to its peak
  const auto difference = [&](const std::string& density) {
    const fs::path out = output() / density;
    const Result d = trifem({"-q", "run", dynamic_case(density).string(), "-o", out.string()});
    EXPECT_EQ(d.exit_code, kSuccess) << d;
    const History hd = read_history(out / "history.csv");
    const auto& ud = hd["top.uz [mm]"];
    EXPECT_EQ(uq.size(), ud.size());
    EXPECT_EQ(hq["time [s]"], hd["time [s]"]);
    double peak = 0.0, worst = 0.0;
    for (std::size_t k = 0; k < std::min(uq.size(), ud.size()); ++k) {
      peak = std::max(peak, std::abs(uq[k]));
      worst = std::max(worst, std::abs(ud[k] - uq[k]));
    }
    EXPECT_GT(peak, 0.0);
    return worst / peak;
  };
  const double tissue = difference("1.05e-9"); // cartilage
  EXPECT_LT(tissue, 1e-6);
  // the control: the inertia acts (a mass 10^7 times the tissue's changes the history far
  // above the round-off of the tissue's comparison)
  const double heavy = difference("1e-2");
  EXPECT_GT(heavy, 1e-9);
  EXPECT_GT(heavy, 1e3 * tissue);
  std::cout << "biphasic creep, dynamic against quasi-static: " << tissue
            << " of the settlement (density 1.05e-9), " << heavy << " (1e-2)\n";
}

namespace {

/// The rows of the continued history `b` after its first (the restart state itself) equal the
/// last rows of the uninterrupted `a`, every column to 1e-12 of its unit's largest magnitude.
void expect_the_same_rows(const History& a, const History& b) {
  const std::map<std::string, double> scale = unit_scales(a);
  const std::size_t offset = a.columns[0].size() - b.columns[0].size();
  for (std::size_t c = 0; c < a.names.size(); ++c)
    for (std::size_t i = 1; i < b.columns[c].size(); ++i)
      ASSERT_LE(std::abs(b.columns[c][i] - a.columns[c][offset + i]),
                1e-12 * scale.at(unit_of(a.names[c])))
          << a.names[c] << " at t = " << b.columns[0][i];
}

} // namespace

TEST_F(CliDynamic, ARunRestartedInsideTheDynamicStepContinuesTheUninterruptedOne) {
  // the restart file holds the inertia's history (v, a and the weighted static residual of the
  // last step): the continued run takes the same steps to round-off
  const fs::path file =
      write_file("press_release.toml", press_release_case("vtu = true\ntimes = [1.0001, 1.0002]"));
  const fs::path whole = output() / "whole", resumed = output() / "resumed";
  Result r = trifem({"-q", "run", file.string(), "-o", whole.string(), "--write-restart"});
  ASSERT_EQ(r.exit_code, kSuccess) << r;
  const std::vector<fs::path> files = restart_files(whole);
  ASSERT_GE(files.size(), 3u);
  const fs::path restart = files[files.size() - 3]; // 1.0001 s (then 1.0002 s and the end)
  r = trifem({"-q", "run", file.string(), "-o", resumed.string(), "--restart", restart.string()});
  ASSERT_EQ(r.exit_code, kSuccess) << r;
  const History a = read_history(whole / "history.csv");
  const History b = read_history(resumed / "history.csv");
  ASSERT_EQ(a.names, b.names);
  ASSERT_GT(b.columns[0].size(), 50u) << "the continued run takes the last 100 steps";
  EXPECT_NEAR(b["time [s]"].front(), 1.0001, 1e-12);
  expect_the_same_rows(a, b);
}

TEST_F(CliDynamic, ASwingingRigidBodyRestartedMidSwingContinuesTheUninterruptedRun) {
  // a bone (rigid cells) hinged off its center with a torsion spring, carrying a tissue cube,
  // set swinging by its starting angular velocity: the restart file holds the motion of the
  // bone's nodes and the residual history of its six unknowns
  const fs::path file = write_file("swing.toml", R"(
[[mesh.box]]
name = "cube"
size = [1.0, 1.0, 1.0]
divisions = [1, 1, 2]
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
density = 1e-9
[analysis]
type = "dynamic"
[dynamic]
rho_inf = 0.8
[time]
end_time = 0.2
dt = 0.005
[solver]
residual_tolerance = 1e-12
increment_tolerance = 1e-13
[[rigid_body]]
name = "femur"
set = "cube.zmax"
blocks = ["bone"]
density = 2e-9
velocity = [0.0, 0.0, -10.0]
angular_velocity = [20.0, 0.0, 0.0]
[[connector]]
type = "revolute"
name = "hinge"
body_a = "ground"
body_b = "femur"
origin = [0.5, 1.0, 1.15]
axis = [1.0, 0.0, 0.0]
torsion_stiffness = 2e-6
)");
  const fs::path whole = output() / "whole", resumed = output() / "resumed";
  Result r = trifem({"-q", "run", file.string(), "-o", whole.string(), "--write-restart"});
  ASSERT_EQ(r.exit_code, kSuccess) << r;
  const std::vector<fs::path> files = restart_files(whole);
  ASSERT_EQ(files.size(), 40u);       // one per step
  const fs::path restart = files[19]; // 0.1 s
  r = trifem({"-q", "run", file.string(), "-o", resumed.string(), "--restart", restart.string()});
  ASSERT_EQ(r.exit_code, kSuccess) << r;
  const History a = read_history(whole / "history.csv");
  const History b = read_history(resumed / "history.csv");
  ASSERT_EQ(a.names, b.names);
  ASSERT_EQ(b.columns[0].size(), 21u) << "the continued run takes the last 20 steps";
  EXPECT_NEAR(b["time [s]"].front(), 0.1, 1e-12);
  const auto& angle = a["femur.rx [rad]"];
  EXPECT_GT(*std::max_element(angle.begin(), angle.end()), 0.1) << "the bone swings";
  expect_the_same_rows(a, b);
}

TEST_F(CliDynamic, AFreeRigidBodyWithoutMassIsNamedInAWarning) {
  // a bone of rigid cells without density on a hinge: its rotation about the hinge is free and
  // nothing gives it inertia; held in all six components it draws no warning
  const std::string bone = R"(
[[mesh.box]]
name = "bone"
size = [2.0, 1.0, 0.5]
divisions = [2, 1, 1]
[analysis]
type = "dynamic"
[time]
end_time = 0.1
dt = 0.01
[[rigid_body]]
name = "arm"
blocks = ["bone"]
)";
  Result r = trifem({"check", write_file("massless.toml", bone + R"(
[[connector]]
type = "revolute"
name = "hinge"
body_a = "ground"
body_b = "arm"
origin = [-0.5, 0.5, 0.25]
axis = [0.0, 0.0, 1.0]
torsion_stiffness = 1e-6
)")
                                  .string()});
  ASSERT_EQ(r.exit_code, kSuccess) << r;
  EXPECT_TRUE(contains(r.out, "warning: rigid_body[1]: the body has no mass")) << r;
  std::string held = bone;
  for (const std::string k : {"x", "y", "z"})
    held += k + " = { displacement = 0.0 }\nr" + k + " = { rotation = 0.0 }\n";
  r = trifem({"check", write_file("held.toml", held).string()});
  ASSERT_EQ(r.exit_code, kSuccess) << r;
  EXPECT_FALSE(contains(r.out, "has no mass")) << r;
}

TEST_F(CliDynamic, ADynamicStepThenAQuasiStaticOneEndsAtTheStaticEquilibrium) {
  // after the release, a quasi-static step from the moving state: with no load the static
  // equilibrium is the undeformed block, whatever the motion it starts from
  const fs::path file = write_file("press_release_settle.toml",
                                   press_release_case() +
                                       "\n[[step]]\nname = \"settle\"\nend_time = 2.0\ndt = 0.5\n");
  const Result r = trifem({"run", file.string(), "-o", output().string()});
  ASSERT_EQ(r.exit_code, kSuccess) << r;
  EXPECT_TRUE(contains(r.out, "analysis step 3 'settle': t = 1.0003 to 2 s")) << r;
  const History h = read_history(output() / "history.csv");
  const auto& time = h["time [s]"];
  const auto& top = h["top.uz [mm]"];
  std::size_t press_end = 0;
  while (press_end < time.size() && time[press_end] < 1.0 - 1e-12)
    ++press_end;
  ASSERT_LT(press_end, time.size());
  const double pressed = std::abs(top[press_end]);
  EXPECT_GT(pressed, 0.03);
  EXPECT_NEAR(time.back(), 2.0, 1e-12);
  EXPECT_LT(std::abs(top.back()), 1e-8 * pressed);
  EXPECT_LT(std::abs(h["block.zmin.Rz [N]"].back()), 1e-8 * 0.01); // of the pressing force
}

namespace {

/// A free block given a starting velocity of (2, 0, -1) mm/s over all its nodes: an analysis of
/// `analysis` type and its settings.
std::string flying_block(const std::string& analysis) {
  return R"(
[analysis]
type = ")" +
         analysis +
         R"("
[[mesh.box]]
name = "block"
size = [1.0, 1.0, 1.0]
divisions = [2, 2, 2]
material = "rubber"
[materials.rubber]
type = "neo-hookean"
E = 0.8
nu = 0.3
density = 1.1e-9
[[initial_velocity]]
set = "block.all"
value = [2.0, 0.0, -1.0]
[time]
end_time = 1e-3
)" + (analysis == "dynamic" ? "dt = 1e-4\n" : "[explicit]\npenalty = 4000.0\n") +
         R"(
[output]
interval = 2.5e-4
[[output.probe]]
name = "corner"
point = [1.0, 1.0, 1.0]
)";
}

} // namespace

// With no support and no load a block given a uniform velocity translates: u = v t at every
// output, in implicit and in explicit dynamics.
TEST_F(CliDynamic, AFreeBlockGivenAnInitialVelocityTranslatesWithIt) {
  for (const std::string analysis : {"dynamic", "dynamic-explicit"}) {
    SCOPED_TRACE(analysis);
    const fs::path out = output() / analysis;
    const Result r = trifem({"run", write_file(analysis + ".toml", flying_block(analysis)).string(),
                             "-o", out.string()});
    ASSERT_EQ(r.exit_code, kSuccess) << r;
    const History h = read_history(out / "history.csv");
    const auto& t = h["time [s]"];
    ASSERT_GE(t.size(), 4u);
    EXPECT_NEAR(t.back(), 1e-3, 1e-15);
    for (std::size_t i = 0; i < t.size(); ++i) {
      EXPECT_NEAR(h["corner.ux [mm]"][i], 2.0 * t[i], 1e-12) << "t = " << t[i];
      EXPECT_NEAR(h["corner.uy [mm]"][i], 0.0, 1e-12) << "t = " << t[i];
      EXPECT_NEAR(h["corner.uz [mm]"][i], -1.0 * t[i], 1e-12) << "t = " << t[i];
    }
  }
}

TEST_F(CliDynamic, AnInitialVelocityOfAQuasiStaticAnalysisIsAnInputError) {
  std::string text = flying_block("quasi-static");
  text.replace(text.find("[explicit]\npenalty = 4000.0\n"), 27, "dt = 1e-4\n");
  const Result r = trifem({"check", write_file("static.toml", text).string()});
  EXPECT_EQ(r.exit_code, kInvalidInput) << r;
  EXPECT_TRUE(contains(r.err, "initial_velocity[1]: only applies to dynamic analyses")) << r;
}
