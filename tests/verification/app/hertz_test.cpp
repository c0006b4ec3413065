// SPDX-License-Identifier: MIT
// Contact with a rigid surface: a rigid sphere or cylinder (a body of rigid cells whose bottom
// face lies on it) pressed into an elastic block on symmetry planes. Hertz, E* = E/(1 − ν²):
//   sphere (a quarter):          a³ = 3 P R / (4 E*),  p = p0 √(1 − r²/a²),  <r²> = 2a²/5
//   cylinder (half, plane strain): a² = 4 P' R / (π E*) (P' per length),      <x²> = a²/4
// with <r²> = ∫ p r² dA / ∫ p dA. The second moment is measured from the slave nodes' contact
// forces: an integral of the pressure, insensitive to where the discrete contact edge falls,
// and (unlike the approach δ) to the block's finite size.
#include "case_runner.hpp"
#include "mapped_mesh.hpp"
#include "trifem/mesh/box.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace trifem;

namespace {

constexpr Real kR = 20.0;     // sphere radius [mm]
constexpr Real kDepth = 0.05; // indentation [mm]: a ≈ √(R δ) = 1 mm, a/R = 0.05
constexpr Real kE = 1.0, kNu = 0.3;
constexpr Real kBlock = 20.0; // the quarter block's side and depth [mm]: 20 a
constexpr Real kCap = 2.0;    // the quarter cap's side [mm]
constexpr Real kWidth = 0.2;  // the thickness of the plane-strain model [mm]

enum class Indenter { Sphere, Cylinder };

/// How the rigid indenter is meshed: a body of cells whose bottom face is the contact surface,
/// or only that surface, triangulated (a surface mesh that bounds no cell: a bone surface).
enum class IndenterMesh { Cells, Triangles };

/// The cap: a box of `n` x `n` x 1 cells over [0, kCap]² (`n` x 1 x 1 over [0, kCap] x
/// [0, kWidth] for the cylinder) whose nodes are lifted by the indenter's height above its
/// lowest point, R − √(R² − r²): its face "cap.zmin" lies on the indenter, which touches the
/// block's top at the origin (r² = x² + y², or x² for the cylinder).
mesh::Mesh rigid_cap(Indenter indenter, int n) {
  const bool sphere = indenter == Indenter::Sphere;
  mesh::BoxSpec box;
  box.name = "cap";
  box.size = Vec3(kCap, sphere ? kCap : kWidth, 0.5);
  box.divisions = {n, sphere ? n : 1, 1};
  return test::map_nodes(mesh::make_box(box), [&](const Vec3& X) {
    const Real r2 = X.x() * X.x() + (sphere ? X.y() * X.y() : 0.0);
    return Vec3(X + Vec3(0.0, 0.0, kR - std::sqrt(kR * kR - r2)));
  });
}

/// The bottom face of rigid_cap only, each facet split into two triangles (quads whose last
/// node repeats the third), as the surface "cap.zmin" of a mesh without cells (its nodes keep
/// their positions; the others are unused).
mesh::Mesh triangulated_cap(Indenter indenter, int n) {
  const mesh::Mesh solid = rigid_cap(indenter, n);
  mesh::Mesh cap;
  for (const Vec3& X : solid.nodes())
    cap.add_node(X);
  mesh::Surface bottom;
  for (const mesh::Facet& f : solid.surface("cap.zmin").facets) {
    const auto& a = f.nodes;
    bottom.facets.push_back({.nodes = {a[0], a[1], a[2], a[2]}, .cell = -1, .local_face = -1});
    bottom.facets.push_back({.nodes = {a[0], a[2], a[3], a[3]}, .cell = -1, .local_face = -1});
  }
  cap.add_surface("cap.zmin", bottom);
  return cap;
}

/// The case: the block (n cells per edge, graded towards the contact; one cell thick in y,
/// held in y, for the cylinder) and the cap (`cap_cells` per edge) pushed down by kDepth.
/// The block is of neo-Hookean "soft" (E, ν), or with `biphasic` a biphasic tissue of that solid
/// pressed at equilibrium: each time of the ramp a steady state (drained, the solid's answer).
io::CaseSpec hertz_case(Indenter indenter, int n, int cap_cells,
                        IndenterMesh cap_mesh = IndenterMesh::Cells, bool biphasic = false) {
  const bool sphere = indenter == Indenter::Sphere;
  const Real grading = 28.0; // the outermost cell over the innermost
  io::CaseSpec spec = io::parse_case(
      fmt::format(R"(
[[mesh.box]]
name = "half"
origin = [0.0, 0.0, {}]
size = [{}, {}, {}]
divisions = [{}, {}, {}]
grading = [{}, {}, {}]
material = "soft"
{}
E = {}
nu = {}
[curves.ramp]
points = [[0.0, 0.0], [1.0, 1.0]]
[[boundary.fixed]]
set = "half.xmin"
components = ["x"]
[[boundary.fixed]]
set = "half.ymin"
components = ["y"]
[[boundary.fixed]]
set = "{}"
components = ["y"]
[[boundary.fixed]]
set = "half.zmin"
[[rigid_body]]
name = "ball"
{}
center = [0.0, 0.0, {}]
x = {{ displacement = 0.0 }}
y = {{ displacement = 0.0 }}
z = {{ displacement = {}, curve = "ramp" }}
rx = {{ rotation = 0.0 }}
ry = {{ rotation = 0.0 }}
rz = {{ rotation = 0.0 }}
[[contact]]
master = "cap.zmin"
slave = "half.zmax"
integration = "slave-nodes"
{}
end_time = 1.0
dt = 0.25
)",
                  -kBlock, kBlock, sphere ? kBlock : kWidth, kBlock, n, sphere ? n : 1, n, grading,
                  sphere ? grading : 1.0, 1.0 / grading,
                  biphasic ? "[materials.soft]\ntype = \"biphasic\"\nphi_s0 = "
                             "0.2\npermeability = 1e-3\n[materials.soft.solid]\ntype = "
                             "\"neo-hookean\""
                           : "[materials.soft]\ntype = \"neo-hookean\"",
                  kE, kNu, sphere ? "half.ymin" : "half.ymax",
                  cap_mesh == IndenterMesh::Cells ? R"(blocks = ["cap"])" : R"(set = "cap.zmin")",
                  kR, -kDepth, biphasic ? "[[step]]\nname = \"press\"\nsteady = true" : "[time]"),
      "hertz.toml");
  io::InlineMeshSpec cap;
  cap.mesh = cap_mesh == IndenterMesh::Cells ? rigid_cap(indenter, cap_cells)
                                             : triangulated_cap(indenter, cap_cells);
  spec.meshes.push_back(std::move(cap));
  return spec;
}

struct HertzMeasure {
  Real force = 0.0;         ///< P of the whole sphere [N], P' of the cylinder [N/mm]
  Real second_moment = 0.0; ///< <r²> (<x²>) of the contact pressure [mm²]
};

HertzMeasure measure(const model::Model& m, Indenter indenter) {
  const contact::ContactTerm& contact = *m.contacts.at(0);
  Real force = 0.0, moment = 0.0;
  for (const contact::SlaveNodeState& s : contact.slave_states(m.problem->state())) {
    const Real fz = s.multiplier[0] * s.area_vector.z(); // λ a_k: ≥ 0 on the block's top
    const Real r2 = s.position.x() * s.position.x() +
                    (indenter == Indenter::Sphere ? s.position.y() * s.position.y() : 0.0);
    force += fz;
    moment += fz * r2;
  }
  return {indenter == Indenter::Sphere ? 4.0 * std::abs(force) : 2.0 * std::abs(force) / kWidth,
          moment / force};
}

/// The contact radius (half-width) of Hertz against the measured one, on two meshes: the
/// relative errors.
std::vector<Real> contact_radius_errors(Indenter indenter, bool biphasic = false) {
  const bool sphere = indenter == Indenter::Sphere;
  const Real E_star = kE / (1.0 - kNu * kNu);
  std::vector<Real> errors;
  for (const auto& [n, cap] : {std::pair{12, 10}, {18, 16}}) {
    const io::CaseSpec spec = hertz_case(indenter, n, cap, IndenterMesh::Cells, biphasic);
    const test::CaseRun run = biphasic ? test::run_case_steps(spec) : test::run_case_spec(spec);
    EXPECT_TRUE(run.report.success) << run.report.failure;
    if (!run.report.success)
      return {1.0};
    const HertzMeasure h = measure(*run.model, indenter);
    EXPECT_GT(h.force, 0.0);
    const Real a_hertz = sphere ? std::cbrt(3.0 * h.force * kR / (4.0 * E_star))
                                : std::sqrt(4.0 * h.force * kR / (std::numbers::pi * E_star));
    const Real a_fe = sphere ? std::sqrt(2.5 * h.second_moment) : 2.0 * std::sqrt(h.second_moment);
    errors.push_back(std::abs(a_fe / a_hertz - 1.0));
    std::cout << "  " << (sphere ? "sphere" : "cylinder") << ", cells " << n << ": P = " << h.force
              << (sphere ? " N" : " N/mm") << ", a = " << a_fe << " mm, Hertz " << a_hertz
              << " mm, error " << 100.0 * errors.back() << " %\n";
  }
  return errors;
}

} // namespace

TEST(Hertz, ARigidSpherePressedIntoABlockHasHertzsContactRadius) {
  const std::vector<Real> errors = contact_radius_errors(Indenter::Sphere);
  EXPECT_LT(errors.back(), 0.03);
  EXPECT_LT(errors.back(), errors.front()); // converging under refinement
}

// The sphere given only by its triangulated surface (the rigid body of a bone surface from a
// segmentation): Hertz again on the finer mesh.
TEST(Hertz, ARigidSphereGivenByATriangulatedSurfaceHasHertzsContactRadius) {
  const test::CaseRun run =
      test::run_case_spec(hertz_case(Indenter::Sphere, 18, 16, IndenterMesh::Triangles));
  ASSERT_TRUE(run.report.success) << run.report.failure;
  const HertzMeasure h = measure(*run.model, Indenter::Sphere);
  const Real a_hertz = std::cbrt(3.0 * h.force * kR / (4.0 * kE / (1.0 - kNu * kNu)));
  const Real a_fe = std::sqrt(2.5 * h.second_moment);
  std::cout << "  triangulated sphere: P = " << h.force << " N, a = " << a_fe << " mm, Hertz "
            << a_hertz << " mm, error " << 100.0 * std::abs(a_fe / a_hertz - 1.0) << " %\n";
  EXPECT_LT(std::abs(a_fe / a_hertz - 1.0), 0.03);
}

TEST(Hertz, ARigidCylinderPressedIntoABlockHasHertzsContactHalfWidth) {
  const std::vector<Real> errors = contact_radius_errors(Indenter::Cylinder);
  EXPECT_LT(errors.back(), 0.03);
  EXPECT_LT(errors.back(), errors.front());
}

// A biphasic block at equilibrium (steady states: drained, the fluid pressure gone) is its solid:
// Hertz with the solid's E and ν, the cylinder's flat face impermeable.
TEST(Hertz, ARigidCylinderPressedIntoABiphasicBlockAtEquilibriumHasHertzsContactHalfWidth) {
  const std::vector<Real> errors = contact_radius_errors(Indenter::Cylinder, true);
  EXPECT_LT(errors.back(), 0.03);
  EXPECT_LT(errors.back(), errors.front());
}

namespace {

/// A triphasic block (a quarter, on symmetry planes) on a frictionless base, its top pushed
/// down 5 % in 1 s then held, and `top` appended (how the top is pushed).
std::string pressed_block(const std::string& top) {
  return R"(
[[mesh.box]]
name = "block"
size = [1.0, 1.0, 1.0]
divisions = [3, 3, 3]
material = "tissue"
[materials.tissue]
type = "triphasic"
phi_s0 = 0.25
permeability = 1.07e-3
fixed_charge = 2.0e-4
d_plus = 5.0e-4
d_minus = 8.0e-4
[materials.tissue.solid]
type = "neo-hookean"
E = 0.3
nu = 0.0
[analysis]
initial_state = "donnan-prestressed"
[curves.ramp]
points = [[0.0, 0.0], [1.0, 1.0]]
[[boundary.fixed]]
set = "block.zmin"
components = ["z"]
[[boundary.fixed]]
set = "block.xmin"
components = ["x"]
[[boundary.fixed]]
set = "block.ymin"
components = ["y"]
[time]
end_time = 2.0
dt = 0.25
)" + top;
}

/// The force on the block's base [N] after every step.
std::vector<Real> base_forces(const std::string& text, const std::string& file) {
  std::vector<Real> forces;
  const test::CaseRun run =
      test::run_case_text(text, file, [&](const test::CaseRun& r, const auto&) {
        const model::Model& m = *r.model;
        Real f = 0.0;
        for (Index n : m.mesh.node_set("block.zmin"))
          f += m.problem->full_residual()[m.dofs.dof(m.fields.u, n, 2)];
        forces.push_back(f);
      });
  EXPECT_TRUE(run.report.success) << run.report.failure;
  return forces;
}

} // namespace

TEST(RigidContact, ATriphasicBlockPressedByARigidPlatenIsItsTopPrescribedAndImpermeable) {
  // a platen of rigid cells over the whole top, in frictionless contact: the top follows it in
  // z, slides freely and lets no fluid or ions through, as a top with a prescribed z
  // displacement and an impermeable face
  const std::vector<Real> platen = base_forces(pressed_block(R"(
[[mesh.box]]
name = "plate"
origin = [-0.2, -0.2, 1.0]
size = [1.4, 1.4, 0.2]
divisions = [2, 2, 1]
[[rigid_body]]
name = "platen"
blocks = ["plate"]
x = { displacement = 0.0 }
y = { displacement = 0.0 }
z = { displacement = -0.05, curve = "ramp" }
rx = { rotation = 0.0 }
ry = { rotation = 0.0 }
rz = { rotation = 0.0 }
[[contact]]
master = "plate.zmin"
slave = "block.zmax"
integration = "slave-nodes"
)"),
                                               "platen.toml");
  const std::vector<Real> prescribed = base_forces(pressed_block(R"(
[[boundary.prescribed]]
set = "block.zmax"
component = "z"
value = -0.05
curve = "ramp"
[[boundary.impermeable]]
set = "block.zmax"
normal = "z"
)"),
                                                   "prescribed.toml");
  ASSERT_EQ(platen.size(), prescribed.size());
  ASSERT_GT(std::abs(prescribed.back()), 1e-3);                       // a real load
  const Real scale = std::abs(prescribed[prescribed.size() / 2 - 1]); // the end of the ramp
  for (std::size_t i = 0; i < platen.size(); ++i)
    EXPECT_NEAR(platen[i], prescribed[i], 1e-8 * scale) << "step " << i + 1;
}

namespace {

/// Cattaneo–Mindlin in plane strain: a rigid cylinder (R = kR) pressed by kDepth into a
/// nearly incompressible block (ν = 0.49: the normal and tangential problems barely couple)
/// through Coulomb friction μ, then moved sideways by `slide` (less than the slip distance).
/// Of the tangential force Q < μ P, the stick zone |x| < c, c² = a² (1 - Q/(μ P)), carries
///   q = μ p0 [√(1 - x²/a²) - (c/a) √(1 - x²/c²)],  with  <x²>_q = (a² + c²)/4
/// for its second moment, against <x²>_p = a²/4 of the pressure: <x²>_q / <x²>_p = 2 - Q/(μ P),
/// independent of a (2: all stuck, 1: all slipping).
constexpr Real kFriction = 0.5;
constexpr Real kNearlyIncompressible = 0.49;

/// The whole block in x (cells graded towards x = 0 and z = 0 on both sides), one cell thick in
/// y: 2 n x 1 x n cells.
mesh::Mesh cattaneo_block(int n) {
  mesh::BoxSpec box;
  box.name = "block";
  box.divisions = {2 * n, 1, n};
  const std::vector<Real> half = mesh::graded_coordinates(kBlock, n, 28.0);
  const auto at = [&](int i) { // of the graded half, mirrored for i < 0
    return i < 0 ? -half[static_cast<std::size_t>(-i)] : half[static_cast<std::size_t>(i)];
  };
  return test::map_nodes(mesh::make_box(box), [&](const Vec3& X) {
    const auto i = static_cast<int>(std::lround(X.x() * 2 * n)) - n;
    const auto k = static_cast<int>(std::lround(X.z() * n));
    return Vec3(at(i), X.y() * kWidth, -at(n - k));
  });
}

/// The cylinder's cap over [-kCap, kCap] x [0, kWidth] (2 `cells` x 1 x 1), its bottom face
/// "cap.zmin" on the cylinder, touching the block's top at the origin.
mesh::Mesh full_cylinder_cap(int cells) {
  mesh::BoxSpec box;
  box.name = "cap";
  box.origin = Vec3(-kCap, 0.0, 0.0);
  box.size = Vec3(2.0 * kCap, kWidth, 0.5);
  box.divisions = {2 * cells, 1, 1};
  return test::map_nodes(mesh::make_box(box), [](const Vec3& X) {
    return Vec3(X + Vec3(0.0, 0.0, kR - std::sqrt(kR * kR - X.x() * X.x())));
  });
}

io::CaseSpec cattaneo_case(int n, int cap_cells, Real slide) {
  // (the box stands for the graded block, which replaces it)
  io::CaseSpec spec =
      io::parse_case(fmt::format(R"(
[[mesh.box]]
name = "block"
size = [1.0, 1.0, 1.0]
divisions = [1, 1, 1]
material = "soft"
[materials.soft]
type = "neo-hookean"
E = {}
nu = {}
[curves.press]
points = [[0.0, 0.0], [1.0, 1.0], [2.0, 1.0]]
[curves.slide]
points = [[0.0, 0.0], [1.0, 0.0], [2.0, 1.0]]
[[boundary.fixed]]
set = "block.all"
components = ["y"]
[[boundary.fixed]]
set = "block.zmin"
[[rigid_body]]
name = "cylinder"
blocks = ["cap"]
center = [0.0, 0.0, {}]
x = {{ displacement = {}, curve = "slide" }}
y = {{ displacement = 0.0 }}
z = {{ displacement = {}, curve = "press" }}
rx = {{ rotation = 0.0 }}
ry = {{ rotation = 0.0 }}
rz = {{ rotation = 0.0 }}
[[contact]]
master = "cap.zmin"
slave = "block.zmax"
integration = "slave-nodes"
friction = {}
[time]
end_time = 2.0
dt = 0.25
)",
                                 kE, kNearlyIncompressible, kR, slide, -kDepth, kFriction),
                     "cattaneo.toml");
  spec.boxes.clear();
  io::InlineMeshSpec block, cap;
  block.mesh = cattaneo_block(n);
  block.materials = {{"block", "soft"}};
  cap.mesh = full_cylinder_cap(cap_cells);
  spec.meshes.push_back(std::move(block));
  spec.meshes.push_back(std::move(cap));
  return spec;
}

struct CattaneoMeasure {
  Real normal = 0.0, tangential = 0.0; ///< P, Q of the slave nodes [N]
  Real p_moment = 0.0, q_moment = 0.0; ///< <x²>_p, <x²>_q about the pressure's centre [mm²]
  Index slipping = 0, active = 0;
};

CattaneoMeasure cattaneo_measure(const model::Model& m) {
  const contact::ContactTerm& contact = *m.contacts.at(0);
  const auto states = contact.slave_states(m.problem->state());
  CattaneoMeasure c;
  Real centre = 0.0;
  for (const contact::SlaveNodeState& s : states) {
    const Real fn = -s.multiplier[0] * std::abs(s.area_vector.z());
    c.normal += fn;
    centre += fn * s.position.x();
  }
  centre /= c.normal;
  for (const contact::SlaveNodeState& s : states) {
    const Real fn = -s.multiplier[0] * std::abs(s.area_vector.z());
    const Real ft = s.multiplier[1] * s.area_vector.norm();
    const Real d2 = (s.position.x() - centre) * (s.position.x() - centre);
    c.tangential += ft;
    c.p_moment += fn * d2;
    c.q_moment += ft * d2;
    c.slipping += s.slipping ? 1 : 0;
    c.active += s.active ? 1 : 0;
  }
  c.p_moment /= c.normal;
  c.q_moment /= c.tangential;
  return c;
}

} // namespace

TEST(Hertz, ARigidCylinderPushedSidewaysWithFrictionHasCattaneosStickZone) {
  const test::CaseRun run = test::run_case_spec(cattaneo_case(24, 40, 0.02));
  ASSERT_TRUE(run.report.success) << run.report.failure;
  const CattaneoMeasure c = cattaneo_measure(*run.model);
  const Real load = std::abs(c.tangential) / (kFriction * c.normal);
  const Real ratio = c.q_moment / c.p_moment;
  std::cout << "  Cattaneo: P = " << c.normal << " N, Q = " << c.tangential
            << " N, Q/(mu P) = " << load << ", <x2>_q/<x2>_p = " << ratio << " (exact "
            << 2.0 - load << "), a = " << 2.0 * std::sqrt(c.p_moment) << " mm, slipping "
            << c.slipping << " of " << c.active << " nodes in contact\n";
  EXPECT_GT(load, 0.2);
  EXPECT_LT(load, 0.8);
  EXPECT_LT(std::abs(ratio / (2.0 - load) - 1.0), 0.03);
}
