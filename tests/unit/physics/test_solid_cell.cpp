// SPDX-License-Identifier: MIT
// The solid element of every cell family (physics/solid_cell.hpp) against answers that do not
// use it: the nodal forces of a homogeneous stress are its tractions integrated over the
// cell's facets (divergence theorem, with the facets' own shape functions and rules), a rigid
// rotation loads no node, the hex8 family is the hex8 kernel, and an inverted cell is refused.
#include "cell_families.hpp"
#include "trifem/material/registry.hpp"
#include "trifem/physics/solid_cell.hpp"
#include "trifem/physics/solid_kernel.hpp"
#include "trifem/tensor/rotation.hpp"

#include <gtest/gtest.h>

using namespace trifem;

namespace {

std::unique_ptr<material::ElasticLaw> neo_hookean() {
  return material::create_law("neo-hookean", {{"E", 2.0}, {"nu", 0.3}}, "test");
}

/// The reference nodes of `type` under the affine map X = A ξ + b (det A > 0): flat facets,
/// constant Jacobian, so the rules integrate the element's polynomials exactly.
fe::CellNodeCoords affine_cell(fe::CellType type) {
  Mat3 A;
  A << 1.3, 0.2, -0.1, 0.1, 0.9, 0.3, -0.2, 0.1, 1.1;
  const Vec3 b(0.4, -0.2, 0.7);
  fe::CellNodeCoords X = fe::reference_cell(type).nodes();
  for (Index a = 0; a < X.rows(); ++a)
    X.row(a) = (A * X.row(a).transpose() + b).transpose();
  return X;
}

/// Σ over the facets of ∫ N_a P N dA: the nodal forces of the first Piola stress P acting on
/// the boundary of the cell with node coordinates X.
physics::CellVectorX facet_tractions(fe::CellType type, const fe::CellNodeCoords& X,
                                     const Mat3& P) {
  const fe::ReferenceCell& cell = fe::reference_cell(type);
  physics::CellVectorX f = physics::CellVectorX::Zero(3 * cell.num_nodes());
  for (const fe::CellFacet& facet : cell.facets()) {
    const fe::ReferenceFacet& ref = fe::reference_facet(facet.type);
    for (const fe::FacetQuadraturePoint& p : ref.rule().points) {
      const fe::FacetShapeValues N = ref.shape(p.xi);
      const fe::FacetShapeGrads dN = ref.shape_grad(p.xi);
      Eigen::Matrix<Real, 3, 2> tangents = Eigen::Matrix<Real, 3, 2>::Zero();
      for (std::size_t i = 0; i < facet.nodes.size(); ++i)
        tangents += X.row(facet.nodes[i]).transpose() * dN.row(static_cast<Index>(i));
      const Vec3 area = tangents.col(0).cross(tangents.col(1)) * p.weight; // N dA
      for (std::size_t i = 0; i < facet.nodes.size(); ++i)
        f.segment<3>(3 * facet.nodes[i]) += P * area * N[static_cast<Index>(i)];
    }
  }
  return f;
}

} // namespace

TEST(SolidCell, TheForcesOfAHomogeneousStressAreItsTractionsOnTheFacets) {
  const auto law = neo_hookean();
  Mat3 F;
  F << 1.1, 0.05, 0.0, -0.03, 0.95, 0.1, 0.02, 0.0, 1.05;
  for (const fe::CellType type : test::kCellFamilies) {
    SCOPED_TRACE(static_cast<int>(type));
    const fe::CellNodeCoords X = affine_cell(type);
    const auto geo = physics::cell_geometry(fe::reference_cell(type), X);
    ASSERT_TRUE(geo.has_value());
    const fe::CellNodeCoords u = X * (F - Mat3::Identity()).transpose(); // u = (F − I) X
    physics::CellVectorX f;
    ASSERT_TRUE(physics::solid_cell(*geo, u, *law, f, nullptr));
    const Mat3 P = F * law->stress(F.transpose() * F);
    const physics::CellVectorX expected = facet_tractions(type, X, P);
    EXPECT_LE((f - expected).lpNorm<Eigen::Infinity>(), 1e-12 * expected.lpNorm<Eigen::Infinity>());
    EXPECT_GT(expected.lpNorm<Eigen::Infinity>(), 1e-3); // a stress that loads the nodes
  }
}

TEST(SolidCell, ARigidRotationLoadsNoNode) {
  const auto law = neo_hookean();
  const Mat3 R = rotation::matrix(Vec3(0.3, -0.7, 1.1));
  for (const fe::CellType type : test::kCellFamilies) {
    const fe::CellNodeCoords X = affine_cell(type);
    const auto geo = physics::cell_geometry(fe::reference_cell(type), X);
    ASSERT_TRUE(geo.has_value());
    physics::CellVectorX f;
    physics::CellMatrixX K;
    ASSERT_TRUE(physics::solid_cell(*geo, X * (R - Mat3::Identity()).transpose(), *law, f, &K));
    EXPECT_LE(f.lpNorm<Eigen::Infinity>(), 1e-13 * K.lpNorm<Eigen::Infinity>())
        << static_cast<int>(type); // forces of order E L², K of order E L
  }
}

TEST(SolidCell, TheHex8FamilyIsTheHex8Kernel) {
  const auto law = neo_hookean();
  fe::CellNodeCoords X = affine_cell(fe::CellType::Hex8);
  X(6, 0) += 0.15; // not affine
  X(3, 2) -= 0.1;
  fe::HexCoords X8, u8;
  fe::CellNodeCoords u(8, 3);
  for (int a = 0; a < 8; ++a) {
    X8.row(a) = X.row(a);
    u.row(a) << 0.05 * a, -0.02 * a * a / 8.0, 0.03 * (a % 3);
    u8.row(a) = u.row(a);
  }
  const auto geo = physics::cell_geometry(fe::reference_cell(fe::CellType::Hex8), X);
  const auto geo8 = fe::hex8_geometry(X8);
  ASSERT_TRUE(geo.has_value() && geo8.has_value());
  physics::CellVectorX f;
  physics::CellMatrixX K;
  physics::HexVector f8;
  physics::HexMatrix K8;
  ASSERT_TRUE(physics::solid_cell(*geo, u, *law, f, &K));
  ASSERT_TRUE(physics::solid_hex8(*geo8, u8, *law, f8, &K8));
  EXPECT_LE((f - f8).lpNorm<Eigen::Infinity>(), 1e-13 * f8.lpNorm<Eigen::Infinity>());
  EXPECT_LE((K - K8).lpNorm<Eigen::Infinity>(), 1e-13 * K8.lpNorm<Eigen::Infinity>());
}

TEST(SolidCell, AnInvertedCellHasNoGeometry) {
  for (const fe::CellType type : test::kCellFamilies) {
    fe::CellNodeCoords X = affine_cell(type);
    X.col(2) *= -1.0; // mirrored: det(dX/dxi) < 0 everywhere
    EXPECT_FALSE(physics::cell_geometry(fe::reference_cell(type), X).has_value())
        << static_cast<int>(type);
  }
}
