// SPDX-License-Identifier: MIT
// Material axes through the whole chain (case reader, model, solver, VTU arrays): a block of a
// neo-Hookean matrix with one fibre family, compressed to a stretch of 0.8 along x with
// symmetry planes.
// - The fibre given in local axes (type "vector") is the fibre given globally along e1: the FE
//   states agree to round-off, for e1 = y and for an off-axis e1; the global basis (a = x,
//   d = y) gives the same bits as no axes.
// - Cylindrical axes give each cell the basis at its centroid: two separate boxes with
//   circumferential fibres equal two materials with the constant bases of their centroids;
//   cells with the same basis share one law.
// - A biphasic material's solid is rotated per cell (spherical axes), its mixture shared.
// - The VTU arrays material_axis and fibre_direction.
// - Axes from the mesh (type "mesh"): a Gmsh file with $ElementData written by the test; a
//   constant e1 gives the same bits as type "vector" with the completing d, two blocks with
//   different directions equal two materials with constant axes, a d_view fixes e2; the
//   errors of missing views and values.
// "The same bits" holds on one process; on several (mpirun) the two runs agree to round-off
// (run_to_run.hpp).
#include "case_runner.hpp"
#include "run_to_run.hpp"
#include "trifem/analysis/axis_fields.hpp"
#include "trifem/analysis/output_fields.hpp"
#include "trifem/material/material_axes.hpp"
#include "trifem/material/rotated_law.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <string>

using namespace trifem;

namespace {

const std::filesystem::path kFile = "memory/axes.toml";

std::string text(const Vec3& v) {
  return fmt::format("[{:.17g}, {:.17g}, {:.17g}]", v.x(), v.y(), v.z());
}

/// A box `name` at `origin` (unit cube, `divisions`) of `material`, with symmetry planes at its
/// minimum faces and its xmax face moved by -0.2 mm (stretch 0.8: the lateral expansion
/// stretches fibres across x, which then restrain it).
std::string box(const std::string& name, const Vec3& origin, const std::string& divisions,
                const std::string& material) {
  return fmt::format(R"(
[[mesh.box]]
name = "{0}"
origin = {1}
size = [1, 1, 1]
divisions = {2}
material = "{3}"
[[boundary.fixed]]
set = "{0}.xmin"
components = ["x"]
[[boundary.fixed]]
set = "{0}.ymin"
components = ["y"]
[[boundary.fixed]]
set = "{0}.zmin"
components = ["z"]
[[boundary.prescribed]]
set = "{0}.xmax"
component = "x"
value = -0.2
curve = "ramp"
)",
                     name, text(origin), divisions, material);
}

/// The fibre-reinforced material `name` with the fibre `fibre` and the axes table `axes`
/// ("" for none).
std::string fibre_material(const std::string& name, const Vec3& fibre, const std::string& axes) {
  std::string m = fmt::format(R"(
[materials.{0}]
type = "solid-mixture"
[[materials.{0}.constituent]]
type = "neo-hookean"
E = 1.0
nu = 0.3
[[materials.{0}.constituent]]
type = "fibre-exp-pow"
ksi = 5.0
alpha = 0.5
beta = 2.5
fibre = {1}
)",
                              name, text(fibre));
  if (!axes.empty())
    m += fmt::format("[materials.{}.axes]\n{}", name, axes);
  return m;
}

const std::string kTime = R"(
[curves.ramp]
points = [[0, 0], [1, 1]]
[time]
end_time = 1.0
dt = 0.25
)";

std::string vector_axes(const Vec3& a, const Vec3& d) {
  return fmt::format("type = \"vector\"\na = {}\nd = {}\n", text(a), text(d));
}

/// max |a - b| / max |b| of two FE states.
Real relative_difference(const Vector& a, const Vector& b) {
  return (a - b).lpNorm<Eigen::Infinity>() / b.lpNorm<Eigen::Infinity>();
}

Vector solve(const std::string& case_text) {
  test::CaseRun run = test::run_case_text(case_text, kFile);
  EXPECT_TRUE(run.report.success) << case_text;
  return run.model->problem->state();
}

void record(const char* key, Real value) {
  std::ostringstream out;
  out << std::scientific << value;
  testing::Test::RecordProperty(key, out.str());
}

} // namespace

TEST(MaterialAxesChain, LocalFibreEqualsTheGlobalFibreAlongE1) {
  const std::string block = box("block", Vec3::Zero(), "[2, 2, 2]", "m");
  struct Axes {
    const char* name;
    Vec3 a, d;
  };
  Real worst = 0.0;
  for (const Axes& axes : {Axes{"e1 = y", Vec3(0, 1, 0), Vec3(0, 0, 1)},
                           Axes{"off-axis", Vec3(0.4, 1.0, 0.7), Vec3(1.0, -0.2, 0.3)}}) {
    const Mat3 Q = material::vector_basis(axes.a, axes.d, "test");
    const Vector local =
        solve(block + kTime + fibre_material("m", Vec3(1, 0, 0), vector_axes(axes.a, axes.d)));
    const Vector global = solve(block + kTime + fibre_material("m", Q.col(0), ""));
    const Real difference = relative_difference(local, global);
    EXPECT_LE(difference, 1e-12) << axes.name;
    worst = std::max(worst, difference);
    // and the axes matter: the fibre along global x gives another answer
    const Vector along_x = solve(block + kTime + fibre_material("m", Vec3(1, 0, 0), ""));
    EXPECT_GT(relative_difference(along_x, global), 1e-2) << axes.name;
  }
  record("max_relative_difference", worst);
}

// The same on blocks of tet4, tet10, penta6 and hex20 cells: the per-cell basis is that of the
// cell, whatever its family.
TEST(MaterialAxesChain, LocalFibreEqualsTheGlobalFibreOnEveryCellFamily) {
  const Vec3 a(0.4, 1.0, 0.7), d(1.0, -0.2, 0.3);
  const Mat3 Q = material::vector_basis(a, d, "test");
  for (const char* family : {"tet4", "tet10", "penta6", "hex20"}) {
    std::string block = box("block", Vec3::Zero(), "[2, 2, 2]", "m");
    block.insert(block.find("material = \"m\""), fmt::format("cell = \"{}\"\n", family));
    const Vector local =
        solve(block + kTime + fibre_material("m", Vec3(1, 0, 0), vector_axes(a, d)));
    const Vector global = solve(block + kTime + fibre_material("m", Q.col(0), ""));
    EXPECT_LE(relative_difference(local, global), 1e-12) << family;
    const Vector along_x = solve(block + kTime + fibre_material("m", Vec3(1, 0, 0), ""));
    EXPECT_GT(relative_difference(along_x, global), 1e-2) << family;
  }
}

TEST(MaterialAxesChain, GlobalBasisGivesTheSameBitsAsNoAxes) {
  const std::string block = box("block", Vec3::Zero(), "[2, 2, 2]", "m");
  const Vec3 fibre(1.0, 0.7, 0.4);
  const Vector with =
      solve(block + kTime + fibre_material("m", fibre, vector_axes(Vec3(2, 0, 0), Vec3(1, 3, 0))));
  const Vector without = solve(block + kTime + fibre_material("m", fibre, ""));
  EXPECT_TRUE(test::same_run_to_run(with, without));
}

TEST(MaterialAxesChain, CylindricalAxesGiveEachCellTheBasisAtItsCentroid) {
  // Two separate boxes, each two cells high (both cells of a box have the same radial
  // direction), circumferential fibres (local e2).
  const Vec3 origin_a(1.0, 0.5, 0.0), origin_b(-1.0, 2.0, 0.0);
  const std::string cylindrical = "type = \"cylindrical\"\ncenter = [0, 0, -3]\naxis = [0, 0, 2]\n";
  const std::string boxes =
      box("a", origin_a, "[1, 1, 2]", "cyl") + box("b", origin_b, "[1, 1, 2]", "cyl") + kTime;
  test::CaseRun run =
      test::run_case_text(boxes + fibre_material("cyl", Vec3(0, 1, 0), cylindrical), kFile);
  ASSERT_TRUE(run.report.success);
  const model::Model& m = *run.model;
  ASSERT_EQ(m.axes.size(), 4u);
  // the bases at the centroids (1.5, 1, z) and (-0.5, 2.5, z)
  const Mat3 Qa = material::cylindrical_basis(Vec3(0, 0, -3), Vec3(0, 0, 2), Vec3(1.5, 1, 0), "a");
  const Mat3 Qb =
      material::cylindrical_basis(Vec3(0, 0, -3), Vec3(0, 0, 2), Vec3(-0.5, 2.5, 0), "b");
  EXPECT_LE((Qa.col(0) - Vec3(1.5, 1, 0).normalized()).norm(), 1e-16);
  EXPECT_LE((Qa.col(1) - Vec3(-1, 1.5, 0).normalized()).norm(), 1e-16);
  for (Index c : m.mesh.cell_block("a"))
    EXPECT_TRUE(m.axes[c] == Qa) << c;
  for (Index c : m.mesh.cell_block("b"))
    EXPECT_TRUE(m.axes[c] == Qb) << c;
  // the cells of a box share their law; the boxes do not
  const auto& a = m.mesh.cell_block("a");
  const auto& b = m.mesh.cell_block("b");
  EXPECT_EQ(m.materials[a[0]].solid, m.materials[a[1]].solid);
  EXPECT_NE(m.materials[a[0]].solid, m.materials[b[0]].solid);
  const auto* rotated = dynamic_cast<const material::RotatedLaw*>(m.materials[b[1]].solid.get());
  ASSERT_NE(rotated, nullptr);
  EXPECT_TRUE(rotated->basis() == Qb);

  // the same with a constant basis per box (two materials)
  const std::string constant =
      box("a", origin_a, "[1, 1, 2]", "ma") + box("b", origin_b, "[1, 1, 2]", "mb") + kTime +
      fibre_material("ma", Vec3(0, 1, 0), vector_axes(Qa.col(0), Qa.col(1))) +
      fibre_material("mb", Vec3(0, 1, 0), vector_axes(Qb.col(0), Qb.col(1)));
  const Real difference = relative_difference(m.problem->state(), solve(constant));
  EXPECT_LE(difference, 1e-12);
  record("relative_difference_to_constant_bases", difference);
}

TEST(MaterialAxesChain, BiphasicSolidIsRotatedPerCell) {
  const std::string text = box("block", Vec3(1, 1, 1), "[2, 1, 1]", "cart") + kTime + R"(
[materials.cart]
type = "biphasic"
phi_s0 = 0.2
permeability = 2e-3
[materials.cart.axes]
type = "spherical"
center = [0, 0, 0]
[materials.cart.solid]
type = "solid-mixture"
[[materials.cart.solid.constituent]]
type = "neo-hookean"
E = 0.5
nu = 0.1
[[materials.cart.solid.constituent]]
type = "fibre-distribution"
ksi = 2.0
alpha = 0.0
beta = 2.5
semi_axes = [3, 1, 1]
)";
  const auto model = model::build_model(io::parse_case(text, kFile));
  ASSERT_EQ(model->axes.size(), 2u);
  for (Index c = 0; c < 2; ++c) {
    const Vec3 centroid(1.25 + 0.5 * Real(c), 1.5, 1.5);
    const Mat3 Q = material::spherical_basis(Vec3::Zero(), Vec3::UnitZ(), centroid, "s");
    EXPECT_TRUE(model->axes[c] == Q) << c;
    const auto& mixture = *model->materials[c].mixture;
    EXPECT_EQ(mixture.permeability, 2e-3);
    const auto* solid = dynamic_cast<const material::RotatedLaw*>(mixture.solid.get());
    ASSERT_NE(solid, nullptr) << c;
    EXPECT_TRUE(solid->basis() == Q) << c;
    EXPECT_EQ(solid->type(), "solid-mixture");
  }
  EXPECT_NE(model->materials[0].mixture, model->materials[1].mixture);
}

TEST(MaterialAxesChain, NoAxesNoArraysAndPlainLaws) {
  const auto model = model::build_model(io::parse_case(
      box("block", Vec3::Zero(), "[1, 1, 1]", "m") + kTime + fibre_material("m", Vec3(1, 0, 0), ""),
      kFile));
  EXPECT_TRUE(model->axes.empty());
  EXPECT_EQ(dynamic_cast<const material::RotatedLaw*>(model->materials[0].solid.get()), nullptr);
  EXPECT_TRUE(analysis::axis_fields(*model, model->problem->state()).empty());
  for (const auto& a : analysis::cell_fields(*model))
    EXPECT_NE(a.name, "material_axis");
}

TEST(MaterialAxesChain, VtuArraysHoldTheReferenceAndCurrentFibreDirections) {
  // fibre along local x = global y; the block is compressed along x: the state is homogeneous,
  // F = diag(0.8, t_y, t_z), and the fibre stays along y.
  const std::string block = box("block", Vec3::Zero(), "[2, 2, 2]", "m");
  test::CaseRun run = test::run_case_text(
      block + kTime + fibre_material("m", Vec3(1, 0, 0), vector_axes(Vec3(0, 1, 0), Vec3(0, 0, 1))),
      kFile);
  ASSERT_TRUE(run.report.success);
  const model::Model& m = *run.model;
  const auto arrays = analysis::cell_fields(m);
  const io::DataArray* axis = nullptr;
  const io::DataArray* fibre = nullptr;
  for (const auto& a : arrays) {
    if (a.name == "material_axis")
      axis = &a;
    if (a.name == "fibre_direction")
      fibre = &a;
  }
  ASSERT_NE(axis, nullptr);
  ASSERT_NE(fibre, nullptr);
  ASSERT_EQ(axis->components, 3);
  ASSERT_EQ(fibre->values.size(), 3u * 8u);
  Real worst = 0.0;
  for (std::size_t c = 0; c < 8; ++c) {
    EXPECT_EQ(Vec3(axis->values[3 * c], axis->values[3 * c + 1], axis->values[3 * c + 2]),
              Vec3(0, 1, 0));
    const Vec3 f(fibre->values[3 * c], fibre->values[3 * c + 1], fibre->values[3 * c + 2]);
    worst = std::max(worst, (f - Vec3(0, 1, 0)).norm());
  }
  EXPECT_LE(worst, 1e-12);
  // the centre F of a cell: stretch 0.8 along x, the fibre stretched (t_y > 1)
  const Mat3 F = analysis::centre_deformation_gradient(m, 0, m.problem->state());
  EXPECT_NEAR(F(0, 0), 0.8, 1e-12);
  EXPECT_GT(F(1, 1), 1.0);
  EXPECT_LE(std::abs(F(0, 1)) + std::abs(F(1, 0)) + std::abs(F(0, 2)), 1e-12);
  record("fibre_direction_error", worst);
}

// --- axes from the mesh's element data ---------------------------------------------------------

namespace {

/// A structured Gmsh mesh (MSH 2.2) of the box [0, 2] x [0, 1] x [0, 1] with n cells per mm, the
/// physical volumes "left" (x < 1) and "right", the physical surfaces xmin, ymin, zmin and xmax,
/// and one $ElementData view per entry of `views`: name -> the vector of a cell at its centroid.
struct GmshBox {
  int n = 2;
  std::map<std::string, std::function<Vec3(const Vec3&)>> views;

  int nx() const { return 2 * n; }
  int node_tag(int i, int j, int k) const { return 1 + i + (nx() + 1) * (j + (n + 1) * k); }
  Vec3 centroid(int i, int j, int k) const {
    return Vec3(i + 0.5, j + 0.5, k + 0.5) / static_cast<Real>(n);
  }

  /// Writes the file `name` into the test's temporary directory, unique per process (ctest
  /// runs the tests of this binary in parallel processes).
  void write(const std::filesystem::path& file) const {
    std::ofstream out(file);
    out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n6\n"
           "2 1 \"xmin\"\n2 2 \"ymin\"\n2 3 \"zmin\"\n2 4 \"xmax\"\n3 5 \"left\"\n3 6 \"right\"\n"
           "$EndPhysicalNames\n$Nodes\n";
    out << (nx() + 1) * (n + 1) * (n + 1) << "\n";
    for (int k = 0; k <= n; ++k)
      for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= nx(); ++i)
          out << fmt::format("{} {:.17g} {:.17g} {:.17g}\n", node_tag(i, j, k), Real(i) / n,
                             Real(j) / n, Real(k) / n);
    out << "$EndNodes\n$Elements\n";
    std::vector<std::string> lines;
    auto quad = [&](int physical, int a, int b, int c, int d) {
      lines.push_back(fmt::format("{} 3 2 {} {} {} {} {} {}", lines.size() + 1, physical, physical,
                                  a, b, c, d));
    };
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j) {
        quad(1, node_tag(0, j, k), node_tag(0, j + 1, k), node_tag(0, j + 1, k + 1),
             node_tag(0, j, k + 1));
        quad(4, node_tag(nx(), j, k), node_tag(nx(), j + 1, k), node_tag(nx(), j + 1, k + 1),
             node_tag(nx(), j, k + 1));
      }
    for (int k = 0; k < n; ++k)
      for (int i = 0; i < nx(); ++i)
        quad(2, node_tag(i, 0, k), node_tag(i + 1, 0, k), node_tag(i + 1, 0, k + 1),
             node_tag(i, 0, k + 1));
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < nx(); ++i)
        quad(3, node_tag(i, j, 0), node_tag(i + 1, j, 0), node_tag(i + 1, j + 1, 0),
             node_tag(i, j + 1, 0));
    const std::size_t first_hex = lines.size() + 1;
    std::vector<Vec3> centroids;
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < nx(); ++i) {
          const int physical = i < n ? 5 : 6;
          lines.push_back(fmt::format("{} 5 2 {} {} {} {} {} {} {} {} {} {}", lines.size() + 1,
                                      physical, physical, node_tag(i, j, k), node_tag(i + 1, j, k),
                                      node_tag(i + 1, j + 1, k), node_tag(i, j + 1, k),
                                      node_tag(i, j, k + 1), node_tag(i + 1, j, k + 1),
                                      node_tag(i + 1, j + 1, k + 1), node_tag(i, j + 1, k + 1)));
          centroids.push_back(centroid(i, j, k));
        }
    out << lines.size() << "\n";
    for (const auto& line : lines)
      out << line << "\n";
    out << "$EndElements\n";
    for (const auto& [view, vector] : views) {
      out << fmt::format("$ElementData\n1\n\"{}\"\n1\n0\n3\n0\n3\n{}\n", view, centroids.size());
      for (std::size_t e = 0; e < centroids.size(); ++e) {
        const Vec3 v = vector(centroids[e]);
        out << fmt::format("{} {:.17g} {:.17g} {:.17g}\n", first_hex + e, v.x(), v.y(), v.z());
      }
      out << "$EndElementData\n";
    }
  }
};

/// A GmshBox written to a per-process file of the temporary directory, removed at the end of
/// its scope.
struct GmshFile {
  std::filesystem::path path;
  GmshFile(const GmshBox& box, const std::string& name)
      : path(std::filesystem::path(testing::TempDir()) /
             fmt::format("trifem_axes_{}_{}.msh", getpid(), name)) {
    box.write(path);
  }
  GmshFile(const GmshFile&) = delete;
  GmshFile& operator=(const GmshFile&) = delete;
  ~GmshFile() { std::filesystem::remove(path); }
};

/// A case on the Gmsh file `file`: its blocks left and right of the materials `left` and
/// `right`, the symmetry planes xmin, ymin, zmin and xmax moved by -0.4 mm (stretch 0.8).
std::string gmsh_case(const std::filesystem::path& file, const std::string& left,
                      const std::string& right) {
  std::string text = fmt::format(R"(
[[mesh.gmsh]]
file = "{}"
materials = {{ left = "{}", right = "{}" }}
[[boundary.prescribed]]
set = "xmax"
component = "x"
value = -0.4
curve = "ramp"
)",
                                 file.generic_string(), left, right);
  for (const auto& [set, component] :
       {std::pair{"xmin", "x"}, std::pair{"ymin", "y"}, std::pair{"zmin", "z"}})
    text +=
        fmt::format("[[boundary.fixed]]\nset = \"{}\"\ncomponents = [\"{}\"]\n", set, component);
  return text + kTime;
}

std::string mesh_axes(const std::string& view, const std::string& d_view = "") {
  std::string axes = fmt::format("type = \"mesh\"\nview = \"{}\"\n", view);
  if (!d_view.empty())
    axes += fmt::format("d_view = \"{}\"\n", d_view);
  return axes;
}

/// The message of the InputError of building the model of `text` ("" if none).
std::string model_error(const std::string& text) {
  try {
    model::build_model(io::parse_case(text, kFile));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

} // namespace

TEST(MaterialAxesChain, ConstantMeshDirectionEqualsVectorAxes) {
  // e1 = unit(1, 2, 0.5): completed_basis takes d = z (the least aligned global axis), so
  // type "vector" with a = e1, d = z is the same basis; local fibre e1 plus e2 for a
  // difference in the (e1, e2) plane
  const Vec3 a(1.0, 2.0, 0.5);
  GmshBox mesh;
  mesh.views["fibre"] = [&](const Vec3&) { return a; };
  const GmshFile gmsh(mesh, "constant");
  const std::filesystem::path& file = gmsh.path;
  const Vec3 fibre(1.0, 0.5, 0.0);
  const Vector from_mesh =
      solve(gmsh_case(file, "m", "m") + fibre_material("m", fibre, mesh_axes("fibre")));
  const Vector from_vector =
      solve(gmsh_case(file, "m", "m") + fibre_material("m", fibre, vector_axes(a, Vec3::UnitZ())));
  EXPECT_TRUE(test::same_run_to_run(from_mesh, from_vector));
  const Real difference = relative_difference(from_mesh, from_vector);
  EXPECT_LE(difference, 1e-12);
  record("constant_relative_difference", difference);
  // and the direction matters
  const Vector global = solve(gmsh_case(file, "m", "m") + fibre_material("m", fibre, ""));
  EXPECT_GT(relative_difference(global, from_vector), 1e-2);
  record("constant_global_fibre_difference", relative_difference(global, from_vector));
}

TEST(MaterialAxesChain, PerCellMeshDirectionsEqualTwoMaterialsWithConstantAxes) {
  // left block: e1 = unit(0, 1, 1); right block: e1 = unit(1, 0, -1), by the view's values at
  // the cell centroids
  const Vec3 a_left(0.0, 1.0, 1.0), a_right(1.0, 0.0, -1.0);
  GmshBox mesh;
  mesh.views["fibre"] = [&](const Vec3& x) { return x.x() < 1.0 ? a_left : a_right; };
  mesh.views["angle"] = [](const Vec3& x) { return Vec3(x.x(), 0.0, 0.0); }; // unused
  const GmshFile gmsh(mesh, "two_blocks");
  const std::filesystem::path& file = gmsh.path;
  const Vec3 fibre(1, 0, 0);
  test::CaseRun run = test::run_case_text(
      gmsh_case(file, "m", "m") + fibre_material("m", fibre, mesh_axes("fibre")), kFile);
  ASSERT_TRUE(run.report.success);
  const model::Model& m = *run.model;
  const Mat3 Q_left = material::completed_basis(a_left, "left");
  const Mat3 Q_right = material::completed_basis(a_right, "right");
  for (Index c : m.mesh.cell_block("left"))
    EXPECT_TRUE(m.axes[c] == Q_left) << c;
  for (Index c : m.mesh.cell_block("right"))
    EXPECT_TRUE(m.axes[c] == Q_right) << c;
  // two distinct bases: two laws shared by the cells of each block
  const auto& left = m.mesh.cell_block("left");
  const auto& right = m.mesh.cell_block("right");
  EXPECT_EQ(m.materials[left.front()].solid, m.materials[left.back()].solid);
  EXPECT_NE(m.materials[left.front()].solid, m.materials[right.front()].solid);

  const Vector constant =
      solve(gmsh_case(file, "ml", "mr") +
            fibre_material("ml", fibre, vector_axes(Q_left.col(0), Q_left.col(1))) +
            fibre_material("mr", fibre, vector_axes(Q_right.col(0), Q_right.col(1))));
  const Real difference = relative_difference(m.problem->state(), constant);
  EXPECT_LE(difference, 1e-12);
  record("two_blocks_relative_difference", difference);
}

TEST(MaterialAxesChain, MeshDViewFixesE2) {
  // the fibre along local e2: only the d view decides where it points
  const Vec3 a(1.0, 0.0, 0.0), d(0.3, 1.0, 1.0);
  GmshBox mesh;
  mesh.views["fibre"] = [&](const Vec3&) { return a; };
  mesh.views["sheet"] = [&](const Vec3&) { return d; };
  const GmshFile gmsh(mesh, "d_view");
  const std::filesystem::path& file = gmsh.path;
  const Vec3 fibre(0, 1, 0);
  const Vector from_mesh =
      solve(gmsh_case(file, "m", "m") + fibre_material("m", fibre, mesh_axes("fibre", "sheet")));
  const Vector from_vector =
      solve(gmsh_case(file, "m", "m") + fibre_material("m", fibre, vector_axes(a, d)));
  const Real difference = relative_difference(from_mesh, from_vector);
  EXPECT_TRUE(test::same_run_to_run(from_mesh, from_vector));
  record("d_view_relative_difference", difference);
  // without the d view, e2 = the completed basis' y: another answer
  const Vector completed =
      solve(gmsh_case(file, "m", "m") + fibre_material("m", fibre, mesh_axes("fibre")));
  EXPECT_GT(relative_difference(completed, from_vector), 1e-2);
  record("d_view_completed_difference", relative_difference(completed, from_vector));
}

TEST(MaterialAxesChain, MeshAxesErrorsNameTheViewAndTheCell) {
  GmshBox mesh;
  mesh.n = 1;
  mesh.views["fibre"] = [](const Vec3& x) { return x.x() < 1.0 ? Vec3(0, 0, 0) : Vec3(1, 0, 0); };
  mesh.views["angle"] = [](const Vec3&) { return Vec3(1, 0, 0); };
  const GmshFile gmsh(mesh, "errors");
  const std::filesystem::path& file = gmsh.path;
  const Vec3 fibre(1, 0, 0);
  const std::string base = gmsh_case(file, "m", "m");
  auto expect_message = [&](const std::string& text, const std::string& fragment) {
    const std::string message = model_error(text);
    EXPECT_NE(message.find(fragment), std::string::npos)
        << "'" << fragment << "' not in: " << message;
  };
  expect_message(base + fibre_material("m", fibre, mesh_axes("fibres")),
                 "materials.m.axes.view = 'fibres': the mesh has no element data view of this "
                 "name (views: angle, fibre;");
  expect_message(base + fibre_material("m", fibre, mesh_axes("fibre")),
                 "materials.m.axes (cell 0, centroid [0.5, 0.5, 0.5]): the view 'fibre' (view) "
                 "gives the zero vector");
  expect_message(base + fibre_material("m", fibre, mesh_axes("angle", "fibre")),
                 "materials.m.axes (cell 0, centroid [0.5, 0.5, 0.5]): the view 'fibre' (d_view) "
                 "gives the zero vector");
  // a box without element data next to the Gmsh mesh
  const std::string with_box = base + R"(
[[mesh.box]]
name = "extra"
origin = [5, 0, 0]
size = [1, 1, 1]
divisions = [1, 1, 1]
material = "m"
)";
  expect_message(with_box + fibre_material("m", fibre, mesh_axes("angle")),
                 "materials.m.axes (cell 0, centroid [5.5, 0.5, 0.5]): the view 'angle' (view) "
                 "has no value for this cell");
}
