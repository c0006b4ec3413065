// SPDX-License-Identifier: MIT
// [[constraint]]: each kind against the same problem solved another way or a closed form.
//   * symmetry planes: a cube turned about an oblique axis (its planes held by multipliers)
//     deforms as the axis-aligned cube (its planes fixed components), turned;
//   * linear constraints: the top of a cube tied to its fixed bottom with an offset is the top
//     prescribed, and the multipliers are the reactions;
//   * rigid wall: a wall pressing a block is the top prescribed (frictionless), the wall's force
//     the reaction; a wall that withdraws releases the block;
//   * normal displacement: a thick sphere whose outer surface may only slide, under internal
//     pressure, converges to Lamé's solution with u(B) = 0;
//   * a rigid body made only of a surface mesh (quads that bound no cell) pressing a block
//     through contact is the top prescribed.
#include "case_runner.hpp"
#include "generated_meshes.hpp"
#include "tissue_materials.hpp"
#include "trifem/analysis/output_writer.hpp"
#include "trifem/parallel/communicator.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

using namespace trifem;

namespace {

/// A 2x2x2 unit cube of `material` (a [materials.tissue] table, default neo-Hookean); `rest` is
/// appended.
std::string cube_case(const std::string& rest, Real end_time = 1.0, Real dt = 0.5,
                      const std::string& material = test::kSolid) {
  return fmt::format(R"(
[time]
end_time = {}
dt = {}
)",
                     end_time, dt) +
         R"(
[[mesh.box]]
name = "box"
size = [1.0, 1.0, 1.0]
divisions = [2, 2, 2]
material = "tissue"
[curves.ramp]
points = [[0.0, 0.0], [1.0, 1.0]]
[solver]
residual_tolerance = 1e-12
increment_tolerance = 1e-12
)" + material +
         rest;
}

Vec3 displacement(const model::Model& m, Index node) {
  const Vector& x = m.problem->state();
  return {x[m.dofs.dof(m.fields.u, node, 0)], x[m.dofs.dof(m.fields.u, node, 1)],
          x[m.dofs.dof(m.fields.u, node, 2)]};
}

Real max_displacement(const model::Model& m) {
  Real u = 0.0;
  for (Index n = 0; n < m.mesh.num_nodes(); ++n)
    u = std::max(u, displacement(m, n).norm());
  return u;
}

/// The mesh node at X (exactly, as the box generator places it).
Index node_at(const mesh::Mesh& mesh, const Vec3& X) {
  for (Index n = 0; n < mesh.num_nodes(); ++n)
    if ((mesh.node(n) - X).norm() < 1e-12)
      return n;
  throw std::runtime_error("no node at the point");
}

/// Expects the displacements of the nodes of `expected` (the first ones of `got`) to agree to
/// 1e-9 of the largest.
void expect_same_displacements(const model::Model& got, const model::Model& expected) {
  const Real scale = max_displacement(expected);
  ASSERT_GT(scale, 0.05); // a real deformation
  for (Index n = 0; n < expected.mesh.num_nodes(); ++n)
    EXPECT_LT((displacement(got, n) - displacement(expected, n)).norm(), 1e-9 * scale)
        << "node " << n;
}

/// Sum over the nodes of `set` of the internal force's component k: the force the conditions
/// there apply [N].
Real reaction(const model::Model& m, const std::string& set, int k) {
  Real f = 0.0;
  for (Index n : m.mesh.node_set(set))
    f += m.problem->full_residual()[m.dofs.dof(m.fields.u, n, k)];
  return f;
}

const char* kSymmetricCube = R"(
[[constraint]]
type = "symmetry-plane"
surface = "box.xmin"
[[constraint]]
type = "symmetry-plane"
surface = "box.ymin"
[[constraint]]
type = "symmetry-plane"
surface = "box.zmin"
[[loads.pressure]]
surface = "box.xmax"
value = 0.2
curve = "ramp"
[[loads.pressure]]
surface = "box.ymax"
value = -0.1
curve = "ramp"
)";

} // namespace

/// The tissue of the symmetry-plane test: solid, biphasic or triphasic.
class SymmetryPlanes : public testing::TestWithParam<const char*> {};

TEST_P(SymmetryPlanes, ObliqueOnesGiveTheTurnedSolutionOfAxisAlignedOnes) {
  const std::string text = cube_case(kSymmetricCube, 1.0, 0.5, GetParam());
  const test::CaseRun aligned = test::run_case_text(text, "aligned.toml");
  ASSERT_TRUE(aligned.report.success) << aligned.report.failure;
  EXPECT_FALSE(aligned.model->constraint_forces.valid()); // axis normals: fixed components

  const Mat3 R = Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, 3.0).normalized()).toRotationMatrix();
  io::CaseSpec spec = io::parse_case(text, "turned.toml");
  const mesh::Mesh box = mesh::make_box({"box", Vec3::Zero(), Vec3::Ones(), {2, 2, 2}});
  spec.boxes.clear();
  spec.meshes.push_back({test::transform_nodes(box, [&](const Vec3& X) { return Vec3(R * X); }),
                         {{"box", "tissue"}}});
  const test::CaseRun turned = test::run_case_spec(std::move(spec));
  ASSERT_TRUE(turned.report.success) << turned.report.failure;
  ASSERT_TRUE(turned.model->constraint_forces.valid()); // oblique normals: multipliers

  const Real scale = max_displacement(*aligned.model);
  ASSERT_GT(scale, 0.05); // a real deformation
  for (Index n = 0; n < box.num_nodes(); ++n)
    EXPECT_LT((displacement(*turned.model, n) - R * displacement(*aligned.model, n)).norm(),
              1e-9 * scale)
        << "node " << n;
}

std::string tissue_name(const testing::TestParamInfo<const char*>& info) {
  const char* names[] = {"Solid", "Biphasic", "Triphasic"};
  return names[info.index];
}

INSTANTIATE_TEST_SUITE_P(Tissues, SymmetryPlanes,
                         testing::Values(test::kSolid, test::kBiphasic, test::kTriphasic),
                         tissue_name);

TEST(Constraints, ALinearConstraintToTheFixedBottomIsTheTopPrescribedAndItsForceTheReaction) {
  const mesh::Mesh box = mesh::make_box({"box", Vec3::Zero(), Vec3::Ones(), {2, 2, 2}});
  std::string tied = R"(
[[boundary.fixed]]
set = "box.zmin"
)";
  std::vector<Index> top;
  for (Index a : box.node_set("box.zmax")) {
    const Index b = node_at(box, Vec3(box.node(a).x(), box.node(a).y(), 0.0));
    top.push_back(a);
    tied += fmt::format("[[constraint]]\ntype = \"linear\"\nvalue = 0.2\ncurve = \"ramp\"\n"
                        "terms = [{{ node = {}, component = \"z\", coefficient = 1.0 }}, "
                        "{{ node = {}, component = \"z\", coefficient = -1.0 }}]\n",
                        a, b);
  }
  const test::CaseRun linear = test::run_case_text(cube_case(tied), "tied.toml");
  ASSERT_TRUE(linear.report.success) << linear.report.failure;

  const test::CaseRun prescribed = test::run_case_text(cube_case(R"(
[[boundary.fixed]]
set = "box.zmin"
[[boundary.prescribed]]
set = "box.zmax"
component = "z"
value = 0.2
curve = "ramp"
)"),
                                                       "prescribed.toml");
  ASSERT_TRUE(prescribed.report.success) << prescribed.report.failure;
  const model::Model& m = *linear.model;
  const model::Model& p = *prescribed.model;
  expect_same_displacements(m, p);
  // the multiplier of the equation of top node a is minus the internal force there
  const Real force = std::abs(reaction(p, "box.zmax", 2));
  ASSERT_GT(force, 0.05);
  for (std::size_t i = 0; i < top.size(); ++i) {
    const Real lambda = m.problem->state()[m.dofs.dof(m.constraint_forces, Index(i), 0)];
    const Real r = p.problem->full_residual()[p.dofs.dof(p.fields.u, top[i], 2)];
    EXPECT_NEAR(lambda, -r, 1e-9 * force) << "top node " << top[i];
  }
}

namespace {

/// The cube on its symmetry planes, its top pressed down by `top`.
std::string pressed_cube(const std::string& top, Real end_time = 1.0, Real dt = 0.5) {
  return cube_case(R"(
[[boundary.fixed]]
set = "box.zmin"
components = ["z"]
[[boundary.fixed]]
set = "box.xmin"
components = ["x"]
[[boundary.fixed]]
set = "box.ymin"
components = ["y"]
)" + top,
                   end_time, dt);
}

/// The top pressed by 0.15 mm as a prescribed displacement (frictionless: x, y free).
const char* kTopPrescribed = R"(
[[boundary.prescribed]]
set = "box.zmax"
component = "z"
value = -0.15
curve = "ramp"
)";

const char* kWall = R"(
[[constraint]]
type = "rigid-wall"
name = "wall"
surface = "box.zmax"
point = [0.0, 0.0, 1.0]
normal = [0.0, 0.0, -1.0]
offset = 0.15
curve = "ramp"
)";

} // namespace

TEST(Constraints, ARigidWallPressingABlockIsTheTopPrescribedAndItsForceTheReaction) {
  const test::CaseRun walled = test::run_case_text(pressed_cube(kWall), "wall.toml");
  ASSERT_TRUE(walled.report.success) << walled.report.failure;
  const test::CaseRun prescribed = test::run_case_text(pressed_cube(kTopPrescribed), "top.toml");
  ASSERT_TRUE(prescribed.report.success) << prescribed.report.failure;
  const model::Model& m = *walled.model;
  const model::Model& p = *prescribed.model;
  expect_same_displacements(m, p);
  ASSERT_EQ(m.walls.size(), 1u);
  const contact::RigidWallTerm& wall = *m.walls[0].term;
  EXPECT_EQ(wall.num_active(), 9);
  const Real force = reaction(p, "box.zmax", 2);
  ASSERT_LT(force, -0.05); // the top is pushed down
  const Vec3 f = wall.force(m.problem->state());
  EXPECT_NEAR(f.z(), force, 1e-9 * std::abs(force));
  EXPECT_NEAR(f.x(), 0.0, 1e-15 * std::abs(force)); // frictionless on a horizontal wall
}

TEST(Constraints, ARigidWallThatWithdrawsReleasesTheBlock) {
  const test::CaseRun run = test::run_case_text(pressed_cube(R"(
[[constraint]]
type = "rigid-wall"
name = "wall"
surface = "box.zmax"
point = [0.0, 0.0, 1.0]
normal = [0.0, 0.0, -1.0]
offset = 0.15
curve = "press"
[curves.press]
points = [[0.0, 0.0], [1.0, 1.0], [2.0, -1.0]]
)",
                                                             2.0, 0.25),
                                                "withdraw.toml");
  ASSERT_TRUE(run.report.success) << run.report.failure;
  const model::Model& m = *run.model;
  const contact::RigidWallTerm& wall = *m.walls[0].term;
  EXPECT_EQ(wall.num_active(), 0);
  EXPECT_EQ(wall.force(m.problem->state()).norm(), 0.0); // inactive rows hold λ = 0 exactly
  EXPECT_LT(max_displacement(m), 1e-12);                 // back to the reference
}

namespace {

/// Radial displacement u(A) of the thick sphere A ≤ r ≤ B under internal pressure p whose
/// outer surface is held radially (u(B) = 0), linear elasticity (Lamé): u = a r + b / r²,
/// σ_rr(A) = −p.
Real lame_inner_displacement(Real A, Real B, Real p, Real E, Real nu) {
  const Real mu = E / (2.0 * (1.0 + nu)), lambda = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  const Real b = p / ((3.0 * lambda + 2.0 * mu) / (B * B * B) + 4.0 * mu / (A * A * A));
  return b * (1.0 / (A * A) - A / (B * B * B));
}

/// A case on the neo-Hookean sphere octant `shell` (material "soft"); `rest` is appended.
io::CaseSpec shell_case(const std::string& rest, const test::ShellOctantSpec& shell) {
  io::CaseSpec spec = io::parse_case(R"(
[[mesh.box]]
name = "placeholder"
size = [1.0, 1.0, 1.0]
divisions = [1, 1, 1]
material = "soft"
[materials.soft]
type = "neo-hookean"
E = 1.0
nu = 0.3
)" + rest,
                                     "shell.toml");
  spec.boxes.clear(); // the box only satisfies the reader: the shell replaces it
  spec.meshes.push_back({test::make_shell_octant(shell), {{"shell", "soft"}}});
  return spec;
}

/// Mean relative error of the radial displacement of the inner surface against Lamé.
Real sphere_error(int divisions) {
  constexpr Real A = 1.0, B = 2.0, p = 1e-5, E = 1.0, nu = 0.3;
  test::ShellOctantSpec shell;
  shell.inner = A;
  shell.outer = B;
  shell.divisions = divisions;
  shell.layers = 2 * divisions;
  io::CaseSpec spec = shell_case(R"(
[[boundary.fixed]]
set = "shell.x0"
components = ["x"]
[[boundary.fixed]]
set = "shell.y0"
components = ["y"]
[[boundary.fixed]]
set = "shell.z0"
components = ["z"]
[[constraint]]
type = "normal-displacement"
surface = "shell.outer"
[[loads.pressure]]
surface = "shell.inner"
value = 1e-5
[time]
end_time = 1.0
dt = 1.0
[solver]
residual_tolerance = 1e-12
increment_tolerance = 1e-12
)",
                                 shell);
  const test::CaseRun run = test::run_case_spec(std::move(spec));
  EXPECT_TRUE(run.report.success) << run.report.failure;
  const model::Model& m = *run.model;
  const Real exact = lame_inner_displacement(A, B, p, E, nu);
  Real error = 0.0;
  const auto inner = mesh::surface_nodes(m.mesh.surface("shell.inner"));
  for (Index n : inner) {
    const Vec3 X = m.mesh.node(n);
    error += std::abs(displacement(m, n).dot(X.normalized()) - exact) / exact;
  }
  // the outer surface slides: no node moves along its normal
  for (Index n : mesh::surface_nodes(m.mesh.surface("shell.outer")))
    EXPECT_LT(std::abs(displacement(m, n).dot(m.mesh.node(n).normalized())), 0.05 * exact);
  return error / static_cast<Real>(inner.size());
}

} // namespace

TEST(Constraints, ASphereWhoseOuterSurfaceSlidesConvergesToLamesSolution) {
  const Real coarse = sphere_error(2), fine = sphere_error(4);
  std::printf("inner radial displacement against Lame: %.3e (2 cells), %.3e (4 cells)\n", coarse,
              fine);
  EXPECT_LT(fine, 0.02);
  EXPECT_LT(fine, 0.4 * coarse); // second order: about a quarter
}

namespace {

/// The 2x2x2 cube and, above its top, a 3x3 plate of quads (0.5 mm) that bounds no cell,
/// facing down, touching the top (gap 0), offset by a quarter facet: the contact is not
/// conforming. `triangles`: each quad split into two triangles (quads whose last node repeats
/// the third).
mesh::Mesh cube_and_plate(bool triangles = false) {
  mesh::Mesh m = mesh::make_box({"box", Vec3::Zero(), Vec3::Ones(), {2, 2, 2}});
  const Index first = m.num_nodes();
  for (int j = 0; j <= 3; ++j)
    for (int i = 0; i <= 3; ++i)
      m.add_node(Vec3(-0.25 + 0.5 * i, -0.25 + 0.5 * j, 1.0));
  mesh::Surface plate;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      const Index a = first + 4 * j + i;
      if (!triangles) {
        plate.facets.push_back({.nodes = {a, a + 4, a + 5, a + 1}, .cell = -1, .local_face = -1});
        continue;
      }
      plate.facets.push_back({.nodes = {a, a + 4, a + 5, a + 5}, .cell = -1, .local_face = -1});
      plate.facets.push_back({.nodes = {a, a + 5, a + 1, a + 1}, .cell = -1, .local_face = -1});
    }
  m.add_surface("plate", plate);
  return m;
}

} // namespace

class RigidSurface : public testing::TestWithParam<bool> {};

TEST_P(RigidSurface, APlateMadeOnlyOfASurfaceMeshPressesABlockAsAPrescribedTop) {
  io::CaseSpec spec = io::parse_case(pressed_cube(R"(
[[rigid_body]]
name = "plate"
set = "plate"
x = { displacement = 0.0 }
y = { displacement = 0.0 }
z = { displacement = -0.15, curve = "ramp" }
rx = { rotation = 0.0 }
ry = { rotation = 0.0 }
rz = { rotation = 0.0 }
[[contact]]
master = "plate"
slave = "box.zmax"
)"),
                                     "plate.toml");
  spec.boxes.clear();
  spec.meshes.push_back({cube_and_plate(GetParam()), {{"box", "tissue"}}});
  const test::CaseRun plate = test::run_case_spec(std::move(spec));
  ASSERT_TRUE(plate.report.success) << plate.report.failure;
  const test::CaseRun prescribed = test::run_case_text(pressed_cube(kTopPrescribed), "top.toml");
  ASSERT_TRUE(prescribed.report.success) << prescribed.report.failure;
  const model::Model& m = *plate.model;
  const model::Model& p = *prescribed.model;
  expect_same_displacements(m, p); // the cube's nodes come first
  // the plate moved rigidly by its prescribed translation
  for (Index n : m.mesh.node_set("plate"))
    EXPECT_LT((displacement(m, n) - Vec3(0.0, 0.0, -0.15)).norm(), 1e-14);
  // the contact force on the block is the reaction of the prescribed top (the plate's own
  // force, from the master side of the both-surface integration, is not: issue 38)
  const Real force = reaction(p, "box.zmax", 2);
  ASSERT_LT(force, -0.05);
  const Vec3 f = m.contacts.at(0)->slave_force(m.problem->state());
  EXPECT_NEAR(f.z(), force, 1e-9 * std::abs(force));
  // the plate is drawn (by rank 0): surfaces.pvd lists surfaces_0000.vtu, its 16 nodes and 9
  // quads (18 triangles)
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / fmt::format("trifem_rigid_surface_{}", GetParam());
  if (parallel::is_root())
    std::filesystem::remove_all(dir);
  { // (every process writes its part of the volume)
    analysis::OutputWriter writer(m, plate.spec.output, dir, 1.0);
    writer.write(1.0, 4, 0.25, 1, true);
    if (!parallel::is_root())
      return;
    EXPECT_EQ(writer.surfaces_pvd_file(), dir / "surfaces.pvd");
  }
  const auto text = [](const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  };
  EXPECT_NE(text(dir / "surfaces.pvd").find("surfaces_0000.vtu"), std::string::npos);
  const std::string vtu = text(dir / "surfaces_0000.vtu");
  EXPECT_NE(vtu.find(fmt::format(R"(NumberOfPoints="16" NumberOfCells="{}")", GetParam() ? 18 : 9)),
            std::string::npos);
  EXPECT_NE(vtu.find(R"(Name="displacement [mm]")"), std::string::npos);
  std::filesystem::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Facets, RigidSurface, testing::Values(false, true),
                         [](const auto& info) { return info.param ? "Triangles" : "Quads"; });

namespace {

/// The message of the InputError that building the model of `text` throws ("" if none).
std::string model_error(const std::string& text) {
  try {
    model::build_model(io::parse_case(text, "bad.toml"));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

} // namespace

TEST(Constraints, BadConstraintsAreInputErrorsNamingTheConstraint) {
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {R"(
[[constraint]]
type = "symmetry-plane"
surface = "nowhere"
)",
       {"constraint[1]", "surface = 'nowhere'", "no such surface"}},
      {R"(
[[boundary.fixed]]
set = "box.zmin"
[[constraint]]
type = "linear"
terms = [{ node = 0, component = "z", coefficient = 1.0 }]
)",
       {"constraint[1]", "every displacement component it names is fixed"}},
      {R"(
[[boundary.fixed]]
set = "box.zmin"
[[constraint]]
type = "linear"
terms = [{ node = 27, component = "z", coefficient = 1.0 }]
)",
       {"constraint[1]", "terms[1].node = 27", "nodes 0 to 26"}},
      {R"(
[[boundary.fixed]]
set = "box.zmin"
[[rigid_body]]
name = "lid"
set = "box.zmax"
[[constraint]]
type = "symmetry-plane"
surface = "box.xmax"
)",
       {"constraint[1]", "belongs to a rigid body"}},
  };
  for (const auto& [rest, phrases] : cases) {
    const std::string message = model_error(cube_case(rest));
    ASSERT_FALSE(message.empty()) << rest;
    for (const std::string& phrase : phrases)
      EXPECT_NE(message.find(phrase), std::string::npos) << message;
  }
}

TEST(Constraints, ACurvedSymmetryPlaneIsAnInputErrorNamingAFacet) {
  io::CaseSpec spec = shell_case(R"(
[[constraint]]
type = "symmetry-plane"
surface = "shell.outer"
[time]
end_time = 1.0
dt = 1.0
)",
                                 {});
  try {
    model::build_model(spec);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    const std::string message = e.what();
    for (const char* phrase : {"constraint[1]", "a symmetry plane must be flat",
                               "the facet of nodes", "normal-displacement"})
      EXPECT_NE(message.find(phrase), std::string::npos) << message;
  }
}
