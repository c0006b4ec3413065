// SPDX-License-Identifier: MIT
// Point location: the natural coordinates of points of distorted cells are recovered, points
// on nodes snap exactly, points outside every cell are not found.
#include "trifem/fe/hex8.hpp"
#include "trifem/fe/point_location.hpp"
#include "trifem/mesh/box.hpp"
#include "trifem/mesh/convert_cells.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace trifem;

namespace {

/// A 3x2x2 box of size 3x2x2 mm with its interior nodes moved randomly by up to 0.2 mm.
mesh::Mesh distorted_box() {
  mesh::BoxSpec spec;
  spec.divisions = {3, 2, 2};
  spec.size = Vec3(3.0, 2.0, 2.0);
  mesh::Mesh box = mesh::make_box(spec);
  std::mt19937 rng(7);
  std::uniform_real_distribution<Real> shift(-0.2, 0.2);
  mesh::Mesh out;
  for (const Vec3& x : box.nodes()) {
    const bool interior =
        (x.array() > 1e-12).all() && (x.array() < spec.size.array() - 1e-12).all();
    out.add_node(interior ? Vec3(x + Vec3(shift(rng), shift(rng), shift(rng))) : x);
  }
  for (Index c = 0; c < box.num_cells(); ++c)
    out.add_cell(box.cell_type(c), box.cell_nodes(c));
  return out;
}

Vec3 map_point(const mesh::Mesh& m, Index c, const Vec3& xi) {
  const fe::HexShape N = fe::hex8_shape(xi);
  Vec3 x = Vec3::Zero();
  for (int a = 0; a < 8; ++a)
    x += N[a] * m.node(m.cell(c)[a]);
  return x;
}

TEST(PointLocation, RecoversNaturalCoordinatesInDistortedCells) {
  const mesh::Mesh m = distorted_box();
  std::mt19937 rng(3);
  std::uniform_real_distribution<Real> coord(-0.95, 0.95);
  for (Index c = 0; c < m.num_cells(); ++c)
    for (int i = 0; i < 10; ++i) {
      const Vec3 xi(coord(rng), coord(rng), coord(rng));
      const Vec3 X = map_point(m, c, xi);
      const auto found = fe::locate_point(m, X);
      ASSERT_TRUE(found) << "cell " << c;
      EXPECT_EQ(found->cell, c);
      EXPECT_LT((found->xi - xi).norm(), 1e-12);
      EXPECT_LT((map_point(m, found->cell, found->xi) - X).norm(), 1e-12);
    }
}

TEST(PointLocation, PointsOnNodesSnapAndPointsOutsideAreNotFound) {
  const mesh::Mesh m = distorted_box();
  for (Index n = 0; n < m.num_nodes(); ++n) {
    const auto found = fe::locate_point(m, m.node(n));
    ASSERT_TRUE(found) << "node " << n;
    const fe::HexShape N = fe::hex8_shape(found->xi);
    int ones = 0;
    for (int a = 0; a < 8; ++a)
      ones += N[a] == 1.0 && m.cell(found->cell)[a] == n;
    EXPECT_EQ(ones, 1) << "node " << n << " is not exactly a node of its cell";
  }
  for (const Vec3& X : {Vec3(-1e-3, 1.0, 1.0), Vec3(3.001, 1.0, 1.0), Vec3(1.5, 1.0, 2.01),
                        Vec3(100.0, -50.0, 7.0)})
    EXPECT_FALSE(fe::locate_point(m, X)) << X.transpose();
}

/// A random point of the reference domain of `type`, off its boundary.
Vec3 random_xi(mesh::CellType type, std::mt19937& rng) {
  std::uniform_real_distribution<Real> unit(0.02, 0.96);
  for (;;) {
    const Vec3 r(unit(rng), unit(rng), unit(rng));
    switch (type) {
    case mesh::CellType::Tet4:
    case mesh::CellType::Tet10:
      if (r.sum() < 0.96)
        return r;
      break;
    case mesh::CellType::Penta6:
      if (r[0] + r[1] < 0.96)
        return {r[0], r[1], 2.0 * r[2] - 1.0};
      break;
    default:
      return 2.0 * r - Vec3::Ones();
    }
  }
}

class PointLocationFamilies : public ::testing::TestWithParam<mesh::CellType> {};

// The distorted box made of each family (quadratic cells with their mid-edge nodes at the
// midpoints of the distorted edges): points mapped from random natural coordinates are found in
// their cell at those coordinates, and every node is found as exactly a node of its cell.
TEST_P(PointLocationFamilies, RecoversNaturalCoordinatesAndNodes) {
  const mesh::Mesh m = mesh::convert_cells(distorted_box(), GetParam());
  const fe::ReferenceCell& ref = fe::reference_cell(GetParam());
  auto map = [&](Index c, const Vec3& xi) {
    const fe::ShapeValues N = ref.shape(xi);
    Vec3 x = Vec3::Zero();
    for (Index a = 0; a < N.size(); ++a)
      x += N[a] * m.node(m.cell_nodes(c)[static_cast<std::size_t>(a)]);
    return x;
  };
  std::mt19937 rng(5);
  for (Index c = 0; c < m.num_cells(); c += 3) {
    const Vec3 xi = random_xi(GetParam(), rng);
    const auto found = fe::locate_point(m, map(c, xi));
    ASSERT_TRUE(found) << "cell " << c;
    EXPECT_EQ(found->cell, c);
    EXPECT_LT((found->xi - xi).norm(), 1e-12);
  }
  for (Index n = 0; n < m.num_nodes(); ++n) {
    const auto found = fe::locate_point(m, m.node(n));
    ASSERT_TRUE(found) << "node " << n;
    const fe::ShapeValues N = ref.shape(found->xi);
    int ones = 0;
    for (Index a = 0; a < N.size(); ++a)
      ones += N[a] == 1.0 && m.cell_nodes(found->cell)[static_cast<std::size_t>(a)] == n;
    EXPECT_EQ(ones, 1) << "node " << n << " is not exactly a node of its cell";
  }
  EXPECT_FALSE(fe::locate_point(m, Vec3(3.001, 1.0, 1.0)));
}

INSTANTIATE_TEST_SUITE_P(Cells, PointLocationFamilies,
                         ::testing::Values(mesh::CellType::Tet4, mesh::CellType::Tet10,
                                           mesh::CellType::Penta6, mesh::CellType::Hex20),
                         [](const auto& info) { return std::string(mesh::name(info.param)); });

} // namespace
