// SPDX-License-Identifier: MIT
// Meshes of tet4, tet10, penta6 and hex20 cells: boxes made of them (convert_cells) and the Gmsh
// reader on meshes made by Gmsh 4.8 from the .geo files in data/ (a unit cube with a physical
// volume and six physical faces):
//   gmsh -3 cube_tet.geo -format msh22 -o cube_tet4_v22.msh
//   gmsh -3 -order 2 cube_tet.geo -format msh41 -o cube_tet10_v41.msh
//   gmsh -3 cube_penta6.geo -format msh41 -o cube_penta6_v41.msh
//   gmsh -3 -order 2 cube_hex20.geo -format msh22 -o cube_hex20_v22.msh
#include "trifem/core/error.hpp"
#include "trifem/fe/reference_element.hpp"
#include "trifem/mesh/box.hpp"
#include "trifem/mesh/gmsh_reader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

namespace cell_families_test {

using namespace trifem;
using mesh::CellType;

std::filesystem::path data(const std::string& name) {
  return std::filesystem::path(TRIFEM_TEST_DATA_DIR) / name;
}

struct Family {
  const char* file;
  CellType type;
  Index cells; ///< as Gmsh wrote them
};

const Family kFamilies[] = {{"cube_tet4_v22.msh", CellType::Tet4, 100},
                            {"cube_tet10_v41.msh", CellType::Tet10, 100},
                            {"cube_penta6_v41.msh", CellType::Penta6, 28},
                            {"cube_hex20_v22.msh", CellType::Hex20, 8}};

/// ∫ dV over the cell by its family's rule.
Real cell_volume(const mesh::Mesh& m, Index c) {
  const fe::ReferenceCell& ref = fe::reference_cell(m.cell_type(c));
  const std::span<const Index> nodes = m.cell_nodes(c);
  fe::CellNodeCoords X(static_cast<Index>(nodes.size()), 3);
  for (std::size_t a = 0; a < nodes.size(); ++a)
    X.row(static_cast<Index>(a)) = m.node(nodes[a]).transpose();
  Real volume = 0.0;
  for (const fe::CellQuadraturePoint& p : ref.rule().points) {
    const Real det = (X.transpose() * ref.shape_grad(p.xi)).determinant();
    EXPECT_GT(det, 0.0) << "cell " << c;
    volume += det * p.weight;
  }
  return volume;
}

/// The sorted corners of every face of every cell, with the number of cells sharing it.
std::map<std::array<Index, 4>, int> face_counts(const mesh::Mesh& m) {
  std::map<std::array<Index, 4>, int> count;
  for (Index c = 0; c < m.num_cells(); ++c)
    for (const mesh::CellFace& face : mesh::cell_faces(m.cell_type(c))) {
      const bool triangle = mesh::num_nodes(face.type) % 3 == 0;
      std::array<Index, 4> key{-1, -1, -1, -1};
      for (int i = 0; i < (triangle ? 3 : 4); ++i)
        key[static_cast<std::size_t>(i)] = m.cell_nodes(c)[static_cast<std::size_t>(face.nodes[i])];
      std::sort(key.begin(), key.end());
      ++count[key];
    }
  return count;
}

/// Checks that the surface `name` of `m` covers the plane X_k = value of the unit cube: its
/// facets are faces of the cells of the family's facet types, their area vectors point out of
/// the cube and add up to its unit face, and its node set holds exactly the nodes on the plane.
void expect_face_surface(const mesh::Mesh& m, const std::string& name, int k, Real value,
                         const Vec3& outward) {
  SCOPED_TRACE(name);
  ASSERT_TRUE(m.has_surface(name));
  Vec3 area = Vec3::Zero();
  for (const mesh::Facet& f : m.surface(name).facets) {
    ASSERT_TRUE(f.bounds_cell());
    const mesh::CellFace& face =
        mesh::cell_faces(m.cell_type(f.cell))[static_cast<std::size_t>(f.local_face)];
    EXPECT_EQ(f.type, face.type);
    for (int i = 0; i < f.num_nodes(); ++i) {
      EXPECT_EQ(f.node(i), m.cell_nodes(f.cell)[static_cast<std::size_t>(face.nodes[i])]);
      EXPECT_NEAR(m.node(f.node(i))[k], value, 1e-12);
    }
    const Vec3 a = mesh::facet_area_vector(m, f);
    EXPECT_GT(a.dot(outward), 0.0);
    area += a;
  }
  EXPECT_NEAR((area - outward).norm(), 0.0, 1e-12);
  std::vector<Index> expected;
  for (Index n = 0; n < m.num_nodes(); ++n)
    if (std::abs(m.node(n)[k] - value) < 1e-12)
      expected.push_back(n);
  EXPECT_EQ(m.node_set(name), expected);
}

/// The six faces of a box of size `size` at the origin: name suffix, axis, value, normal.
void expect_box_faces(const mesh::Mesh& m, const std::string& prefix, const Vec3& size) {
  const char* sides[3][2] = {{"xmin", "xmax"}, {"ymin", "ymax"}, {"zmin", "zmax"}};
  for (int k = 0; k < 3; ++k)
    for (int side = 0; side < 2; ++side) {
      Vec3 outward = Vec3::Zero();
      outward[k] = (side == 0 ? -1.0 : 1.0) * size[(k + 1) % 3] * size[(k + 2) % 3];
      expect_face_surface(m, prefix + sides[k][side], k, side * size[k], outward);
    }
}

class BoxFamilies : public ::testing::TestWithParam<CellType> {};

// A 3 x 2 x 2 box of 2 x 1 x 1 mm made of each family: the cells fill its volume, every face
// inside is shared by exactly two cells (the splits conform) and those of one cell lie on the
// box's faces, whose surfaces are made of them and whose node sets hold the nodes on them.
TEST_P(BoxFamilies, CellsConformAndFillTheBox) {
  mesh::BoxSpec spec;
  spec.size = {2.0, 1.0, 1.0};
  spec.divisions = {3, 2, 2};
  spec.cell = GetParam();
  const mesh::Mesh m = mesh::make_box(spec);
  const Index per_hex = GetParam() == CellType::Tet4 || GetParam() == CellType::Tet10 ? 6
                        : GetParam() == CellType::Penta6                              ? 2
                                                                                      : 1;
  ASSERT_EQ(m.num_cells(), 12 * per_hex);
  Real volume = 0.0;
  for (Index c = 0; c < m.num_cells(); ++c) {
    EXPECT_EQ(m.cell_type(c), GetParam());
    volume += cell_volume(m, c);
  }
  EXPECT_NEAR(volume, 2.0, 1e-13);
  EXPECT_EQ(m.cell_block("box").size(), static_cast<std::size_t>(m.num_cells()));
  for (const auto& [key, count] : face_counts(m)) {
    ASSERT_LE(count, 2);
    if (count == 2)
      continue;
    bool on_a_face = false; // all corners on one plane of the box
    for (int k = 0; k < 3; ++k)
      for (Real plane : {0.0, spec.size[k]})
        on_a_face = on_a_face || std::all_of(key.begin(), key.end(), [&](Index n) {
                      return n < 0 || std::abs(m.node(n)[k] - plane) < 1e-12;
                    });
    EXPECT_TRUE(on_a_face);
  }
  const char* sides[3][2] = {
      {"box.xmin", "box.xmax"}, {"box.ymin", "box.ymax"}, {"box.zmin", "box.zmax"}};
  for (int k = 0; k < 3; ++k)
    for (int side = 0; side < 2; ++side) {
      std::vector<Index> expected;
      for (Index n = 0; n < m.num_nodes(); ++n)
        if (std::abs(m.node(n)[k] - side * spec.size[k]) < 1e-12)
          expected.push_back(n);
      EXPECT_EQ(m.node_set(sides[k][side]), expected) << sides[k][side];
    }
  expect_box_faces(m, "box.", spec.size);
  EXPECT_EQ(m.node_set("box.all").size(), static_cast<std::size_t>(m.num_nodes()));
}

INSTANTIATE_TEST_SUITE_P(Cells, BoxFamilies,
                         ::testing::Values(CellType::Tet4, CellType::Tet10, CellType::Penta6,
                                           CellType::Hex20, CellType::Hex8),
                         [](const auto& info) { return std::string(mesh::name(info.param)); });

class GmshFamilies : public ::testing::TestWithParam<Family> {};

TEST_P(GmshFamilies, CellsFillTheCubeWithPositiveVolume) {
  const Family& f = GetParam();
  const mesh::Mesh m = mesh::read_gmsh(data(f.file));
  ASSERT_EQ(m.num_cells(), f.cells);
  Real volume = 0.0;
  for (Index c = 0; c < m.num_cells(); ++c) {
    EXPECT_EQ(m.cell_type(c), f.type);
    volume += cell_volume(m, c);
  }
  EXPECT_NEAR(volume, 1.0, 1e-12); // the unit cube
  EXPECT_EQ(m.cell_block("cube").size(), static_cast<std::size_t>(f.cells));
  EXPECT_FALSE(m.all_hex8());
  EXPECT_EQ(m.first_non_hex8(), 0);
}

// The physical faces become surfaces of the cells' faces (tri3, tri6, quad4 or quad8 facets
// with their mid-edge nodes), oriented out of the cube, and node sets of the nodes on them.
TEST_P(GmshFamilies, PhysicalFacesAreOutwardSurfacesOfTheCellsFaces) {
  expect_box_faces(mesh::read_gmsh(data(GetParam().file)), "", Vec3::Ones());
}

INSTANTIATE_TEST_SUITE_P(Meshes, GmshFamilies, ::testing::ValuesIn(kFamilies),
                         [](const auto& info) { return std::string(mesh::name(info.param.type)); });

/// The text of `file` with the first element line of `type` (a 2.2 file) changed by `edit`.
std::filesystem::path edited(const std::string& file, const std::string& name,
                             void (*edit)(std::vector<std::string>&)) {
  std::ifstream in(data(file));
  std::stringstream out;
  std::string line;
  bool in_elements = false, done = false;
  while (std::getline(in, line)) {
    in_elements = line == "$Elements" || (in_elements && line != "$EndElements");
    std::istringstream words(line);
    std::vector<std::string> w;
    for (std::string s; words >> s;)
      w.push_back(s);
    if (in_elements && !done && w.size() > 3 && w[1] == "4") {
      edit(w);
      done = true;
      line.clear();
      for (const std::string& s : w)
        line += s + " ";
    }
    out << line << "\n";
  }
  const auto path = std::filesystem::temp_directory_path() / name;
  std::ofstream(path) << out.str();
  return path;
}

std::string read_error(const std::filesystem::path& file) {
  try {
    mesh::read_gmsh(file);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(GmshFamilyErrors, AnInvertedTetIsNamedWithItsLine) {
  const auto file =
      edited("cube_tet4_v22.msh", "trifem_inverted_tet.msh",
             [](std::vector<std::string>& w) { std::swap(w[w.size() - 1], w[w.size() - 2]); });
  const std::string what = read_error(file);
  EXPECT_NE(what.find("trifem_inverted_tet.msh:"), std::string::npos) << what;
  EXPECT_NE(what.find("tet4 element"), std::string::npos) << what;
  EXPECT_NE(what.find("negative volume"), std::string::npos) << what;
}

TEST(GmshFamilyErrors, ADegenerateTetIsRefused) {
  const auto file = edited("cube_tet4_v22.msh", "trifem_flat_tet.msh",
                           [](std::vector<std::string>& w) { w[w.size() - 1] = w[w.size() - 2]; });
  const std::string what = read_error(file);
  EXPECT_NE(what.find("tet4 element"), std::string::npos) << what;
  EXPECT_NE(what.find("degenerate"), std::string::npos) << what;
}

} // namespace cell_families_test
