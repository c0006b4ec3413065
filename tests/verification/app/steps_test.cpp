// SPDX-License-Identifier: MIT
// Analysis steps ([[step]]), through the case reader, the model and the analysis:
// - the tr01 protocol in one case: free swelling of a confined triphasic column from its
//   stress-free reference to equilibrium (step 1, top free), then a relative confined
//   compression ramp and hold (step 2): the swollen height equals the closed-form swelling root,
//   and the relaxation equals that of the run that prescribes the swelling analytically;
// - a released condition: a biphasic column held compressed to equilibrium (step 1) and then
//   released (step 2, no condition on the top) recovers as the Terzaghi series of the reverse
//   load predicts.
#include "case_runner.hpp"
#include "exact_solutions.hpp"
#include "trifem/core/error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>

using namespace trifem;

namespace {

/// Runs a case text through run_steps, calling `observer` after every accepted step.
test::CaseRun run_stepped(const std::string& text,
                          const std::function<void(const model::Model&, Real)>& observer = {}) {
  return test::run_case_steps(text, "steps.toml", observer);
}

/// Mean z displacement of the top nodes of the column.
Real top_displacement(const model::Model& m) {
  Real sum = 0.0;
  const auto& top = m.mesh.node_set("layer.zmax");
  for (Index n : top)
    sum += m.problem->state()[m.dofs.dof(m.fields.u, n, 2)];
  return sum / static_cast<Real>(top.size());
}

/// Total z reaction on the top nodes (residual at their z DOFs).
Real top_reaction(const model::Model& m) {
  Real sum = 0.0;
  for (Index n : m.mesh.node_set("layer.zmax"))
    sum += m.problem->full_residual()[m.dofs.dof(m.fields.u, n, 2)];
  return sum;
}

// ---------------------------------------------------------------------------------------------
// tr01: swell, then compress

constexpr Real kSwellEnd = 1e5; ///< s: about 30 consolidation times of the 1 mm column

/// The confined triphasic column of the paper (E = 0.3 MPa, cF0 = 0.2 M, 0.15 M bath), 1 x 1 x 6
/// cells, bottom bonded, sides confined and impermeable, top draining to the bath; `swelling`
/// is the first step's table body, the second step compresses the top by 0.1 mm in 200 s
/// (relative to the swollen state) and holds to 2000 s.
std::string tr01_case(const std::string& swelling) {
  return fmt::format(R"(
[[mesh.box]]
name = "layer"
size = [1.0, 1.0, 1.0]
divisions = [1, 1, 6]
material = "cartilage"

[materials.cartilage]
type = "triphasic"
phi_s0 = 0.25
permeability = 1.07e-3
fixed_charge = 2.0e-4
d_plus = 5.0e-4
d_minus = 8.0e-4
[materials.cartilage.solid]
type = "saint-venant-kirchhoff"
E = 0.3
nu = 0.0

[curves.squeeze]
points = [[{0}, 0.0], [{1}, 1.0]]

[[boundary.fixed]]
set = "layer.all"
components = ["x", "y"]
[[boundary.fixed]]
set = "layer.all"
field = "fluxes"
components = ["x", "y"]
[[boundary.bonded]]
set = "layer.zmin"

[[step]]
name = "swelling"
end_time = {0}
dt = 1.0
dt_max = 1e4
growth = 2.0
{2}

[[step]]
name = "compression"
duration = 2000.0
dt = 10.0
dt_max = 10.0
[[step.boundary.prescribed]]
set = "layer.zmax"
component = "z"
value = -0.1
curve = "squeeze"
relative = true
)",
                     kSwellEnd, kSwellEnd + 200.0, swelling);
}

/// The tr01 protocol with `swelling` as the first step's extra keys: the mean top displacement
/// at the end of the swelling and the top reaction after it (by whole seconds).
struct SwellThenCompress {
  Real swollen_top = 0.0;
  std::map<long, Real> reaction;
  Real final_top = 0.0;
};

SwellThenCompress swell_then_compress(const std::string& swelling) {
  SwellThenCompress out;
  const auto run = run_stepped(tr01_case(swelling), [&](const model::Model& m, Real t) {
    if (std::abs(t - kSwellEnd) < 1e-6)
      out.swollen_top = top_displacement(m);
    if (t > kSwellEnd)
      out.reaction[std::lround(t - kSwellEnd)] = top_reaction(m);
  });
  EXPECT_TRUE(run.report.success) << run.report.failure;
  out.final_top = top_displacement(*run.model);
  return out;
}

Real peak_of(const std::map<long, Real>& history) {
  Real peak = 0.0;
  for (const auto& [t, r] : history)
    peak = std::max(peak, std::abs(r));
  return peak;
}

TEST(Steps, Tr01SwellThenCompressMatchesPrescribedSwelling) {
  const exact::SwellingState swollen =
      exact::swelling_equilibrium(exact::SolidLaw::StVenantKirchhoff, exact::Deformation::Confined,
                                  0.3, 0.0, exact::paper_medium());
  // free swelling (top free in step 1)
  const SwellThenCompress free = swell_then_compress("");
  EXPECT_NEAR(1.0 + free.swollen_top, swollen.stretch, 1e-6 * swollen.stretch);
  EXPECT_NEAR(free.final_top, free.swollen_top - 0.1, 1e-12);
  // the same protocol with the swelling prescribed from the closed form (ramped over 1000 s)
  const std::string prescribed = fmt::format(R"(
[[step.boundary.prescribed]]
set = "layer.zmax"
component = "z"
value = {}
curve = "swell"
[curves.swell]
points = [[0.0, 0.0], [1000.0, 1.0]]
)",
                                             swollen.stretch - 1.0);
  const SwellThenCompress ref = swell_then_compress(prescribed);
  ASSERT_EQ(free.reaction.size(), 200u);
  ASSERT_EQ(ref.reaction.size(), free.reaction.size());
  const Real peak = peak_of(ref.reaction);
  EXPECT_GT(peak, 1e-3); // N: the compression loads the layer
  Real worst = 0.0;
  for (const auto& [t, r] : free.reaction) {
    EXPECT_NEAR(r, ref.reaction.at(t), 1e-6 * peak) << "t = t1 + " << t << " s";
    worst = std::max(worst, std::abs(r - ref.reaction.at(t)));
  }
  std::printf("[tr01] swollen stretch %.10f (closed form %.10f, relative difference %.2e); "
              "relaxation peak %.6e N, largest difference %.2e of it\n",
              1.0 + free.swollen_top, swollen.stretch,
              (1.0 + free.swollen_top) / swollen.stretch - 1.0, peak, worst / peak);
}

// A steady-state swelling step (steady = true) reaches the swelling equilibrium at each of its
// times: the swollen height is the closed-form root, and the compression that follows relaxes as
// after the long transient swelling (the same problem solved two ways).
TEST(Steps, SteadySwellingStepIsTheLongTimeLimitOfTheTransientOne) {
  const exact::SwellingState swollen =
      exact::swelling_equilibrium(exact::SolidLaw::StVenantKirchhoff, exact::Deformation::Confined,
                                  0.3, 0.0, exact::paper_medium());
  const SwellThenCompress transient = swell_then_compress("");
  const SwellThenCompress steady = swell_then_compress("steady = true");
  EXPECT_NEAR(1.0 + steady.swollen_top, swollen.stretch, 1e-9 * swollen.stretch);
  ASSERT_EQ(steady.reaction.size(), transient.reaction.size());
  const Real peak = peak_of(transient.reaction);
  Real worst = 0.0;
  for (const auto& [t, r] : steady.reaction) {
    EXPECT_NEAR(r, transient.reaction.at(t), 1e-6 * peak) << "t = t1 + " << t << " s";
    worst = std::max(worst, std::abs(r - transient.reaction.at(t)));
  }
  std::printf("[steady] swollen stretch %.12f (closed form %.12f, relative difference %.2e); "
              "compression after it differs from that after the transient swelling by %.2e of "
              "the peak\n",
              1.0 + steady.swollen_top, swollen.stretch,
              (1.0 + steady.swollen_top) / swollen.stretch - 1.0, worst / peak);
}

// ---------------------------------------------------------------------------------------------
// release: compress to equilibrium, then let go

constexpr Real kHold = 3e4;    ///< s: end of step 1 (about 10 consolidation times)
constexpr Real kSquash = 3e-4; ///< mm: compression of the 1 mm layer (strain 3e-4)
const exact::ConfinedLayer kLayer{1.0, 0.3, 1.07e-3};

std::string release_case(Real release_time) {
  return fmt::format(R"(
[[mesh.box]]
name = "layer"
size = [1.0, 1.0, 1.0]
divisions = [1, 1, 40]
material = "tissue"

[materials.tissue]
type = "biphasic"
phi_s0 = 0.25
permeability = 1.07e-3
[materials.tissue.solid]
type = "saint-venant-kirchhoff"
E = 0.3
nu = 0.0

[curves.squash]
points = [[0.0, 0.0], [1e-3, 1.0]]

[[boundary.fixed]]
set = "layer.all"
components = ["x", "y"]
[[boundary.fixed]]
set = "layer.all"
field = "fluid_flux"
components = ["x", "y"]
[[boundary.bonded]]
set = "layer.zmin"

[[step]]
name = "hold"
end_time = {0}
dt = 1e-3
dt_max = 1e3
growth = 2.0
[[step.boundary.prescribed]]
set = "layer.zmax"
component = "z"
value = {1}
curve = "squash"

[[step]]
name = "release"
duration = 600.0
dt = 1.25
dt_max = 10.0
release_time = {2}
)",
                     kHold, -kSquash, release_time);
}

TEST(Steps, ReleasedPlatenRecoversAsTheReverseTerzaghiCreep) {
  const Real sigma0 = kLayer.H_A * kSquash; // the equilibrium compressive stress released
  int checked = 0;
  const auto run = run_stepped(release_case(0.0), [&](const model::Model& m, Real t) {
    if (t <= kHold + 20.0) // after the early transient, resolved only by finer steps
      return;
    // the reverse load: the held state minus the creep under sigma0
    const Real exact = -kSquash - exact::creep_surface_displacement(kLayer, sigma0, t - kHold);
    EXPECT_NEAR(top_displacement(m), exact, 5e-3 * kSquash) << "t = " << t;
    ++checked;
  });
  ASSERT_TRUE(run.report.success) << run.report.failure;
  EXPECT_GT(checked, 50);
  // after 600 s (0.19 consolidation times) about half the squash is recovered
  EXPECT_GT(top_displacement(*run.model), -0.6 * kSquash) << "the layer recovers";
}

TEST(Steps, ReleaseTimeCarriesTheReactionSoTheStateDoesNotJump) {
  Real first = 0.0;
  const auto run = run_stepped(release_case(100.0), [&](const model::Model& m, Real t) {
    if (first == 0.0 && t > kHold)
      first = top_displacement(m);
  });
  ASSERT_TRUE(run.report.success) << run.report.failure;
  // one step of 1.25 s into a 100 s release: the load fell by 1.25 %, the top moved by
  // less than that fraction of the squash (it cannot move faster than the load falls)
  EXPECT_NEAR(first, -kSquash, 0.0125 * kSquash);
  EXPECT_GT(top_displacement(*run.model), -0.6 * kSquash) << "the layer recovers";
}

/// The InputError of building the model of `text`.
std::string build_error(const std::string& text) {
  try {
    model::build_model(io::parse_case(text, "steps.toml"));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Steps, AStepMayNotConstrainWhatTheCaseHolds) {
  std::string text = release_case(0.0);
  text += R"(
[[step]]
name = "bad"
duration = 10.0
dt = 1.0
[[step.boundary.prescribed]]
set = "layer.zmin"
component = "z"
value = 0.1
)";
  const std::string e = build_error(text);
  EXPECT_NE(e.find("step[3].boundary.prescribed[1]"), std::string::npos) << e;
  EXPECT_NE(e.find("already held in every step"), std::string::npos) << e;
  const std::string set = build_error(release_case(0.0) + R"(
[[step]]
duration = 10.0
dt = 1.0
[[step.boundary.fixed]]
set = "layer.top"
components = ["z"]
)");
  EXPECT_NE(set.find("step[3].boundary.fixed[1].set"), std::string::npos) << set;
  EXPECT_NE(set.find("layer.top"), std::string::npos) << set;
}

} // namespace

// ---------------------------------------------------------------------------------------------
// steady permeation driven by a bath pressure

namespace {

/// A layer 1 mm high of `layers` cells clamped at both ends and confined laterally (its fluxes
/// too: `fluxes` names the flux field), a bath at gauge pressure 0.1 MPa ramped under it and the
/// reference bath above it, solved by one steady-state step; `material` is the body of its
/// [materials.tissue] table.
std::string permeation_case(int layers, const std::string& material, const std::string& fluxes) {
  return fmt::format(R"(
[[mesh.box]]
name = "layer"
size = [1.0, 1.0, 1.0]
divisions = [1, 1, {}]
material = "tissue"

[materials.tissue]
{}
[materials.tissue.solid]
type = "neo-hookean"
E = 0.3
nu = 0.0

[curves.up]
points = [[0.0, 0.0], [1.0, 1.0]]

[[boundary.fixed]]
set = "layer.all"
components = ["x", "y"]
[[boundary.fixed]]
set = "layer.all"
field = "{}"
components = ["x", "y"]
[[boundary.fixed]]
set = "layer.zmin"
components = ["z"]
[[boundary.fixed]]
set = "layer.zmax"
components = ["z"]
[[boundary.bath]]
surface = "layer.zmin"
pressure = 0.1
curve = "up"

[[step]]
name = "permeation"
end_time = 1.0
dt = 0.25
steady = true
)",
                     layers, material, fluxes);
}

} // namespace

// The triphasic layer of the test below without fixed charge, the reference bath's
// concentration at both ends, its free-solution diffusivities d0 above the tissue's d (FEBio's
// free_diff: the ions also drag on the solid). Its concentration stays the bath's and its ion
// potentials uniform, so each ion's momentum balance A_w w = A_ion j reads j = (d/d0) c w: the
// ions are carried at the fraction d/d0 of the water's velocity (with d0 = d, with it).
TEST(Steps, SteadyPermeationCarriesTheIonsAtTheFractionDOverD0OfTheWater) {
  for (const bool hindered : {true, false}) {
    const std::string free = hindered ? "free_d_plus = 1.2e-3\nfree_d_minus = 2.0e-3\n" : "";
    const std::string text = permeation_case(6, R"(type = "triphasic"
phi_s0 = 0.25
permeability = 1.07e-3
fixed_charge = 0.0
d_plus = 6.0e-4
d_minus = 8.0e-4
)" + free,
                                             "fluxes");
    const auto run = run_stepped(text);
    ASSERT_TRUE(run.report.success) << run.report.failure;
    const model::Model& m = *run.model;
    const Vector& x = m.problem->state();
    const Real h_plus = hindered ? 6.0e-4 / 1.2e-3 : 1.0,
               h_minus = hindered ? 8.0e-4 / 2.0e-3 : 1.0;
    int checked = 0;
    for (Index n = 0; n < m.mesh.num_nodes(); ++n) {
      const Real w = x[m.dofs.dof(m.fields.w, n, 2)]; // j holds j / c_ref, c = c_ref here
      ASSERT_GT(w, 0.0);
      EXPECT_NEAR(x[m.dofs.dof(m.fields.j_plus, n, 2)], h_plus * w, 1e-8 * w) << n;
      EXPECT_NEAR(x[m.dofs.dof(m.fields.j_minus, n, 2)], h_minus * w, 1e-8 * w) << n;
      ++checked;
    }
    EXPECT_EQ(checked, 28);
  }
}

// A biphasic layer clamped at both ends (so its current height stays h), confined laterally,
// with a bath at gauge pressure p0 under it and the reference bath (p = 0) above it, solved by a
// steady-state step. With a constant permeability the steady Darcy flux is uniform in the
// current configuration, so w_z = kappa p0 / h exactly however the drag compacts the solid
// (p0 = 0.1 MPa against E = 0.3 MPa: strains of tens of percent along the layer).
TEST(Steps, SteadyPermeationUnderABathPressureGivesDarcysFlux) {
  constexpr Real kappa = 1.07e-3, p0 = 0.1, h = 1.0;
  const std::string text = permeation_case(8, R"(type = "biphasic"
phi_s0 = 0.25
permeability = 1.07e-3
)",
                                           "fluid_flux");
  std::vector<Real> flux; // w_z at the top nodes, end of the run
  Real stretch_range = 0.0;
  const auto run = run_stepped(text);
  ASSERT_TRUE(run.report.success) << run.report.failure;
  const model::Model& m = *run.model;
  for (Index n : m.mesh.node_set("layer.zmax"))
    flux.push_back(m.problem->state()[m.dofs.dof(m.fields.w, n, 2)]);
  for (Index n : m.mesh.node_set("layer.zmin"))
    flux.push_back(m.problem->state()[m.dofs.dof(m.fields.w, n, 2)]);
  ASSERT_EQ(flux.size(), 8u);
  Real worst_flux = 0.0;
  for (Real w : flux) {
    EXPECT_NEAR(w, kappa * p0 / h, 1e-8 * kappa * p0 / h); // the Newton tolerance
    worst_flux = std::max(worst_flux, std::abs(w / (kappa * p0 / h) - 1.0));
  }
  // the drag compacts the layer towards its top: the solid is far from its reference state
  Real lowest = 1.0, highest = 1.0;
  for (Index c = 0; c < m.mesh.num_cells(); ++c) {
    const auto& cell = m.mesh.cell(c);
    const Real dz =
        (m.mesh.node(cell[4]).z() + m.problem->state()[m.dofs.dof(m.fields.u, cell[4], 2)]) -
        (m.mesh.node(cell[0]).z() + m.problem->state()[m.dofs.dof(m.fields.u, cell[0], 2)]);
    const Real stretch = dz / (m.mesh.node(cell[4]).z() - m.mesh.node(cell[0]).z());
    lowest = std::min(lowest, stretch);
    highest = std::max(highest, stretch);
  }
  stretch_range = highest - lowest;
  EXPECT_GT(stretch_range, 0.1);
  std::printf("[permeation] w_z = %.15e (kappa p0 / h = %.15e; largest relative difference of "
              "the 8 nodes %.1e), cell stretches %.4f to %.4f\n",
              flux.front(), kappa * p0 / h, worst_flux, lowest, highest);
}
