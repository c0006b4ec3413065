// SPDX-License-Identifier: MIT
// Patch test: a distorted multi-element block under a homogeneous finite deformation
// u = (F - I) X prescribed on its boundary reproduces the exact stress in every element.
#include "solid_model.hpp"
#include "trifem/tensor/kinematics.hpp"

#include <gtest/gtest.h>

using namespace trifem;

namespace {

/// A 3x3x3 box whose interior nodes are moved randomly (distorted cells).
mesh::Mesh distorted_block() {
  mesh::BoxSpec spec;
  spec.divisions = {3, 3, 3};
  mesh::Mesh box = mesh::make_box(spec);
  mesh::Mesh out;
  std::srand(42);
  for (Index n = 0; n < box.num_nodes(); ++n) {
    Vec3 x = box.node(n);
    const bool interior = (x.array() > 1e-12).all() && (x.array() < 1 - 1e-12).all();
    if (interior)
      x += 0.08 * Vec3::Random();
    out.add_node(x);
  }
  for (Index c = 0; c < box.num_cells(); ++c)
    out.add_cell(box.cell_type(c), box.cell_nodes(c));
  std::vector<Index> boundary;
  for (const auto& f : box.boundary_facets())
    boundary.insert(boundary.end(), f.nodes.begin(), f.nodes.end());
  out.add_node_set("boundary", boundary);
  return out;
}

/// A general homogeneous deformation (det F = 1.16).
Mat3 general_deformation() {
  Mat3 F;
  F << 1.2, 0.1, -0.05, 0.02, 0.9, 0.08, -0.1, 0.05, 1.1;
  return F;
}

void run_patch_test(const std::string& law_type,
                    physics::SolidElement element = physics::SolidElement::Displacement,
                    const Mat3& F = general_deformation(), Real nu = 0.3) {
  test::SolidModel m(distorted_block(), law_type, {{"E", 1.0}, {"nu", nu}});
  m.element = element;
  const auto& boundary = m.mesh.node_set("boundary");
  for (Index n : boundary) {
    const Vec3 u = (F - Mat3::Identity()) * m.mesh.node(n);
    for (int k = 0; k < 3; ++k) {
      dofs::DirichletCondition c{{m.dofs.dof(m.u, n, k)},
                                 u[k],
                                 dofs::LoadCurve({{0, 0}, {1, 1}}, dofs::Interpolation::Linear)};
      m.conditions.push_back(std::move(c));
    }
  }
  m.build();
  for (int step = 1; step <= 2; ++step) {
    const auto report = m.solve_step(0.5 * step, 0.5);
    ASSERT_EQ(report.status, solver::SolveStatus::Converged) << law_type;
  }
  const Mat3 exact = kinematics::cauchy_from_pk2(F, m.law->stress(F.transpose() * F));
  // the pressure is the bulk modulus times J - 1, and J is known to a few ulp: stresses are
  // exact to 1e-10 of the stress plus 1e-14 of the bulk modulus
  const Real bulk = m.law->p_wave_modulus() - 4.0 / 3.0 * m.law->shear_modulus();
  const Real tolerance = 1e-10 * exact.norm() + 1e-14 * bulk;
  for (Index e = 0; e < m.solid->num_elements(); ++e) {
    const physics::CellStress s = m.solid->stress(e, m.problem->state());
    EXPECT_LE((s.cauchy - exact).norm(), tolerance) << law_type << " element " << e;
    EXPECT_NEAR(s.J, F.determinant(), 1e-12 * F.determinant());
  }
  // interior nodes follow the homogeneous map, to 1e-12 of the 1 mm block (|u| ~ 0.2 mm; a
  // non-homogeneous solution would be off by the 0.08 mm distortion of the cells)
  const Real edge = 1.0;
  for (Index n = 0; n < m.mesh.num_nodes(); ++n) {
    const Vec3 expected = (F - Mat3::Identity()) * m.mesh.node(n);
    EXPECT_LE((m.displacement(n) - expected).norm(), 1e-12 * edge) << "node " << n;
  }
}

} // namespace

TEST(PatchTest, NeoHookeanDistortedBlockIsExact) {
  run_patch_test("neo-hookean");
}
TEST(PatchTest, SaintVenantKirchhoffDistortedBlockIsExact) {
  run_patch_test("saint-venant-kirchhoff");
}
TEST(PatchTest, MeanDilatationDistortedBlockIsExact) {
  run_patch_test("neo-hookean", physics::SolidElement::MeanDilatation);
  run_patch_test("saint-venant-kirchhoff", physics::SolidElement::MeanDilatation);
}
TEST(PatchTest, ConstrainedVolumeKeepsJOneToRoundOff) {
  // An isochoric deformation (stretch 1.2 / 1/1.2 and shear 0.3, det F = 1) of a nearly
  // incompressible block (bulk/shear = 3.3e6): every cell keeps J = 1 and the interior
  // nodes follow the affine map, with the bulk stiffness 10^6 times the shear stiffness.
  Mat3 F;
  F << 1.2, 0.3 / 1.2, 0.0, 0.0, 1.0 / 1.2, 0.0, 0.0, 0.0, 1.0;
  ASSERT_NEAR(F.determinant(), 1.0, 1e-15);
  run_patch_test("neo-hookean", physics::SolidElement::MeanDilatation, F, 0.4999999);
}
