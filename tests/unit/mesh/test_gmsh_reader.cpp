// SPDX-License-Identifier: MIT
// Tests of the Gmsh MSH reader on small hand-written files.
#include "trifem/core/error.hpp"
#include "trifem/mesh/gmsh_reader.hpp"
#include "trifem/mesh/hex_faces.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace {

using trifem::Index;
using trifem::InputError;
using trifem::Vec3;
using trifem::mesh::Facet;
using trifem::mesh::Mesh;
using trifem::mesh::read_gmsh;

std::filesystem::path data(const std::string& name) {
  return std::filesystem::path(TRIFEM_TEST_DATA_DIR) / name;
}

/// Message of the InputError thrown by read_gmsh(file), or "" if none is thrown.
std::string read_error(const std::string& file) {
  try {
    read_gmsh(data(file));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

/// Expects read_gmsh(file) to throw InputError starting with "<file>:<line>: " and containing
/// `phrase`.
void expect_error(const std::string& file, int line, const std::string& phrase) {
  const std::string message = read_error(file);
  SCOPED_TRACE(message);
  const std::string prefix = data(file).string() + ":" + std::to_string(line) + ": ";
  EXPECT_EQ(message.rfind(prefix, 0), 0u) << "expected prefix " << prefix;
  EXPECT_NE(message.find(phrase), std::string::npos) << "expected phrase " << phrase;
}

/// Right-hand-rule normal (not normalised) of a facet: (x1 - x0) x (x2 - x1).
Vec3 facet_normal(const Mesh& mesh, const Facet& f) {
  const Vec3& x0 = mesh.node(f.nodes[0]);
  const Vec3& x1 = mesh.node(f.nodes[1]);
  const Vec3& x2 = mesh.node(f.nodes[2]);
  return (x1 - x0).cross(x2 - x1);
}

/// Expected contents of two_hex_v41.msh / two_hex_v22.msh (see the files): nodes with tags
/// 7..11, 5000000 (z = 1) then 1..6 (z = 0), two unit cubes side by side along x.
void check_two_hex(const Mesh& mesh) {
  ASSERT_EQ(mesh.num_nodes(), 12);
  ASSERT_EQ(mesh.num_cells(), 2);
  EXPECT_TRUE(mesh.node(5).isApprox(Vec3(2, 1, 1)));
  EXPECT_TRUE(mesh.node(6).isApprox(Vec3(0, 0, 0)));
  const trifem::mesh::Hex8 cell0{6, 7, 10, 9, 0, 1, 4, 3};
  const trifem::mesh::Hex8 cell1{7, 8, 11, 10, 1, 2, 5, 4};
  EXPECT_EQ(mesh.cell(0), cell0);
  EXPECT_EQ(mesh.cell(1), cell1);

  ASSERT_EQ(mesh.cell_blocks().size(), 1u);
  EXPECT_EQ(mesh.cell_block("cartilage"), (std::vector<Index>{0, 1}));

  ASSERT_EQ(mesh.surfaces().size(), 1u);
  const auto& top = mesh.surface("top");
  ASSERT_EQ(top.facets.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const Facet& f = top.facets[i];
    EXPECT_EQ(f.cell, static_cast<Index>(i));
    EXPECT_EQ(f.local_face, 1); // zeta = +1
    const Vec3 n = facet_normal(mesh, f);
    EXPECT_GT(n.z(), 0.0) << "facet " << i << " is not oriented outward";
    EXPECT_NEAR(n.normalized().z(), 1.0, 1e-12);
  }
  EXPECT_EQ(mesh.node_set("top"), (std::vector<Index>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(mesh.node_set("edge"), (std::vector<Index>{0, 1}));
  EXPECT_EQ(mesh.node_set("corner"), (std::vector<Index>{6}));
  EXPECT_EQ(mesh.node_sets().size(), 3u);
}

TEST(GmshReader, ReadsTwoHexFormat41) {
  const Mesh mesh = read_gmsh(data("two_hex_v41.msh"));
  check_two_hex(mesh);
}

TEST(GmshReader, ReadsTwoHexFormat22) {
  const Mesh mesh = read_gmsh(data("two_hex_v22.msh"));
  check_two_hex(mesh);
}

TEST(GmshReader, Formats41And22GiveTheSameMesh) {
  const Mesh a = read_gmsh(data("two_hex_v41.msh"));
  const Mesh b = read_gmsh(data("two_hex_v22.msh"));
  EXPECT_EQ(a.nodes(), b.nodes());
  EXPECT_EQ(a.cells(), b.cells());
  EXPECT_EQ(a.cell_blocks(), b.cell_blocks());
  EXPECT_EQ(a.node_sets(), b.node_sets());
  ASSERT_EQ(a.surfaces().size(), b.surfaces().size());
  for (const auto& [name, surface] : a.surfaces()) {
    const auto& other = b.surface(name).facets;
    ASSERT_EQ(surface.facets.size(), other.size());
    for (std::size_t i = 0; i < other.size(); ++i) {
      EXPECT_EQ(surface.facets[i].nodes, other[i].nodes);
      EXPECT_EQ(surface.facets[i].cell, other[i].cell);
      EXPECT_EQ(surface.facets[i].local_face, other[i].local_face);
    }
  }
}

TEST(GmshReader, WithoutPhysicalGroupsAllHexesGoToBlockVolume) {
  const Mesh mesh = read_gmsh(data("no_physical.msh"));
  EXPECT_EQ(mesh.num_nodes(), 12);
  EXPECT_EQ(mesh.num_cells(), 2);
  ASSERT_EQ(mesh.cell_blocks().size(), 1u);
  EXPECT_EQ(mesh.cell_block("volume"), (std::vector<Index>{0, 1}));
  EXPECT_TRUE(mesh.surfaces().empty());
  EXPECT_TRUE(mesh.node_sets().empty());
}

TEST(GmshReader, UnnamedGroupsAndUnassignedHexes) {
  const Mesh mesh = read_gmsh(data("unassigned.msh"));
  EXPECT_EQ(mesh.num_nodes(), 12);
  EXPECT_EQ(mesh.cell_blocks().size(), 2u);
  EXPECT_EQ(mesh.cell_block("volume_7"), (std::vector<Index>{0}));
  EXPECT_EQ(mesh.cell_block("unassigned"), (std::vector<Index>{1}));
  const auto& side = mesh.surface("surface_9");
  ASSERT_EQ(side.facets.size(), 1u);
  EXPECT_EQ(side.facets[0].cell, 0);
  const Vec3 n = facet_normal(mesh, side.facets[0]).normalized();
  EXPECT_NEAR(n.y(), -1.0, 1e-12);
  EXPECT_EQ(mesh.node_set("surface_9"), (std::vector<Index>{0, 1, 6, 7}));
}

TEST(GmshReaderErrors, MissingFile) {
  const std::string message = read_error("no_such_file.msh");
  EXPECT_NE(message.find("no_such_file.msh"), std::string::npos) << message;
  EXPECT_NE(message.find("cannot open"), std::string::npos) << message;
}

TEST(GmshReaderErrors, EmptyFile) {
  expect_error("empty.msh", 1, "empty file");
}

TEST(GmshReaderErrors, BinaryFile) {
  expect_error("binary.msh", 2, "binary");
}

TEST(GmshReaderErrors, UnsupportedVersion) {
  expect_error("bad_version.msh", 2, "unsupported MSH format version '3.0'");
}

TEST(GmshReaderErrors, TruncatedNodeBlock) {
  expect_error("truncated_nodes.msh", 14, "section $Nodes is truncated");
}

TEST(GmshReaderErrors, TruncatedAtEndOfFile) {
  expect_error("truncated_eof.msh", 17, "section $Elements is truncated");
}

TEST(GmshReaderErrors, UndefinedNodeTag) {
  expect_error("undefined_node.msh", 27, "node tag 99, which is not defined");
}

TEST(GmshReaderErrors, QuadThatIsNoHexFace) {
  expect_error("quad_not_face.msh", 23, "element 2 of physical surface 'diagonal' is not a face");
}

TEST(GmshReaderErrors, InvertedHex) {
  expect_error("inverted_hex.msh", 17, "hex8 element 42 has negative volume");
}

TEST(GmshReaderErrors, TetrahedronIsUnsupported) {
  expect_error("tetra.msh", 18, "unsupported element type 4 (tetra4)");
}

TEST(GmshReaderErrors, TriangleIsUnsupported) {
  expect_error("triangle.msh", 17, "unsupported element type 2 (triangle3)");
}

} // namespace
