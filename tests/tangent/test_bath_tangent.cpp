// SPDX-License-Identifier: MIT
// Finite-difference check of the bath boundary term (follower area vectors in the water and ion
// rows) on a deformed facet.
#include "trifem/mesh/box.hpp"
#include "trifem/mesh/convert_cells.hpp"
#include "trifem/physics/bath_term.hpp"

#include <gtest/gtest.h>

using namespace trifem;

namespace {

/// On the first facet of the face z = 1 of a unit box of `type` cells.
void expect_tangent_matches(Real pressure, mesh::CellType type = mesh::CellType::Hex8) {
  mesh::BoxSpec spec;
  const mesh::Mesh mesh = mesh::convert_cells(mesh::make_box(spec), type);
  dofs::DofMap map;
  physics::MixtureFields f;
  f.u = map.add_field("u", FieldRole::displacement, mesh.num_nodes(), 3);
  f.w = map.add_field("w", FieldRole::flux, mesh.num_nodes(), 3);
  f.j_plus = map.add_field("j+", FieldRole::flux, mesh.num_nodes(), 3);
  f.j_minus = map.add_field("j-", FieldRole::flux, mesh.num_nodes(), 3);
  f.p = map.add_field("p", FieldRole::potential, 1, 1);
  f.eta = map.add_field("eta", FieldRole::potential, 1, 1);
  map.finalize();
  material::Electrochemistry chem;
  const mesh::Facet& facet = mesh.surface("box.zmax").facets.front();
  const physics::BathTerm term(mesh, map, f, {facet}, chem, 4e-5, dofs::LoadCurve::constant(),
                               pressure);
  std::srand(9);
  Vector x = 0.1 * Vector::Random(map.num_dofs());
  const Vector x_old = x;
  std::vector<Index> dofs;
  term.element_dofs(0, dofs);
  // u at every node of the facet, the three fluxes at its corners
  const int n = 3 * facet.num_nodes() + 9 * facet.num_corners();
  ASSERT_EQ(dofs.size(), static_cast<std::size_t>(n));
  physics::LocalVector r;
  physics::LocalMatrix K;
  ASSERT_TRUE(term.evaluate(0, {x, x_old, 1.0, 0.5}, r, &K));
  EXPECT_GT(r.norm(), 0.0);
  Eigen::MatrixXd K_fd(n, n);
  for (int j = 0; j < n; ++j) {
    Vector xp = x, xm = x;
    xp[dofs[j]] += 1e-6;
    xm[dofs[j]] -= 1e-6;
    physics::LocalVector rp, rm;
    term.evaluate(0, {xp, x_old, 1.0, 0.5}, rp, nullptr);
    term.evaluate(0, {xm, x_old, 1.0, 0.5}, rm, nullptr);
    K_fd.col(j) = (rp - rm) / 2e-6;
  }
  EXPECT_LE((K - K_fd).norm() / K.norm(), 1e-7) << mesh::name(facet.type);
}

} // namespace

TEST(BathTerm, TangentMatchesFiniteDifferences) {
  expect_tangent_matches(0.0);
}

// A bath at a gauge pressure (0.1 MPa, of the size of the osmotic terms) adds p* a to the water
// rows: its tangent is p* da/du.
TEST(BathTerm, TangentWithBathPressureMatchesFiniteDifferences) {
  expect_tangent_matches(0.1);
}

// The facets of the other families: tri3 (penta6), tri6 (tet10), quad8 (hex20); the fluxes at
// the corners weighted by their linear functions on the (curved) facet.
TEST(BathTerm, TangentOnTriangleAndQuadraticFacetsMatchesFiniteDifferences) {
  for (mesh::CellType type : {mesh::CellType::Penta6, mesh::CellType::Tet10, mesh::CellType::Hex20})
    expect_tangent_matches(0.1, type);
}
