// SPDX-License-Identifier: MIT
// The biphasic and triphasic mixture on tet10, penta6 and hex20 cells against the exact answers
// (docs/verification.md "Cell families"): Terzaghi's confined creep, Donnan equilibrium at a
// prescribed stretch and free swelling; and tet4, whose Jacobian is singular.
#include "exact/exact_solutions.hpp"
#include "mixture_model.hpp"
#include "trifem/mesh/convert_cells.hpp"
#include "trifem/physics/bath_term.hpp"

#include <Eigen/SVD>
#include <gtest/gtest.h>

#include <cmath>

using namespace trifem;

namespace mixture_families_test {

constexpr Real kSigma0 = 1e-4; ///< applied compressive stress [MPa]
const exact::ConfinedLayer kLayer{1.0, 0.3, 1.07e-3};

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
test::MixtureModel stretched_cube(mesh::CellType type, Real stretch) {
  mesh::BoxSpec spec;
  spec.divisions = {1, 1, 1};
  test::MixtureModel m(mesh::convert_cells(mesh::make_box(spec), type), test::paper_tissue(true));
  for (Index n = 0; n < m.mesh.num_nodes(); ++n)
    for (int k = 0; k < 3; ++k)
      m.conditions.push_back({{m.dofs.dof(m.f.u, n, k)},
                              k == 2 ? (stretch - 1.0) * m.mesh.node(n).z() : 0.0,
                              dofs::LoadCurve::constant()});
  m.build();
  return m;
}

/// Every cell holds the Donnan state at J (relative tolerance `tolerance`).
void expect_donnan_everywhere(const test::MixtureModel& m, Real J, Real tolerance) {
  const exact::DonnanState d = exact::donnan_at(exact::paper_medium(), J);
  for (Index e = 0; e < m.mixture->num_elements(); ++e) {
    const physics::MixtureCellOutput out = m.mixture->output(e, m.problem->state());
    const Index c = m.mixture->cell(e);
    const std::string where = fmt::format("{} cell {}", mesh::name(m.mesh.cell_type(c)), c);
    EXPECT_NEAR(out.J, J, tolerance * J) << where;
    EXPECT_NEAR(out.chem.c_plus, d.c_plus, tolerance * d.c_plus) << where;
    EXPECT_NEAR(out.chem.c_minus, d.c_minus, tolerance * d.c_minus) << where;
    EXPECT_NEAR(m.value(m.f.p, c), d.pressure, tolerance * d.pressure) << where;
    EXPECT_NEAR(m.value(m.f.eta, c) / m.chem.c_ref, d.eta, tolerance * std::abs(d.eta)) << where;
  }
}

/// A 1 mm cube of 2 x 2 x 2 box cells turned into `type` cells: symmetry planes xmin, ymin,
/// zmin (normal u = 0, impermeable), the other faces traction-free in the reference bath.
test::MixtureModel free_cube(mesh::CellType type) {
  mesh::BoxSpec spec;
  spec.divisions = {2, 2, 2};
  test::MixtureModel m(mesh::convert_cells(mesh::make_box(spec), type), test::paper_tissue(true));
  const char* planes[3] = {"box.xmin", "box.ymin", "box.zmin"};
  for (int k = 0; k < 3; ++k) {
    m.fix(planes[k], m.f.u, k);
    m.impermeable(planes[k], k);
  }
  m.build();
  return m;
}

/// The families that carry triphasic materials besides hex8.
constexpr mesh::CellType kMixtureFamilies[] = {mesh::CellType::Penta6, mesh::CellType::Hex20};

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

/// Biphasic tet10 cells (quadratic displacement, fluxes linear from the corners, pressure per
/// cell) converge to Terzaghi's series at first order in h (docs/theory/elements.md): within
/// 0.5 % at 80 layers of box cells (480 tets). (The error is the mesh's: steps of 5 s.)
TEST(MixtureFamilies, TerzaghiCreepOnTet10ConvergesToTheSeries) {
  const Real coarse = creep_error(mesh::CellType::Tet10, 20, 5.0);
  const Real medium = creep_error(mesh::CellType::Tet10, 40, 5.0);
  const Real fine = creep_error(mesh::CellType::Tet10, 80, 5.0);
  std::cout << "tet10 relative error of u_top(400 s): " << coarse << ", " << medium << ", " << fine
            << "\n";
  EXPECT_LT(fine, 5e-3);
  EXPECT_GT(coarse / medium, 1.7); // first order: 2
  EXPECT_GT(medium / fine, 1.7);
}

/// IC-1 at a prescribed homogeneous stretch is the closed-form Donnan state in every cell and an
/// exact equilibrium: the first residual vanishes, no iteration.
TEST(MixtureFamilies, DonnanStateAtAPrescribedStretchIsExactOnEveryFamily) {
  for (mesh::CellType type : kMixtureFamilies)
    for (Real J : {1.0, 0.9, 1.15}) {
      test::MixtureModel m = stretched_cube(type, J);
      expect_donnan_everywhere(m, J, 1e-8);
      const solver::RunReport run = m.run(10.0, 10.0, 10.0);
      ASSERT_TRUE(run.success) << mesh::name(type) << ": " << run.failure;
      EXPECT_EQ(run.iterations, 0) << mesh::name(type) << " J = " << J;
      expect_donnan_everywhere(m, J, 1e-8);
    }
}

/// Free swelling of a cube from IC-1 (docs/theory/reference-solutions.md §R4): the stretch is
/// the closed-form root (SVK, 1.0755...) to 1e-6 and every cell holds the Donnan state there.
TEST(MixtureFamilies, FreeSwellingMatchesTheClosedFormOnEveryFamily) {
  const exact::SwellingState exact_state =
      exact::swelling_equilibrium(exact::SolidLaw::StVenantKirchhoff, exact::Deformation::Isotropic,
                                  0.3, 0.0, exact::paper_medium());
  for (mesh::CellType type : kMixtureFamilies) {
    test::MixtureModel m = free_cube(type);
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
  for (mesh::CellType type : kMixtureFamilies) {
    mesh::BoxSpec spec;
    spec.divisions = {2, 2, 2};
    test::MixtureModel m(mesh::convert_cells(mesh::make_box(spec), type), test::paper_tissue(true));
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
      EXPECT_NEAR(out.chem.c_plus, eq.donnan.c_plus, 1e-6 * eq.donnan.c_plus) << mesh::name(type);
      EXPECT_NEAR(out.chem.c_minus, eq.donnan.c_minus, 1e-6 * eq.donnan.c_minus)
          << mesh::name(type);
    }
  }
}

/// The free cube's Jacobian is regular for the pairs the models take (hex8, penta6, hex20 with
/// either mixture, tet10 biphasic) and singular where they refuse (docs/theory/elements.md): a
/// tet10's electric potential per cell is balanced by the ion fluxes alone, linear on a tet, and
/// a tet4's pressure by linear fluxes and displacements.
TEST(MixtureFamilies, JacobiansAreRegularExceptWhereTheModelsRefuseThePair) {
  const std::tuple<mesh::CellType, bool, bool> cases[] = {
      {mesh::CellType::Hex8, true, true},   {mesh::CellType::Penta6, true, true},
      {mesh::CellType::Hex20, true, true},  {mesh::CellType::Tet10, false, true},
      {mesh::CellType::Tet10, true, false}, {mesh::CellType::Tet4, false, false}};
  for (const auto& [type, charged, regular] : cases) {
    mesh::BoxSpec spec;
    spec.divisions = {2, 2, 2};
    test::MixtureModel m(mesh::convert_cells(mesh::make_box(spec), type),
                         test::paper_tissue(charged));
    const char* planes[3] = {"box.xmin", "box.ymin", "box.zmin"};
    for (int k = 0; k < 3; ++k) {
      m.fix(planes[k], m.f.u, k);
      m.impermeable(planes[k], k);
    }
    m.build();
    const auto [smallest, null] = smallest_singular_value(m);
    std::cout << mesh::name(type) << (charged ? " triphasic" : " biphasic")
              << ": smallest singular value " << smallest << ", " << null << " below 1e-12\n";
    if (regular) {
      EXPECT_GT(smallest, 1e-6) << mesh::name(type) << (charged ? " triphasic" : " biphasic");
    } else {
      EXPECT_GT(null, 0) << mesh::name(type) << (charged ? " triphasic" : " biphasic");
    }
  }
}
