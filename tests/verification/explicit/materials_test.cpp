// SPDX-License-Identifier: MIT
// Several materials in one explicit model: the lumped mass uses each cell's density, the cell
// loop each cell's law (two disjoint cubes of different stiffness each reach their own exact
// uniaxial state).
#include "exact_uniaxial.hpp"
#include "fixtures.hpp"

#include "trifem/mesh/box.hpp"

#include <gtest/gtest.h>

using namespace trifem;
using namespace trifem::explicit_dynamics;

namespace {

constexpr Real kAlpha = 1e3;

mesh::Mesh two_cubes() {
  mesh::BoxSpec a, b;
  a.name = "a";
  b.name = "b";
  a.divisions = b.divisions = {2, 2, 2};
  b.origin = Vec3(2.0, 0.0, 0.0);
  mesh::Mesh mesh = mesh::make_box(a);
  mesh.append(mesh::make_box(b));
  return mesh;
}

/// Two unit cubes of 2x2x2 cells, "a" at the origin (μ = 1, ρ = 1) and "b" at x = 2 (μ = mu_b,
/// ρ = 3), each with rollers on its min faces and the dead traction (P, 0, 0) on its xmax face,
/// ramped smoothly over 5 s.
test::TestModel two_materials(Real P, Real mu_b) {
  test::ExplicitTestCase c(two_cubes(), test::deviatoric_material(1.0, 1.0));
  c.block("b", test::deviatoric_material(mu_b, 3.0));
  for (const std::string cube : {"a", "b"}) {
    c.fix(cube + ".xmin", {0}).fix(cube + ".ymin", {1}).fix(cube + ".zmin", {2});
    c.traction(cube + ".xmax", Vec3(P, 0.0, 0.0), test::smooth_ramp(5.0));
  }
  return test::TestModel(c);
}

/// Mean axial and lateral stretch of a cube from its corner node (X = origin + (1, 1, 1)).
Vec3 corner_stretch(const ExplicitSolver& solver, const Vec3& origin) {
  const mesh::Mesh& mesh = solver.model().mesh();
  for (Index n = 0; n < mesh.num_nodes(); ++n)
    if ((mesh.node(n) - origin - Vec3::Ones()).norm() < 1e-12)
      return Vec3::Ones() + solver.displacement().segment<3>(3 * n);
  ADD_FAILURE() << "no corner node";
  return Vec3::Zero();
}

} // namespace

TEST(ExplicitMaterials, LumpedMassUsesTheDensityOfEachCell) {
  const test::TestModel model = two_materials(0.1, 3.0);
  // relative to each exact mass: sums of positive quadrature terms, a few ulp each
  const Real total = 1.0 * 1.0 + 3.0 * 1.0, corner_a = 1.0 * 0.125 / 8.0,
             first_b = 3.0 * 0.125 / 8.0;
  EXPECT_NEAR(model.mass().sum() / 3.0, total, 2.5e-14 * total); // Σ ρ V
  EXPECT_NEAR(model.mass()[0], corner_a, 5e-14 * corner_a);      // corner of a: ρ V_cell / 8
  EXPECT_NEAR(model.mass()[3 * 27], first_b, 2e-14 * first_b);   // first node of b
  EXPECT_EQ(model.density(0), 1.0);
  EXPECT_EQ(model.density(15), 3.0);
  EXPECT_EQ(model.law(15).shear_modulus(), 3.0);
}

TEST(ExplicitMaterials, EachBodyReachesTheUniaxialStateOfItsOwnLaw) {
  const Real mu_b = 3.0;
  const test::Uniaxial a = test::uniaxial_state(1.0, kAlpha, 1.3);
  const Real P = a.P;
  // The stiffer cube stretches less under the same P: find its stretch by bisection on P(stretch).
  Real lo = 1.0, hi = 1.3;
  for (int it = 0; it < 200; ++it) {
    const Real mid = 0.5 * (lo + hi);
    (test::uniaxial_state(mu_b, kAlpha, mid).P < P ? lo : hi) = mid;
  }
  const test::Uniaxial b = test::uniaxial_state(mu_b, kAlpha, 0.5 * (lo + hi));
  ASSERT_NEAR(b.P, P, 1e-12);
  const test::TestModel model = two_materials(P, mu_b);
  ExplicitSettings s;
  s.penalty = kAlpha;
  s.damping = 2.0;
  ExplicitSolver solver(model, s);
  const StepReport r = solver.run(60.0);
  ASSERT_TRUE(r.ok()) << r.message;
  const Vec3 stretch_a = corner_stretch(solver, Vec3::Zero());
  const Vec3 stretch_b = corner_stretch(solver, Vec3(2.0, 0.0, 0.0));
  EXPECT_NEAR(stretch_a[0], a.a, 1e-10);
  EXPECT_NEAR(stretch_a[1], a.b, 1e-10);
  EXPECT_NEAR(stretch_b[0], b.a, 1e-10);
  EXPECT_NEAR(stretch_b[2], b.b, 1e-10);
  EXPECT_GT(stretch_a[0] - stretch_b[0], 0.1) << "the two laws must give different states";
  // Λ per cell: the closed-form λ of each material (J − 1 = λ/α).
  EXPECT_NEAR(solver.multiplier()[0], a.lambda, 1e-8 * std::abs(a.lambda));
  EXPECT_NEAR(solver.multiplier()[15], b.lambda, 1e-8 * std::abs(b.lambda));
}
