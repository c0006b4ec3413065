// SPDX-License-Identifier: MIT
// Cook's membrane, quasi-static, plane strain, nearly incompressible neo-Hookean (E = 240.565 MPa,
// nu = 0.499), 100 N shear on the free edge: the mean-dilatation element converges to the
// reference tip deflection (about 6.89 mm) while the displacement element locks.
#include "case_runner.hpp"
#include "generated_meshes.hpp"
#include "run_to_run.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

using namespace trifem;
namespace fs = std::filesystem;

namespace {

/// Reference tip deflection of the converged plane-strain problem [mm] (the value the
/// literature's mixed elements converge to for this material and load).
constexpr Real kReferenceTip = 6.89;

/// Writes the Cook's membrane of n x n x 1 cells as a Gmsh 2.2 file with the physical groups
/// "membrane" (cells), "clamp" (the x = 0 edge) and "load" (the x = 48 mm edge).
void write_cook_mesh(int n, const fs::path& file) {
  test::CookSpec spec;
  spec.nx = spec.ny = n;
  const mesh::Mesh m = test::make_cook_membrane(spec);
  std::ofstream out(file);
  out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
  out << "$PhysicalNames\n3\n2 1 \"clamp\"\n2 2 \"load\"\n3 3 \"membrane\"\n$EndPhysicalNames\n";
  out.precision(17);
  out << "$Nodes\n" << m.num_nodes() << "\n";
  for (Index i = 0; i < m.num_nodes(); ++i)
    out << i + 1 << " " << m.node(i).x() << " " << m.node(i).y() << " " << m.node(i).z() << "\n";
  out << "$EndNodes\n";
  const auto& clamp = m.surface("cook.xmin").facets;
  const auto& load = m.surface("cook.xmax").facets;
  out << "$Elements\n" << clamp.size() + load.size() + m.num_cells() << "\n";
  Index id = 1;
  for (const auto& [facets, tag] : {std::pair{&clamp, 1}, std::pair{&load, 2}})
    for (const mesh::Facet& f : *facets)
      out << id++ << " 3 2 " << tag << " " << tag << " " << f.nodes[0] + 1 << " " << f.nodes[1] + 1
          << " " << f.nodes[2] + 1 << " " << f.nodes[3] + 1 << "\n";
  for (Index c = 0; c < m.num_cells(); ++c) {
    out << id++ << " 5 2 3 3";
    for (Index a : m.cell(c))
      out << " " << a + 1;
    out << "\n";
  }
  out << "$EndElements\n";
}

/// The case: clamped edge, plane strain (u_z = 0), dead shear traction 100 N / 16 mm² on the
/// free edge ramped over 1 s. `element` is the material's element key ("" to leave it out).
std::string cook_case(const std::string& element) {
  return R"(
[[mesh.gmsh]]
file = "cook.msh"
materials = { membrane = "rubber" }

[materials.rubber]
type = "neo-hookean"
E = 240.565
nu = 0.499
)" + (element.empty() ? "" : "element = \"" + element + "\"\n") +
         R"(
[curves.ramp]
points = [[0, 0], [1, 1]]

[[boundary.fixed]]
set = "clamp"

[[boundary.fixed]]
set = "membrane"
components = ["z"]

[[loads.traction]]
surface = "load"
value = [0, 6.25, 0]
curve = "ramp"

[time]
end_time = 1.0
dt = 0.25
dt_max = 0.25
)";
}

/// Vertical displacement of the top corner (48, 60) [mm] at the end of the run.
Real tip_deflection(int n, const std::string& element) {
  const fs::path dir = fs::temp_directory_path() /
                       ("trifem_cook_" + std::to_string(getpid()) + "_" + std::to_string(n));
  fs::create_directories(dir);
  write_cook_mesh(n, dir / "cook.msh");
  const test::CaseRun run = test::run_case_text(cook_case(element), dir / "case.toml");
  EXPECT_TRUE(run.report.success) << element << " " << n << ": " << run.report.failure;
  const model::Model& m = *run.model;
  for (Index i = 0; i < m.mesh.num_nodes(); ++i)
    if ((m.mesh.node(i) - Vec3(48.0, 60.0, 0.0)).norm() < 1e-9)
      return m.problem->state()[m.dofs.dof(m.fields.u, i, 1)];
  ADD_FAILURE() << "no node at the tip";
  return 0.0;
}

} // namespace

TEST(CookMembrane, MeanDilatationConvergesToTheReferenceWhereTheDisplacementElementLocks) {
  std::map<int, Real> tip;
  for (int n : {8, 16, 32})
    tip[n] = tip_deflection(n, "mean-dilatation");
  // within 1 % of the reference at 32 x 32, and converging: each halving of h at least halves
  // the distance to the finest mesh's answer
  EXPECT_NEAR(tip[32], kReferenceTip, 0.01 * kReferenceTip);
  EXPECT_LT(std::abs(tip[16] - tip[32]), 0.5 * std::abs(tip[8] - tip[32]));
  // the displacement element on the same 16 x 16 mesh locks: far stiffer
  const Real locked = tip_deflection(16, "displacement");
  EXPECT_LT(locked, 0.7 * tip[16]);
  // "auto" (no key) chooses the mean-dilatation element for nu = 0.499
  EXPECT_TRUE(test::same_run_to_run(tip_deflection(8, ""), tip[8], kReferenceTip));
  std::printf("tip deflection [mm]: mean dilatation 8x8 %.4f, 16x16 %.4f, 32x32 %.4f; "
              "displacement 16x16 %.4f\n",
              tip[8], tip[16], tip[32], locked);
}

TEST(CookMembrane, ElementKeyErrorsNameTheKeyAndTheChoices) {
  const auto error_of = [](const std::string& text) -> std::string {
    try {
      io::parse_case(text, "memory/case.toml");
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  const std::string box = R"(
[[mesh.box]]
name = "block"
size = [1, 1, 1]
divisions = [1, 1, 1]
material = "rubber"
[time]
end_time = 1.0
dt = 0.5
[materials.rubber]
type = "neo-hookean"
E = 1.0
density = 1e-9
)";
  const std::string bad = error_of(box + "element = \"q1p0\"\n");
  EXPECT_NE(bad.find("materials.rubber.element"), std::string::npos) << bad;
  EXPECT_NE(bad.find("auto, displacement, mean-dilatation"), std::string::npos) << bad;
  const std::string explicit_run =
      error_of("[analysis]\ntype = \"dynamic-explicit\"\n" + box + "element = \"auto\"\n");
  EXPECT_NE(explicit_run.find("materials.rubber.element: not used in dynamic-explicit analyses"),
            std::string::npos)
      << explicit_run;
  EXPECT_EQ(io::parse_case(box + "element = \"displacement\"\n", "memory/case.toml")
                .materials.at("rubber")
                .element,
            io::SolidElementSpec::Displacement);
}
