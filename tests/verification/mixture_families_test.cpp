// SPDX-License-Identifier: MIT
// The biphasic and triphasic mixture on tet10, penta6 and hex20 cells against the exact answers
// (docs/verification.md "Cell families"): Terzaghi's confined creep, Donnan equilibrium at a
// prescribed stretch and free swelling; tets with their potentials linear from the corners, on
// Kuhn-split and unstructured (Gmsh) meshes.
#include "exact/exact_solutions.hpp"
#include "mixture_model.hpp"
#include "trifem/mesh/convert_cells.hpp"
#include "trifem/mesh/gmsh_reader.hpp"
#include "trifem/physics/bath_term.hpp"

#include <Eigen/SVD>
#include <gtest/gtest.h>

#include <cmath>

using namespace trifem;

namespace mixture_families_test {

constexpr Real kSigma0 = 1e-4; ///< applied compressive stress [MPa]
const exact::ConfinedLayer kLayer{1.0, 0.3, 1.07e-3};

/// The Gmsh tet10 cube (1 mm, 100 cells; tests/unit/mesh/data/cube_tet.geo) with the node sets
/// of the box meshes: box.xmin, ..., box.zmax.
mesh::Mesh gmsh_tet10_cube() {
  mesh::Mesh m =
      mesh::read_gmsh(std::string(TRIFEM_SOURCE_DIR) + "/tests/unit/mesh/data/cube_tet10_v41.msh");

  for (const char* side : {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"})
    m.add_surface(std::string("box.") + side, m.surface(side)); // (and its node set)
  return m;
}

/// One box cell turned into `type` cells, or the Gmsh tet10 cube for Tet10 if `gmsh`.
mesh::Mesh cube_mesh(mesh::CellType type, int divisions, bool gmsh) {
  if (gmsh)
    return gmsh_tet10_cube();
  mesh::BoxSpec spec;
  spec.divisions = {divisions, divisions, divisions};
  return mesh::convert_cells(mesh::make_box(spec), type);
}

test::MixtureModel creep_column(mesh::CellType type, int n) {
  return test::creep_column(n, test::paper_tissue(false), kSigma0, type);
}

/// The top's displacement at t = 400 s (about 0.4 of the consolidation time), steps of dt.
Real creep_top(mesh::CellType type, int n, Real dt) {
  test::MixtureModel m = creep_column(type, n);
  const solver::RunReport run = m.run(400.0, dt, dt, {});
  EXPECT_TRUE(run.success) << mesh::name(type) << ": " << run.failure;
  return m.value(m.f.u, m.mesh.node_set("box.zmax").front(), 2);
}

Real creep_error(mesh::CellType type, int n, Real dt) {
  const Real exact = exact::creep_surface_displacement(kLayer, kSigma0, 400.0);
  return std::abs(creep_top(type, n, dt) - exact) / std::abs(exact);
}

/// One box cell turned into `type` cells in the reference bath, every node moved by the
/// homogeneous stretch `stretch` along z: J = stretch in every cell.
test::MixtureModel stretched_cube(mesh::CellType type, Real stretch, bool gmsh) {
  test::MixtureModel m(cube_mesh(type, 1, gmsh), test::paper_tissue(true));
  for (Index n = 0; n < m.mesh.num_nodes(); ++n)
    for (int k = 0; k < 3; ++k)
      m.conditions.push_back({{m.dofs.dof(m.f.u, n, k)},
                              k == 2 ? (stretch - 1.0) * m.mesh.node(n).z() : 0.0,
                              dofs::LoadCurve::constant()});
  m.build();
  return m;
}

/// Every cell holds the Donnan state at J: the largest relative error of J, c+, c- (relative to
/// the ions' sum), p and η over the cells is at most `tolerance`.
void expect_donnan_everywhere(const test::MixtureModel& m, Real J, Real tolerance) {
  const exact::DonnanState d = exact::donnan_at(exact::paper_medium(), J);
  std::array<Real, 5> worst{};
  for (Index e = 0; e < m.mixture->num_elements(); ++e) {
    const physics::MixtureCellOutput out = m.mixture->output(e, m.problem->state());
    const auto [p, eta] =
        physics::cell_potentials(m.mesh, m.dofs, m.f, m.problem->state(), m.mixture->cell(e));
    const std::array<Real, 5> error = {
        std::abs(out.J - J) / J, std::abs(out.chem.c_plus - d.c_plus) / (d.c_plus + d.c_minus),
        std::abs(out.chem.c_minus - d.c_minus) / (d.c_plus + d.c_minus),
        std::abs(p - d.pressure) / d.pressure,
        std::abs(eta / m.chem.c_ref - d.eta) / std::abs(d.eta)};
    for (std::size_t i = 0; i < error.size(); ++i)
      worst[i] = std::max(worst[i], error[i]);
  }
  const char* names[5] = {"J", "c+", "c-", "p", "eta"};
  const std::string family = mesh::name(m.mesh.cell_type(m.mixture->cell(0))).data();
  std::cout << family << ": largest relative errors of the Donnan state";
  for (std::size_t i = 0; i < worst.size(); ++i) {
    std::cout << (i ? ", " : " ") << names[i] << " " << worst[i];
    EXPECT_LE(worst[i], tolerance) << family << " " << names[i];
  }
  std::cout << "\n";
}

/// A 1 mm cube of 2 x 2 x 2 box cells turned into `type` cells: symmetry planes xmin, ymin,
/// zmin (normal u = 0, impermeable), the other faces traction-free in the reference bath.
test::MixtureModel free_cube(mesh::CellType type, bool gmsh, bool charged = true) {
  test::MixtureModel m(cube_mesh(type, 2, gmsh), test::paper_tissue(charged));
  const char* planes[3] = {"box.xmin", "box.ymin", "box.zmin"};
  for (int k = 0; k < 3; ++k) {
    m.fix(planes[k], m.f.u, k);
    m.impermeable(planes[k], k);
  }
  m.build();
  return m;
}

/// The families that carry triphasic materials besides hex8, and whether their mesh is Gmsh's.
struct Family {
  mesh::CellType type;
  bool gmsh;
};
constexpr Family kMixtureFamilies[] = {{mesh::CellType::Penta6, false},
                                       {mesh::CellType::Hex20, false}};
/// Those and the tet10 kernel with corner potentials on an unstructured mesh (which the models
/// do not take for triphasic tissue yet: docs/theory/elements.md).
constexpr Family kKernelFamilies[] = {
    {mesh::CellType::Penta6, false}, {mesh::CellType::Hex20, false}, {mesh::CellType::Tet10, true}};

/// The smallest singular value of the Jacobian of `m` at the first step (dt = 1 s), relative to
/// the largest, after scaling each row and then each column by its largest entry (the unknowns
/// and equations have different units), and the number below 1e-12 of the largest.
std::pair<Real, int> smallest_singular_value(test::MixtureModel& m) {
  m.problem->begin_step(1.0, 1.0);
  solver::Linearization lin;
  m.problem->linearize(lin, true);
  Eigen::MatrixXd A(lin.jacobian);
  for (Index i = 0; i < A.rows(); ++i)
    A.row(i) /= A.row(i).cwiseAbs().maxCoeff();
  for (Index j = 0; j < A.cols(); ++j)
    A.col(j) /= A.col(j).cwiseAbs().maxCoeff();
  const Eigen::VectorXd sv = Eigen::BDCSVD<Eigen::MatrixXd>(A).singularValues();
  int null = 0;
  for (Index i = 0; i < sv.size(); ++i)
    null += sv[i] < 1e-12 * sv[0] ? 1 : 0;
  return {sv[sv.size() - 1] / sv[0], null};
}

} // namespace mixture_families_test

using namespace mixture_families_test;

/// In this one-dimensional problem a column of hex20 cells or of wedges gives the hex8 column's
/// answer (the fluxes of a hex20 are its corners' trilinear functions), within 0.5 % of
/// Terzaghi's series; refined in h and dt together the error falls as the hex8's.
TEST(MixtureFamilies, TerzaghiCreepOnHex20AndPenta6IsTheHex8Answer) {
  for (int n : {10, 20}) {
    const Real dt = 50.0 / n;
    const Real hex8 = creep_top(mesh::CellType::Hex8, n, dt);
    for (mesh::CellType type : {mesh::CellType::Hex20, mesh::CellType::Penta6})
      EXPECT_NEAR(creep_top(type, n, dt), hex8, 1e-9 * std::abs(hex8)) << mesh::name(type);
  }
  EXPECT_LT(creep_error(mesh::CellType::Hex20, 20, 2.5), 5e-3);
}

/// Biphasic tet10 cells (quadratic displacement, fluxes and pressure linear from the corners)
/// converge to Terzaghi's series as the hex8 column does, refined in h and dt together, and are
/// more accurate than it at every level (docs/theory/elements.md).
TEST(MixtureFamilies, TerzaghiCreepOnTet10ConvergesToTheSeries) {
  std::vector<Real> errors;
  for (int n : {10, 20, 40}) {
    const Real tet10 = creep_error(mesh::CellType::Tet10, n, 50.0 / n);
    const Real hex8 = creep_error(mesh::CellType::Hex8, n, 50.0 / n);
    std::cout << n << " layers: relative error of u_top(400 s) tet10 " << tet10 << ", hex8 " << hex8
              << "\n";
    EXPECT_LT(tet10, hex8) << n << " layers";
    errors.push_back(tet10);
  }
  EXPECT_LT(errors[2], 2e-4);
  EXPECT_GT(errors[0] / errors[1], 1.5);
  EXPECT_GT(errors[0] / errors[2], 6.0); // first order would give 4
}

/// IC-1 at a prescribed homogeneous stretch is the closed-form Donnan state in every cell and an
/// exact equilibrium: the first residual vanishes, no iteration.
TEST(MixtureFamilies, DonnanStateAtAPrescribedStretchIsExactOnEveryFamily) {
  for (const auto& [type, gmsh] : kKernelFamilies)
    for (Real J : {1.0, 0.9, 1.15}) {
      test::MixtureModel m = stretched_cube(type, J, gmsh);
      expect_donnan_everywhere(m, J, 1e-8);
      const solver::RunReport run = m.run(10.0, 10.0, 10.0);
      ASSERT_TRUE(run.success) << mesh::name(type) << ": " << run.failure;
      EXPECT_EQ(run.iterations, 0) << mesh::name(type) << " J = " << J;
      expect_donnan_everywhere(m, J, 1e-8);
    }
}

/// Free swelling of a cube from IC-1 (docs/theory/reference-solutions.md §R4): the stretch is
/// the closed-form root (SVK, 1.0755...) and every cell holds the Donnan state there, to 1e-6.
TEST(MixtureFamilies, FreeSwellingMatchesTheClosedFormOnEveryFamily) {
  const exact::SwellingState exact_state =
      exact::swelling_equilibrium(exact::SolidLaw::StVenantKirchhoff, exact::Deformation::Isotropic,
                                  0.3, 0.0, exact::paper_medium());
  for (const auto& [type, gmsh] : kMixtureFamilies) {
    test::MixtureModel m = free_cube(type, gmsh);
    Index corner = -1;
    for (Index n = 0; n < m.mesh.num_nodes(); ++n)
      if ((m.mesh.node(n) - Vec3::Ones()).norm() < 1e-12)
        corner = n;
    ASSERT_GE(corner, 0);
    const solver::RunReport run = m.run(2e5, 1.0, 1e4);
    ASSERT_TRUE(run.success) << mesh::name(type) << ": " << run.failure;
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(1.0 + m.value(m.f.u, corner, k), exact_state.stretch, 1e-6 * exact_state.stretch)
          << mesh::name(type) << " direction " << k;
    expect_donnan_everywhere(m, exact_state.J, 1e-6);
  }
}

/// The free cube moved to a 0.015 M bath on its faces x, y, z = 1 mm (BathTerm on tri3 and quad4
/// facets of wedges, quad8 facets of hex20 cells) swells to the closed-form isotropic stretch
/// (docs/theory/reference-solutions.md §R4.4: 1.38074) with the Donnan state of the new bath in
/// every cell.
TEST(MixtureFamilies, FreeCubeInADiluteBathMatchesTheClosedFormOnEveryFamily) {
  exact::ChargedMedium medium = exact::paper_medium();
  medium.c_bath = 1.5e-5;
  const exact::SwellingState eq = exact::swelling_equilibrium(
      exact::SolidLaw::StVenantKirchhoff, exact::Deformation::Isotropic, 0.3, 0.0, medium);
  for (const auto& [type, gmsh] : kMixtureFamilies) {
    test::MixtureModel m(cube_mesh(type, 2, gmsh), test::paper_tissue(true));
    std::vector<mesh::Facet> bath;
    for (const char* face : {"box.xmax", "box.ymax", "box.zmax"}) {
      const auto& f = m.mesh.surface(face).facets;
      bath.insert(bath.end(), f.begin(), f.end());
    }
    const char* planes[3] = {"box.xmin", "box.ymin", "box.zmin"};
    for (int k = 0; k < 3; ++k) {
      m.fix(planes[k], m.f.u, k);
      m.impermeable(planes[k], k);
    }
    m.loads.push_back(std::make_unique<physics::BathTerm>(
        m.mesh, m.dofs, m.f, bath, m.chem, medium.c_bath,
        dofs::LoadCurve({{0.0, 0.0}, {1.0, 1.0}}, dofs::Interpolation::Linear)));
    m.build();
    const solver::RunReport run = m.run(3e5, 0.1, 2e4);
    ASSERT_TRUE(run.success) << mesh::name(type) << ": " << run.failure;
    Index corner = -1;
    for (Index n = 0; n < m.mesh.num_nodes(); ++n)
      if ((m.mesh.node(n) - Vec3::Ones()).norm() < 1e-12)
        corner = n;
    ASSERT_GE(corner, 0);
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(1.0 + m.value(m.f.u, corner, k), eq.stretch, 1e-6 * eq.stretch)
          << mesh::name(type) << " direction " << k;
    for (Index e = 0; e < m.mixture->num_elements(); ++e) {
      const auto out = m.mixture->output(e, m.problem->state());
      const Real ions = eq.donnan.c_plus + eq.donnan.c_minus; // (the co-ions are few)
      EXPECT_NEAR(out.chem.c_plus, eq.donnan.c_plus, 1e-6 * ions) << mesh::name(type);
      EXPECT_NEAR(out.chem.c_minus, eq.donnan.c_minus, 1e-6 * ions) << mesh::name(type);
    }
  }
}

/// The free cube's Jacobian is regular for the pairs the models take (hex8, penta6, hex20 with
/// either mixture; tet10 with its potentials linear from the corners, biphasic on any mesh and
/// triphasic on an unstructured one) and singular where they refuse it (docs/theory/elements.md):
/// on Kuhn's split of hexes every tet has one corner of each of four colours, and the electric
/// potential, seen only through its mean over every tet, is free in the three colour modes; a
/// tet10's pressure is held there by the quadratic displacement.
TEST(MixtureFamilies, JacobiansAreRegularExceptWhereTheModelsRefuseThePair) {
  struct Case {
    mesh::CellType type;
    bool charged, gmsh;
    int null; ///< singular values below 1e-12 of the largest
  };
  const Case cases[] = {
      {mesh::CellType::Hex8, true, false, 0},  {mesh::CellType::Penta6, true, false, 0},
      {mesh::CellType::Hex20, true, false, 0}, {mesh::CellType::Tet10, false, false, 0},
      {mesh::CellType::Tet10, false, true, 0}, {mesh::CellType::Tet10, true, true, 0},
      {mesh::CellType::Tet10, true, false, 3}};
  for (const Case& c : cases) {
    test::MixtureModel m = free_cube(c.type, c.gmsh, c.charged);
    const auto [smallest, null] = smallest_singular_value(m);
    const std::string name =
        fmt::format("{} {} ({})", mesh::name(c.type), c.charged ? "triphasic" : "biphasic",
                    c.gmsh ? "Gmsh" : "Kuhn");
    std::cout << name << ": smallest singular value " << smallest << ", " << null
              << " below 1e-12\n";
    EXPECT_EQ(null, c.null) << name;
    if (c.null == 0)
      EXPECT_GT(smallest, 1e-6) << name;
  }
}
