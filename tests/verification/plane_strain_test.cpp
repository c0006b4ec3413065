// SPDX-License-Identifier: MIT
// Plane strain by one hex layer (docs/theory/reference-solutions.md §R9): with all y-components of
// u, w, j+, j- fixed, the solution per unit depth does not depend on the layer thickness (exact
// answer: equality of the nodal fields, element p and eta, and the platen reaction per depth at
// thickness 1 and 0.1).
#include "mixture_model.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace trifem;

namespace {

/// A 2 x 1 mm (x by z) triphasic block of 4 x 2 cells, one layer of thickness `depth` in y:
/// bottom fixed and impermeable, xmin symmetry (u_x = 0, impermeable in x), top platen u_z ramped
/// to -0.02 mm over 10 s (free-draining), xmax traction-free bath.
test::MixtureModel plane_block(Real depth) {
  mesh::BoxSpec spec;
  spec.size = {2.0, depth, 1.0};
  spec.divisions = {4, 1, 2};
  test::MixtureModel m(mesh::make_box(spec), test::paper_tissue(true));
  m.fix("box.all", m.f.u, 1);
  m.impermeable("box.all", 1);
  for (int k = 0; k < 3; ++k)
    m.fix("box.zmin", m.f.u, k);
  m.impermeable("box.zmin", 2);
  m.fix("box.xmin", m.f.u, 0);
  m.impermeable("box.xmin", 0);
  m.fix("box.zmax", m.f.u, 2, -0.02,
        dofs::LoadCurve({{0.0, 0.0}, {10.0, 1.0}}, dofs::Interpolation::Linear));
  m.build();
  return m;
}

/// Reaction force on the platen (z component) per unit depth.
Real platen_force_per_depth(const test::MixtureModel& m, Real depth) {
  Real force = 0.0;
  const Vector r = m.problem->full_residual();
  for (Index n : m.mesh.node_set("box.zmax"))
    force += r[m.dofs.dof(m.f.u, n, 2)];
  return force / depth;
}

/// The node (or cell centroid) of `b` with the same (x, z) as `x` at y = 0.
Index match_node(const mesh::Mesh& b, const Vec3& x) {
  for (Index n = 0; n < b.num_nodes(); ++n) {
    const Vec3& y = b.node(n);
    if (std::abs(y.x() - x.x()) < 1e-12 && std::abs(y.z() - x.z()) < 1e-12 && y.y() == 0.0)
      return n;
  }
  return -1;
}

Vec3 centroid(const mesh::Mesh& mesh, Index c) {
  Vec3 s = Vec3::Zero();
  for (Index n : mesh.cell(c))
    s += mesh.node(n);
  return s / 8.0;
}

Index match_cell(const mesh::Mesh& b, const Vec3& x) {
  for (Index c = 0; c < b.num_cells(); ++c) {
    const Vec3 y = centroid(b, c);
    if (std::abs(y.x() - x.x()) < 1e-12 && std::abs(y.z() - x.z()) < 1e-12)
      return c;
  }
  return -1;
}

/// Largest difference between the two models of one field, relative to its largest magnitude.
struct Comparison {
  Real difference = 0.0;
  Real magnitude = 0.0;
  Real relative() const { return magnitude > 0.0 ? difference / magnitude : difference; }
};

} // namespace

TEST(PlaneStrain, OneHexLayerIsIndependentOfItsThickness) {
  const Real depths[2] = {1.0, 0.1};
  test::MixtureModel a = plane_block(depths[0]);
  test::MixtureModel b = plane_block(depths[1]);
  Real worst_force = 0.0;
  const auto run = [&](test::MixtureModel& m, Real end) {
    // a fixed step: both thicknesses must march through the same step sequence
    const solver::RunReport r = m.run(end, 0.5, 0.5);
    ASSERT_TRUE(r.success) << r.failure;
  };
  for (Real t : {5.0, 10.0, 20.0, 30.0}) {
    run(a, t);
    run(b, t);
    const Real fa = platen_force_per_depth(a, depths[0]);
    const Real fb = platen_force_per_depth(b, depths[1]);
    worst_force = std::max(worst_force, std::abs(fa - fb) / std::abs(fa));
    std::printf("t = %4.1f s  platen force per depth %.12e vs %.12e\n", t, fa, fb);
    EXPECT_NEAR(fb, fa, 1e-9 * std::abs(fa)) << "t = " << t;
  }

  // nodal fields at matching (x, z) on y = 0
  const dofs::FieldId nodal[4] = {a.f.u, a.f.w, a.f.j_plus, a.f.j_minus};
  const char* names[6] = {"u", "w", "j+", "j-", "p", "eta"};
  Comparison cmp[6];
  int matched = 0;
  for (Index n = 0; n < a.mesh.num_nodes(); ++n) {
    const Vec3& x = a.mesh.node(n);
    if (x.y() != 0.0)
      continue;
    const Index nb = match_node(b.mesh, x);
    ASSERT_GE(nb, 0) << "no node at x = " << x.x() << ", z = " << x.z();
    ++matched;
    for (int f = 0; f < 4; ++f)
      for (int k = 0; k < 3; ++k) {
        const Real va = a.value(nodal[f], n, k), vb = b.value(nodal[f], nb, k);
        if (k == 1) { // out of plane: fixed
          EXPECT_EQ(va, 0.0);
          EXPECT_EQ(vb, 0.0);
        }
        cmp[f].difference = std::max(cmp[f].difference, std::abs(va - vb));
        cmp[f].magnitude = std::max(cmp[f].magnitude, std::abs(va));
      }
  }
  EXPECT_EQ(matched, 15);
  // element p and eta at matching centroids
  for (Index c = 0; c < a.mesh.num_cells(); ++c) {
    const Index cb = match_cell(b.mesh, centroid(a.mesh, c));
    ASSERT_GE(cb, 0);
    const dofs::FieldId scalar[2] = {a.f.p, a.f.eta};
    for (int f = 0; f < 2; ++f) {
      const Real va = a.value(scalar[f], c), vb = b.value(scalar[f], cb);
      cmp[4 + f].difference = std::max(cmp[4 + f].difference, std::abs(va - vb));
      cmp[4 + f].magnitude = std::max(cmp[4 + f].magnitude, std::abs(va));
    }
  }
  for (int f = 0; f < 6; ++f) {
    std::printf("%-3s max |difference| %.3e, max |value| %.3e, relative %.3e\n", names[f],
                cmp[f].difference, cmp[f].magnitude, cmp[f].relative());
    EXPECT_GT(cmp[f].magnitude, 0.0) << names[f];
    EXPECT_LE(cmp[f].relative(), 1e-9) << names[f];
  }
  std::printf("platen force per depth: worst relative difference %.3e\n", worst_force);
}
