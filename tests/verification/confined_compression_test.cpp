// SPDX-License-Identifier: MIT
// Biphasic confined creep (Terzaghi; docs/theory/reference-solutions.md §R1) and the exact
// reduction of the triphasic model to the biphasic one when the tissue is uncharged (§R2).
#include "exact/exact_solutions.hpp"
#include "mixture_model.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace trifem;

namespace {

constexpr Real kSigma0 = 1e-4; ///< applied compressive stress [MPa]

/// Laterally confined, impermeable column of n cells, bottom fixed and impermeable, top
/// free-draining under a step compressive traction sigma0.
test::MixtureModel creep_column(int n, material::MixtureProperties props) {
  return test::creep_column(n, std::move(props), kSigma0);
}

Real top_displacement(const test::MixtureModel& m) {
  return m.value(m.f.u, m.mesh.node_set("box.zmax").front(), 2);
}

const exact::ConfinedLayer kLayer{1.0, 0.3, 1.07e-3};

/// Relative error of u_top at t = 400 s for n cells and step dt (`lumped`: [analysis]
/// flux_mass = "lumped") with the solid volume fraction `phi_s0`.
Real creep_error(int n, Real dt, bool lumped = false, Real phi_s0 = 0.25) {
  test::MixtureModel m = creep_column(n, test::paper_tissue(false, 2e-4, 0.0, phi_s0));
  m.mixture->set_lumped_flux_mass(lumped);
  const solver::RunReport run = m.run(400.0, dt, dt, {});
  EXPECT_TRUE(run.success) << run.failure;
  const Real exact = exact::creep_surface_displacement(kLayer, kSigma0, 400.0);
  return std::abs(top_displacement(m) - exact) / std::abs(exact);
}

} // namespace

/// V1: u_top(400 s) within 0.5 % of the series, and the error falls under refinement of h and
/// dt together (backward Euler: first order in dt).
TEST(ConfinedCreep, BiphasicMatchesTerzaghiAndConvergesUnderRefinement) {
  const Real coarse = creep_error(10, 5.0);
  const Real medium = creep_error(20, 2.5);
  const Real fine = creep_error(40, 1.25);
  std::cout << "relative error of u_top(400 s): " << coarse << ", " << medium << ", " << fine
            << "\n";
  EXPECT_LT(fine, 5e-3);
  EXPECT_LT(medium, coarse);
  EXPECT_LT(fine, medium);
}

/// The same with the friction terms' mass lumped (docs/theory/solvers.md §4): the same accuracy
/// and convergence.
TEST(ConfinedCreep, BiphasicWithLumpedFluxMassMatchesTerzaghiAndConvergesUnderRefinement) {
  const Real coarse = creep_error(10, 5.0, true);
  const Real medium = creep_error(20, 2.5, true);
  const Real fine = creep_error(40, 1.25, true);
  std::cout << "relative error of u_top(400 s), lumped flux mass: " << coarse << ", " << medium
            << ", " << fine << "\n";
  EXPECT_LT(fine, 5e-3);
  EXPECT_LT(medium, coarse);
  EXPECT_LT(fine, medium);
}

/// A solid of no volume (φˢ₀ = 0, which FEBio allows): with a constant permeability the solid
/// volume fraction enters nothing of the biphasic column, which consolidates as Terzaghi's.
TEST(ConfinedCreep, BiphasicWithoutSolidVolumeMatchesTerzaghi) {
  const Real error = creep_error(20, 2.5, false, 0.0);
  EXPECT_LT(error, 1e-2);
  EXPECT_NEAR(error, creep_error(20, 2.5), 1e-12); // the same bits up to round-off
}

/// The pressure at the impermeable bottom follows the series (after the early transient).
TEST(ConfinedCreep, BottomPressureMatchesSeries) {
  test::MixtureModel m = creep_column(40, test::paper_tissue(false));
  for (Real t : {200.0, 800.0, 2000.0}) {
    ASSERT_TRUE(m.run(t, 2.0, 10.0).success);
    // bottom cell centre z = h/80
    const Real exact = exact::creep_pressure(kLayer, kSigma0, 1.0 / 80.0, t);
    EXPECT_NEAR(m.value(m.f.p, 0), exact, 5e-3 * kSigma0) << "t = " << t;
  }
}

/// V2: with cF = 0 the triphasic model carries the ions with the water at the bath
/// concentration and reproduces the biphasic run to round-off.
TEST(ConfinedCreep, UnchargedTriphasicEqualsBiphasic) {
  test::MixtureModel bi = creep_column(10, test::paper_tissue(false));
  test::MixtureModel tri = creep_column(10, test::paper_tissue(true, 0.0));
  ASSERT_TRUE(bi.run(300.0, 5.0, 5.0).success);
  ASSERT_TRUE(tri.run(300.0, 5.0, 5.0).success);
  EXPECT_NEAR(top_displacement(tri), top_displacement(bi), 1e-10 * std::abs(top_displacement(bi)));
  for (Index e = 0; e < bi.mesh.num_cells(); ++e) {
    EXPECT_NEAR(tri.value(tri.f.p, e), bi.value(bi.f.p, e), 1e-10 * kSigma0) << "cell " << e;
    const auto out = tri.mixture->output(e, tri.problem->state());
    EXPECT_NEAR(out.chem.c_plus, tri.chem.c_ref, 1e-12 * tri.chem.c_ref);
    EXPECT_NEAR(out.chem.c_minus, tri.chem.c_ref, 1e-12 * tri.chem.c_ref);
  }
}

namespace {

/// Ramp-displacement stress relaxation (docs/theory/reference-solutions.md §R1.4): the
/// free-draining top is moved to a strain eps0 over t0 and held; the surface stress follows the
/// series of Mow et al. (1980).
Real ramp_relaxation_error(int n, Real dt) {
  mesh::BoxSpec spec;
  spec.divisions = {1, 1, n};
  test::MixtureModel m(mesh::make_box(spec), test::paper_tissue(false));
  for (int k = 0; k < 2; ++k) {
    m.fix("box.all", m.f.u, k);
    m.impermeable("box.all", k);
  }
  m.fix("box.zmin", m.f.u, 2);
  m.impermeable("box.zmin", 2);
  const Real eps0 = 1e-4, t0 = 300.0; // t0 / tau ~ 0.1, small strain
  m.fix("box.zmax", m.f.u, 2, -eps0,
        dofs::LoadCurve({{0.0, 0.0}, {t0, 1.0}}, dofs::Interpolation::Linear));
  m.build();
  Real worst = 0.0;
  for (Real t : {t0, 2 * t0, 5 * t0}) {
    EXPECT_TRUE(m.run(t, dt, dt).success);
    Real force = 0.0;
    for (Index node : m.mesh.node_set("box.zmax"))
      force += m.problem->full_residual()[m.dofs.dof(m.f.u, node, 2)];
    const Real exact = exact::ramp_relaxation_stress(kLayer, eps0, t0, t);
    worst = std::max(worst, std::abs(force - exact) / std::abs(exact));
    std::cout << "  n = " << n << " t = " << t << " error " << (force - exact) / exact << "\n";
  }
  return worst;
}

} // namespace

/// Ramp relaxation within 0.5 % of the series at t0, 2 t0 and 5 t0 (the peak is the hardest
/// point), with the error falling under refinement of h and dt.
TEST(RampRelaxation, BiphasicMatchesSeriesAndConvergesUnderRefinement) {
  const Real coarse = ramp_relaxation_error(10, 10.0);
  const Real medium = ramp_relaxation_error(20, 5.0);
  const Real fine = ramp_relaxation_error(40, 2.5);
  std::cout << "worst relative error of the surface stress: " << coarse << ", " << medium << ", "
            << fine << "\n";
  EXPECT_LT(fine, 5e-3);
  EXPECT_LT(medium, coarse);
  EXPECT_LT(fine, medium);
}
