// SPDX-License-Identifier: MIT
// Donnan equilibrium of the triphasic element (docs/theory/reference-solutions.md §R3).
#include "exact/exact_solutions.hpp"
#include "mixture_model.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace trifem;

namespace {

/// One element in a bath (all faces free-draining), u prescribed homogeneously: J = stretch.
test::MixtureModel single_element(Real stretch) {
  mesh::BoxSpec spec;
  spec.divisions = {1, 1, 1};
  test::MixtureModel m(mesh::make_box(spec), test::paper_tissue(true));
  for (int k = 0; k < 3; ++k)
    m.fix("box.all", m.f.u, k, 0.0);
  dofs::DirichletCondition top{{}, stretch - 1.0, dofs::LoadCurve::constant()};
  m.conditions.push_back(top);
  for (Index n : m.mesh.node_set("box.zmax"))
    m.conditions.back().dofs.push_back(m.dofs.dof(m.f.u, n, 2));
  m.build();
  return m;
}

void expect_donnan(const test::MixtureModel& m, Real J) {
  const exact::DonnanState d =
      exact::donnan(exact::fixed_charge(2e-4, 0.25, J), m.chem.c_ref, m.chem.RT(), m.chem.faraday);
  for (Index e = 0; e < m.mixture->num_elements(); ++e) {
    const physics::MixtureCellOutput out = m.mixture->output(e, m.problem->state());
    EXPECT_NEAR(out.J, J, 1e-14 * J); // prescribed: a determinant of three stretches
    EXPECT_NEAR(out.chem.c_plus, d.c_plus, 1e-8 * d.c_plus) << "element " << e;
    EXPECT_NEAR(out.chem.c_minus, d.c_minus, 1e-8 * d.c_minus);
    EXPECT_NEAR(out.chem.c_fixed, exact::fixed_charge(2e-4, 0.25, J), 1e-12 * d.c_plus);
    EXPECT_NEAR(m.value(m.f.p, m.mixture->cell(e)), d.pressure, 1e-8 * d.pressure);
    EXPECT_NEAR(m.value(m.f.eta, m.mixture->cell(e)) / m.chem.c_ref, d.eta, 1e-8 * std::abs(d.eta));
    // bath-normalised potentials vanish (relative to the scales Pi and RT)
    EXPECT_NEAR(out.chem.mu_w, 0.0, 1e-9 * d.pressure);
    EXPECT_NEAR(out.chem.mu_plus, 0.0, 1e-9 * m.chem.RT());
    EXPECT_NEAR(out.chem.mu_minus, 0.0, 1e-9 * m.chem.RT());
  }
}

} // namespace

/// IC-1 reproduces the closed form and is an exact equilibrium: zero residual, no iteration.
TEST(Donnan, SingleElementInBathMatchesClosedFormAtSeveralJ) {
  for (Real J : {1.0, 0.9, 1.15}) {
    test::MixtureModel m = single_element(J);
    expect_donnan(m, J);
    solver::Linearization lin;
    ASSERT_EQ(m.problem->linearize(lin, false), solver::SolveStatus::Converged);
    // every free equation (w, j+-, p, eta) is satisfied; the u rows hold the reaction to the
    // osmotic pressure (the solid is stress-free, total stress -Pi I)
    EXPECT_LE(lin.residual.lpNorm<Eigen::Infinity>(), 1e-14 * 0.15)
        << "J = " << J; // round-off of Pi
    const solver::RunReport run = m.run(10.0, 10.0, 10.0);
    ASSERT_TRUE(run.success) << run.failure;
    EXPECT_EQ(run.iterations, 0) << "J = " << J;
    expect_donnan(m, J);
  }
}

/// Paper values (reference-solutions.md §R3.5): c+ = 0.280278 M, c- = 0.080278 M,
/// Pi = 0.150030 MPa, psi = -16.05 mV at J = 1 (cF0 = 0.2 M per water volume, c* = 0.15 M,
/// T = 298 K).
TEST(Donnan, PaperInitialStateValues) {
  test::MixtureModel m = single_element(1.0);
  const Index c = m.mixture->cell(0);
  const physics::MixtureCellOutput out = m.mixture->output(0, m.problem->state());
  EXPECT_NEAR(out.chem.c_plus * 1e3, 0.280278, 5e-7);
  EXPECT_NEAR(out.chem.c_minus * 1e3, 0.080278, 5e-7);
  EXPECT_NEAR(m.value(m.f.p, c), 0.150030, 5e-7);
  EXPECT_NEAR(m.value(m.f.eta, c) / m.chem.c_ref / m.chem.faraday, -16.05, 5e-3);
}

/// V3: a column with all u fixed, bath on the top face, starts electroneutral but out of
/// Donnan equilibrium (c+ = cF + c*, c- = c*); it relaxes to the closed form. At every step
/// c+ - c- = cF holds in every element and the total ion moles change exactly by the boundary
/// outflow.
TEST(Donnan, RelaxationFromElectroneutralStateConvergesToClosedForm) {
  mesh::BoxSpec spec;
  spec.divisions = {1, 1, 4};
  test::MixtureModel m(mesh::make_box(spec), test::paper_tissue(true));
  for (int k = 0; k < 3; ++k)
    m.fix("box.all", m.f.u, k);
  m.impermeable("box.zmin", 2);
  for (const char* side : {"box.xmin", "box.xmax"})
    m.impermeable(side, 0);
  for (const char* side : {"box.ymin", "box.ymax"})
    m.impermeable(side, 1);
  m.build();
  const Real c_star = m.chem.c_ref, cF = 2e-4;
  for (Index e = 0; e < m.mixture->num_elements(); ++e) {
    physics::MixtureHistory h = m.mixture->history(e);
    const Real Vw = h.V0 * 0.75;
    h.N_plus = (cF + c_star) * Vw;
    h.N_minus = c_star * Vw;
    m.mixture->set_history(e, h);
  }
  Real moles_before = m.mixture->total_moles(true) + m.mixture->total_moles(false);
  Real worst_neutrality = 0.0, worst_balance = 0.0;
  auto observer = [&](const solver::StepInfo& info) {
    const Vector& x = m.problem->state();
    for (Index e = 0; e < m.mixture->num_elements(); ++e) {
      const auto out = m.mixture->output(e, x);
      worst_neutrality = std::max(worst_neutrality,
                                  std::abs(out.chem.c_plus - out.chem.c_minus - out.chem.c_fixed));
    }
    // boundary outflow through the bath face = sum over its nodes of (area vector . j)
    Real outflow = 0.0;
    for (const mesh::Facet& facet : m.mesh.surface("box.zmax").facets)
      for (int a = 0; a < 4; ++a)
        for (dofs::FieldId fl : {m.f.j_plus, m.f.j_minus})
          outflow += 0.25 * m.chem.c_ref * x[m.dofs.dof(fl, facet.nodes[a], 2)];
    const Real moles = m.mixture->total_moles(true) + m.mixture->total_moles(false);
    worst_balance =
        std::max(worst_balance, std::abs(moles - (moles_before - info.dt * outflow)) / moles);
    moles_before = moles;
  };
  const solver::RunReport run = m.run(4e4, 1.0, 4000.0, {}, observer);
  ASSERT_TRUE(run.success) << run.failure;
  EXPECT_LE(worst_neutrality, 1e-12 * c_star);
  EXPECT_LE(worst_balance, 1e-13);
  expect_donnan(m, 1.0);
}
