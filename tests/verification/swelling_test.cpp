// SPDX-License-Identifier: MIT
// Free swelling from IC-1 (docs/theory/reference-solutions.md §R4): the equilibrium stretch of a
// laterally confined column and of an unconstrained cube equals the closed-form root of
// sigma_e(lambda) = Pi(cF(J)) (SVK and neo-Hookean), and every element holds the Donnan state at J.
// From the prestressed state IC-3a the same cube does not move at all.
#include "exact/exact_solutions.hpp"
#include "mixture_model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace trifem;

namespace {

constexpr Real kE = 0.3;
constexpr Real kTolerance = 1e-6; // relative, on the stretch and the Donnan state

/// The paper's tissue with a SVK or neo-Hookean solid (E = 0.3, nu = 0).
material::MixtureProperties tissue(exact::SolidLaw law) {
  if (law == exact::SolidLaw::StVenantKirchhoff)
    return test::paper_tissue(true);
  auto solid = material::create_law("neo-hookean", {{"E", kE}, {"nu", 0.0}}, "s");
  return material::make_mixture(true, std::move(solid),
                                {{"phi_s0", 0.25},
                                 {"permeability", 1.07e-3},
                                 {"fixed_charge", 2e-4},
                                 {"d_plus", 5e-4},
                                 {"d_minus", 8e-4}},
                                "t");
}

/// 1 x 1 x 1 mm column, 1 x 1 x 4 cells: bottom fixed and impermeable, lateral faces confined
/// and impermeable (one cell across: all nodes), top traction-free bath.
test::MixtureModel confined_column(exact::SolidLaw law) {
  mesh::BoxSpec spec;
  spec.divisions = {1, 1, 4};
  test::MixtureModel m(mesh::make_box(spec), tissue(law));
  for (int k = 0; k < 2; ++k) {
    m.fix("box.all", m.f.u, k);
    m.impermeable("box.all", k);
  }
  m.fix("box.zmin", m.f.u, 2);
  m.impermeable("box.zmin", 2);
  m.build();
  return m;
}

/// 1 mm cube, 2 x 2 x 2 cells: symmetry planes xmin, ymin, zmin (normal u = 0, impermeable),
/// the other faces traction-free bath.
test::MixtureModel free_cube(exact::SolidLaw law,
                             physics::InitialState initial = physics::InitialState::Donnan) {
  mesh::BoxSpec spec;
  spec.divisions = {2, 2, 2};
  test::MixtureModel m(mesh::make_box(spec), tissue(law));
  const char* planes[3] = {"box.xmin", "box.ymin", "box.zmin"};
  for (int k = 0; k < 3; ++k) {
    m.fix(planes[k], m.f.u, k);
    m.impermeable(planes[k], k);
  }
  m.build(initial);
  return m;
}

/// Runs to equilibrium with a growing step (1 s to 1e4 s), printing a coarse history of `probe`.
template <class Probe>
void run_to_equilibrium(test::MixtureModel& m, Probe&& probe, const char* label) {
  Real next_print = 10.0;
  const solver::RunReport run = m.run(2e5, 1.0, 1e4, {}, [&](const solver::StepInfo& info) {
    if (info.time >= next_print) {
      std::printf("[%s] t = %9.1f s  dt = %8.1f s  stretch = %.10f\n", label, info.time, info.dt,
                  probe());
      next_print *= 10.0;
    }
  });
  ASSERT_TRUE(run.success) << run.failure;
  std::printf("[%s] %d steps, %d iterations, %d cutbacks\n", label, run.steps, run.iterations,
              run.cutbacks);
}

/// Donnan state at J in every element: J itself, c+-, cF, p and eta.
void expect_donnan_everywhere(const test::MixtureModel& m, Real J) {
  const exact::DonnanState d = exact::donnan_at(exact::paper_medium(), J);
  for (Index e = 0; e < m.mixture->num_elements(); ++e) {
    const physics::MixtureCellOutput out = m.mixture->output(e, m.problem->state());
    const Index c = m.mixture->cell(e);
    EXPECT_NEAR(out.J, J, kTolerance * J) << "element " << e;
    EXPECT_NEAR(out.chem.c_plus, d.c_plus, kTolerance * d.c_plus) << "element " << e;
    EXPECT_NEAR(out.chem.c_minus, d.c_minus, kTolerance * d.c_minus) << "element " << e;
    EXPECT_NEAR(out.chem.c_fixed, exact::fixed_charge(2e-4, 0.25, J), kTolerance * d.c_plus);
    EXPECT_NEAR(m.value(m.f.p, c), d.pressure, kTolerance * d.pressure) << "element " << e;
    EXPECT_NEAR(m.value(m.f.eta, c) / m.chem.c_ref, d.eta, kTolerance * std::abs(d.eta))
        << "element " << e;
  }
}

void report(const char* label, Real found, Real expected) {
  std::printf("[%s] stretch found %.10f expected %.10f relative difference %.3e\n", label, found,
              expected, (found - expected) / expected);
}

/// Top displacement of the column -> axial stretch (height 1 mm).
Real column_stretch(const test::MixtureModel& m) {
  Real sum = 0.0;
  const auto& top = m.mesh.node_set("box.zmax");
  for (Index n : top)
    sum += m.value(m.f.u, n, 2);
  return 1.0 + sum / static_cast<Real>(top.size());
}

/// The corner (1, 1, 1) of the cube.
Index far_corner(const test::MixtureModel& m) {
  for (Index n = 0; n < m.mesh.num_nodes(); ++n)
    if ((m.mesh.node(n) - Vec3::Ones()).norm() < 1e-12)
      return n;
  return -1;
}

void check_confined(exact::SolidLaw law, Real table_value, const char* label) {
  const exact::SwellingState exact_state = exact::swelling_equilibrium(
      law, exact::Deformation::Confined, kE, 0.0, exact::paper_medium());
  // the closed-form library reproduces the published digits
  EXPECT_NEAR(exact_state.stretch, table_value, 5e-7);
  test::MixtureModel m = confined_column(law);
  run_to_equilibrium(
      m, [&] { return column_stretch(m); }, label);
  // every top node moves the same, every element has the same J = lambda
  for (Index n : m.mesh.node_set("box.zmax"))
    EXPECT_NEAR(1.0 + m.value(m.f.u, n, 2), exact_state.stretch, kTolerance * exact_state.stretch);
  const Real lambda = column_stretch(m);
  report(label, lambda, exact_state.stretch);
  EXPECT_NEAR(lambda, exact_state.stretch, kTolerance * exact_state.stretch);
  expect_donnan_everywhere(m, exact_state.J);
}

void check_isotropic(exact::SolidLaw law, Real table_value, const char* label) {
  const exact::SwellingState exact_state = exact::swelling_equilibrium(
      law, exact::Deformation::Isotropic, kE, 0.0, exact::paper_medium());
  EXPECT_NEAR(exact_state.stretch, table_value, 5e-6);
  test::MixtureModel m = free_cube(law);
  const Index corner = far_corner(m);
  ASSERT_GE(corner, 0);
  run_to_equilibrium(
      m, [&] { return 1.0 + m.value(m.f.u, corner, 0); }, label);
  const Real lambda = 1.0 + m.value(m.f.u, corner, 0);
  report(label, lambda, exact_state.stretch);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(1.0 + m.value(m.f.u, corner, k), exact_state.stretch,
                kTolerance * exact_state.stretch)
        << "direction " << k;
  expect_donnan_everywhere(m, exact_state.J);
}

} // namespace

/// reference-solutions.md §R4.4, SVK, 1-D: lambda E (lambda^2 - 1)/2 = Pi(J = lambda), 1.225066.
TEST(FreeSwelling, ConfinedColumnSvkMatchesClosedForm) {
  check_confined(exact::SolidLaw::StVenantKirchhoff, 1.225066, "confined SVK");
}

/// reference-solutions.md §R4.4, SVK, isotropic: E (lambda^2 - 1)/(2 lambda) = Pi(J = lambda^3),
/// 1.17354.
TEST(FreeSwelling, FreeCubeSvkMatchesClosedForm) {
  check_isotropic(exact::SolidLaw::StVenantKirchhoff, 1.17354, "isotropic SVK");
}

/// reference-solutions.md §R4.3 table (b), neo-Hookean, 1-D: 1.300923.
TEST(FreeSwelling, ConfinedColumnNeoHookeanMatchesClosedForm) {
  check_confined(exact::SolidLaw::NeoHookean, 1.300923, "confined NH");
}

/// reference-solutions.md §R4.3 table (b), neo-Hookean, isotropic: 1.209410.
TEST(FreeSwelling, FreeCubeNeoHookeanMatchesClosedForm) {
  check_isotropic(exact::SolidLaw::NeoHookean, 1.209410, "isotropic NH");
}

/// IC-3a: the Cauchy prestress Pi0 balances the Donnan pressure, so the traction-free cube that
/// swells to 1.17354 from IC-1 (above) is in equilibrium at the reference: no Newton iteration is
/// needed in any step, nothing moves, and every element keeps the Donnan state at J = 1.
TEST(FreeSwelling, PrestressedCubeStaysAtRestInItsBath) {
  test::MixtureModel m =
      free_cube(exact::SolidLaw::StVenantKirchhoff, physics::InitialState::DonnanPrestressed);
  const solver::RunReport run = m.run(2e5, 1.0, 1e4);
  ASSERT_TRUE(run.success) << run.failure;
  Real largest = 0.0;
  for (Index n = 0; n < m.mesh.num_nodes(); ++n)
    for (int k = 0; k < 3; ++k)
      largest = std::max(largest, std::abs(m.value(m.f.u, n, k)));
  std::printf("[prestressed cube] %d steps, %d Newton iterations, max |u| = %.3e mm\n", run.steps,
              run.iterations, largest);
  EXPECT_GT(run.steps, 5);
  EXPECT_EQ(run.iterations, 0);
  // no iteration: u stays exactly 0; the IC-1 cube moves by 0.17 of its 1 mm edge
  const Real edge = 1.0;
  EXPECT_LT(largest, 1e-14 * edge);
  expect_donnan_everywhere(m, 1.0);
}
