// SPDX-License-Identifier: MIT
// FEBio's own test problems under refinement: each file run unchanged, then with its mesh split
// into eight per cell and its time steps halved, once and twice (analysis::refine_case). Where
// the file ends before the transient does, the quantity at its end time is compared with the
// same problem converged under refinement (Richardson extrapolation of the three levels); where
// the reference is reached exactly, every level reaches it. Skipped without
// TRIFEM_FEBIO_TESTSUITE (the files are not stored here); about 15 minutes on 2 cores with it.
// Results: docs/feb.md (FEBio's test problems).
#include "exact_solutions.hpp"
#include "febio_suite.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

using namespace trifem;
using namespace trifem::test;

namespace {

constexpr int kLevels = 2; ///< refinement levels after the file's own (0)

/// A quantity measured on a finished run.
using Quantity = std::function<Real(const SuiteRun&)>;

/// The values of a quantity at levels 0..kLevels and what they converge to.
struct Series {
  std::vector<Real> values;
  Real ratio = 0.0;        ///< (q0 - q1) / (q1 - q2): 2 for first order, 4 for second
  Real extrapolated = 0.0; ///< Richardson: q2 + (q2 - q1) / (ratio - 1)
};

/// Runs `file` at every level and measures `quantity` on each run.
Series refine(const std::filesystem::path& file, const Quantity& quantity) {
  Series s;
  for (int level = 0; level <= kLevels; ++level) {
    const SuiteRun r = run_refined(file, level);
    EXPECT_TRUE(r.report.success) << "level " << level << ": " << r.report.failure;
    s.values.push_back(r.report.success ? quantity(r) : NAN);
  }
  const Real d01 = s.values[0] - s.values[1], d12 = s.values[1] - s.values[2];
  s.ratio = d01 / d12;
  s.extrapolated = s.ratio > 1.0 ? s.values[2] - d12 / (s.ratio - 1.0) : s.values[2];
  return s;
}

/// Prints the series and the difference of each level from the extrapolated value (relative to
/// it), and checks that the differences fall: each level closer than the one before, at a rate
/// of at least `min_ratio` per level.
void expect_converging(const char* name, const char* quantity, const Series& s,
                       Real min_ratio = 1.5) {
  std::printf("[refinement] %s: %s: levels 0-2: %.9g %.9g %.9g; ratio %.2f; converged %.9g; "
              "differences %.2e %.2e %.2e\n",
              name, quantity, s.values[0], s.values[1], s.values[2], s.ratio, s.extrapolated,
              std::abs(s.values[0] / s.extrapolated - 1.0),
              std::abs(s.values[1] / s.extrapolated - 1.0),
              std::abs(s.values[2] / s.extrapolated - 1.0));
  EXPECT_GT(s.ratio, min_ratio) << name;
  EXPECT_LT(std::abs(s.values[2] - s.extrapolated), std::abs(s.values[1] - s.extrapolated));
  EXPECT_LT(std::abs(s.values[1] - s.extrapolated), std::abs(s.values[0] - s.extrapolated));
}

/// The mean displacement along `axis` of the nodes at the top along it.
Real top_displacement(const SuiteRun& r, int axis) {
  const model::Model& m = *r.model;
  return mean_of(m, m.fields.u, end_nodes(m, axis, 1), axis);
}

/// The reaction along `axis` of the nodes at the top along it.
Real top_reaction(const SuiteRun& r, int axis) {
  return reaction(*r.model, end_nodes(*r.model, axis, 1), axis);
}

} // namespace

// bp04: the top reaction at 1000 s (the relaxation after a 10 % ramp, 10 graded layers).
TEST(FebioTestSuiteRefinement, Bp04RelaxationConverges) {
  SUITE_FILE(file, "bp04.feb");
  const Series s = refine(file, [](const SuiteRun& r) { return top_reaction(r, 2); });
  expect_converging("bp04", "top reaction at 1000 s [N]", s);
}

// bp12: the flux at 1000 s through a free layer under a pressure drop (still creeping).
TEST(FebioTestSuiteRefinement, Bp12PermeationFluxConverges) {
  SUITE_FILE(file, "bp12.feb");
  const Series s = refine(file, [](const SuiteRun& r) {
    const model::Model& m = *r.model;
    return std::abs(mean_of(m, m.fields.w, end_nodes(m, 2, 1), 2));
  });
  expect_converging("bp12", "flux at 1000 s [mm/s]", s);
}

// bp13: the cell pressures against the exact steady profile: the difference itself falls.
TEST(FebioTestSuiteRefinement, Bp13PressureProfileConvergesToTheExactOne) {
  SUITE_FILE(file, "bp13.feb");
  std::vector<Real> errors;
  for (int level = 0; level <= kLevels; ++level) {
    const SuiteRun r = run_refined(file, level);
    ASSERT_TRUE(r.report.success) << r.report.failure;
    errors.push_back(bp13_pressure_error(*r.model) /
                     (kBp13Flux * extent(*r.model, 2) / kBp13Permeability));
  }
  std::printf("[refinement] bp13: largest cell pressure difference / pressure drop, levels 0-2: "
              "%.2e %.2e %.2e\n",
              errors[0], errors[1], errors[2]);
  EXPECT_LT(errors[1], 0.6 * errors[0]);
  EXPECT_LT(errors[2], 0.6 * errors[1]);
}

// bp15: the top reaction at 3000 s of the bricks in biphasic contact (relaxation left).
TEST(FebioTestSuiteRefinement, Bp15ContactRelaxationConverges) {
  SUITE_FILE(file, "bp15.feb");
  const Series s = refine(file, [](const SuiteRun& r) { return top_reaction(r, 1); });
  expect_converging("bp15", "top reaction at 3000 s [N]", s);
}

// bp16: the top displacement at 10 000 s of the bricks creeping in biphasic contact.
TEST(FebioTestSuiteRefinement, Bp16ContactCreepConverges) {
  SUITE_FILE(file, "bp16.feb");
  const Series s = refine(file, [](const SuiteRun& r) { return top_displacement(r, 1); });
  expect_converging("bp16", "top displacement at 10000 s [mm]", s);
}

// bp22: the rigid body displacement at 10 000 s (creep through contact).
TEST(FebioTestSuiteRefinement, Bp22RigidBodyCreepConverges) {
  SUITE_FILE(file, "bp22.feb");
  const Series s = refine(file, [](const SuiteRun& r) { return top_displacement(r, 2); });
  expect_converging("bp22", "rigid body displacement at 10000 s [mm]", s);
}

// tr01: the top reaction at 2001 s, after the compression of the swollen triphasic column
// (0.1 mm in 200 s, then held), and how far it still is from the loaded Donnan equilibrium.
TEST(FebioTestSuiteRefinement, Tr01CompressionConverges) {
  SUITE_FILE(file, "tr01.feb");
  const Series s = refine(file, [](const SuiteRun& r) { return top_reaction(r, 2); });
  expect_converging("tr01", "top reaction at 2001 s [N]", s);
  const exact::ChargedMedium medium{2e-4, 0.2, 1.5e-4, 8.314 * 293.0, 96.485};
  const Real swollen = exact::swelling_equilibrium(exact::SolidLaw::NeoHookean,
                                                   exact::Deformation::Confined, 0.3, 0.0, medium)
                           .stretch;
  const Real equilibrium = exact::confined_column_equilibrium(swollen - 0.1, 0.3, 0.0, medium,
                                                              exact::SolidLaw::NeoHookean)
                               .total_stress;
  std::printf("[refinement] tr01: equilibrium reaction %.9g N (converged value at 2001 s: %.2e "
              "from it)\n",
              equilibrium, std::abs(s.extrapolated / equilibrium - 1.0));
}

// co01 and bp11 reach their references exactly (homogeneous contact; steady Darcy flux): so does
// every level.
TEST(FebioTestSuiteRefinement, ExactAnswersStayExact) {
  SUITE_FILE(co01, "co01.feb");
  SUITE_FILE(bp11, "bp11.feb");
  for (int level = 1; level <= kLevels; ++level) {
    const SuiteRun contact = run_refined(co01, level);
    ASSERT_TRUE(contact.report.success) << contact.report.failure;
    const model::Model& m = *contact.model;
    const Real s = 1.0 + top_displacement(contact, 2) / extent(m, 2);
    const Real expected = neo_hookean_confined(1.0, s) * section_area(m, 2);
    EXPECT_NEAR(top_reaction(contact, 2), expected, 1e-9 * std::abs(expected)) << level;
    const SuiteRun flow = run_refined(bp11, level);
    ASSERT_TRUE(flow.report.success) << flow.report.failure;
    const model::Model& f = *flow.model;
    const auto up = end_nodes(f, 2, -1), down = end_nodes(f, 2, 1);
    const Real h = extent(f, 2) + mean_of(f, f.fields.u, down, 2) - mean_of(f, f.fields.u, up, 2);
    const Real darcy = 1e-3 * 0.2 / h;
    EXPECT_NEAR(std::abs(mean_of(f, f.fields.w, down, 2)), darcy, 1e-6 * darcy) << level;
  }
}
