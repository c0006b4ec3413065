// SPDX-License-Identifier: MIT
// FEBio's own test problems (the Verify folder of FEBio's public TestSuite repository), run from
// their unchanged .feb files and compared with independent answers. The files carry no licence,
// so they are not stored here: set TRIFEM_FEBIO_TESTSUITE to the folder that holds them (e.g.
// a checkout's Verify/); without it these tests are skipped. Results: docs/verification.md.
#include "exact_solutions.hpp"
#include "febio_suite.hpp"
#include "trifem/analysis/case_file.hpp"
#include "trifem/analysis/run.hpp"
#include "trifem/linalg/linear_solver.hpp"
#include "trifem/model/model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <map>

using namespace trifem;
using namespace trifem::test;

// bp04: confined ramp-relaxation of a biphasic column (10 graded layers), drained at the top:
// the top reaction at 1000 s against the finite-strain equilibrium (neo-Hookean, nu = 0, 10 %).
TEST(FebioTestSuite, Bp04ConfinedRelaxationReachesTheFiniteStrainEquilibrium) {
  SUITE_FILE(file, "bp04.feb");
  const SuiteRun r = run(file);
  ASSERT_TRUE(r.report.success) << r.report.failure;
  const model::Model& m = *r.model;
  const auto top = end_nodes(m, 2, 1);
  const Real s = 1.0 + mean_of(m, m.fields.u, top, 2) / extent(m, 2);
  const Real expected = neo_hookean_confined(1.0, s) * section_area(m, 2);
  const Real f = reaction(m, top, 2);
  report("bp04", "top reaction at 1000 s [N]", f, expected);
  EXPECT_NEAR(f, expected, 1e-4 * std::abs(expected)); // the transient left: 2e-5 (linear theory)
}

// co01: two blocks in sliding-facet-on-facet contact compressed 10 % (neo-Hookean, nu = 0):
// uniaxial strain is homogeneous, so the reaction is the closed form to round-off.
TEST(FebioTestSuite, Co01ContactOfTwoBlocksIsHomogeneousCompression) {
  SUITE_FILE(file, "co01.feb");
  const SuiteRun r = run(file);
  ASSERT_TRUE(r.report.success) << r.report.failure;
  const model::Model& m = *r.model;
  ASSERT_EQ(m.contacts.size(), 1u);
  const auto top = end_nodes(m, 2, 1);
  const Real s = 1.0 + mean_of(m, m.fields.u, top, 2) / extent(m, 2);
  const Real expected = neo_hookean_confined(1.0, s) * section_area(m, 2);
  const Real f = reaction(m, top, 2);
  report("co01", "top reaction [N]", f, expected);
  EXPECT_NEAR(f, expected, 1e-9 * std::abs(expected));
}

namespace {

/// tr01 and mp01: free swelling of a confined triphasic column (steady-state step to t = 1 s)
/// against the closed-form Donnan swelling stretch (neo-Hookean E = 0.3, nu = 0, phi_s0 = 0.2,
/// cF = 200 mM, 150 mM bath, T = 293 K).
void expect_free_swelling(const char* name) {
  SUITE_FILE(file, std::string(name) + ".feb");
  const exact::ChargedMedium medium{2e-4, 0.2, 1.5e-4, 8.314 * 293.0, 96.485};
  const Real expected = exact::swelling_equilibrium(exact::SolidLaw::NeoHookean,
                                                    exact::Deformation::Confined, 0.3, 0.0, medium)
                            .stretch;
  Real swollen = 0.0;
  const SuiteRun r = run(file, [&](const model::Model& m, Real t) {
    if (std::abs(t - 1.0) < 1e-9)
      swollen = 1.0 + mean_of(m, m.fields.u, end_nodes(m, 2, 1), 2) / extent(m, 2);
  });
  ASSERT_TRUE(r.report.success) << r.report.failure;
  report(name, "swollen stretch at t = 1 s", swollen, expected);
  EXPECT_NEAR(swollen, expected, 1e-8 * expected);
}

} // namespace

TEST(FebioTestSuite, Tr01SteadySwellingIsTheDonnanEquilibrium) {
  expect_free_swelling("tr01");
}

TEST(FebioTestSuite, Mp01SteadySwellingIsTheDonnanEquilibrium) {
  expect_free_swelling("mp01");
}

namespace {

/// bp11 and bp12: steady permeation of a confined biphasic layer (neo-Hookean E = 1, nu = 0,
/// k = 1e-3) driven by p = 0.2 upstream (z = 0 face), drained downstream. The steady Darcy flux
/// is uniform in the current configuration: w = k p0 / h with h the current height; and with
/// the upstream end free (bp12) the solid carries sigma_e = p, so h = H p0 / int_0^p0 dp /
/// lambda(p), lambda(p) the confined neo-Hookean stretch at stress p. The files end at 1000 s,
/// one consolidation time H^2/(E k): the clamped layer (bp11) is steady by then, the free one
/// (bp12) still creeps (measured: its flux 0.35 %, its height 1.2e-4 from the steady state).
void expect_steady_permeation(const char* name, bool upstream_free) {
  SUITE_FILE(file, std::string(name) + ".feb");
  const SuiteRun r = run(file);
  ASSERT_TRUE(r.report.success) << r.report.failure;
  const model::Model& m = *r.model;
  constexpr Real k = 1e-3, p0 = 0.2, mu = 0.5;
  const Real H = extent(m, 2);
  const auto up = end_nodes(m, 2, -1), down = end_nodes(m, 2, 1);
  const Real h = H + mean_of(m, m.fields.u, down, 2) - mean_of(m, m.fields.u, up, 2);
  const Real w = std::abs(mean_of(m, m.fields.w, down, 2));
  report(name, "steady flux [mm/s]", w, k * p0 / h);
  EXPECT_NEAR(w, k * p0 / h, (upstream_free ? 1e-2 : 1e-6) * k * p0 / h);
  if (!upstream_free)
    return;
  const auto stretch = [&](Real p) { return (p + std::sqrt(p * p + 4 * mu * mu)) / (2 * mu); };
  Real integral = 0.0; // Simpson on 2000 intervals
  const int n = 2000;
  for (int i = 0; i <= n; ++i) {
    const Real weight = i == 0 || i == n ? 1.0 : i % 2 ? 4.0 : 2.0;
    integral += weight / stretch(p0 * i / n);
  }
  integral *= p0 / n / 3.0;
  report(name, "current height [mm]", h, H * p0 / integral);
  EXPECT_NEAR(h, H * p0 / integral, 1e-3 * H);
}

} // namespace

TEST(FebioTestSuite, Bp11SteadyPermeationGivesDarcysFlux) {
  expect_steady_permeation("bp11", false);
}

TEST(FebioTestSuite, Bp12SteadyPermeationOfAFreeLayerGivesItsHeightAndFlux) {
  expect_steady_permeation("bp12", true);
}

// bp13: the layer of bp11 (both ends clamped) driven by a prescribed inflow q = 2e-4 mm/s: the
// steady pressure drop is linear in the current coordinate, p = q (h - z) / k with h = H, which
// the cell pressures sample at their centroids.
TEST(FebioTestSuite, Bp13PrescribedFluxGivesTheLinearPressureProfile) {
  SUITE_FILE(file, "bp13.feb");
  const SuiteRun r = run(file);
  ASSERT_TRUE(r.report.success) << r.report.failure;
  const Real drop = kBp13Flux * extent(*r.model, 2) / kBp13Permeability;
  const Real worst = bp13_pressure_error(*r.model);
  report("bp13", "largest cell pressure difference [MPa]", worst + drop, drop);
  EXPECT_LT(worst, 1e-3 * drop);
}

// bp15: two biphasic bricks in sliding-biphasic contact, compressed 25 % along y in 500 s and
// held to 3000 s: the top reaction against the Holmes-Mow confined equilibrium (beta = 0.3).
TEST(FebioTestSuite, Bp15BiphasicContactRelaxesTowardsTheHolmesMowEquilibrium) {
  SUITE_FILE(file, "bp15.feb");
  const SuiteRun r = run(file);
  ASSERT_TRUE(r.report.success) << r.report.failure;
  const model::Model& m = *r.model;
  ASSERT_EQ(m.contacts.size(), 1u);
  const auto top = end_nodes(m, 1, 1);
  const Real s = 1.0 + mean_of(m, m.fields.u, top, 1) / extent(m, 1);
  const Real expected = holmes_mow_confined(1.0, 0.3, s) * section_area(m, 1);
  const Real f = reaction(m, top, 1);
  report("bp15", "top reaction at 3000 s [N]", f, expected);
  EXPECT_NEAR(f, expected, 0.05 * std::abs(expected));
}

// bp16: the bricks of bp15 under a creep traction of 0.2 MPa (step 2, to 10 000 s): the top
// displacement against the Holmes-Mow confined stretch at 0.2 MPa.
TEST(FebioTestSuite, Bp16BiphasicContactCreepsTowardsTheHolmesMowStretch) {
  SUITE_FILE(file, "bp16.feb");
  const SuiteRun r = run(file);
  ASSERT_TRUE(r.report.success) << r.report.failure;
  const model::Model& m = *r.model;
  ASSERT_EQ(m.contacts.size(), 1u);
  Real a = 0.5, b = 1.0; // bisection: sigma(s) = -0.2
  for (int i = 0; i < 200; ++i) {
    const Real c = 0.5 * (a + b);
    (holmes_mow_confined(1.0, 0.3, c) < -0.2 ? a : b) = c;
  }
  const Real H = extent(m, 1);
  const Real u = mean_of(m, m.fields.u, end_nodes(m, 1, 1), 1);
  report("bp16", "top displacement at 10000 s [mm]", u, (a - 1.0) * H);
  EXPECT_NEAR(u, (a - 1.0) * H, 0.01 * std::abs((a - 1.0) * H));
}

// bp22: two biphasic columns (neo-Hookean, nu = 0) in sliding-biphasic contact, loaded through a
// rigid body ("rigid body" material attached to the top nodes, rotations fixed) by a creep force
// of 0.2 N (to 10 000 s). The columns start overlapping by 0.001, which the contact closes: the
// top moves by s H - (extent of the mesh), H the sum of the column heights, s the confined
// stretch at 0.2 MPa.
TEST(FebioTestSuite, Bp22RigidBodyCreepsTowardsTheNeoHookeanStretch) {
  SUITE_FILE(file, "bp22.feb");
  const SuiteRun r = run(file);
  ASSERT_TRUE(r.report.success) << r.report.failure;
  const model::Model& m = *r.model;
  ASSERT_EQ(r.spec.rigid_bodies.size(), 1u);
  EXPECT_EQ(r.spec.rigid_bodies[0].components, std::vector<io::Component>{2});
  Real H = 0.0;
  for (const auto& [part, material] : r.spec.meshes.at(0).materials) { // the two columns
    Real lo = 1e300, hi = -1e300;
    for (Index c : m.mesh.cell_block(part))
      for (Index n : m.mesh.cell(c)) {
        lo = std::min(lo, m.mesh.node(n).z());
        hi = std::max(hi, m.mesh.node(n).z());
      }
    H += hi - lo;
  }
  const Real s = 0.5 * (-0.4 + std::sqrt(0.16 + 4.0)); // mu (s - 1/s) = -0.2, mu = 0.5
  const Real expected = s * H - extent(m, 2);
  const Real u = mean_of(m, m.fields.u, end_nodes(m, 2, 1), 2);
  report("bp22", "rigid body displacement at 10000 s [mm]", u, expected);
  EXPECT_NEAR(u, expected, 0.01 * std::abs(expected));
}
