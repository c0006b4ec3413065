// SPDX-License-Identifier: MIT
// Tests of the uniform refinement of hex8 meshes (refine_uniformly): geometry, sharing of new
// nodes, and the named sets, against boxes built directly at the finer size.
#include "trifem/core/error.hpp"
#include "trifem/mesh/box.hpp"
#include "trifem/mesh/hex_faces.hpp"
#include "trifem/mesh/refine.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>

namespace {

using trifem::Index;
using trifem::InputError;
using trifem::Mat3;
using trifem::Real;
using trifem::Vec3;
using trifem::mesh::BoxSpec;
using trifem::mesh::CellData;
using trifem::mesh::Facet;
using trifem::mesh::kHexNodeCoords;
using trifem::mesh::make_box;
using trifem::mesh::Mesh;
using trifem::mesh::refine_uniformly;
using trifem::mesh::Surface;

/// The trilinear map of cell c at natural coordinates xi, and its Jacobian.
Vec3 map_point(const Mesh& mesh, Index c, const Vec3& xi, Mat3* jac = nullptr) {
  Vec3 x = Vec3::Zero();
  if (jac)
    jac->setZero();
  for (int a = 0; a < 8; ++a) {
    const auto& r = kHexNodeCoords[a];
    const Real n[3] = {1 + r[0] * xi[0], 1 + r[1] * xi[1], 1 + r[2] * xi[2]};
    x += mesh.node(mesh.cell(c)[a]) * (n[0] * n[1] * n[2] / 8);
    if (jac)
      *jac +=
          mesh.node(mesh.cell(c)[a]) *
          Vec3(r[0] * n[1] * n[2] / 8, n[0] * r[1] * n[2] / 8, n[0] * n[1] * r[2] / 8).transpose();
  }
  return x;
}

/// Volume of a hex8 by 2x2x2 Gauss quadrature (exact for a trilinear map).
Real hex_volume(const Mesh& mesh, Index c) {
  const Real g = 1.0 / std::sqrt(3.0);
  Real volume = 0.0;
  for (const auto& r : kHexNodeCoords) {
    Mat3 jac;
    map_point(mesh, c, Vec3(r[0] * g, r[1] * g, r[2] * g), &jac);
    volume += jac.determinant();
  }
  return volume;
}

/// One strongly distorted (non-affine) hex8.
Mesh distorted_hex() {
  Mesh mesh;
  const std::array<Vec3, 8> x = {Vec3(0, 0, 0),       Vec3(2, 0.1, 0),    Vec3(2.3, 1.7, 0.2),
                                 Vec3(-0.2, 1.2, 0),  Vec3(0.1, 0, 1),    Vec3(1.8, -0.2, 1.4),
                                 Vec3(2.1, 1.9, 1.1), Vec3(0.3, 1.1, 0.9)};
  for (const Vec3& p : x)
    mesh.add_node(p);
  mesh.add_cell({0, 1, 2, 3, 4, 5, 6, 7});
  mesh.add_cell_block("part", {0});
  return mesh;
}

/// Rounded coordinates, to compare point sets built in different orders.
using PointKey = std::tuple<long, long, long>;
PointKey key_of(const Vec3& x) {
  return {std::lround(x[0] * 1e9), std::lround(x[1] * 1e9), std::lround(x[2] * 1e9)};
}

std::set<PointKey> node_points(const Mesh& mesh, const std::vector<Index>& nodes) {
  std::set<PointKey> points;
  for (Index n : nodes)
    points.insert(key_of(mesh.node(n)));
  return points;
}

/// Centroid and outward area vector of every facet (the area vector from the diagonals).
std::set<std::pair<PointKey, PointKey>> facet_geometry(const Mesh& mesh, const Surface& s) {
  std::set<std::pair<PointKey, PointKey>> geometry;
  for (const Facet& f : s.facets) {
    const auto& n = f.nodes;
    const Vec3 centroid =
        (mesh.node(n[0]) + mesh.node(n[1]) + mesh.node(n[2]) + mesh.node(n[3])) / 4;
    const Vec3 area =
        (mesh.node(n[2]) - mesh.node(n[0])).cross(mesh.node(n[3]) - mesh.node(n[1])) / 2;
    geometry.insert({key_of(centroid), key_of(area)});
  }
  return geometry;
}

TEST(RefineUniformly, ChildrenTileTheParentExactly) {
  const Mesh coarse = distorted_hex();
  const Mesh fine = refine_uniformly(coarse);
  ASSERT_EQ(fine.num_cells(), 8);
  ASSERT_EQ(fine.num_nodes(), 27); // 8 corners, 12 edge midpoints, 6 face centres, 1 centre
  for (Index n = 0; n < coarse.num_nodes(); ++n)
    EXPECT_EQ(fine.node(n), coarse.node(n)); // the corners keep their indices
  // Every node of child (i, j, k) is the parent's trilinear map at its natural coordinates.
  const Real scale = 2.0; // the cell's size
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i)
        for (int l = 0; l < 8; ++l) {
          const auto& r = kHexNodeCoords[l];
          const Vec3 xi(i - 0.5 + r[0] / 2, j - 0.5 + r[1] / 2, k - 0.5 + r[2] / 2);
          const Index child = i + 2 * j + 4 * k;
          EXPECT_LT((fine.node(fine.cell(child)[l]) - map_point(coarse, 0, xi)).norm(),
                    1e-14 * scale);
        }
  Real volume = 0.0;
  for (Index c = 0; c < fine.num_cells(); ++c) {
    EXPECT_GT(hex_volume(fine, c), 0.0);
    volume += hex_volume(fine, c);
  }
  EXPECT_NEAR(volume, hex_volume(coarse, 0), 1e-14 * hex_volume(coarse, 0));
  EXPECT_EQ(fine.cell_block("part").size(), 8u);
}

TEST(RefineUniformly, GivesTheBoxOfTwiceTheDivisions) {
  BoxSpec spec;
  spec.size = Vec3(2.0, 1.0, 0.5);
  spec.divisions = {2, 1, 3};
  const Mesh fine = refine_uniformly(make_box(spec));
  spec.divisions = {4, 2, 6};
  const Mesh direct = make_box(spec);
  ASSERT_EQ(fine.num_nodes(), direct.num_nodes()); // new nodes are shared, never duplicated
  ASSERT_EQ(fine.num_cells(), direct.num_cells());
  EXPECT_EQ(node_points(fine, fine.node_set("box.all")),
            node_points(direct, direct.node_set("box.all")));
  EXPECT_EQ(fine.node_set("box.all").size(), static_cast<std::size_t>(fine.num_nodes()));
  ASSERT_EQ(fine.surfaces().size(), 6u);
  for (const auto& [name, surface] : direct.surfaces()) {
    SCOPED_TRACE(name);
    ASSERT_EQ(fine.surface(name).facets.size(), surface.facets.size());
    EXPECT_EQ(facet_geometry(fine, fine.surface(name)), facet_geometry(direct, surface));
    EXPECT_EQ(node_points(fine, fine.node_set(name)), node_points(direct, direct.node_set(name)));
  }
  Real volume = 0.0;
  for (Index c : fine.cell_block("box"))
    volume += hex_volume(fine, c);
  EXPECT_NEAR(volume, 1.0, 1e-14);
}

TEST(RefineUniformly, NodeSetsGainTheNewNodesBuiltFromTheirMembers) {
  BoxSpec spec;
  spec.divisions = {2, 2, 2};
  Mesh coarse = make_box(spec);
  // the nodes of the edge x = 0, y = 0 and one lone corner
  std::vector<Index> edge, corner;
  for (Index n = 0; n < coarse.num_nodes(); ++n) {
    const Vec3& x = coarse.node(n);
    if (x[0] == 0.0 && x[1] == 0.0)
      edge.push_back(n);
    if (x == Vec3(1, 1, 1))
      corner.push_back(n);
  }
  coarse.add_node_set("edge", edge);
  coarse.add_node_set("corner", corner);
  const Mesh fine = refine_uniformly(coarse);
  const auto& fine_edge = fine.node_set("edge");
  EXPECT_EQ(fine_edge.size(), 5u); // 3 nodes and the 2 midpoints between them
  for (Index n : fine_edge)
    EXPECT_TRUE(fine.node(n)[0] == 0.0 && fine.node(n)[1] == 0.0);
  EXPECT_EQ(fine.node_set("corner").size(), 1u);
}

TEST(RefineUniformly, CellDataAndLevels) {
  Mesh coarse = distorted_hex();
  coarse.add_cell_data("fibre", CellData{.components = 3, .values = {0.1, 0.2, 0.3}});
  const Mesh fine = refine_uniformly(coarse, 2);
  ASSERT_EQ(fine.num_cells(), 64);
  EXPECT_EQ(fine.num_nodes(), 125);
  const CellData& data = fine.cell_data("fibre");
  for (Index c = 0; c < fine.num_cells(); ++c)
    EXPECT_EQ(data.value(c, 2), 0.3);
  Real volume = 0.0;
  for (Index c = 0; c < fine.num_cells(); ++c)
    volume += hex_volume(fine, c);
  EXPECT_NEAR(volume, hex_volume(coarse, 0), 1e-13 * hex_volume(coarse, 0));
  EXPECT_EQ(refine_uniformly(coarse, 0).num_cells(), 1);
  EXPECT_THROW(refine_uniformly(coarse, -1), InputError);
}

} // namespace
