// SPDX-License-Identifier: MIT
// Hanging nodes between cells (mesh/conformity.hpp): meshes whose cells meet face to face pass,
// and a quadratic face on a linear one, a quadrilateral face on tets' triangles and a coarse
// face beside a finer mesh are found, naming the two cells; bodies that only touch (contact)
// and the doubled nodes of a crack are not hanging nodes.
#include "box_assembly.hpp"
#include "trifem/core/error.hpp"
#include "trifem/mesh/conformity.hpp"
#include "trifem/mesh/gmsh_reader.hpp"
#include "trifem/mesh/gmsh_writer.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <map>

namespace conformity_test {

using namespace trifem;
using mesh::CellType;
using mesh::Mesh;

using Assembly = test::BoxAssembly;

const Vec3 kUnit = Vec3::Ones();
const Vec3 kRight = Vec3(1.0, 0.0, 0.0);

TEST(HangingNodes, MeshesWhoseCellsMeetFaceToFaceHaveNone) {
  for (const CellType type :
       {CellType::Hex8, CellType::Tet4, CellType::Tet10, CellType::Penta6, CellType::Hex20}) {
    Assembly a;
    a.add_box(type, Vec3::Zero(), Vec3(2.0, 1.0, 1.0), {2, 2, 2});
    EXPECT_FALSE(mesh::find_hanging_nodes(a.mesh())) << mesh::name(type);
  }
  Assembly wedges_beside_hexes; // the wedges' quadrilateral faces on the hexes' faces
  wedges_beside_hexes.add_box(CellType::Hex8, Vec3::Zero(), kUnit, {2, 2, 2});
  wedges_beside_hexes.add_box(CellType::Penta6, kRight, kUnit, {2, 2, 2});
  EXPECT_FALSE(mesh::find_hanging_nodes(wedges_beside_hexes.mesh()));
}

TEST(HangingNodes, AQuadraticFaceOnALinearOneIsFound) {
  Assembly a;
  a.add_box(CellType::Hex8, Vec3::Zero(), kUnit, {1, 1, 1});
  a.add_box(CellType::Hex20, kRight, kUnit, {1, 1, 1});
  const auto hanging = mesh::find_hanging_nodes(a.mesh());
  ASSERT_TRUE(hanging);
  EXPECT_EQ(hanging->cell, 0);
  EXPECT_EQ(hanging->other, 1);
  EXPECT_NE(hanging->how.find("mid-edge"), std::string::npos) << hanging->how;
}

TEST(HangingNodes, AQuadrilateralFaceOnTheTrianglesOfTetsIsFound) {
  Assembly a;
  a.add_box(CellType::Hex8, Vec3::Zero(), kUnit, {1, 1, 1});
  a.add_box(CellType::Tet4, kRight, kUnit, {1, 1, 1});
  const auto hanging = mesh::find_hanging_nodes(a.mesh());
  ASSERT_TRUE(hanging);
  EXPECT_EQ(hanging->cell, 0) << "the hex";
  EXPECT_GE(hanging->other, 1);
  EXPECT_NE(hanging->how.find("quad4 face and a tri3 face"), std::string::npos) << hanging->how;
}

TEST(HangingNodes, ACoarseFaceBesideAFinerMeshIsFound) {
  Assembly a; // one hex beside 2 x 2 x 2 hexes of half its size: 5 hanging nodes on its face
  a.add_box(CellType::Hex8, Vec3::Zero(), kUnit, {1, 1, 1});
  a.add_box(CellType::Hex8, kRight, kUnit, {2, 2, 2});
  const auto hanging = mesh::find_hanging_nodes(a.mesh());
  ASSERT_TRUE(hanging);
  EXPECT_EQ(hanging->cell, 0);
  EXPECT_NE(hanging->how.find("overlap"), std::string::npos) << hanging->how;
}

TEST(HangingNodes, BodiesThatOnlyTouchAndTheSidesOfACrackAreNotHangingNodes) {
  Assembly touching; // a fine block on a coarse one, no node shared: a contact interface
  touching.add_box(CellType::Hex8, Vec3::Zero(), kUnit, {1, 1, 1});
  touching.add_box(CellType::Hex8, kRight, kUnit, {2, 2, 2}, false);
  EXPECT_FALSE(mesh::find_hanging_nodes(touching.mesh()));

  // a crack: two hexes on either side of the plane x = 1 sharing only their nodes at y = 0
  Mesh crack;
  std::vector<Index> left, right;
  for (const Vec3& x : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0), Vec3(0, 0, 1),
                        Vec3(1, 0, 1), Vec3(1, 1, 1), Vec3(0, 1, 1)})
    left.push_back(crack.add_node(x));
  const Index on_crack[] = {1, 2, 6, 5}; // left's nodes on x = 1: y = 0 shared, y = 1 doubled
  std::map<Index, Index> twin;
  for (Index n : on_crack)
    twin[n] = crack.node(left[n]).y() == 0.0 ? left[n] : crack.add_node(crack.node(left[n]));
  for (const Vec3& x : {Vec3(2, 0, 0), Vec3(2, 1, 0), Vec3(2, 1, 1), Vec3(2, 0, 1)})
    right.push_back(crack.add_node(x));
  crack.add_cell(CellType::Hex8, left);
  const std::vector<Index> hex = {twin[1], right[0], right[1], twin[2],
                                  twin[5], right[3], right[2], twin[6]};
  crack.add_cell(CellType::Hex8, hex);
  EXPECT_FALSE(mesh::find_hanging_nodes(crack));
}

TEST(HangingNodes, AGmshFileWithThemIsAnErrorNamingTheElementTags) {
  Assembly a;
  a.add_box(CellType::Hex8, Vec3::Zero(), kUnit, {1, 1, 1});
  a.add_box(CellType::Hex20, kRight, kUnit, {1, 1, 1});
  Mesh mesh = a.mesh();
  mesh.add_cell_block("body", {0, 1});
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / "trifem_hanging_nodes.msh";
  mesh::write_gmsh(mesh, file);
  try {
    mesh::read_gmsh(file);
    ADD_FAILURE() << "read without an error";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(file.string() + ":", 0), 0u) << message;
    EXPECT_NE(message.find("elements 1 (hex8) and 2 (hex20)"), std::string::npos) << message;
    EXPECT_NE(message.find("conforming"), std::string::npos) << message;
  }
  std::filesystem::remove(file);
}

} // namespace conformity_test
