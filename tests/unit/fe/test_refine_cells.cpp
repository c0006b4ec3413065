// SPDX-License-Identifier: MIT
// Uniform refinement of meshes of every cell family (fe::refine_uniformly): volumes and surface
// area vectors kept exactly (curved quadratic cells included: each child's map is the restriction
// of its parent's), nodes shared between neighbours (a conforming mesh: the boundary grows by four
// facets per facet), children oriented, named sets carried over, and hex8 meshes left to
// mesh::refine_uniformly bit for bit.
#include "trifem/core/error.hpp"
#include "trifem/fe/refine_cells.hpp"
#include "trifem/mesh/box.hpp"
#include "trifem/mesh/convert_cells.hpp"
#include "trifem/mesh/refine.hpp"

#include "cell_families.hpp"

#include <gtest/gtest.h>

#include <set>

namespace trifem {
namespace {

/// Volume of cell c by its family's rule, and its smallest Jacobian determinant at the points.
std::pair<Real, Real> cell_volume(const mesh::Mesh& m, Index c) {
  const fe::ReferenceCell& ref = fe::reference_cell(m.cell_type(c));
  const auto nodes = m.cell_nodes(c);
  Real volume = 0, smallest = std::numeric_limits<Real>::infinity();
  for (const auto& p : ref.rule().points) {
    const fe::ShapeGrads G = ref.shape_grad(p.xi);
    Mat3 J = Mat3::Zero();
    for (Index a = 0; a < G.rows(); ++a)
      J += m.node(nodes[static_cast<std::size_t>(a)]) * G.row(a);
    volume += J.determinant() * p.weight;
    smallest = std::min(smallest, J.determinant());
  }
  return {volume, smallest};
}

Real mesh_volume(const mesh::Mesh& m) {
  Real v = 0;
  for (Index c = 0; c < m.num_cells(); ++c)
    v += cell_volume(m, c).first;
  return v;
}

/// Area vector ∫ n da of a surface by each facet's rule (exact: a polynomial on every facet
/// type, while the area of a warped facet is not).
Vec3 area_vector(const mesh::Mesh& m, const std::vector<mesh::Facet>& facets) {
  Vec3 area = Vec3::Zero();
  for (const mesh::Facet& f : facets) {
    const fe::ReferenceFacet& ref = fe::reference_facet(f.type);
    for (const auto& p : ref.rule().points) {
      const fe::FacetShapeGrads G = ref.shape_grad(p.xi);
      Vec3 t1 = Vec3::Zero(), t2 = Vec3::Zero();
      for (int a = 0; a < f.num_nodes(); ++a) {
        t1 += m.node(f.node(a)) * G(a, 0);
        t2 += m.node(f.node(a)) * G(a, 1);
      }
      area += t1.cross(t2) * p.weight;
    }
  }
  return area;
}

/// A 2 x 2 x 1 box of `type` cells with every node moved at random by up to `noise` (mid-edge
/// nodes too: curved quadratic cells), a cell block, cell data and a node set of the nodes on
/// its face x = 0.
mesh::Mesh distorted_block(mesh::CellType type, Real amplitude = 0.04) {
  mesh::BoxSpec spec;
  spec.name = "b";
  spec.divisions = {2, 2, 1};
  mesh::Mesh m = mesh::convert_cells(mesh::make_box(spec), type);
  std::vector<Index> face;
  for (Index n = 0; n < m.num_nodes(); ++n)
    if (m.node(n)[0] == 0.0)
      face.push_back(n);
  test::Noise noise(7);
  std::vector<Vec3> moved = m.nodes();
  for (Vec3& x : moved)
    for (int k = 0; k < 3; ++k)
      x[k] += amplitude * noise.next();
  mesh::Mesh out;
  for (const Vec3& x : moved)
    out.add_node(x);
  for (Index c = 0; c < m.num_cells(); ++c)
    out.add_cell(m.cell_type(c), m.cell_nodes(c));
  for (const auto& [name, set] : m.node_sets())
    if (!m.has_surface(name))
      out.add_node_set(name, set);
  for (const auto& [name, s] : m.surfaces())
    out.add_surface(name, s);
  out.add_node_set("face", face);
  out.add_cell_block("first", {0});
  std::vector<double> values;
  for (Index c = 0; c < m.num_cells(); ++c)
    values.insert(values.end(), {static_cast<double>(c), -1.0});
  out.add_cell_data("tag", {.components = 2, .values = values});
  return out;
}

class RefineCells : public ::testing::TestWithParam<mesh::CellType> {};

TEST_P(RefineCells, KeepsVolumeSurfacesAndSetsAndSharesNodes) {
  const mesh::Mesh coarse = distorted_block(GetParam());
  const mesh::Mesh fine = fe::refine_uniformly(coarse);
  ASSERT_EQ(fine.num_cells(), 8 * coarse.num_cells());
  for (Index c = 0; c < fine.num_cells(); ++c) {
    EXPECT_EQ(fine.cell_type(c), GetParam());
    EXPECT_GT(cell_volume(fine, c).second, 0.0) << "child " << c << " is inverted";
  }
  // the same region, to round-off (each child's map is its parent's on the child's part)
  const Real volume = mesh_volume(coarse);
  EXPECT_NEAR(mesh_volume(fine), volume, 1e-13 * volume);
  // conforming: the boundary is the coarse one, in four facets per facet
  EXPECT_EQ(fine.boundary_facets().size(), 4 * coarse.boundary_facets().size());
  // no two nodes at one place
  std::set<std::array<long long, 3>> places;
  for (const Vec3& x : fine.nodes())
    places.insert({std::llround(x[0] * 1e9), std::llround(x[1] * 1e9), std::llround(x[2] * 1e9)});
  EXPECT_EQ(static_cast<Index>(places.size()), fine.num_nodes());
  // surfaces: four facets per facet, the same area, their nodes in their node set
  for (const auto& [name, s] : coarse.surfaces()) {
    const mesh::Surface& f = fine.surface(name);
    EXPECT_EQ(f.facets.size(), 4 * s.facets.size()) << name;
    EXPECT_LE((area_vector(fine, f.facets) - area_vector(coarse, s.facets)).norm(), 1e-13) << name;
    EXPECT_EQ(fine.node_set(name).size(), mesh::surface_nodes(f).size()) << name;
  }
  // a node set of a face gains exactly the new nodes on that face (seen on the undistorted mesh)
  const mesh::Mesh straight = fe::refine_uniformly(distorted_block(GetParam(), 0.0));
  std::vector<Index> on_face;
  for (Index n = 0; n < straight.num_nodes(); ++n)
    if (std::abs(straight.node(n)[0]) < 1e-14)
      on_face.push_back(n);
  EXPECT_EQ(straight.node_set("face"), on_face);
  EXPECT_EQ(fine.node_set("face"), on_face); // the same numbering with distortion
  // cell blocks and data follow the children
  EXPECT_EQ(fine.cell_block("first"), (std::vector<Index>{0, 1, 2, 3, 4, 5, 6, 7}));
  EXPECT_EQ(fine.cell_data("tag").values[2 * 9], 1.0); // child 1 of cell 1
}

INSTANTIATE_TEST_SUITE_P(EveryFamily, RefineCells,
                         ::testing::Values(mesh::CellType::Tet4, mesh::CellType::Tet10,
                                           mesh::CellType::Penta6, mesh::CellType::Hex20),
                         [](const auto& info) { return std::string(mesh::name(info.param)); });

TEST(RefineCellsHex8, IsMeshRefineUniformlyBitForBit) {
  mesh::BoxSpec spec;
  spec.divisions = {2, 1, 3};
  const mesh::Mesh coarse = mesh::make_box(spec);
  const mesh::Mesh a = fe::refine_uniformly(coarse, 2), b = mesh::refine_uniformly(coarse, 2);
  ASSERT_EQ(a.num_nodes(), b.num_nodes());
  for (Index n = 0; n < a.num_nodes(); ++n)
    EXPECT_EQ(a.node(n), b.node(n));
  for (Index c = 0; c < a.num_cells(); ++c)
    EXPECT_TRUE(std::ranges::equal(a.cell_nodes(c), b.cell_nodes(c)));
}

TEST(RefineCellsTet4, AddsOneNodePerEdge) {
  const mesh::Mesh coarse = distorted_block(mesh::CellType::Tet4);
  std::set<std::pair<Index, Index>> edges;
  for (Index c = 0; c < coarse.num_cells(); ++c) {
    const auto n = coarse.cell_nodes(c);
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        edges.emplace(std::min(n[i], n[j]), std::max(n[i], n[j]));
  }
  EXPECT_EQ(fe::refine_uniformly(coarse).num_nodes(),
            coarse.num_nodes() + static_cast<Index>(edges.size()));
  EXPECT_EQ(fe::refine_uniformly(coarse, 2).num_cells(), 64 * coarse.num_cells());
  EXPECT_THROW(fe::refine_uniformly(coarse, -1), InputError);
}

} // namespace
} // namespace trifem
