// SPDX-License-Identifier: MIT
// Cases on meshes of tet4, tet10, penta6 and hex20 cells through the executable: a Gmsh mesh of
// tet10 cells (made by Gmsh 4.8, tests/unit/mesh/data) stretched with free lateral faces gives
// the closed-form uniaxial reaction, probes and averages; a traction on its faces is carried by
// the supports; triphasic cubes of tet10 and penta6 cells swell in a bath to the closed form;
// what these cells do not take yet stops with an error naming the key.
#include "cli_harness.hpp"

#include <fmt/format.h>

#include <cmath>

namespace trifem::cli_test {
namespace {

const fs::path kMeshes = fs::path(TRIFEM_SOURCE_DIR) / "tests" / "unit" / "mesh" / "data";

/// The unit cube of `mesh` (physical faces xmin ... zmax) stretched along x by `stretch`.
std::string cube_case(const std::string& mesh, double stretch) {
  return fmt::format(R"(
[[mesh.gmsh]]
file = "{}"
materials = {{ cube = "tissue" }}

[materials.tissue]
type = "neo-hookean"
E = 1.0
nu = 0.3

[[boundary.fixed]]
set = "xmin"
components = ["x"]
[[boundary.fixed]]
set = "ymin"
components = ["y"]
[[boundary.fixed]]
set = "zmin"
components = ["z"]

[curves.ramp]
points = [[0.0, 0.0], [1.0, 1.0]]

[[boundary.prescribed]]
set = "xmax"
component = "x"
value = {}
curve = "ramp"

[time]
end_time = 1.0
dt = 0.25

[[output.reaction]]
set = "xmax"
)",
                     (kMeshes / mesh).generic_string(), stretch - 1.0);
}

/// The x force on the face x = 1 of the unit cube stretched uniaxially by l: P11 times the
/// reference area 1, P11 = J σ11 / l with σ11 = (μ (l² − 1) + λ ln J) / J and the lateral
/// stretch t of μ (t² − 1) + λ ln(l t²) = 0 (E = 1, ν = 0.3).
double uniaxial_force(double l) {
  const double lambda = 0.3 / (1.3 * 0.4), mu = 1.0 / 2.6;
  double t = 1.0;
  for (int it = 0; it < 60; ++it)
    t -= (mu * (t * t - 1) + lambda * std::log(l * t * t)) / (2 * mu * t + 2 * lambda / t);
  const double J = l * t * t;
  return (mu * (l * l - 1) + lambda * std::log(J)) / l;
}

class CellsCli : public Cli {};

TEST_F(CellsCli, AGmshTet10CubeStretchedGivesTheClosedFormReactionAndProbes) {
  const fs::path file = write_file("cube.toml", cube_case("cube_tet10_v41.msh", 1.2) + R"(
[[output.probe]]
name = "corner"
point = [1.0, 1.0, 1.0]
[[output.probe]]
name = "inside"
point = [0.3, 0.6, 0.45]
[[output.average]]
name = "mean"
quantity = "displacement"
block = "cube"
)");
  const Result r = trifem({"run", file.string(), "-o", output().string()});
  ASSERT_EQ(r.exit_code, 0) << r;
  const History h = read_history(output() / "history.csv");
  const auto& force = h["xmax.Rx [N]"];
  ASSERT_FALSE(force.empty());
  EXPECT_NEAR(force.back(), uniaxial_force(1.2), 1e-8 * uniaxial_force(1.2));
  // probes at a corner and inside a tet follow the homogeneous stretch (lateral stretch t)
  const double l = 1.2, lambda = 0.3 / (1.3 * 0.4), mu = 1.0 / 2.6;
  double t = 1.0;
  for (int it = 0; it < 60; ++it)
    t -= (mu * (t * t - 1) + lambda * std::log(l * t * t)) / (2 * mu * t + 2 * lambda / t);
  for (const auto& [name, X] : {std::pair<std::string, std::array<double, 3>>{"corner", {1, 1, 1}},
                                {"inside", {0.3, 0.6, 0.45}}}) {
    EXPECT_NEAR(h[name + ".ux [mm]"].back(), (l - 1) * X[0], 1e-9) << name;
    EXPECT_NEAR(h[name + ".uy [mm]"].back(), (t - 1) * X[1], 1e-9) << name;
    EXPECT_NEAR(h[name + ".uz [mm]"].back(), (t - 1) * X[2], 1e-9) << name;
  }
  // the average over the cube is that of the homogeneous field: ((l − 1)/2, (t − 1)/2, (t − 1)/2)
  EXPECT_NEAR(h["mean.ux [mm]"].back(), (l - 1) / 2, 1e-9);
  EXPECT_NEAR(h["mean.uy [mm]"].back(), (t - 1) / 2, 1e-9);
  // 100 tets: the VTU files hold them as cells on the mesh's points (corners and mid-edge)
  const std::string vtu = read_text(output() / "volume_0004.vtu");
  EXPECT_TRUE(contains(vtu, R"(NumberOfCells="100")")) << vtu.substr(0, 400);
}

// The same cube pulled by a dead traction on its tri6 faces: the supports carry the load
// (the stretch is checked against the closed form in Cells/ElementFamilies).
TEST_F(CellsCli, ATractionOnTheFacesOfATet10CubeIsCarriedByTheSupports) {
  std::string text = cube_case("cube_tet10_v41.msh", 1.2);
  const std::size_t first = text.find("[[boundary.prescribed]]");
  text.replace(first, text.find("[time]") - first,
               "[[loads.traction]]\nsurface = \"xmax\"\nvalue = [0.2, 0.0, 0.0]\ncurve = "
               "\"ramp\"\n\n");
  text.replace(text.find("set = \"xmax\"\n", text.find("[[output.reaction]]")), 13,
               "set = \"xmin\"\n");
  const fs::path file = write_file("cube.toml", text);
  const Result r = trifem({"run", file.string(), "-o", output().string()});
  ASSERT_EQ(r.exit_code, 0) << r;
  const History h = read_history(output() / "history.csv");
  EXPECT_NEAR(h["xmin.Rx [N]"].back(), -0.2, 1e-10);
}

TEST_F(CellsCli, ANearlyIncompressibleLawOnTetsAsksForTheElement) {
  std::string text = cube_case("cube_tet4_v22.msh", 1.1);
  text.replace(text.find("nu = 0.3"), 8, "nu = 0.49");
  const fs::path file = write_file("cube.toml", text);
  const Result r = trifem({"run", file.string(), "-o", output().string()});
  EXPECT_EQ(r.exit_code, kInvalidInput) << r;
  EXPECT_TRUE(contains(r.err, "materials.tissue")) << r;
  EXPECT_TRUE(contains(r.err, "nearly incompressible")) << r;
  EXPECT_TRUE(contains(r.err, "tet4")) << r;
  EXPECT_TRUE(contains(r.err, "element = \"displacement\"")) << r;
  // asked for, it runs (and locks: the issue of its own)
  text.replace(text.find("nu = 0.49"), 9, "nu = 0.49\nelement = \"displacement\"");
  write_file("cube.toml", text);
  EXPECT_EQ(trifem({"run", file.string(), "-o", output().string()}).exit_code, 0);
}

// A plate of biphasic hex8 cells pressed on the tri6 faces of a biphasic tet10 cube: mixture
// contact takes linear facets so far (solid contact takes these: the patch test above).
TEST_F(CellsCli, MixtureContactOnQuadraticFacetsIsRefusedNamingTheSurface) {
  std::string text = cube_case("cube_tet10_v41.msh", 1.1);
  text.replace(text.find("type = \"neo-hookean\"\nE = 1.0\nnu = 0.3"),
               std::string("type = \"neo-hookean\"\nE = 1.0\nnu = 0.3").size(),
               "type = \"biphasic\"\nphi_s0 = 0.2\npermeability = 1e-2\n"
               "[materials.tissue.solid]\ntype = \"neo-hookean\"\nE = 1.0\nnu = 0.3");
  text += R"(
[[mesh.box]]
name = "plate"
origin = [0.0, 0.0, 1.0]
size = [1.0, 1.0, 0.2]
divisions = [1, 1, 1]
material = "tissue"

[[contact]]
master = "plate.zmin"
slave = "zmax"
)";
  const fs::path file = write_file("cube.toml", text);
  const Result r = trifem({"run", file.string(), "-o", output().string()});
  EXPECT_EQ(r.exit_code, kInvalidInput) << r;
  EXPECT_TRUE(contains(r.err, "contact[1].slave")) << r;
  EXPECT_TRUE(contains(r.err, "the surface 'zmax' has tri6 facets")) << r;
  EXPECT_TRUE(contains(r.err, "contact of biphasic or triphasic tissue takes linear facets")) << r;
}

TEST_F(CellsCli, ABoxOfWedgesRunsAndTetsRefuseRefinement) {
  const fs::path file = write_file("box.toml", R"(
[[mesh.box]]
name = "bar"
size = [2.0, 1.0, 1.0]
divisions = [2, 1, 1]
cell = "penta6"
material = "tissue"
[materials.tissue]
type = "neo-hookean"
E = 1.0
nu = 0.3
[[boundary.fixed]]
set = "bar.xmin"
[curves.ramp]
points = [[0.0, 0.0], [1.0, 1.0]]
[[boundary.prescribed]]
set = "bar.xmax"
component = "z"
value = -0.1
curve = "ramp"
[time]
end_time = 1.0
dt = 0.5
)");
  EXPECT_EQ(trifem({"run", file.string(), "-o", output().string()}).exit_code, 0);
  const Result r =
      trifem({"run", file.string(), "-o", (dir_ / "fine").string(), "--refine-mesh", "1"});
  EXPECT_EQ(r.exit_code, kInvalidInput) << r;
  EXPECT_TRUE(contains(r.err, "penta6")) << r;
}

/// The octant of a triphasic cube of `mesh` (the paper's tissue, SVK, E = 0.3 MPa, nu = 0):
/// symmetry planes xmin, ymin, zmin (normal displacement and fluxes fixed), the other faces in a
/// bath whose NaCl concentration falls from the reference 0.15 M to `bath` [mmol/mm^3] over 1 s,
/// run to equilibrium (`extra` is appended).
std::string swelling_octant(const std::string& mesh, double bath, const std::string& extra = "") {
  std::string text = fmt::format(R"(
[[mesh.gmsh]]
file = "{}"
materials = {{ cube = "tissue" }}

[materials.tissue]
type = "triphasic"
phi_s0 = 0.25
permeability = 1.07e-3
fixed_charge = 2e-4
d_plus = 5e-4
d_minus = 8e-4
[materials.tissue.solid]
type = "saint-venant-kirchhoff"
E = 0.3
nu = 0.0

[curves.ramp]
points = [[0.0, 0.0], [1.0, 1.0]]

[[boundary.bath]]
surface = "xmax"
concentration = {}
curve = "ramp"
[[boundary.bath]]
surface = "ymax"
concentration = {}
curve = "ramp"
[[boundary.bath]]
surface = "zmax"
concentration = {}
curve = "ramp"

[time]
end_time = 3e5
dt = 0.1
dt_max = 2e4

[[output.probe]]
name = "corner"
point = [1.0, 1.0, 1.0]
)",
                                 (kMeshes / mesh).generic_string(), bath, bath, bath);
  for (const auto& [set, axis] :
       {std::pair<const char*, const char*>{"xmin", "x"}, {"ymin", "y"}, {"zmin", "z"}})
    for (const char* field : {"displacement", "fluid_flux", "cation_flux", "anion_flux"})
      text += fmt::format("[[boundary.fixed]]\nset = \"{}\"\nfield = \"{}\"\ncomponents = "
                          "[\"{}\"]\n",
                          set, field, axis);
  return text + extra;
}

// The contact patch test across cell families through the executable: the Gmsh tet10 cube
// (tri6 faces) pressed by q = 0.1 MPa onto a box of 3 x 3 hex8 cells (quad4 faces) below it, on
// rollers. The exact solution is uniform: traction -q at every slave node (corners and
// mid-edge nodes of the tri6 facets, or the box's nodes), the reaction q times the current
// (laterally expanded) area.
TEST_F(CellsCli, AGmshTet10CubePressedOntoAHexBoxPassesTheContactPatchTest) {
  for (const bool tet_is_slave : {true, false}) {
    SCOPED_TRACE(tet_is_slave ? "tri6 slave" : "quad4 slave");
    const fs::path file =
        write_file("patch.toml", fmt::format(R"(
[[mesh.gmsh]]
file = "{}"
materials = {{ cube = "tissue" }}

[[mesh.box]]
name = "lower"
origin = [0.0, 0.0, -1.0]
size = [1.0, 1.0, 1.0]
divisions = [3, 3, 1]
material = "tissue"

[materials.tissue]
type = "neo-hookean"
E = 1.0
nu = 0.3

[curves.ramp]
points = [[0.0, 0.0], [1.0, 1.0]]

[[boundary.fixed]]
set = "lower.zmin"
components = ["z"]
[[boundary.fixed]]
set = "lower.xmin"
components = ["x"]
[[boundary.fixed]]
set = "lower.ymin"
components = ["y"]
[[boundary.fixed]]
set = "xmin"
components = ["x"]
[[boundary.fixed]]
set = "ymin"
components = ["y"]

[[loads.pressure]]
surface = "zmax"
value = 0.1
curve = "ramp"

[time]
end_time = 1.0
dt = 0.5

[[output.reaction]]
set = "lower.zmin"

[[contact]]
master = "{}"
slave = "{}"
)",
                                             (kMeshes / "cube_tet10_v41.msh").generic_string(),
                                             tet_is_slave ? "lower.zmax" : "zmin",
                                             tet_is_slave ? "zmin" : "lower.zmax"));
    const Result r = trifem({"run", file.string(), "-o", output().string()});
    ASSERT_EQ(r.exit_code, 0) << r;
    const History s = read_history(output() / "contact1_surface_0002.csv");
    const auto& t = s["contact_traction [MPa]"];
    ASSERT_GE(t.size(), 16u); // 4 x 4 box nodes, or the cube face's corner and mid-edge nodes
    for (std::size_t k = 0; k < t.size(); ++k)
      EXPECT_NEAR(t[k], -0.1, 1e-10 * 0.1) << "slave node " << k;
    // the follower pressure acts on the laterally expanded face, the contact on the equal one
    const History h = read_history(output() / "history.csv");
    const double area = h["contact1.area [mm^2]"].back();
    EXPECT_GT(area, 1.05); // lateral strain ν q / E = 3 %
    EXPECT_NEAR(h["lower.zmin.Rz [N]"].back(), 0.1 * area, 1e-10 * 0.1);
    // (the force on the slave body: up on the cube, down on the box)
    EXPECT_NEAR(h["contact1.Fz [N]"].back(), tet_is_slave ? 0.1 * area : -0.1 * area, 1e-10 * 0.1);
  }
}

// A triphasic cube of wedges extruded by Gmsh from an unstructured triangle mesh, moved to a
// 0.015 M bath on its tri3 and quad4 faces, swells to the closed-form isotropic stretch 1.38074
// (docs/theory/reference-solutions.md §R4.4; the hex8 cube: OsmoticLoading.FreeCubeInDiluteBath).
TEST_F(CellsCli, ATriphasicGmshCubeOfWedgesSwellsInADiluteBathToTheClosedForm) {
  const fs::path file = write_file("swell.toml", swelling_octant("cube_penta6_v41.msh", 1.5e-5));
  const Result r = trifem({"run", file.string(), "-o", output().string()});
  ASSERT_EQ(r.exit_code, 0) << r;
  const History h = read_history(output() / "history.csv");
  for (const char* u : {"corner.ux [mm]", "corner.uy [mm]", "corner.uz [mm]"})
    EXPECT_NEAR(1.0 + h[u].back(), 1.38074, 1e-5) << u;
}

// The Gmsh tet10 cube as a biphasic tissue stretched by 20 % in 1 s and held: the fluid first
// carries part of the load (the reaction peaks at the end of the ramp), then drains through the
// free faces until the reaction is the solid's closed-form uniaxial one.
TEST_F(CellsCli, ABiphasicGmshTet10CubeRelaxesToTheDrainedClosedForm) {
  std::string text = cube_case("cube_tet10_v41.msh", 1.2);
  const auto replace = [&](const std::string& from, const std::string& to) {
    text.replace(text.find(from), from.size(), to);
  };
  replace("type = \"neo-hookean\"\nE = 1.0\nnu = 0.3",
          "type = \"biphasic\"\nphi_s0 = 0.2\npermeability = 1e-2\n[materials.tissue.solid]\n"
          "type = \"neo-hookean\"\nE = 1.0\nnu = 0.3");
  replace("end_time = 1.0\ndt = 0.25", "end_time = 20000.0\ndt = 0.25\ndt_max = 2000.0");
  replace("points = [[0.0, 0.0], [1.0, 1.0]]", "points = [[0.0, 0.0], [1.0, 1.0], [20000.0, 1.0]]");
  for (const auto& [set, axis] : {std::pair<const char*, const char*>{"xmin", "x"},
                                  {"ymin", "y"},
                                  {"zmin", "z"},
                                  {"xmax", "x"}})
    text += fmt::format("[[boundary.fixed]]\nset = \"{}\"\nfield = \"fluid_flux\"\n"
                        "components = [\"{}\"]\n",
                        set, axis);
  const fs::path file = write_file("relax.toml", text);
  const Result r = trifem({"run", file.string(), "-o", output().string()});
  ASSERT_EQ(r.exit_code, 0) << r;
  const History h = read_history(output() / "history.csv");
  const auto& force = h["xmax.Rx [N]"];
  const auto& time = h["time [s]"];
  ASSERT_GT(force.size(), 5u);
  double at_ramp_end = 0.0;
  for (std::size_t i = 0; i < time.size(); ++i)
    if (std::abs(time[i] - 1.0) < 1e-9)
      at_ramp_end = force[i];
  EXPECT_GT(at_ramp_end, 1.05 * uniaxial_force(1.2)); // pressurised
  EXPECT_NEAR(force.back(), uniaxial_force(1.2), 1e-6 * uniaxial_force(1.2));
}

TEST_F(CellsCli, MixturesOnTet4AndTriphasicOnTet10AreRefusedNamingTheMaterial) {
  const std::pair<const char*, const char*> cases[] = {
      {"cube_tet4_v22.msh", "tet4 cells cannot carry it"},
      {"cube_tet10_v41.msh", "tet10 cells carry biphasic materials only so far"}};
  for (const auto& [mesh, message] : cases) {
    const fs::path file = write_file("refused.toml", swelling_octant(mesh, 1.5e-4));
    const Result r = trifem({"run", file.string(), "-o", output().string()});
    EXPECT_EQ(r.exit_code, kInvalidInput) << r;
    EXPECT_TRUE(contains(r.err, "materials.tissue")) << r;
    EXPECT_TRUE(contains(r.err, message)) << r;
  }
}

} // namespace
} // namespace trifem::cli_test
