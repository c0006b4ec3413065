// SPDX-License-Identifier: MIT
// Tests of the structured box generator make_box.
#include "trifem/core/error.hpp"
#include "trifem/mesh/box.hpp"
#include "trifem/mesh/hex_faces.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

namespace {

using trifem::Index;
using trifem::InputError;
using trifem::Mat3;
using trifem::Real;
using trifem::Vec3;
using trifem::mesh::BoxSpec;
using trifem::mesh::kHexFaces;
using trifem::mesh::kHexNodeCoords;
using trifem::mesh::make_box;
using trifem::mesh::Mesh;

/// Volume of a hex8 cell by 2x2x2 Gauss quadrature of det(dx/dxi).
Real cell_volume(const Mesh& mesh, Index c) {
  const Real g = 1.0 / std::sqrt(3.0);
  Real volume = 0.0;
  for (int q = 0; q < 8; ++q) {
    const Real xi[3] = {kHexNodeCoords[q][0] * g, kHexNodeCoords[q][1] * g,
                        kHexNodeCoords[q][2] * g};
    Mat3 jac = Mat3::Zero();
    for (int a = 0; a < 8; ++a) {
      const auto& r = kHexNodeCoords[a];
      const Real n[3] = {1 + r[0] * xi[0], 1 + r[1] * xi[1], 1 + r[2] * xi[2]};
      const Vec3 dn(r[0] * n[1] * n[2] / 8, n[0] * r[1] * n[2] / 8, n[0] * n[1] * r[2] / 8);
      jac += mesh.node(mesh.cell(c)[a]) * dn.transpose();
    }
    volume += jac.determinant(); // Gauss weights are 1
  }
  return volume;
}

BoxSpec graded_spec() {
  BoxSpec spec;
  spec.name = "b";
  spec.origin = Vec3(1.0, -1.0, 0.5);
  spec.size = Vec3(2.0, 1.0, 3.0);
  spec.divisions = {3, 2, 4};
  spec.grading = Vec3(1.0, 1.0, 4.0);
  return spec;
}

TEST(Box, CountsAndBlock) {
  const Mesh mesh = make_box(graded_spec());
  EXPECT_EQ(mesh.num_nodes(), 4 * 3 * 5);
  EXPECT_EQ(mesh.num_cells(), 3 * 2 * 4);
  EXPECT_EQ(mesh.cell_block("b").size(), 24u);
  EXPECT_EQ(mesh.node_set("b.all").size(), 60u);
}

TEST(Box, SurfacesAreOutwardAndOnTheirPlanes) {
  const BoxSpec spec = graded_spec();
  const Mesh mesh = make_box(spec);
  const char* names[3][2] = {{"xmin", "xmax"}, {"ymin", "ymax"}, {"zmin", "zmax"}};
  const std::size_t facets[3] = {2 * 4, 3 * 4, 3 * 2};
  const std::size_t nodes[3] = {3 * 5, 4 * 5, 4 * 3};
  for (int d = 0; d < 3; ++d) {
    for (int side = 0; side < 2; ++side) {
      const std::string name = std::string("b.") + names[d][side];
      SCOPED_TRACE(name);
      const auto& surface = mesh.surface(name);
      EXPECT_EQ(surface.facets.size(), facets[d]);
      EXPECT_EQ(mesh.node_set(name).size(), nodes[d]);
      const Real plane = spec.origin[d] + side * spec.size[d];
      for (const auto& f : surface.facets) {
        const Vec3 n = (mesh.node(f.nodes[1]) - mesh.node(f.nodes[0]))
                           .cross(mesh.node(f.nodes[2]) - mesh.node(f.nodes[1]))
                           .normalized();
        EXPECT_NEAR(n[d], side == 0 ? -1.0 : 1.0, 1e-12);
        for (int a = 0; a < 4; ++a) {
          EXPECT_EQ(f.nodes[a], mesh.cell(f.cell)[kHexFaces[f.local_face][a]]);
          EXPECT_NEAR(mesh.node(f.nodes[a])[d], plane, 1e-12);
        }
      }
    }
  }
}

TEST(Box, CellVolumesSumToBoxVolume) {
  const Mesh mesh = make_box(graded_spec());
  Real total = 0.0;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const Real v = cell_volume(mesh, c);
    EXPECT_GT(v, 0.0);
    total += v;
  }
  EXPECT_NEAR(total, 2.0 * 1.0 * 3.0, 1e-12);
}

TEST(Box, GradedCoordinates) {
  const BoxSpec spec = graded_spec();
  const Mesh mesh = make_box(spec);
  std::set<Real> z;
  for (const Vec3& x : mesh.nodes())
    z.insert(x.z());
  ASSERT_EQ(z.size(), 5u);
  const std::vector<Real> zs(z.begin(), z.end());
  EXPECT_NEAR(zs.front(), 0.5, 1e-12);
  EXPECT_NEAR(zs.back(), 3.5, 1e-12);
  const Real first = zs[1] - zs[0];
  const Real last = zs[4] - zs[3];
  EXPECT_NEAR(last / first, 4.0, 1e-12);
  // cell lengths grow geometrically
  const Real r = std::cbrt(4.0);
  for (int i = 1; i < 4; ++i)
    EXPECT_NEAR((zs[i + 1] - zs[i]) / (zs[i] - zs[i - 1]), r, 1e-12);

  const auto x = trifem::mesh::graded_coordinates(2.0, 3, 1.0);
  ASSERT_EQ(x.size(), 4u);
  for (int i = 0; i < 4; ++i)
    EXPECT_NEAR(x[i], 2.0 * i / 3.0, 1e-12);
}

TEST(Box, BadInputsThrow) {
  BoxSpec zero_size = graded_spec();
  zero_size.size.y() = 0.0;
  EXPECT_THROW(make_box(zero_size), InputError);
  BoxSpec zero_divisions = graded_spec();
  zero_divisions.divisions[2] = 0;
  EXPECT_THROW(make_box(zero_divisions), InputError);
  BoxSpec negative_grading = graded_spec();
  negative_grading.grading.x() = -2.0;
  EXPECT_THROW(make_box(negative_grading), InputError);
}

} // namespace
