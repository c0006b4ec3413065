// SPDX-License-Identifier: MIT
// Tests of the Gmsh MSH writer: what read_gmsh reads back is the mesh written.
#include "trifem/core/error.hpp"
#include "trifem/mesh/box.hpp"
#include "trifem/mesh/convert_cells.hpp"
#include "trifem/mesh/gmsh_reader.hpp"
#include "trifem/mesh/gmsh_writer.hpp"
#include "trifem/mesh/hex_faces.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

using trifem::Index;
using trifem::InputError;
using trifem::Vec3;
using trifem::mesh::Facet;
using trifem::mesh::Mesh;

/// A file name of the test's temporary directory, unique per process.
std::filesystem::path temp_path(const std::string& name) {
  return std::filesystem::path(testing::TempDir()) /
         ("gmsh_writer_" + std::to_string(::getpid()) + "_" + name);
}

/// write_gmsh then read_gmsh.
Mesh round_trip(const Mesh& mesh, const std::string& name) {
  const auto file = temp_path(name);
  trifem::mesh::write_gmsh(mesh, file);
  Mesh read = trifem::mesh::read_gmsh(file);
  std::filesystem::remove(file);
  return read;
}

bool same_bits(const Vec3& a, const Vec3& b) {
  return std::memcmp(a.data(), b.data(), sizeof(double) * 3) == 0;
}

bool same_facet(const Facet& a, const Facet& b) {
  return a.nodes == b.nodes && a.cell == b.cell && a.local_face == b.local_face &&
         a.type == b.type && a.mid_edge_nodes == b.mid_edge_nodes;
}

/// Everything of `a` is in `b` identically; `b` may have a node set for each cell block
/// (read_gmsh adds the nodes of each block under its name).
void expect_same_mesh(const Mesh& a, const Mesh& b) {
  ASSERT_EQ(a.num_nodes(), b.num_nodes());
  for (Index i = 0; i < a.num_nodes(); ++i)
    EXPECT_TRUE(same_bits(a.node(i), b.node(i))) << "node " << i;
  ASSERT_EQ(a.num_cells(), b.num_cells());
  for (Index c = 0; c < a.num_cells(); ++c) {
    EXPECT_EQ(a.cell_type(c), b.cell_type(c)) << "cell " << c;
    EXPECT_TRUE(std::ranges::equal(a.cell_nodes(c), b.cell_nodes(c))) << "cell " << c;
  }
  EXPECT_EQ(a.cell_blocks(), b.cell_blocks());
  ASSERT_EQ(a.surfaces().size(), b.surfaces().size());
  for (const auto& [name, surface] : a.surfaces()) {
    ASSERT_TRUE(b.has_surface(name)) << name;
    const auto& facets = b.surface(name).facets;
    ASSERT_EQ(surface.facets.size(), facets.size()) << name;
    for (std::size_t i = 0; i < facets.size(); ++i)
      EXPECT_TRUE(same_facet(surface.facets[i], facets[i])) << name << " facet " << i;
  }
  for (const auto& [name, nodes] : a.node_sets()) {
    ASSERT_TRUE(b.has_node_set(name)) << name;
    EXPECT_EQ(nodes, b.node_set(name)) << name;
  }
  for (const auto& [name, nodes] : b.node_sets())
    EXPECT_TRUE(a.has_node_set(name) || a.has_cell_block(name)) << "extra node set " << name;
}

/// A 3 x 2 x 2 box with coordinates that are not short decimals, two overlapping cell blocks,
/// an interior surface oriented out of the higher cells, and node sets sharing nodes.
Mesh test_mesh() {
  trifem::mesh::BoxSpec spec;
  spec.name = "tissue";
  spec.size = Vec3(1.0 / 3.0, 0.7, 2.0 / 7.0);
  spec.origin = Vec3(-0.1, 1e-17, std::sqrt(2.0));
  spec.divisions = {3, 2, 2};
  spec.grading = Vec3(1.3, 1.0, 0.77);
  Mesh mesh = trifem::mesh::make_box(spec);
  mesh.add_cell_block("lower", {0, 1, 2, 3, 4, 5});
  mesh.add_cell_block("mid", {3, 4, 5, 6, 7});
  // faces z = const between the layers, oriented out of the upper cells (face 4: zmin)
  trifem::mesh::Surface interface;
  for (Index c = 6; c < 12; ++c)
    interface.facets.push_back(
        {{mesh.cell(c)[trifem::mesh::kHexFaces[4][0]], mesh.cell(c)[trifem::mesh::kHexFaces[4][1]],
          mesh.cell(c)[trifem::mesh::kHexFaces[4][2]], mesh.cell(c)[trifem::mesh::kHexFaces[4][3]]},
         c,
         4});
  mesh.add_surface("interface (upper side)", interface);
  mesh.add_node_set("corner", {0});
  mesh.add_node_set("edge", {0, 1, 2, 3});
  return mesh;
}

TEST(GmshWriter, RoundTripIsTheSameMesh) {
  const Mesh mesh = test_mesh();
  const Mesh read = round_trip(mesh, "round_trip.msh");
  expect_same_mesh(mesh, read);
  EXPECT_TRUE(read.has_node_set("lower")); // added by the reader for the block
}

// Boxes of tet4, tet10, penta6 and hex20 cells: the cells, and the surfaces' tri3, tri6, quad4
// and quad8 facets with their cells, faces and mid-edge nodes, read back as written (a wedge
// box's side faces are quads and its bottom and top triangles: one element block each, so
// that the facets of such a surface come back grouped by type).
TEST(GmshWriter, RoundTripOfEveryCellFamily) {
  for (const trifem::mesh::CellType type :
       {trifem::mesh::CellType::Tet4, trifem::mesh::CellType::Tet10, trifem::mesh::CellType::Penta6,
        trifem::mesh::CellType::Hex20}) {
    trifem::mesh::BoxSpec spec;
    spec.divisions = {2, 1, 2};
    const Mesh mesh = trifem::mesh::convert_cells(trifem::mesh::make_box(spec), type);
    const Mesh read = round_trip(mesh, "family.msh");
    ASSERT_EQ(mesh.num_cells(), read.num_cells());
    for (Index c = 0; c < mesh.num_cells(); ++c) {
      EXPECT_EQ(mesh.cell_type(c), read.cell_type(c));
      EXPECT_TRUE(std::ranges::equal(mesh.cell_nodes(c), read.cell_nodes(c)));
    }
    for (const auto& [name, surface] : mesh.surfaces()) {
      const auto& facets = read.surface(name).facets;
      ASSERT_EQ(surface.facets.size(), facets.size()) << name;
      for (const Facet& f : surface.facets)
        EXPECT_TRUE(std::any_of(facets.begin(), facets.end(),
                                [&](const Facet& g) { return same_facet(f, g); }))
            << trifem::mesh::name(type) << " " << name;
    }
  }
}

TEST(GmshWriter, InteriorFacetsKeepTheirSide) {
  const Mesh read = round_trip(test_mesh(), "interior.msh");
  for (const Facet& f : read.surface("interface (upper side)").facets)
    EXPECT_GE(f.cell, 6);
}

TEST(GmshWriter, WrittenTwiceIsTheSameText) {
  const Mesh mesh = test_mesh();
  const auto a = temp_path("a.msh"), b = temp_path("b.msh");
  trifem::mesh::write_gmsh(mesh, a);
  trifem::mesh::write_gmsh(trifem::mesh::read_gmsh(a), b);
  std::ifstream fa(a), fb(b);
  const std::string ta((std::istreambuf_iterator<char>(fa)), std::istreambuf_iterator<char>());
  const std::string tb((std::istreambuf_iterator<char>(fb)), std::istreambuf_iterator<char>());
  EXPECT_EQ(ta, tb);
  std::filesystem::remove(a);
  std::filesystem::remove(b);
}

TEST(GmshWriter, RefusesACellInNoBlock) {
  Mesh mesh;
  for (int k = 0; k < 8; ++k)
    mesh.add_node(Vec3(trifem::mesh::kHexNodeCoords[k][0], trifem::mesh::kHexNodeCoords[k][1],
                       trifem::mesh::kHexNodeCoords[k][2]));
  mesh.add_cell({0, 1, 2, 3, 4, 5, 6, 7});
  std::ostringstream out;
  try {
    trifem::mesh::write_gmsh(mesh, out);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cell 0 is in no cell block"), std::string::npos)
        << e.what();
  }
}

TEST(GmshWriter, RefusesANameWithSurroundingBlanks) {
  Mesh mesh = test_mesh();
  mesh.add_node_set(" padded", {1});
  std::ostringstream out;
  EXPECT_THROW(trifem::mesh::write_gmsh(mesh, out), InputError);
}

} // namespace
