// SPDX-License-Identifier: MIT
// Tests of the Gmsh MSH reader on small hand-written files.
#include "trifem/core/error.hpp"
#include "trifem/mesh/gmsh_reader.hpp"
#include "trifem/mesh/hex_faces.hpp"

#include <gtest/gtest.h>

#include <sys/resource.h>

#include <filesystem>
#include <fstream>
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

/// Writes `text` to a file of the temporary directory and returns its path.
std::filesystem::path temp_file(const std::string& name, const std::string& text) {
  const auto file = std::filesystem::temp_directory_path() / name;
  std::ofstream(file) << text;
  return file;
}

/// The content of two_hex_v41.msh with `from` replaced by `to` (first occurrence).
std::string two_hex_v41_with(const std::string& from, const std::string& to) {
  std::ifstream in(data("two_hex_v41.msh"));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  text.replace(text.find(from), from.size(), to);
  return text;
}

/// Peak resident memory of this process [kB].
long peak_memory_kb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
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
void expect_file_error(const std::string& file, int line, const std::string& phrase) {
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
  // the physical volume gives the node set of its cells' nodes
  std::vector<Index> every(12);
  for (Index n = 0; n < 12; ++n)
    every[n] = n;
  EXPECT_EQ(mesh.node_set("cartilage"), every);
  EXPECT_EQ(mesh.node_sets().size(), 4u);
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
  ASSERT_EQ(a.num_cells(), b.num_cells());
  for (Index c = 0; c < a.num_cells(); ++c) {
    EXPECT_EQ(a.cell_type(c), b.cell_type(c)) << "cell " << c;
    EXPECT_TRUE(std::ranges::equal(a.cell_nodes(c), b.cell_nodes(c))) << "cell " << c;
  }
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
  ASSERT_EQ(mesh.node_sets().size(), 1u);
  EXPECT_EQ(mesh.node_set("volume").size(), 12u);
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
  expect_file_error("empty.msh", 1, "empty file");
}

TEST(GmshReaderErrors, BinaryFile) {
  expect_file_error("binary.msh", 2, "binary");
}

TEST(GmshReaderErrors, UnsupportedVersion) {
  expect_file_error("bad_version.msh", 2, "unsupported MSH format version '3.0'");
}

TEST(GmshReaderErrors, TruncatedNodeBlock) {
  expect_file_error("truncated_nodes.msh", 14, "section $Nodes is truncated");
}

TEST(GmshReaderErrors, TruncatedAtEndOfFile) {
  expect_file_error("truncated_eof.msh", 17, "section $Elements is truncated");
}

TEST(GmshReaderErrors, UndefinedNodeTag) {
  expect_file_error("undefined_node.msh", 27, "node tag 99, which is not defined");
}

TEST(GmshReaderErrors, QuadThatIsNoHexFaceAmongFaces) {
  expect_file_error("quad_not_face.msh", 24,
                    "element 3 of physical surface 'diagonal' is not a face");
}

TEST(GmshReaderErrors, InvertedHex) {
  expect_file_error("inverted_hex.msh", 17, "hex8 element 42 has negative volume");
}

TEST(GmshReaderErrors, PyramidIsUnsupported) {
  expect_file_error("pyramid.msh", 18, "unsupported element type 7 (pyramid5)");
}

TEST(GmshReaderErrors, TriangleAmongHexFaces) {
  expect_file_error("triangle_among_faces.msh", 24,
                    "element 3 of physical surface 'diagonal' is not a face");
}

// A count of 2e9 nodes declared for 12 and a tag of 1e9 used to size a table of 1e9 entries
// (4 GB) before the count was found wrong.
TEST(GmshReaderErrors, WrongNodeCountAndHugeTagDoNotExhaustMemory) {
  const std::string text = two_hex_v41_with("\n5000000\n", "\n1000000000\n");
  const std::string header = "2 12 1 5000000";
  std::string wrong = text;
  wrong.replace(wrong.find(header), header.size(), "2 2000000000 1 5000000");
  const auto file = temp_file("trifem_gmsh_wrong_count.msh", wrong);
  const long before = peak_memory_kb();
  try {
    read_gmsh(file);
    ADD_FAILURE() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("$Nodes declares 2000000000 nodes but its blocks hold 12"),
              std::string::npos)
        << e.what();
  }
  EXPECT_LT(peak_memory_kb() - before, 100'000) << "the node tags took more than 100 MB";
  std::filesystem::remove(file);
}

// A tag first stored among the large (hashed) tags is still found as a duplicate once the dense
// table has grown past it.
TEST(GmshReaderErrors, DuplicateTagAcrossTheDenseAndHashedRanges) {
  std::string text = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n601\n1100 0 0 0\n";
  for (int tag = 1; tag <= 599; ++tag)
    text += std::to_string(tag) + " " + std::to_string(tag) + " 0 0\n";
  text += "1100 1 1 1\n$EndNodes\n";
  const auto file = temp_file("trifem_gmsh_duplicate_tag.msh", text);
  try {
    read_gmsh(file);
    ADD_FAILURE() << "expected an error";
  } catch (const InputError& e) {
    const std::string prefix = file.string() + ":606: ";
    EXPECT_EQ(std::string(e.what()).rfind(prefix, 0), 0u) << e.what();
    EXPECT_NE(std::string(e.what()).find("node tag 1100 is defined twice"), std::string::npos)
        << e.what();
  }
  std::filesystem::remove(file);
}

} // namespace

// A physical surface none of whose quads is a hex face is a surface mesh (e.g. a rigid bone
// surface): its facets keep their node order (the normal) and bound no cell.
TEST(GmshReader, ASurfaceMeshThatBoundsNoCellKeepsItsQuads) {
  const Mesh mesh = read_gmsh(data("free_surface.msh"));
  EXPECT_EQ(mesh.num_nodes(), 12);
  EXPECT_EQ(mesh.num_cells(), 1);
  const trifem::mesh::Surface& plate = mesh.surface("plate");
  ASSERT_EQ(plate.facets.size(), 1u);
  const Facet& f = plate.facets[0];
  EXPECT_FALSE(f.bounds_cell());
  EXPECT_EQ(f.nodes, (std::array<Index, 4>{8, 11, 10, 9}));
  // the normal of the node order 9, 12, 11, 10 points down, towards the block
  EXPECT_LT(facet_normal(mesh, f).z(), 0.0);
  EXPECT_EQ(mesh.node_set("plate").size(), 4u);
}

// Triangles of a surface mesh are quads whose last node repeats the third.
TEST(GmshReader, ATriangulatedSurfaceMeshKeepsItsTriangles) {
  const Mesh mesh = read_gmsh(data("free_triangles.msh"));
  const trifem::mesh::Surface& plate = mesh.surface("plate");
  ASSERT_EQ(plate.facets.size(), 2u);
  EXPECT_EQ(plate.facets[0].nodes, (std::array<Index, 4>{8, 11, 10, 10}));
  EXPECT_EQ(plate.facets[1].nodes, (std::array<Index, 4>{8, 10, 9, 9}));
  EXPECT_FALSE(plate.facets[1].bounds_cell());
  EXPECT_EQ(mesh.node_set("plate").size(), 4u);
}
