// SPDX-License-Identifier: MIT
// The mixture cells' flux-block data of the drained Schur approximation (docs/theory/solvers.md
// §4), checked exactly: at zero fluxes the flux block of the element tangent is
// m_ab ⊗ friction + (g_a ⊗ g_b) gamma and the potential rows of the flux columns are
// coupling · G, in natural units (mixture_hex8_flux_block against mixture_hex8) and in the scaled
// equations (MixtureTerm::transport_cells against MixtureTerm::evaluate, and
// FeProblem::transport_cells against the assembled Jacobian, also with rotated nodal frames).
// With fluxes, the rest is proportional to them.
#include "mixture_setup.hpp"
#include "trifem/assembly/fe_problem.hpp"
#include "trifem/mesh/box.hpp"
#include "trifem/physics/mixture_term.hpp"
#include "trifem/physics/solid_kernel.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>

using namespace trifem;
using namespace trifem::test;
using physics::LocalMatrix;
using physics::LocalVector;

namespace {

using Node3 = Eigen::Matrix<Real, 8, 3>;
using Mass = Eigen::Matrix<Real, 8, 8>;

/// Current area vectors g_a = ∫ ∇N_a dv and mass matrix m_ab = ∫ N_a N_b dv of a cell, computed
/// here from the geometry and the displacements alone.
struct CellIntegrals {
  Node3 g = Node3::Zero();
  Mass m = Mass::Zero();
};

CellIntegrals cell_integrals(const fe::HexGeometry& geo, const fe::HexCoords& u) {
  CellIntegrals out;
  for (int q = 0; q < 8; ++q) {
    const Mat3 F = physics::deformation_gradient(geo.dN_dX[q], u);
    const Real dv = F.determinant() * geo.dV[q];
    const fe::HexShape N = fe::hex8_shape(fe::hex_gauss_2x2x2()[q].xi);
    out.g += geo.dN_dX[q] * F.inverse() * dv;
    out.m += N * N.transpose() * dv;
  }
  return out;
}

/// m_ab ⊗ friction + (g_a ⊗ g_b) gamma over the flux unknowns of `fields` fields (rows and
/// columns 24 field + 3a + k, the order of MixtureLayout from its w block on).
LocalMatrix flux_block(const Mat3& friction, const Mat3& gamma, const Node3& g, const Mass& m,
                       int fields) {
  LocalMatrix F = LocalMatrix::Zero(24 * fields, 24 * fields);
  for (int i = 0; i < fields; ++i)
    for (int j = 0; j < fields; ++j)
      for (int a = 0; a < 8; ++a)
        for (int b = 0; b < 8; ++b)
          for (int k = 0; k < 3; ++k)
            for (int l = 0; l < 3; ++l)
              F(24 * i + 3 * a + k, 24 * j + 3 * b + l) =
                  (k == l ? m(a, b) * friction(i, j) : 0.0) + g(a, k) * gamma(i, j) * g(b, l);
  return F;
}

/// The largest difference of the field sub-blocks (i, j) of `K` and `F` (same layout as
/// flux_block), relative to the sub-block's largest entry of `K` (0 if both vanish).
Real worst_field_block_error(const LocalMatrix& K, const LocalMatrix& F, int fields) {
  Real worst = 0.0;
  for (int i = 0; i < fields; ++i)
    for (int j = 0; j < fields; ++j) {
      const Real diff =
          (K.block<24, 24>(24 * i, 24 * j) - F.block<24, 24>(24 * i, 24 * j)).cwiseAbs().maxCoeff();
      if (diff > 0.0)
        worst = std::max(worst, diff / K.block<24, 24>(24 * i, 24 * j).cwiseAbs().maxCoeff());
    }
  return worst;
}

/// Checks, in the element layout `L` of a (natural or scaled) element matrix K, that the
/// potential rows of the flux columns are coupling · G and the flux rows of the potential columns
/// its transpose (to round-off relative to the row's or column's largest entry).
void expect_coupling(const LocalMatrix& K, const physics::MixtureLayout& L,
                     const Eigen::Matrix<Real, 2, 3>& coupling, const Node3& g) {
  const int fields = L.ions ? 3 : 1;
  for (int P = 0; P < (L.ions ? 2 : 1); ++P) {
    const int potential = P == 0 ? L.p() : L.eta();
    LocalVector predicted(24 * fields);
    for (int j = 0; j < fields; ++j)
      for (int b = 0; b < 8; ++b)
        for (int l = 0; l < 3; ++l)
          predicted[24 * j + 3 * b + l] = coupling(P, j) * g(b, l);
    const LocalVector row = K.row(potential).segment(24, 24 * fields).transpose();
    const LocalVector column = K.col(potential).segment(24, 24 * fields);
    EXPECT_LE((row - predicted).cwiseAbs().maxCoeff(), 1e-13 * row.cwiseAbs().maxCoeff())
        << "row " << P;
    EXPECT_LE((column - predicted).cwiseAbs().maxCoeff(), 1e-13 * column.cwiseAbs().maxCoeff())
        << "column " << P;
  }
}

/// The natural element of make_setup with its fluxes times `flux_scale`: its tangent, its flux
/// block data and its integrals computed here.
struct ElementAtState {
  Setup s;
  LocalMatrix K;
  physics::MixtureFluxBlock block;
  CellIntegrals I;
};

ElementAtState element_at(bool ions, const std::string& solid, Real flux_scale,
                          const material::ParameterValues& laws = {}, bool lumped = false) {
  ElementAtState e{make_setup(ions, solid, laws), {}, {}, {}};
  Setup& s = e.s;
  s.step.chem = &s.chem; // make_setup's pointer is to the copy it returned from
  s.step.lumped_flux_mass = lumped;
  s.x.w *= flux_scale;
  s.x.jp *= flux_scale;
  s.x.jm *= flux_scale;
  const physics::MixtureLayout L{ions};
  LocalVector r;
  EXPECT_TRUE(physics::mixture_hex8(s.geo, s.x, s.h, s.mat, s.step, L, r, &e.K));
  const auto block = physics::mixture_hex8_flux_block(s.geo, s.x, s.h, s.mat, s.step, L);
  EXPECT_TRUE(block.has_value());
  if (block)
    e.block = *block;
  e.I = cell_integrals(s.geo, s.x.u);
  return e;
}

/// The natural element at zero fluxes: the flux block and the couplings are exactly the data.
void check_element(bool ions, const std::string& solid,
                   const material::ParameterValues& laws = {}) {
  const ElementAtState e = element_at(ions, solid, 0.0, laws);
  const Setup& s = e.s;
  const LocalMatrix& K = e.K;
  const physics::MixtureFluxBlock& block = e.block;
  const CellIntegrals& I = e.I;
  const physics::MixtureLayout L{ions};
  const int fields = ions ? 3 : 1;
  EXPECT_LE((block.area - I.g).cwiseAbs().maxCoeff(), 1e-14 * I.g.cwiseAbs().maxCoeff());
  const Eigen::Matrix<Real, 8, 1> lumped = I.m.rowwise().sum();
  EXPECT_LE((block.lumped_mass - lumped).cwiseAbs().maxCoeff(), 1e-14 * lumped.maxCoeff());

  const LocalMatrix F = flux_block(block.friction, block.gamma, I.g, I.m, fields);
  const Real error = worst_field_block_error(K.block(24, 24, 24 * fields, 24 * fields), F, fields);
  EXPECT_LE(error, 1e-12) << (ions ? "triphasic " : "biphasic ") << solid;
  std::cout << "worst field block error " << error << "\n";
  expect_coupling(K, L, block.coupling, I.g);

  // the formulas of docs/theory/solvers.md §4 (fields w, j+, j-)
  const Real RT = s.chem.RT(), dt = s.step.dt;
  if (ions) {
    const Real Vw = block.lumped_mass.sum() - s.mat.phi_s0 * s.h.V0;
    const Real c_plus = s.h.N_plus / Vw, c_minus = s.h.N_minus / Vw; // no outflow at zero flux
    Mat3 gamma = Mat3::Zero();
    gamma(0, 1) = gamma(0, 2) = RT * s.mat.osmotic * dt / Vw;
    gamma(1, 1) = -RT / c_plus * dt / Vw;
    gamma(2, 2) = -RT / c_minus * dt / Vw;
    EXPECT_LE((block.gamma - gamma).cwiseAbs().maxCoeff(), 1e-12 * gamma.cwiseAbs().maxCoeff());
  } else {
    EXPECT_EQ(block.gamma, Mat3::Zero());
  }
  Eigen::Matrix<Real, 2, 3> T = Eigen::Matrix<Real, 2, 3>::Zero();
  T(0, 0) = 1.0;
  if (ions) {
    T(1, 1) = 1.0;
    T(1, 2) = -1.0;
  }
  EXPECT_EQ(block.coupling, T);
}

/// flux_block plus the rates: F(f_i(a,k), f_j(b,l)) += flux_rate(3a + k, 3i + j) g_b[l].
LocalMatrix with_rates(LocalMatrix F, const Eigen::Matrix<Real, 24, 9>& rate, const Node3& g,
                       int fields) {
  for (int i = 0; i < fields; ++i)
    for (int j = 0; j < fields; ++j)
      for (int row = 0; row < 24; ++row)
        for (int b = 0; b < 8; ++b)
          for (int l = 0; l < 3; ++l)
            F(24 * i + row, 24 * j + 3 * b + l) += rate(row, 3 * i + j) * g(b, l);
  return F;
}

/// The element's flux block against the data at the fluxes of make_setup times `scale`: the
/// largest difference relative to the block's largest entry, without the rates (`rates`
/// false) or with them; the element's friction terms are lumped if `lumped`, and the data's mass
/// is the consistent one of the integrals or, `lumped_data`, their row sums.
Real flux_block_error(bool ions, Real scale, bool rates, bool lumped = false,
                      bool lumped_data = false) {
  ElementAtState e = element_at(ions, "neo-hookean", scale, {}, lumped);
  const LocalMatrix& K = e.K;
  const physics::MixtureFluxBlock& block = e.block;
  const CellIntegrals& I = e.I;
  const int fields = ions ? 3 : 1;
  const Mass m = lumped_data ? Mass(I.m.rowwise().sum().asDiagonal()) : I.m;
  LocalMatrix F = flux_block(block.friction, block.gamma, I.g, m, fields);
  if (rates)
    F = with_rates(F, block.flux_rate, I.g, fields);
  return (K.block(24, 24, 24 * fields, 24 * fields) - F).cwiseAbs().maxCoeff() /
         F.cwiseAbs().maxCoeff();
}

} // namespace

TEST(MixtureTransportCells, TriphasicElementAtZeroFluxesSvk) {
  check_element(true, "saint-venant-kirchhoff");
}
TEST(MixtureTransportCells, TriphasicElementAtZeroFluxesNeoHookean) {
  check_element(true, "neo-hookean");
}
TEST(MixtureTransportCells, BiphasicElementAtZeroFluxesSvk) {
  check_element(false, "saint-venant-kirchhoff");
}
TEST(MixtureTransportCells, BiphasicElementAtZeroFluxesNeoHookean) {
  check_element(false, "neo-hookean");
}
// the strain-dependent laws add to the u columns only
TEST(MixtureTransportCells, TriphasicElementAtZeroFluxesWithStrainDependentLaws) {
  material::ParameterValues laws = kHolmesMow;
  laws.insert(kMackieMeares.begin(), kMackieMeares.end());
  check_element(true, "neo-hookean", laws);
}
TEST(MixtureTransportCells, BiphasicElementAtZeroFluxesWithHolmesMowPermeability) {
  check_element(false, "saint-venant-kirchhoff", kHolmesMow);
}

/// With fluxes the triphasic block gains the resistances' derivatives times W, P, M: linear in
/// the fluxes, and exactly the flux rates times the divergences. The biphasic block with a
/// constant permeability has none.
TEST(MixtureTransportCells, RestOfTheFluxBlockIsTheFluxRates) {
  const Real r1 = flux_block_error(true, 1.0, false), r01 = flux_block_error(true, 0.1, false);
  std::cout << "flux block without the rates at fluxes x1, x0.1: " << r1 << ", " << r01 << "\n";
  EXPECT_GT(r1, 1e-8);
  EXPECT_NEAR(r01 / r1, 0.1, 1e-2);
  const Real with = flux_block_error(true, 1.0, true);
  std::cout << "flux block with the rates: " << with << "\n";
  EXPECT_LE(with, 1e-12);
  EXPECT_LE(flux_block_error(false, 1.0, false), 1e-14);
}

/// With the lumped flux mass the flux block is the data with diag(l_a) in place of m_ab.
TEST(MixtureTransportCells, LumpedFluxBlockIsTheDataExactly) {
  for (bool ions : {true, false}) {
    EXPECT_LE(flux_block_error(ions, 1.0, true, true, true), 1e-12) << ions;
    EXPECT_GT(flux_block_error(ions, 1.0, true, true, false), 1e-2) << ions; // it is lumped
  }
}

namespace {

/// A 2x1x1 box of one mixture under a FeProblem, at a deformed state with zero fluxes, potentials
/// off the Donnan state and a non-Donnan ion content; the z-components of the fluxes are
/// prescribed on the bottom (flux DOFs without equations).
class BoxModel {
public:
  /// `rotate_fluid`: the fluid (true) or displacement (false) DOFs of node 0 in a rotated frame;
  /// `dynamic`: in a dynamic step (generalized-α, ρ∞ = 0.5: the mixture's Jacobian weighted by
  /// 1 − α_f = 2/3).
  explicit BoxModel(bool ions, std::optional<bool> rotate_fluid = std::nullopt,
                    bool dynamic = false)
      : mesh_(mesh::make_box({"box", Vec3::Zero(), Vec3(2.0, 1.0, 1.0), {2, 1, 1}})),
        rotate_fluid_(rotate_fluid) {
    props_ = std::make_shared<material::MixtureProperties>(make_setup(ions, "neo-hookean").mat);
    f_.u = dofs_.add_field("displacement", FieldRole::displacement, mesh_.num_nodes(), 3);
    f_.w = dofs_.add_field("fluid_flux", FieldRole::flux, mesh_.num_nodes(), 3);
    if (ions) {
      f_.j_plus = dofs_.add_field("cation_flux", FieldRole::flux, mesh_.num_nodes(), 3);
      f_.j_minus = dofs_.add_field("anion_flux", FieldRole::flux, mesh_.num_nodes(), 3);
    }
    f_.p = dofs_.add_field("pressure", FieldRole::potential, mesh_.num_cells(), 1);
    if (ions)
      f_.eta = dofs_.add_field("potential", FieldRole::potential, mesh_.num_cells(), 1);
    dofs::DirichletCondition bottom;
    for (Index n : mesh_.node_set("box.zmin"))
      for (dofs::FieldId field : {f_.w, f_.j_plus, f_.j_minus})
        if (field.valid())
          bottom.dofs.push_back(dofs_.dof(field, n, 2));
    const std::vector<dofs::DirichletCondition> conditions{bottom};
    dofs::constrain_all(conditions, dofs_);
    dofs_.finalize();
    std::vector<Index> cells = {0, 1};
    auto term = std::make_unique<physics::MixtureTerm>(
        mesh_, dofs_, f_, cells,
        std::vector<std::shared_ptr<const material::MixtureProperties>>(2, props_), chem_);
    mixture_ = term.get();
    std::vector<std::unique_ptr<physics::Term>> terms;
    terms.push_back(std::move(term));
    problem_ = std::make_unique<assembly::FeProblem>(
        dofs_, conditions, std::move(terms), std::vector<solver::FieldScale>(dofs_.num_fields()),
        frames(rotate_fluid));
    set_state();
    if (dynamic) {
      problem_->add_inertia(std::make_unique<physics::InertiaTerm>(
          mesh_, dofs_, f_.u, cells, std::vector<Real>(2, 1e-6), physics::MassMatrix::Consistent,
          physics::GeneralizedAlpha::from_spectral_radius(0.5)));
      problem_->set_dynamic(true);
    }
  }

  BoxModel(const BoxModel&) = delete; // the term holds references to the mesh and the DOFs
  BoxModel& operator=(const BoxModel&) = delete;

  const assembly::FeProblem& problem() const { return *problem_; }
  assembly::FeProblem& problem() { return *problem_; }
  const physics::MixtureTerm& mixture() const { return *mixture_; }
  const physics::MixtureFields& fields() const { return f_; }
  const dofs::DofMap& dofs() const { return dofs_; }
  Real dt() const { return kDt; }
  /// The rotation of the nodal frame of `node` in flux field `field` (0: w, 1: j+, 2: j-).
  Mat3 rotation(Index node, int field) const {
    return rotate_fluid_.value_or(false) && field == 0 && node == 0 ? frame_rotation()
                                                                    : Mat3::Identity();
  }
  Real c_ref() const { return chem_.c_ref; }

  /// Geometry and displacements of element e at the current state.
  CellIntegrals integrals(Index e) const {
    fe::HexCoords X, u;
    const auto& nodes = mesh_.cell(mixture_->cell(e));
    for (int a = 0; a < 8; ++a) {
      X.row(a) = mesh_.node(nodes[a]).transpose();
      for (int k = 0; k < 3; ++k)
        u(a, k) = problem_->state()[dofs_.dof(f_.u, nodes[a], k)];
    }
    return cell_integrals(*fe::hex8_geometry(X), u);
  }

private:
  static constexpr Real kDt = 0.7;
  static Mat3 frame_rotation() { return Eigen::AngleAxisd(0.5, Vec3::UnitZ()).toRotationMatrix(); }

  dofs::NodalFrames frames(std::optional<bool> rotate_fluid) const {
    if (!rotate_fluid)
      return {};
    dofs::NodalFrame frame;
    const dofs::FieldId field = *rotate_fluid ? f_.w : f_.u;
    for (int k = 0; k < 3; ++k)
      frame.dofs[k] = dofs_.dof(field, 0, k);
    frame.Q = frame_rotation();
    return dofs::NodalFrames({frame}, dofs_.num_dofs());
  }

  void set_state() {
    std::mt19937 rng(7);
    std::uniform_real_distribution<Real> d(-0.06, 0.06);
    Vector x = problem_->state();
    for (Index n = 0; n < mesh_.num_nodes(); ++n)
      for (int k = 0; k < 3; ++k)
        x[dofs_.dof(f_.u, n, k)] = d(rng);
    mixture_->initialize(physics::InitialState::Donnan, 0.0, x);
    for (Index e = 0; e < 2; ++e) {
      x[dofs_.dof(f_.p, e, 0)] += 0.03 * (e + 1);
      physics::MixtureHistory h = mixture_->history(e);
      h.V_old *= 0.98;
      h.N_plus *= 1.06;
      h.N_minus *= 0.95;
      mixture_->set_history(e, h);
      if (f_.eta.valid())
        x[dofs_.dof(f_.eta, e, 0)] += chem_.c_ref * 120.0;
    }
    problem_->set_state(x);
    problem_->begin_step(kDt, kDt);
  }

  mesh::Mesh mesh_;
  std::optional<bool> rotate_fluid_;
  dofs::DofMap dofs_;
  physics::MixtureFields f_;
  material::Electrochemistry chem_;
  std::shared_ptr<const material::MixtureProperties> props_;
  physics::MixtureTerm* mixture_ = nullptr;
  std::unique_ptr<assembly::FeProblem> problem_;
};

/// MixtureTerm's scaled cells against its scaled element matrices.
void check_term(bool ions) {
  const BoxModel model(ions);
  const physics::MixtureTerm& term = model.mixture();
  const Vector& x = model.problem().state();
  const physics::EvalState state{x, x, model.dt(), model.dt()};
  std::vector<physics::CellTransport> cells;
  term.transport_cells(state, cells);
  ASSERT_EQ(cells.size(), 2u);
  const physics::MixtureLayout L{ions};
  const int fields = ions ? 3 : 1;
  for (Index e = 0; e < 2; ++e) {
    const physics::CellTransport& t = cells[e];
    std::vector<Index> dofs;
    term.element_dofs(e, dofs);
    for (int i = 0; i < 3; ++i)
      for (int ak = 0; ak < 24; ++ak)
        EXPECT_EQ(t.flux_dof(ak, i), i < fields ? dofs[24 + 24 * i + ak] : -1);
    EXPECT_EQ(t.potential[0], dofs[L.p()]);
    EXPECT_EQ(t.potential[1], ions ? dofs[L.eta()] : -1);

    LocalVector r;
    LocalMatrix K;
    ASSERT_TRUE(term.evaluate(e, state, r, &K));
    const CellIntegrals I = model.integrals(e);
    const LocalMatrix F = flux_block(t.friction, t.gamma, I.g, I.m, fields);
    const Real error =
        worst_field_block_error(K.block(24, 24, 24 * fields, 24 * fields), F, fields);
    EXPECT_LE(error, 1e-12);
    std::cout << "cell " << e << ": worst field block error " << error << "\n";
    expect_coupling(K, L, t.coupling, I.g);

    // scaled: the friction is positive definite, the coupling is -dt T with T's signs in
    // (p, eta) x (w, j+/c_ref, j-/c_ref)
    const Real dt = model.dt();
    const Eigen::MatrixXd friction = t.friction.topLeftCorner(fields, fields);
    EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(friction).eigenvalues().minCoeff(),
              0.0);
    Eigen::Matrix<Real, 2, 3> coupling = Eigen::Matrix<Real, 2, 3>::Zero();
    coupling(0, 0) = -dt;
    if (ions) {
      coupling(1, 1) = -dt;
      coupling(1, 2) = dt;
      EXPECT_LT(t.gamma(0, 1), 0.0);
      EXPECT_LT(t.gamma(0, 2), 0.0);
      EXPECT_GT(t.gamma(1, 1), 0.0);
      EXPECT_GT(t.gamma(2, 2), 0.0);
    }
    EXPECT_LE((t.coupling - coupling).cwiseAbs().maxCoeff(), 1e-15 * dt);
  }
}

/// FeProblem's cells over the equations against the assembled Jacobian: the flux block of the
/// free equations is the sum of the cells' blocks, the potential rows are coupling · G, with the
/// rows and columns of rotated DOFs in their frames (the friction part of a rotated node a and
/// a node b is m_ab friction Q_aᵀ Q_b: the identity for the lumped mass).
void check_problem(bool ions, std::optional<bool> rotate_fluid = std::nullopt,
                   bool dynamic = false) {
  BoxModel model(ions, rotate_fluid, dynamic);
  solver::Linearization lin;
  ASSERT_EQ(model.problem().linearize(lin, true), solver::SolveStatus::Converged);
  const LocalMatrix J = lin.jacobian.toDense();
  const linalg::TransportCells cells = model.problem().transport_cells();
  ASSERT_EQ(cells.size(), 2u);
  const Index neq = model.problem().num_equations();
  LocalMatrix predicted = LocalMatrix::Zero(neq, neq);
  int constrained = 0;
  for (Index e = 0; e < 2; ++e) {
    const linalg::TransportCell& t = cells[e];
    const CellIntegrals I = model.integrals(e);
    const auto frame = [&](int i) { return model.rotation(t.node[(i % 24) / 3], i / 24); };
    for (int i = 0; i < 72; ++i) {
      const Index row = t.flux_equation(i % 24, i / 24);
      constrained += row < 0 && i / 24 < (ions ? 3 : 1);
      if (row < 0)
        continue;
      if (!rotate_fluid) { // the divergences are the area vectors
        EXPECT_NEAR(t.divergence(i % 24, i / 24), I.g((i % 24) / 3, i % 3),
                    1e-15 * I.g.cwiseAbs().maxCoeff());
      }
      for (int j = 0; j < 72; ++j)
        if (const Index col = t.flux_equation(j % 24, j / 24); col >= 0) {
          const Mat3 R = frame(i).transpose() * frame(j);
          predicted(row, col) +=
              I.m((i % 24) / 3, (j % 24) / 3) * t.friction(i / 24, j / 24) * R(i % 3, j % 3) +
              t.divergence(i % 24, i / 24) * t.gamma(i / 24, j / 24) * t.divergence(j % 24, j / 24);
        }
      for (int P = 0; P < 2; ++P)
        if (const Index potential = t.potential[P]; potential >= 0) {
          const Real c = t.coupling(P, i / 24) * t.divergence(i % 24, i / 24);
          predicted(potential, row) += c;
          predicted(row, potential) += c;
        }
    }
    EXPECT_EQ(t.potential[1] >= 0, ions);
  }
  EXPECT_EQ(constrained, (ions ? 3 : 1) * 8); // 4 bottom nodes per cell
  // compare every (field, field) block of the flux and potential equations
  const physics::MixtureFields& f = model.fields();
  const std::vector<int>& field = model.problem().equation_fields();
  std::vector<int> flux_and_potential = {f.w.index, f.p.index};
  if (ions)
    flux_and_potential.insert(flux_and_potential.end(),
                              {f.j_plus.index, f.j_minus.index, f.eta.index});
  Real worst = 0.0;
  for (int fr : flux_and_potential)
    for (int fc : flux_and_potential) {
      Real diff = 0.0, size = 0.0;
      for (Index r = 0; r < neq; ++r)
        for (Index c = 0; c < neq; ++c)
          if (field[r] == fr && field[c] == fc) {
            diff = std::max(diff, std::abs(J(r, c) - predicted(r, c)));
            size = std::max(size, std::abs(J(r, c)));
          }
      EXPECT_LE(diff, 1e-12 * size) << "fields " << fr << ", " << fc;
      worst = std::max(worst, diff > 0.0 ? diff / size : 0.0);
    }
  std::cout << "worst field block error of the Jacobian " << worst << "\n";
}

} // namespace

TEST(MixtureTransportCells, TriphasicTermGivesTheScaledElementMatrix) {
  check_term(true);
}
TEST(MixtureTransportCells, BiphasicTermGivesTheScaledElementMatrix) {
  check_term(false);
}
TEST(MixtureTransportCells, TriphasicProblemGivesTheAssembledJacobian) {
  check_problem(true);
}
TEST(MixtureTransportCells, BiphasicProblemGivesTheAssembledJacobian) {
  check_problem(false);
}

TEST(MixtureTransportCells, TriphasicProblemInADynamicStepGivesTheWeightedJacobian) {
  check_problem(true, std::nullopt, true);
}

TEST(MixtureTransportCells, TriphasicProblemWithARotatedFluidFrame) {
  check_problem(true, true);
}
TEST(MixtureTransportCells, TriphasicProblemWithARotatedDisplacementFrame) {
  check_problem(true, false);
}
