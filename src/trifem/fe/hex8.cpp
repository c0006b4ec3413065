// SPDX-License-Identifier: MIT
#include "trifem/fe/hex8.hpp"

#include "trifem/mesh/hex_faces.hpp"

namespace trifem::fe {

HexShape hex8_shape(const Vec3& xi) {
  HexShape N;
  for (int a = 0; a < 8; ++a) {
    const auto& r = mesh::kHexNodeCoords[a];
    N[a] = 0.125 * (1 + xi[0] * r[0]) * (1 + xi[1] * r[1]) * (1 + xi[2] * r[2]);
  }
  return N;
}

HexShapeGrad hex8_shape_grad(const Vec3& xi) {
  HexShapeGrad G;
  for (int a = 0; a < 8; ++a) {
    const auto& r = mesh::kHexNodeCoords[a];
    const Real fx = 1 + xi[0] * r[0], fy = 1 + xi[1] * r[1], fz = 1 + xi[2] * r[2];
    G(a, 0) = 0.125 * r[0] * fy * fz;
    G(a, 1) = 0.125 * fx * r[1] * fz;
    G(a, 2) = 0.125 * fx * fy * r[2];
  }
  return G;
}

namespace {
constexpr Real kQuadNodes[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
} // namespace

QuadShape quad4_shape(const Vec2& xi) {
  QuadShape N;
  for (int a = 0; a < 4; ++a)
    N[a] = 0.25 * (1 + xi[0] * kQuadNodes[a][0]) * (1 + xi[1] * kQuadNodes[a][1]);
  return N;
}

QuadShapeGrad quad4_shape_grad(const Vec2& xi) {
  QuadShapeGrad G;
  for (int a = 0; a < 4; ++a) {
    G(a, 0) = 0.25 * kQuadNodes[a][0] * (1 + xi[1] * kQuadNodes[a][1]);
    G(a, 1) = 0.25 * (1 + xi[0] * kQuadNodes[a][0]) * kQuadNodes[a][1];
  }
  return G;
}

HexCoords cell_coordinates(const mesh::Mesh& mesh, Index c) {
  HexCoords X;
  for (int a = 0; a < 8; ++a)
    X.row(a) = mesh.node(mesh.cell(c)[a]).transpose();
  return X;
}

std::optional<HexGeometry> hex8_geometry(const HexCoords& X) {
  HexGeometry geo;
  const auto& rule = hex_gauss_2x2x2();
  for (int q = 0; q < 8; ++q) {
    const HexShapeGrad dN = hex8_shape_grad(rule[q].xi);
    const Mat3 J = X.transpose() * dN; // J_ij = dX_i/dxi_j
    const Real det = J.determinant();
    if (!(det > 0.0))
      return std::nullopt;
    geo.dN_dX[q] = dN * J.inverse();
    geo.dV[q] = det * rule[q].weight;
  }
  return geo;
}

std::optional<ReversedCorner> hex8_reversed_corner(const HexCoords& X, const HexCoords& x,
                                                   Real tolerance) {
  std::optional<ReversedCorner> worst;
  for (int a = 0; a < 8; ++a) {
    const auto& r = mesh::kHexNodeCoords[a];
    const HexShapeGrad dN = hex8_shape_grad(Vec3(r[0], r[1], r[2]));
    const Real reference = (X.transpose() * dN).determinant();
    if (!(reference > 0.0))
      continue; // a corner the reference mesh folds already: nothing to compare with
    const Real ratio = (x.transpose() * dN).determinant() / reference;
    if (!(ratio >= -tolerance) && (!worst || ratio < worst->ratio))
      worst = ReversedCorner{a, ratio};
  }
  return worst;
}

} // namespace trifem::fe
