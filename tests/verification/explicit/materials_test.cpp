// SPDX-License-Identifier: MIT
// Several materials in one explicit model: the lumped mass uses each cell's density, the cell
// loop each cell's law (two disjoint cubes of different stiffness each reach their own exact
// uniaxial state), and one material given per cell equals the single-material shorthand.
#include "exact_uniaxial.hpp"
#include "fixtures.hpp"

#include "trifem/core/error.hpp"
#include "trifem/mesh/box.hpp"

#include <gtest/gtest.h>

using namespace trifem;
using namespace trifem::explicit_dynamics;

namespace {

constexpr Real kAlpha = 1e3;

/// Two unit cubes of 2x2x2 cells, "a" at the origin and "b" at x = 2, each with rollers on its
/// min faces and the dead traction (P, 0, 0) on its xmax face, ramped smoothly over 5 s.
ModelSpec two_cube_loads(Real P) {
  ModelSpec spec;
  for (const char* cube : {"a", "b"}) {
    const std::string name = cube;
    spec.fixities.insert(spec.fixities.end(),
                         {{name + ".xmin", 0}, {name + ".ymin", 1}, {name + ".zmin", 2}});
    SurfaceLoad load;
    load.kind = LoadKind::DeadTraction;
    load.surface = name + ".xmax";
    load.traction = Vec3(P, 0.0, 0.0);
    load.curve = dofs::LoadCurve({{0.0, 0.0}, {5.0, 1.0}}, dofs::Interpolation::Smooth);
    spec.loads.push_back(load);
  }
  return spec;
}

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

/// Cube a: μ = 1, ρ = 1; cube b: μ = mu_b, ρ = 3.
ExplicitModel two_materials(Real P, Real mu_b) {
  ModelSpec spec = two_cube_loads(P);
  spec.materials = {{test::deviatoric_neo_hookean(1.0), 1.0},
                    {test::deviatoric_neo_hookean(mu_b), 3.0}};
  spec.cell_material.assign(8, 0);
  spec.cell_material.resize(16, 1);
  return ExplicitModel(two_cubes(), spec);
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
  const ExplicitModel model = two_materials(0.1, 3.0);
  // relative to each exact mass: sums of positive quadrature terms, a few ulp each
  const Real total = 1.0 * 1.0 + 3.0 * 1.0, corner_a = 1.0 * 0.125 / 8.0,
             first_b = 3.0 * 0.125 / 8.0;
  EXPECT_NEAR(model.mass().sum() / 3.0, total, 2.5e-14 * total); // Σ ρ V
  EXPECT_NEAR(model.mass()[0], corner_a, 5e-14 * corner_a);      // corner of a: ρ V_cell / 8
  EXPECT_NEAR(model.mass()[3 * 27], first_b, 2e-14 * first_b);   // first node of b
  EXPECT_EQ(model.material_of(0), 0);
  EXPECT_EQ(model.material_of(15), 1);
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
  const ExplicitModel model = two_materials(P, mu_b);
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

TEST(ExplicitMaterials, OneMaterialPerCellEqualsTheShorthand) {
  ModelSpec listed = two_cube_loads(0.2);
  listed.materials = {{test::deviatoric_neo_hookean(1.0), 1.0}};
  listed.cell_material.assign(16, 0);
  ModelSpec shorthand = two_cube_loads(0.2);
  shorthand.law = test::deviatoric_neo_hookean(1.0);
  shorthand.density = 1.0;
  const ExplicitModel m1(two_cubes(), listed), m2(two_cubes(), shorthand);
  ExplicitSolver s1(m1, ExplicitSettings{}), s2(m2, ExplicitSettings{});
  ASSERT_TRUE(s1.run(3.0).ok());
  ASSERT_TRUE(s2.run(3.0).ok());
  EXPECT_EQ(s1.step_count(), s2.step_count());
  EXPECT_EQ((s1.displacement() - s2.displacement()).lpNorm<Eigen::Infinity>(), 0.0);
  EXPECT_GT(s1.displacement().lpNorm<Eigen::Infinity>(), 0.01);
}

TEST(ExplicitMaterials, InvalidMaterialIndexIsRejected) {
  ModelSpec spec = two_cube_loads(0.1);
  spec.materials = {{test::deviatoric_neo_hookean(1.0), 1.0}};
  spec.cell_material.assign(16, 0);
  spec.cell_material[5] = 1;
  EXPECT_THROW((void)ExplicitModel(two_cubes(), spec), InputError);
  spec.cell_material.resize(15);
  EXPECT_THROW((void)ExplicitModel(two_cubes(), spec), InputError);
}
