// SPDX-License-Identifier: MIT
// Tests of the per-cell data of a mesh: Gmsh $ElementData views (MSH 2.2 and 4.1), their errors,
// and the cell data carried through Mesh::append.
#include "trifem/core/error.hpp"
#include "trifem/mesh/box.hpp"
#include "trifem/mesh/gmsh_reader.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

using trifem::Index;
using trifem::InputError;
using trifem::Real;
using trifem::mesh::CellData;
using trifem::mesh::Mesh;
using trifem::mesh::read_gmsh;

/// The text of a data file of the mesh tests.
std::string data_text(const std::string& name) {
  std::ifstream in(std::filesystem::path(TRIFEM_TEST_DATA_DIR) / name);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// Number of lines of a text that ends with a newline.
int line_count(const std::string& text) {
  return static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

/// A file of the temporary directory, unique per process (ctest runs the tests of one binary
/// in parallel processes), removed at the end of its scope.
struct TempFile {
  std::filesystem::path path;
  TempFile(const std::string& name, const std::string& text)
      : path(std::filesystem::temp_directory_path() /
             ("trifem_element_data_" + std::to_string(getpid()) + "_" + name)) {
    std::ofstream(path) << text;
  }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  ~TempFile() { std::filesystem::remove(path); }
};

/// An $ElementData section of view `name` with `components` values per line `lines`.
std::string element_data(const std::string& name, int components, const std::string& lines) {
  const int count = line_count(lines);
  return "$ElementData\n1\n\"" + name + "\"\n1\n0.0\n3\n0\n" + std::to_string(components) + "\n" +
         std::to_string(count) + "\n" + lines + "$EndElementData\n";
}

/// The fibre view of the two-hex files: hex elements 1 and 2 (cells 0 and 1) and the quad
/// element 3 of the physical surface "top" (ignored).
const std::string kFibreLines = "2 0 1 0\n3 9 9 9\n1 0.6 0.8 0\n";

/// Element 2 only (cell 1): cell 0 has no value.
const std::string kAngleLines = "2 30\n";

void check_views(const Mesh& mesh) {
  ASSERT_EQ(mesh.cell_data().size(), 2u);
  const CellData& fibre = mesh.cell_data("fibre");
  EXPECT_EQ(fibre.components, 3);
  ASSERT_EQ(fibre.values.size(), 6u);
  EXPECT_EQ(fibre.values, (std::vector<Real>{0.6, 0.8, 0, 0, 1, 0}));
  EXPECT_TRUE(fibre.covers(0));
  EXPECT_TRUE(fibre.covers(1));
  const CellData& angle = mesh.cell_data("angle");
  EXPECT_EQ(angle.components, 1);
  EXPECT_FALSE(angle.covers(0));
  EXPECT_TRUE(std::isnan(angle.value(0, 0)));
  EXPECT_TRUE(angle.covers(1));
  EXPECT_EQ(angle.value(1, 0), 30.0);
}

TEST(GmshElementData, ReadFromFormat22) {
  const std::string text = data_text("two_hex_v22.msh") + element_data("fibre", 3, kFibreLines) +
                           element_data("angle", 1, kAngleLines);
  check_views(read_gmsh(TempFile("v22.msh", text).path));
}

TEST(GmshElementData, ReadFromFormat41) {
  // before $Nodes and $Elements: the element tags are resolved at the end of the file
  std::string text = data_text("two_hex_v41.msh");
  const std::string sections =
      element_data("angle", 1, kAngleLines) + element_data("fibre", 3, kFibreLines);
  text.insert(text.find("$Nodes"), sections);
  check_views(read_gmsh(TempFile("v41.msh", text).path));
}

TEST(GmshElementData, SectionsOfOneViewAreJoined) {
  // a view split over two sections (as Gmsh writes partitions), with a 4th integer tag
  const std::string second =
      "$ElementData\n1\n\"fibre\"\n1\n0.0\n4\n0\n3\n1\n1\n1 0.6 0.8 0\n$EndElementData\n";
  const std::string text = data_text("two_hex_v22.msh") + element_data("fibre", 3, "2 0 1 0\n") +
                           second + element_data("angle", 1, kAngleLines);
  check_views(read_gmsh(TempFile("joined.msh", text).path));
}

TEST(GmshElementData, NoElementDataNoCellData) {
  EXPECT_TRUE(read_gmsh(std::filesystem::path(TRIFEM_TEST_DATA_DIR) / "two_hex_v22.msh")
                  .cell_data()
                  .empty());
}

TEST(MeshCellData, CarriedThroughAppend) {
  const std::string text = data_text("two_hex_v22.msh") + element_data("fibre", 3, kFibreLines);
  const Mesh gmsh = read_gmsh(TempFile("append.msh", text).path);
  trifem::mesh::BoxSpec spec;
  spec.name = "box";
  spec.divisions = {3, 1, 1};
  Mesh mesh = trifem::mesh::make_box(spec); // cells 0-2: no data
  mesh.append(gmsh);                        // cells 3-4
  spec.name = "box2";
  mesh.append(trifem::mesh::make_box(spec)); // cells 5-7: no data
  Mesh view_only;                            // one cell with the view alone
  for (int k = 0; k < 8; ++k)
    view_only.add_node(mesh.node(mesh.cell(0)[k]));
  view_only.add_cell({0, 1, 2, 3, 4, 5, 6, 7});
  view_only.add_cell_data("fibre", CellData{.components = 3, .values = {0, 0, 1}});
  mesh.append(view_only);                  // cell 8
  mesh.add_cell({0, 1, 2, 3, 4, 5, 6, 7}); // cell 9: added later, no data

  ASSERT_EQ(mesh.num_cells(), 10);
  const CellData& fibre = mesh.cell_data("fibre");
  ASSERT_EQ(fibre.values.size(), 30u);
  for (Index c : {0, 1, 2, 5, 6, 7, 9})
    EXPECT_FALSE(fibre.covers(c)) << "cell " << c;
  EXPECT_EQ(fibre.value(3, 0), 0.6);
  EXPECT_EQ(fibre.value(3, 1), 0.8);
  EXPECT_EQ(fibre.value(4, 1), 1.0);
  EXPECT_EQ(fibre.value(8, 2), 1.0);
  EXPECT_EQ(fibre.value(8, 0), 0.0);
}

TEST(MeshCellData, Errors) {
  Mesh mesh = trifem::mesh::make_box(trifem::mesh::BoxSpec{});
  EXPECT_THROW(mesh.add_cell_data("f", CellData{.components = 3, .values = {1, 0}}), InputError);
  EXPECT_THROW(mesh.add_cell_data("f", CellData{.components = 0, .values = {}}), InputError);
  mesh.add_cell_data("f", CellData{.components = 3, .values = {1, 0, 0}});
  EXPECT_THROW(mesh.add_cell_data("f", CellData{.components = 3, .values = {1, 0, 0}}), InputError);
  try {
    mesh.cell_data("fibre");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'fibre' (available: f)"), std::string::npos) << e.what();
  }
  Mesh other;
  for (int k = 0; k < 8; ++k)
    other.add_node(mesh.node(k));
  other.add_cell({0, 1, 2, 3, 4, 5, 6, 7});
  other.add_cell_data("f", CellData{.components = 1, .values = {1}});
  EXPECT_THROW(mesh.append(other), InputError);
}

/// Expects read_gmsh of the two-hex 2.2 file followed by `sections` to throw InputError starting
/// with "<file>:<line>: " (line counted from the first line of `sections`) and containing
/// `phrase`.
void expect_error(const std::string& sections, int line, const std::string& phrase) {
  const std::string base = data_text("two_hex_v22.msh");
  const TempFile temp("error.msh", base + sections);
  const std::filesystem::path& file = temp.path;
  std::string message;
  try {
    read_gmsh(file);
  } catch (const InputError& e) {
    message = e.what();
  }
  SCOPED_TRACE(message);
  const std::string prefix = file.string() + ":" + std::to_string(line_count(base) + line) + ": ";
  EXPECT_EQ(message.rfind(prefix, 0), 0u) << "expected prefix " << prefix;
  EXPECT_NE(message.find(phrase), std::string::npos) << "expected phrase " << phrase;
}

TEST(GmshElementDataErrors, UnknownElementTag) {
  expect_error(element_data("fibre", 3, "1 1 0 0\n42 1 0 0\n"), 11,
               "view 'fibre' gives a value to element 42, which is not in $Elements");
}

TEST(GmshElementDataErrors, TooFewValues) {
  expect_error(element_data("fibre", 3, "1 1 0\n"), 10,
               "expected value 3 of 3 of view 'fibre' (its number of components), found the end "
               "of the line");
}

TEST(GmshElementDataErrors, TooManyValues) {
  expect_error(element_data("fibre", 3, "1 1 0 0 0\n"), 10,
               "element 1 has more than 3 values in view 'fibre'");
}

TEST(GmshElementDataErrors, NonFiniteValue) {
  expect_error(element_data("fibre", 3, "1 1 nan 0\n"), 10, "non-finite value in view 'fibre'");
}

TEST(GmshElementDataErrors, SecondValueOfAnElement) {
  expect_error(element_data("fibre", 3, "1 1 0 0\n2 1 0 0\n1 0 1 0\n"), 12,
               "view 'fibre' gives element 1 a second value (first at line " +
                   std::to_string(line_count(data_text("two_hex_v22.msh")) + 10) + ")");
}

TEST(GmshElementDataErrors, MalformedHeader) {
  expect_error("$ElementData\n0\n1\n0.0\n3\n0\n3\n0\n$EndElementData\n", 2,
               "$ElementData needs a string tag (the view name)");
  expect_error("$ElementData\n1\n\"fibre\"\n1\n0.0\n2\n0\n3\n$EndElementData\n", 6,
               "$ElementData needs 3 integer tags");
  expect_error("$ElementData\n1\n\"fibre\"\n1\n0.0\n3\n0\n0\n1\n$EndElementData\n", 8,
               "invalid number of components 0");
  expect_error("$ElementData\n1\n\"fibre\"\nx\n", 4, "expected number of real tags, found 'x'");
}

TEST(GmshElementDataErrors, MoreLinesThanDeclaredOrTruncated) {
  expect_error("$ElementData\n1\n\"fibre\"\n1\n0.0\n3\n0\n3\n1\n1 1 0 0\n2 1 0 0\n"
               "$EndElementData\n",
               11, "expected $EndElementData, found '2 1 0 0'");
  expect_error("$ElementData\n1\n\"fibre\"\n1\n0.0\n3\n0\n3\n2\n1 1 0 0\n$EndElementData\n", 11,
               "section $ElementData is truncated");
}

TEST(GmshElementDataErrors, ComponentsDifferBetweenSectionsOfOneView) {
  expect_error(element_data("fibre", 3, "1 1 0 0\n") + element_data("fibre", 1, "2 1\n"), 20,
               "view 'fibre' has 1 components here but 3 in its section at line");
}

} // namespace

// Cells read from a Gmsh file keep their element tags for messages, through Mesh::append; cells
// of a box are named by their index.
TEST(MeshCellSources, ElementTagsOfTheFileNameItsCellsThroughAppend) {
  const std::filesystem::path file = std::filesystem::path(TRIFEM_TEST_DATA_DIR) / "two_hex_v22.msh";
  const Mesh gmsh = read_gmsh(file);
  trifem::mesh::BoxSpec spec;
  spec.name = "box";
  spec.divisions = {3, 1, 1};
  Mesh mesh = trifem::mesh::make_box(spec); // cells 0-2
  mesh.append(gmsh);                        // cells 3-4
  EXPECT_EQ(mesh.describe(1), "cell 1");
  EXPECT_EQ(mesh.cell_origin(1), "");
  EXPECT_EQ(mesh.describe(3), gmsh.describe(0));
  EXPECT_EQ(mesh.describe(4), gmsh.describe(1));
  // the hexahedra are the file's elements 1 and 2
  EXPECT_EQ(gmsh.describe(0), fmt::format("element 1 of '{}'", file.string()));
  EXPECT_EQ(gmsh.describe(1), fmt::format("element 2 of '{}'", file.string()));
}
