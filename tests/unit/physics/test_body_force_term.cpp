// SPDX-License-Identifier: MIT
// Exact answers checked: the nodal forces of BodyForceTerm on a distorted hex8 cell sum to
// −ρ b V and their first moment Σ_a X_a ⊗ f_a is −ρ (∫X dV) ⊗ b (the trilinear interpolation
// reproduces the linear field X, and 2x2x2 Gauss integrates it exactly); V and ∫X dV come from
// an independent 3x3x3 Gauss rule. The curve scales the forces and the Jacobian is zero.
#include "trifem/core/error.hpp"
#include "trifem/fe/hex8.hpp"
#include "trifem/mesh/hex_faces.hpp"
#include "trifem/physics/body_force_term.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

using namespace trifem;

namespace {

/// A mesh of one cell: the cube [0, 2] x [0, 1] x [0, 1.5] with every node moved randomly by up
/// to ±0.2 per coordinate, and the displacement field of its nodes.
struct OneCell {
  mesh::Mesh mesh;
  dofs::DofMap dofs;
  dofs::FieldId u;

  explicit OneCell(unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<Real> d(-0.2, 0.2);
    const Vec3 size(2.0, 1.0, 1.5);
    mesh::Hex8 cell{};
    for (int a = 0; a < 8; ++a) {
      Vec3 x;
      for (int k = 0; k < 3; ++k)
        x[k] = 0.5 * (mesh::kHexNodeCoords[a][k] + 1.0) * size[k] + d(rng);
      cell[a] = mesh.add_node(x);
    }
    mesh.add_cell(cell);
    u = dofs.add_field("displacement", FieldRole::displacement, mesh.num_nodes(), 3);
  }
};

/// V and ∫X dV of cell 0 by 3x3x3 Gauss (exact: det J X is cubic in each natural coordinate).
std::pair<Real, Vec3> volume_and_moment(const mesh::Mesh& mesh) {
  const fe::HexCoords X = fe::cell_coordinates(mesh, 0);
  const Real p[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)}, w[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
  Real V = 0.0;
  Vec3 first = Vec3::Zero();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) {
        const Vec3 xi(p[i], p[j], p[k]);
        const Real dV =
            (fe::hex8_shape_grad(xi).transpose() * X).determinant() * w[i] * w[j] * w[k];
        V += dV;
        first += dV * (X.transpose() * fe::hex8_shape(xi));
      }
  return {V, first};
}

} // namespace

TEST(BodyForceTerm, NodalForcesSumToTheWeightAndReproduceItsFirstMoment) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const OneCell c(seed);
    const Real rho = 1.3e-9;
    const Vec3 b(120.0, -450.0, -9810.0);
    const physics::BodyForceTerm term(c.mesh, c.dofs, c.u, {0}, {rho}, b,
                                      dofs::LoadCurve::constant());
    ASSERT_EQ(term.num_elements(), 1);
    std::vector<Index> element;
    term.element_dofs(0, element);
    ASSERT_EQ(element.size(), 24u);
    const Vector x = Vector::Zero(c.dofs.num_dofs());
    physics::LocalVector r;
    physics::LocalMatrix K;
    ASSERT_TRUE(term.evaluate(0, {x, x, 0.0, 0.0}, r, &K));
    ASSERT_EQ(r.size(), 24);
    EXPECT_EQ(K.rows(), 24);
    EXPECT_EQ(K.cols(), 24);
    EXPECT_EQ(K.norm(), 0.0); // a dead load
    const auto [V, first] = volume_and_moment(c.mesh);
    Vec3 sum = Vec3::Zero();
    Mat3 moment = Mat3::Zero(); // Σ_a X_a ⊗ f_a
    for (int a = 0; a < 8; ++a) {
      const Index node = c.mesh.cell(0)[a];
      for (int k = 0; k < 3; ++k)
        EXPECT_EQ(element[3 * a + k], c.dofs.dof(c.u, node, k));
      const Vec3 f = -r.segment<3>(3 * a); // f_ext = −R
      sum += f;
      moment += c.mesh.node(node) * f.transpose();
    }
    const Vec3 weight = rho * V * b;
    const Mat3 expected = rho * first * b.transpose();
    EXPECT_LT((sum - weight).norm(), 1e-14 * weight.norm()) << sum.transpose();
    EXPECT_LT((moment - expected).norm(), 1e-14 * expected.norm()) << moment;
    EXPECT_NEAR(term.nodal_mass(0).sum(), rho * V, 1e-14 * rho * V);
    std::printf("seed %u: V = %.15g, |sum f - rho b V| / |rho b V| = %.2e, first moment: %.2e\n",
                seed, V, (sum - weight).norm() / weight.norm(),
                (moment - expected).norm() / expected.norm());
  }
}

TEST(BodyForceTerm, TheCurveScalesTheForce) {
  const OneCell c(7);
  const Vec3 b(0.0, 0.0, -9810.0);
  const physics::BodyForceTerm constant(c.mesh, c.dofs, c.u, {0}, {1e-9}, b,
                                        dofs::LoadCurve::constant());
  const physics::BodyForceTerm ramped(
      c.mesh, c.dofs, c.u, {0}, {1e-9}, b,
      dofs::LoadCurve({{0.0, 0.0}, {2.0, 3.0}}, dofs::Interpolation::Linear));
  const Vector x = Vector::Zero(c.dofs.num_dofs());
  physics::LocalVector r1, r2;
  ASSERT_TRUE(constant.evaluate(0, {x, x, 0.5, 0.1}, r1, nullptr));
  ASSERT_TRUE(ramped.evaluate(0, {x, x, 0.5, 0.1}, r2, nullptr));
  EXPECT_LT((r2 - 0.75 * r1).norm(), 1e-15 * r1.norm()); // curve(0.5) = 0.75
  ASSERT_TRUE(ramped.evaluate(0, {x, x, 0.0, 0.1}, r2, nullptr));
  EXPECT_EQ(r2.norm(), 0.0);
  // the force does not depend on the state (reference volume, fixed direction)
  const Vector moved = Vector::Constant(c.dofs.num_dofs(), 0.3);
  ASSERT_TRUE(constant.evaluate(0, {moved, x, 0.5, 0.1}, r2, nullptr));
  EXPECT_EQ((r2 - r1).norm(), 0.0);
}

TEST(BodyForceTerm, AnInvertedCellIsAnInputErrorNamingIt) {
  mesh::Mesh mesh;
  mesh::Hex8 cell{};
  for (int a = 0; a < 8; ++a) { // the unit cube with its top and bottom faces swapped
    const auto& p = mesh::kHexNodeCoords[a];
    cell[a] = mesh.add_node(Vec3(p[0], p[1], -p[2]));
  }
  mesh.add_cell(cell);
  dofs::DofMap map;
  const dofs::FieldId u = map.add_field("displacement", FieldRole::displacement, 8, 3);
  try {
    physics::BodyForceTerm(mesh, map, u, {0}, {1e-9}, Vec3(0, 0, -1), dofs::LoadCurve::constant());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cell 0 is inverted or degenerate"), std::string::npos)
        << e.what();
  }
}
