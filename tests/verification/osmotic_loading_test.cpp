// SPDX-License-Identifier: MIT
// Osmotic loading and free swelling from an uncharged reference
// (docs/theory/reference-solutions.md §R4; bath term and initial states:
// docs/theory/triphasic.md §2, §6, §8 item 4):
// (a) a free cube in equilibrium with the reference 0.15 M bath is moved to a 0.015 M and to a
// 1.5 M bath (BathTerm): it reaches the closed-form swelling stretch at the new bath;
// (b) a confined column whose fixed charge is ramped from zero (IC-2) reaches the same
// equilibrium as from the Donnan state (the equilibrium does not depend on the path).
#include "exact/exact_solutions.hpp"
#include "mixture_model.hpp"
#include "trifem/physics/bath_term.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace trifem;

namespace {

/// Octant of a free cube (1 mm, 2x2x2 cells) whose outer faces are a bath of concentration c.
test::MixtureModel cube_in_bath(Real c) {
  mesh::BoxSpec spec;
  spec.divisions = {2, 2, 2};
  test::MixtureModel m(mesh::make_box(spec), test::paper_tissue(true));
  const char* planes[3] = {"box.xmin", "box.ymin", "box.zmin"};
  std::vector<mesh::Facet> bath;
  for (const char* face : {"box.xmax", "box.ymax", "box.zmax"}) {
    const auto& f = m.mesh.surface(face).facets;
    bath.insert(bath.end(), f.begin(), f.end());
  }
  for (int k = 0; k < 3; ++k) {
    m.fix(planes[k], m.f.u, k);
    m.impermeable(planes[k], k);
  }
  m.loads.push_back(std::make_unique<physics::BathTerm>(
      m.mesh, m.dofs, m.f, bath, m.chem, c,
      dofs::LoadCurve({{0.0, 0.0}, {1.0, 1.0}}, dofs::Interpolation::Linear)));
  m.build();
  return m;
}

void check_bath_change(Real c_bath) {
  exact::ChargedMedium medium = exact::paper_medium();
  medium.c_bath = c_bath;
  const exact::SwellingState eq = exact::swelling_equilibrium(
      exact::SolidLaw::StVenantKirchhoff, exact::Deformation::Isotropic, 0.3, 0.0, medium);
  test::MixtureModel m = cube_in_bath(c_bath);
  const solver::RunReport run = m.run(3e5, 0.1, 2e4);
  ASSERT_TRUE(run.success) << run.failure;
  Index corner = 0;
  for (Index n = 0; n < m.mesh.num_nodes(); ++n)
    if ((m.mesh.node(n) - Vec3::Ones()).norm() < 1e-12)
      corner = n;
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(1.0 + m.value(m.f.u, corner, k), eq.stretch, 1e-6 * eq.stretch)
        << "bath " << c_bath << " direction " << k;
  // the interstitial state is the Donnan state with the new bath
  for (Index e = 0; e < m.mixture->num_elements(); ++e) {
    const auto out = m.mixture->output(e, m.problem->state());
    EXPECT_NEAR(out.chem.c_plus, eq.donnan.c_plus, 1e-6 * eq.donnan.c_plus);
    EXPECT_NEAR(out.chem.c_minus, eq.donnan.c_minus, 1e-6 * eq.donnan.c_minus);
  }
}

} // namespace

/// reference-solutions.md §R4.4: isotropic stretch 1.38074 in a 0.015 M bath.
TEST(OsmoticLoading, FreeCubeInDiluteBath) {
  check_bath_change(1.5e-5);
}

/// reference-solutions.md §R4.4: isotropic stretch 1.04095 in a 1.5 M bath.
TEST(OsmoticLoading, FreeCubeInConcentratedBath) {
  check_bath_change(1.5e-3);
}

/// IC-2: the fixed charge is ramped from 0 over 100 s (an uncharged, stress-free reference in
/// the bath); the column ends at the same 1-D equilibrium stretch 1.225066.
TEST(OsmoticLoading, FixedChargeRampReachesTheSwellingEquilibrium) {
  mesh::BoxSpec spec;
  spec.divisions = {1, 1, 4};
  test::MixtureModel m(mesh::make_box(spec), test::paper_tissue(true));
  for (int k = 0; k < 2; ++k) {
    m.fix("box.all", m.f.u, k);
    m.impermeable("box.all", k);
  }
  m.fix("box.zmin", m.f.u, 2);
  m.impermeable("box.zmin", 2);
  m.fixed_charge_curve = dofs::LoadCurve({{0.0, 0.0}, {100.0, 1.0}}, dofs::Interpolation::Linear);
  m.build();
  // the start is uncharged: c+ = c- = c*, p = 0, eta = 0 (to round-off of the bath
  // concentration and of the osmotic pressure scale RT c*; a charged start is off by order 1)
  const auto start = m.mixture->output(0, m.problem->state());
  EXPECT_NEAR(start.chem.c_plus, m.chem.c_ref, 1e-12 * m.chem.c_ref);
  EXPECT_NEAR(m.value(m.f.p, 0), 0.0, 1e-14 * m.chem.RT() * m.chem.c_ref);
  ASSERT_TRUE(m.run(2e5, 1.0, 1e4).success);
  const exact::SwellingState eq =
      exact::swelling_equilibrium(exact::SolidLaw::StVenantKirchhoff, exact::Deformation::Confined,
                                  0.3, 0.0, exact::paper_medium());
  for (Index n : m.mesh.node_set("box.zmax"))
    EXPECT_NEAR(1.0 + m.value(m.f.u, n, 2), eq.stretch, 1e-6 * eq.stretch);
  for (Index e = 0; e < m.mixture->num_elements(); ++e) {
    const auto out = m.mixture->output(e, m.problem->state());
    EXPECT_NEAR(out.chem.c_plus - out.chem.c_minus, out.chem.c_fixed, 1e-12 * m.chem.c_ref);
  }
}
