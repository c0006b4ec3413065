// SPDX-License-Identifier: MIT
// The paper's section 4.1 confined column as a whole model (docs/theory/reference-solutions.md
// §R5): stress relaxation of a triphasic column under a ramped platen displacement, against the
// reference history, and its equilibrium against the closed form, from the Donnan state (IC-1)
// and from the prestressed Donnan state (IC-3a).
#include "exact/exact_solutions.hpp"
#include "mixture_model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

using namespace trifem;

namespace {

/// 1 x 1 x 1 mm column of 1 x 1 x 10 cells: bottom fixed and impermeable, lateral faces
/// confined and impermeable, top = porous platen (bath) moved to u_z = -0.05 mm over 50 s.
test::MixtureModel paper_column(physics::InitialState initial = physics::InitialState::Donnan) {
  mesh::BoxSpec spec;
  spec.divisions = {1, 1, 10};
  test::MixtureModel m(mesh::make_box(spec), test::paper_tissue(true));
  for (int k = 0; k < 2; ++k) {
    m.fix("box.all", m.f.u, k);
    m.impermeable("box.all", k);
  }
  m.fix("box.zmin", m.f.u, 2);
  m.impermeable("box.zmin", 2);
  m.fix("box.zmax", m.f.u, 2, -0.05,
        dofs::LoadCurve({{0.0, 0.0}, {50.0, 1.0}}, dofs::Interpolation::Linear));
  m.build(initial);
  return m;
}

/// Total axial stress on the platen: the reaction of the top nodes over the area.
Real platen_stress(const test::MixtureModel& m) {
  Real force = 0.0;
  for (Index n : m.mesh.node_set("box.zmax"))
    force += m.problem->full_residual()[m.dofs.dof(m.f.u, n, 2)];
  return force; // area 1 mm^2
}

/// reference-solutions.md §R5.2: t -> (total stress top, p top, p bottom, eta bottom).
const std::map<Real, std::array<Real, 4>> kReference = {
    {5, {-0.23944, 0.22557, 0.23944, -1733.74}},    {25, {-0.35190, 0.31246, 0.35190, -1966.56}},
    {50, {-0.45976, 0.40887, 0.45976, -2180.17}},   {100, {-0.26328, 0.22775, 0.26312, -1783.87}},
    {200, {-0.22112, 0.19540, 0.21859, -1701.09}},  {500, {-0.19338, 0.17621, 0.18292, -1658.78}},
    {1000, {-0.18530, 0.17096, 0.17185, -1648.11}},
};

} // namespace

TEST(PaperColumn, WholeModelReproducesReferenceHistory) {
  test::MixtureModel m = paper_column();
  const Index top = 9, bottom = 0;
  auto check = [&](Real t) {
    const auto& ref = kReference.at(t);
    const Real got[4] = {platen_stress(m), m.value(m.f.p, top), m.value(m.f.p, bottom),
                         m.value(m.f.eta, bottom) / m.chem.c_ref};
    const char* names[4] = {"total stress", "p top", "p bottom", "eta bottom"};
    for (int i = 0; i < 4; ++i)
      // the table has 5 significant digits; the issue asks for 0.5 %, we hold 1e-4
      EXPECT_NEAR(got[i], ref[i], 1e-4 * std::abs(ref[i])) << names[i] << " at t = " << t;
  };
  // the reference step sequence: 2.5 s to 50 s, then 10 s to 1000 s
  ASSERT_TRUE(m.run(5.0, 2.5, 2.5).success);
  check(5);
  ASSERT_TRUE(m.run(25.0, 2.5, 2.5).success);
  check(25);
  ASSERT_TRUE(m.run(50.0, 2.5, 2.5).success);
  check(50);
  for (Real t : {100.0, 200.0, 500.0, 1000.0}) {
    ASSERT_TRUE(m.run(t, 10.0, 10.0).success);
    check(t);
  }
}

/// Equilibrium at stretch 0.95: total stress = sigma_e(0.95) - Pi(J = 0.95), p = Pi, and eta,
/// c+- from the Donnan closed form at the compressed fixed charge.
TEST(PaperColumn, EquilibriumMatchesClosedForm) {
  test::MixtureModel m = paper_column();
  ASSERT_TRUE(m.run(50.0, 2.5, 2.5).success);
  ASSERT_TRUE(m.run(6e4, 10.0, 5000.0).success);
  const exact::ColumnEquilibrium eq =
      exact::confined_column_equilibrium(0.95, 0.3, 0.0, exact::paper_medium());
  EXPECT_NEAR(platen_stress(m), eq.total_stress, 1e-6 * std::abs(eq.total_stress));
  for (Index e = 0; e < m.mesh.num_cells(); ++e) {
    EXPECT_NEAR(m.value(m.f.p, e), eq.donnan.pressure, 1e-6 * eq.donnan.pressure);
    EXPECT_NEAR(m.value(m.f.eta, e) / m.chem.c_ref, eq.donnan.eta, 1e-6 * std::abs(eq.donnan.eta));
  }
}

/// IC-3a: the prestress Pi0 shifts every total stress and reaction by +Pi0 and changes nothing
/// else. At t = 0 the platen carries no load (IC-1: -Pi0); at equilibrium (stretch 0.95) it
/// carries sigma_e - Pi(0.95) + Pi0 = -0.03400 MPa (IC-1: -0.18403), with the same p and eta.
TEST(PaperColumn, PrestressedEquilibriumIsShiftedByTheDonnanPressure) {
  const exact::ChargedMedium medium = exact::paper_medium();
  const Real pi0 = exact::donnan_at(medium, 1.0).pressure;
  test::MixtureModel m = paper_column(physics::InitialState::DonnanPrestressed);
  solver::Linearization initial; // the reactions of the initial state
  ASSERT_EQ(m.problem->linearize(initial, false), solver::SolveStatus::Converged);
  EXPECT_LT(initial.residual.lpNorm<Eigen::Infinity>(), 1e-12 * pi0); // in equilibrium
  EXPECT_NEAR(platen_stress(m), 0.0, 1e-12 * pi0);
  ASSERT_TRUE(m.run(50.0, 2.5, 2.5).success);
  ASSERT_TRUE(m.run(6e4, 10.0, 5000.0).success);
  const exact::ColumnEquilibrium eq = exact::confined_column_equilibrium(0.95, 0.3, 0.0, medium);
  std::printf("prestressed column: platen stress %.6f MPa (IC-1 closed form %.6f, Pi0 %.6f)\n",
              platen_stress(m), eq.total_stress, pi0);
  EXPECT_NEAR(platen_stress(m), eq.total_stress + pi0, 1e-6 * std::abs(eq.total_stress));
  EXPECT_NEAR(eq.total_stress + pi0, -0.03400, 5e-6); // reference-solutions.md §R5.3, IC-3a
  for (Index e = 0; e < m.mesh.num_cells(); ++e) {
    EXPECT_NEAR(m.value(m.f.p, e), eq.donnan.pressure, 1e-6 * eq.donnan.pressure);
    EXPECT_NEAR(m.value(m.f.eta, e) / m.chem.c_ref, eq.donnan.eta, 1e-6 * std::abs(eq.donnan.eta));
  }
}
