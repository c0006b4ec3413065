// SPDX-License-Identifier: MIT
// Cases on meshes of tet4, tet10, penta6 and hex20 cells through the executable: a Gmsh mesh of
// tet10 cells (made by Gmsh 4.8, tests/unit/mesh/data) stretched with free lateral faces gives
// the closed-form uniaxial reaction, probes and averages; a traction on its faces is carried by
// the supports; triphasic cubes of tet10 and penta6 cells swell in a bath to the closed form;
// what these cells do not take yet stops with an error naming the key.
#include "cli_harness.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

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
/// stretch t of μ (t² − 1) + λ ln(l t²) = 0 (E = 1, Poisson's ratio nu).
double uniaxial_force(double l, double nu = 0.3) {
  const double lambda = nu / ((1.0 + nu) * (1.0 - 2.0 * nu)), mu = 1.0 / (2.0 * (1.0 + nu));
  double t = 1.0;
  for (int it = 0; it < 60; ++it)
    t -= (mu * (t * t - 1) + lambda * std::log(l * t * t)) / (2 * mu * t + 2 * lambda / t);
  const double J = l * t * t;
  return (mu * (l * l - 1) + lambda * std::log(J)) / l;
}

/// The relative mass balance errors of `species` in a run's summary.json (the whole model's, then
/// each body's; docs/cli.md): every number after "species": in the file.
std::vector<double> balance_errors(const fs::path& summary, const std::string& species) {
  const std::string json = read_text(summary), tag = "\"" + species + "\": ";
  std::vector<double> errors;
  for (auto at = json.find(tag); at != std::string::npos; at = json.find(tag, at + 1))
    errors.push_back(std::strtod(json.c_str() + at + tag.size(), nullptr));
  return errors;
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

// A nearly incompressible law (ν = 0.49) on the Gmsh tet4 cube runs with the dilatation averaged
// over the nodes (the element of one volume per tet would lock) and gives the closed-form
// uniaxial reaction: every node's volume ratio is that of the homogeneous stretch.
TEST_F(CellsCli, ANearlyIncompressibleLawOnTetsTakesTheNodallyAveragedDilatation) {
  std::string text = cube_case("cube_tet4_v22.msh", 1.1);
  text.replace(text.find("nu = 0.3"), 8, "nu = 0.49");
  const fs::path file = write_file("cube.toml", text);
  const Result r = trifem({"run", file.string(), "-o", output().string()});
  ASSERT_EQ(r.exit_code, 0) << r;
  const History h = read_history(output() / "history.csv");
  const double force = uniaxial_force(1.1, 0.49);
  EXPECT_NEAR(h["xmax.Rx [N]"].back(), force, 1e-8 * force);
}

/// The Gmsh tet10 cube (tri6 faces) standing on a box "lower" of 3 x 3 x 1 hex8 cells below it,
/// both of the material "tissue".
std::string tet10_cube_on_a_hex_box() {
  return fmt::format(R"(
[[mesh.gmsh]]
file = "{}"
materials = {{ cube = "tissue" }}

[[mesh.box]]
name = "lower"
origin = [0.0, 0.0, -1.0]
size = [1.0, 1.0, 1.0]
divisions = [3, 3, 1]
material = "tissue"
)",
                     (kMeshes / "cube_tet10_v41.msh").generic_string());
}

// Mixture contact on quadratic facets through the executable: the Gmsh tet10 cube (tri6 faces)
// of biphasic tissue on a biphasic box of 3 x 3 hex8 cells, both confined laterally with
// impermeable sides and bottom, pressed by q = 0.1 MPa on the free-draining top: Terzaghi's
// consolidation through the contact interface (the split column of the paper's §4.1 with a
// tet10 upper body, biphasic). At 20000 s (67 consolidation times L²/(H_A k)) the interface
// is drained and carries the load: contact force q to round-off, water potential ~0, and the
// traction -q at every slave node (the tri6 faces' mid-edge nodes included: their potentials'
// multipliers are linear from the corners). With one pressure per tet the drained state kept
// an error of 1.3e-3 q; with the pressure linear from the corners it is exact
// (docs/theory/elements.md).
TEST_F(CellsCli, ABiphasicTet10CubeConsolidatesThroughContactWithAHexBoxToTheDrainedState) {
  std::string text = tet10_cube_on_a_hex_box() + R"(
[materials.tissue]
type = "biphasic"
phi_s0 = 0.2
permeability = 1e-2
[materials.tissue.solid]
type = "neo-hookean"
E = 1.0
nu = 0.3

[curves.ramp]
points = [[0.0, 0.0], [1.0, 1.0], [20000.0, 1.0]]

[[loads.pressure]]
surface = "zmax"
value = 0.1
curve = "ramp"

[time]
end_time = 20000.0
dt = 0.25
dt_max = 2000.0

[[contact]]
master = "lower.zmax"
slave = "zmin"
)";
  const auto hold = [&](const std::string& set, const char* axis) {
    for (const char* field : {"displacement", "fluid_flux"})
      text += fmt::format("[[boundary.fixed]]\nset = \"{}\"\nfield = \"{}\"\ncomponents = "
                          "[\"{}\"]\n",
                          set, field, axis);
  };
  for (const std::string prefix : {"", "lower."}) {
    hold(prefix + "xmin", "x");
    hold(prefix + "xmax", "x");
    hold(prefix + "ymin", "y");
    hold(prefix + "ymax", "y");
  }
  hold("lower.zmin", "z");
  text += "[[output.reaction]]\nset = \"lower.zmin\"\n";
  const fs::path file = write_file("patch.toml", text);
  const Result r = trifem({"run", file.string(), "-o", output().string()});
  ASSERT_EQ(r.exit_code, 0) << r;
  std::vector<fs::path> surfaces;
  for (const auto& entry : fs::directory_iterator(output()))
    if (entry.path().filename().string().starts_with("contact1_surface_"))
      surfaces.push_back(entry.path());
  ASSERT_FALSE(surfaces.empty());
  const History s = read_history(*std::max_element(surfaces.begin(), surfaces.end()));
  const auto& t = s["contact_traction [MPa]"];
  const auto& mu = s["fluid_chemical_potential [MPa]"];
  ASSERT_GT(t.size(), 16u); // the corners and mid-edge nodes of the cube's bottom face
  double worst = 0.0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    worst = std::max(worst, std::abs(t[k] + 0.1));
    EXPECT_NEAR(t[k], -0.1, 1e-10 * 0.1) << "slave node " << k;
    EXPECT_LE(std::abs(mu[k]), 1e-6 * 0.1) << "slave node " << k;
  }
  std::cout << "largest |traction + q| / q = " << worst / 0.1 << "\n";
  const History h = read_history(output() / "history.csv");
  EXPECT_NEAR(h["contact1.Fz [N]"].back(), 0.1, 1e-10 * 0.1); // on the slave body, up
  // the water of each body and of both: change = outflow through the tri6 and quad4 faces (a
  // tet's water balance holds in its corners' sums, so the sum over its cells is exact to
  // Newton's residual tolerance, not cell by cell: docs/theory/elements.md)
  const std::vector<double> water = balance_errors(output() / "summary.json", "water");
  ASSERT_EQ(water.size(), 3u); // the model, the cube, the box
  for (const double e : water)
    EXPECT_LT(e, 1e-10);
  // the box carries the master-side resultant (the both-surface scheme balances the two only
  // for a uniform traction, docs/theory/contact.md §4.1): 8e-5 q apart here
  EXPECT_NEAR(h["lower.zmin.Rz [N]"].back(), -h["contact1.master_Fz [N]"].back(), 1e-10 * 0.1);
}

// [[constraint]]s on the tri6 faces of the Gmsh tet10 cube: symmetry planes on xmin and ymin and
// a normal-displacement constraint on zmin (whose mid-edge nodes take the facets' own normals)
// hold the cube as the fixed components do: the closed-form uniaxial reaction.
TEST_F(CellsCli, ConstraintsOnTheFacesOfTet10CellsGiveTheClosedFormStretch) {
  std::string text = cube_case("cube_tet10_v41.msh", 1.2);
  const std::string fixed = "[[boundary.fixed]]\nset = \"xmin\"\ncomponents = [\"x\"]\n"
                            "[[boundary.fixed]]\nset = \"ymin\"\ncomponents = [\"y\"]\n"
                            "[[boundary.fixed]]\nset = \"zmin\"\ncomponents = [\"z\"]\n";
  const auto at = text.find(fixed);
  ASSERT_NE(at, std::string::npos) << text;
  text.replace(at, fixed.size(),
               "[[constraint]]\ntype = \"symmetry-plane\"\nsurface = \"xmin\"\n"
               "[[constraint]]\ntype = \"symmetry-plane\"\nsurface = \"ymin\"\n"
               "[[constraint]]\ntype = \"normal-displacement\"\nsurface = \"zmin\"\n");
  const fs::path file = write_file("cube.toml", text);
  const Result r = trifem({"run", file.string(), "-o", output().string()});
  ASSERT_EQ(r.exit_code, 0) << r;
  const History h = read_history(output() / "history.csv");
  EXPECT_NEAR(h["xmax.Rx [N]"].back(), uniaxial_force(1.2), 1e-8 * uniaxial_force(1.2));
}

// `--refine-mesh` on every family: the Gmsh cubes of tet4, tet10, penta6 and hex20 cells refined
// once (each cell into eight of its own type, on the parent's own map) keep the closed-form
// uniaxial stretch, and the refined mesh's cells are eight times the given ones.
TEST_F(CellsCli, RefinedGmshCubesOfEveryFamilyKeepTheClosedFormStretch) {
  for (const auto& [mesh, cells] : {std::pair<std::string, int>{"cube_tet4_v22.msh", -1},
                                    {"cube_tet10_v41.msh", 100},
                                    {"cube_penta6_v41.msh", -1},
                                    {"cube_hex20_v22.msh", -1}}) {
    SCOPED_TRACE(mesh);
    const fs::path file = write_file("cube.toml", cube_case(mesh, 1.2));
    const fs::path coarse = dir_ / "coarse", fine = dir_ / "fine";
    ASSERT_EQ(trifem({"run", file.string(), "-o", coarse.string()}).exit_code, 0);
    const Result r = trifem({"run", file.string(), "-o", fine.string(), "--refine-mesh", "1"});
    ASSERT_EQ(r.exit_code, 0) << r;
    const History h = read_history(fine / "history.csv");
    EXPECT_NEAR(h["xmax.Rx [N]"].back(), uniaxial_force(1.2), 1e-8 * uniaxial_force(1.2));
    const auto count = [](const std::string& vtu) {
      const auto at = vtu.find("NumberOfCells=\"");
      return std::stol(vtu.substr(at + 15));
    };
    const long n = count(read_text(coarse / "volume_0004.vtu"));
    if (cells > 0) {
      EXPECT_EQ(n, cells);
    }
    EXPECT_EQ(count(read_text(fine / "volume_0004.vtu")), 8 * n);
  }
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
        write_file("patch.toml",
                   tet10_cube_on_a_hex_box() + fmt::format(R"(
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
  // water and ions conserved through the tri3 and quad4 faces: content change = outflow
  for (const char* species : {"water", "cation", "anion"}) {
    const std::vector<double> errors = balance_errors(output() / "summary.json", species);
    ASSERT_FALSE(errors.empty()) << species;
    for (const double e : errors)
      EXPECT_LT(e, 1e-12) << species;
  }
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

/// Terzaghi's confined creep of the unit cube of `mesh` (Gmsh's unstructured cells): sides on
/// rollers and impermeable, bottom fixed and impermeable, the free-draining top under a step
/// traction of 1e-4 MPa (biphasic, H_A = 0.3 MPa, κ = 1.07e-3 mm⁴/(N s)), a probe at the top.
std::string confined_creep(const std::string& mesh) {
  std::string text = fmt::format(R"(
[[mesh.gmsh]]
file = "{}"
materials = {{ cube = "tissue" }}
[materials.tissue]
type = "biphasic"
phi_s0 = 0.25
permeability = 1.07e-3
[materials.tissue.solid]
type = "saint-venant-kirchhoff"
E = 0.3
nu = 0.0
[curves.step]
points = [[0.0, 0.0], [1e-9, 1.0]]
[[boundary.fixed]]
set = "zmin"
[[boundary.fixed]]
set = "zmin"
field = "fluid_flux"
components = ["z"]
[[loads.traction]]
surface = "zmax"
value = [0.0, 0.0, -1.0e-4]
curve = "step"
[time]
end_time = 400.0
dt = 1.25
dt_max = 5.0
target_iterations = 3
[output]
interval = 400.0
[[output.probe]]
name = "top"
point = [0.5, 0.5, 1.0]
)",
                                 (kMeshes / mesh).generic_string());
  for (const char* side : {"xmin", "xmax", "ymin", "ymax"}) {
    const char* k = side[0] == 'x' ? "x" : "y";
    text += fmt::format("[[boundary.fixed]]\nset = \"{0}\"\ncomponents = [\"{1}\"]\n"
                        "[[boundary.fixed]]\nset = \"{0}\"\nfield = \"fluid_flux\"\n"
                        "components = [\"{1}\"]\n",
                        side, k);
  }
  return text;
}

/// The top's settlement of Terzaghi's creep at time t (the eigenfunction series at ζ = 1):
/// u = σ0 h/H_A (−1 + Σ 2/M_n² e^{−M_n² T}), M_n = (2n + 1)π/2, T = t H_A κ / h².
double terzaghi_top(double t) {
  const double sigma0 = 1e-4, H_A = 0.3, kappa = 1.07e-3, T = t * H_A * kappa;
  double u = -1.0;
  for (int n = 0; n < 200; ++n) {
    const double M = (2 * n + 1) * std::numbers::pi / 2;
    u += 2.0 / (M * M) * std::exp(-M * M * T);
  }
  return sigma0 / H_A * u;
}

// Terzaghi's consolidation on Gmsh's unstructured unit cubes of biphasic tet10 cells (pressure
// linear from the corners) and of wedges: the top's settlement at t = 400 s (T = 0.128, 71 %
// of the final settlement) within 0.5 % of the series, once refined.
TEST_F(CellsCli, TerzaghiCreepOnUnstructuredTet10AndWedgeCubesMatchesTheSeries) {
  for (const auto& [mesh, refine] : {std::pair<const char*, const char*>{"cube_tet10_v41.msh", "1"},
                                     {"cube_penta6_v41.msh", "2"}}) {
    SCOPED_TRACE(mesh);
    const fs::path file = write_file("creep.toml", confined_creep(mesh));
    const Result r =
        trifem({"run", file.string(), "-o", output().string(), "--refine-mesh", refine});
    ASSERT_EQ(r.exit_code, 0) << r;
    const History h = read_history(output() / "history.csv");
    ASSERT_NEAR(h["time [s]"].back(), 400.0, 1e-9);
    const double exact = terzaghi_top(400.0);
    RecordProperty(mesh, fmt::format("{:.3e}", h["top.uz [mm]"].back() / exact - 1.0));
    EXPECT_NEAR(h["top.uz [mm]"].back(), exact, 5e-3 * std::abs(exact));
  }
}

// ... naming the first such cell by its element tag in the Gmsh file (the first tetrahedron of
// either file is its element 85), not by trifem's own cell index.
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
    EXPECT_TRUE(
        contains(r.err, fmt::format("element 85 of '{}'", (kMeshes / mesh).generic_string())))
        << r;
  }
}

/// The unit cube of `mesh` in a dynamic-explicit analysis: the multiplier's law (μ = 1/2,
/// penalty 1000 μ), the face xmax moved to the stretch 1.2 over 5 s and held, damped to rest.
std::string explicit_cube_case(const std::string& mesh) {
  std::string text = cube_case(mesh, 1.2);
  text.replace(text.find("nu = 0.3"), 8, "nu = 0.0\ndensity = 1.0");
  text.replace(text.find("points = [[0.0, 0.0], [1.0, 1.0]]"), 33,
               "interpolation = \"smooth\"\npoints = [[0.0, 0.0], [5.0, 1.0]]");
  text.replace(text.find("end_time = 1.0\ndt = 0.25"), 24, "end_time = 40.0");
  return text + R"(
[analysis]
type = "dynamic-explicit"
[explicit]
penalty = 500.0
damping = 1.0
[output]
interval = 5.0
)";
}

TEST_F(CellsCli, AnExplicitAnalysisOfTheGmshTet10CubeComesToRestAtTheClosedFormStretch) {
  // homogeneous uniaxial stress of W = μ/2 (I1 − 3) − μ ln J with λ = α (J − 1): the lateral
  // stretch b of μ (1 − 1/b²) + α a (a b² − 1) = 0 and the force P = μ (a − 1/a) + λ J / a on
  // the unit face (tests/verification/explicit/exact_uniaxial.hpp)
  const fs::path file = write_file("explicit.toml", explicit_cube_case("cube_tet10_v41.msh"));
  const Result r = trifem({"run", file.string(), "-o", output().string()});
  ASSERT_EQ(r.exit_code, 0) << r;
  const double mu = 0.5, alpha = 1000.0 * mu, a = 1.2;
  double b = 1.0 / std::sqrt(a);
  for (int it = 0; it < 50; ++it)
    b -= (mu * (1.0 - 1.0 / (b * b)) + alpha * a * (a * b * b - 1.0)) /
         (2.0 * mu / (b * b * b) + 2.0 * alpha * a * a * b);
  const double J = a * b * b, force = mu * (a - 1.0 / a) + alpha * (J - 1.0) * J / a;
  const History h = read_history(output() / "history.csv");
  ASSERT_GT(h["xmax.Rx [N]"].size(), 5u);
  EXPECT_NEAR(h["xmax.Rx [N]"].back(), force, 1e-6 * force);
}

TEST_F(CellsCli, AnExplicitAnalysisRefusesTet4CellsNamingTheLocking) {
  const fs::path file = write_file("explicit.toml", explicit_cube_case("cube_tet4_v22.msh"));
  const Result r = trifem({"run", file.string(), "-o", output().string()});
  EXPECT_EQ(r.exit_code, kInvalidInput) << r;
  EXPECT_TRUE(contains(r.err, "dynamic-explicit")) << r;
  EXPECT_TRUE(contains(r.err, "tet4")) << r;
  EXPECT_TRUE(contains(r.err, "lock")) << r;
}

} // namespace
} // namespace trifem::cli_test
