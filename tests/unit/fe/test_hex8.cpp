// SPDX-License-Identifier: MIT
// Shape functions and reference geometry of hex8/quad4.
#include "trifem/fe/hex8.hpp"

#include <gtest/gtest.h>

using namespace trifem;

TEST(Hex8, PartitionOfUnityAndKroneckerProperty) {
  const Vec3 xi(0.3, -0.7, 0.1);
  EXPECT_NEAR(fe::hex8_shape(xi).sum(), 1.0, 1e-15);
  EXPECT_LE(fe::hex8_shape_grad(xi).colwise().sum().norm(), 1e-15);
  const Real r[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                        {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  for (int a = 0; a < 8; ++a) {
    const fe::HexShape N = fe::hex8_shape(Vec3(r[a][0], r[a][1], r[a][2]));
    for (int b = 0; b < 8; ++b)
      EXPECT_NEAR(N[b], a == b ? 1.0 : 0.0, 1e-15);
  }
}

TEST(Hex8, ShapeGradientMatchesFiniteDifferences) {
  const Vec3 xi(0.2, 0.5, -0.4);
  const fe::HexShapeGrad G = fe::hex8_shape_grad(xi);
  for (int d = 0; d < 3; ++d) {
    Vec3 h = Vec3::Zero();
    h[d] = 1e-6;
    const fe::HexShape fd = (fe::hex8_shape(xi + h) - fe::hex8_shape(xi - h)) / 2e-6;
    EXPECT_LE((fd - G.col(d)).norm(), 1e-9);
  }
}

TEST(Hex8, GeometryIntegratesVolumeAndLinearFieldsExactly) {
  // a trilinear (non-affine) cell: the unit cube with one corner moved
  fe::HexCoords X;
  X << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1.3, 1.2, 1.4, 0, 1, 1;
  const auto geo = fe::hex8_geometry(X);
  ASSERT_TRUE(geo.has_value());
  Real volume = 0.0;
  Mat3 grad_x = Mat3::Zero(); // int Grad(X) dV = V I
  for (int q = 0; q < 8; ++q) {
    volume += geo->dV[q];
    grad_x += X.transpose() * geo->dN_dX[q] * geo->dV[q];
  }
  // exact volume of this trilinear cell by a fine midpoint rule on the map
  Real reference = 0.0;
  const int n = 40;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const Vec3 xi(-1 + (2 * i + 1.0) / n, -1 + (2 * j + 1.0) / n, -1 + (2 * k + 1.0) / n);
        reference += (X.transpose() * fe::hex8_shape_grad(xi)).determinant() * 8.0 / (n * n * n);
      }
  EXPECT_NEAR(volume, reference, 1e-4);
  EXPECT_LE((grad_x - volume * Mat3::Identity()).norm(), 1e-13);
}

TEST(Hex8, InvertedCellHasNoGeometry) {
  fe::HexCoords X;
  X << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, -1, 1, 0, -1, 1, 1, -1, 0, 1, -1;
  EXPECT_FALSE(fe::hex8_geometry(X).has_value());
}

namespace {

/// The unit cube, nodes in hex8 order.
fe::HexCoords unit_cube() {
  fe::HexCoords X;
  X << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1;
  return X;
}

} // namespace

TEST(Hex8, AnAffineMapReversesEveryCornerByItsDeterminant) {
  const fe::HexCoords X = unit_cube();
  Mat3 F;
  F << 0.9, 0.2, 0.0, 0.1, 1.1, 0.3, 0.0, 0.4, 1.0;
  EXPECT_FALSE(fe::hex8_reversed_corner(X, X * F.transpose(), 0.5)) << "det F > 0";
  Mat3 mirror = Mat3::Identity();
  for (const Real scale : {0.8, 0.3}) {
    mirror(2, 2) = -scale; // det = -scale at every point of the cell
    const auto reversed = fe::hex8_reversed_corner(X, X * mirror.transpose(), 0.5);
    ASSERT_EQ(reversed.has_value(), scale > 0.5) << scale;
    if (reversed) {
      EXPECT_NEAR(reversed->ratio, -scale, 1e-14);
    }
  }
}

TEST(Hex8, ACellPushedThroughItsFixedBottomIsTurnedOverAtTheBottom) {
  // bottom face fixed, top face moved below it and mirrored in x: at the bottom corners the
  // vertical edges point down, (1, 0, -1) or (-1, 0, -1), while the bottom edges keep their
  // orientation, so det(dx/dxi) = -det(dX/dxi) there
  const fe::HexCoords X = unit_cube();
  fe::HexCoords x = X;
  for (int a = 4; a < 8; ++a) {
    x(a, 0) = 1.0 - X(a, 0);
    x(a, 2) = -1.0;
  }
  const auto reversed = fe::hex8_reversed_corner(X, x, 0.5);
  ASSERT_TRUE(reversed.has_value());
  EXPECT_LT(reversed->corner, 4) << "a bottom corner";
  EXPECT_NEAR(reversed->ratio, -1.0, 1e-14);
}

TEST(Quad4, PartitionOfUnityAndGaussWeights) {
  Real w = 0.0;
  for (const auto& qp : fe::quad_gauss_2x2()) {
    EXPECT_NEAR(fe::quad4_shape(qp.xi).sum(), 1.0, 1e-15);
    EXPECT_LE(fe::quad4_shape_grad(qp.xi).colwise().sum().norm(), 1e-15);
    w += qp.weight;
  }
  EXPECT_DOUBLE_EQ(w, 4.0);
}
