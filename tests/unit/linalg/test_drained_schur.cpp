// SPDX-License-Identifier: MIT
// The augmented Schur system of the drained part (docs/theory/solvers.md §4) against the Schur
// complement formed densely: exact when the flux block's friction mass is lumped.
#include "trifem/core/error.hpp"
#include "trifem/linalg/drained_schur.hpp"
#include "trifem/linalg/krylov_solver.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <random>

using namespace trifem;
using namespace trifem::linalg;

namespace {

using Dense = Eigen::MatrixXd;

/// Two hex cells sharing a face (nodes 4–7), three flux fields, a prescribed flux component,
/// the potentials p and η of each cell, and one potential of no cell (a contact multiplier).
struct TwoCells {
  static constexpr Index kNodes = 12, kDisplacements = 3 * kNodes;
  Index fluxes = 0, potentials = 0;
  TransportCells cells;
  BlockSplit split;
  SparseMatrix A;
  Dense expected; ///< −A_ππ + A_πu diag(A_uu)⁻¹ A_uπ + fixed stress + the drained part
};

Dense random_matrix(std::mt19937& rng, Index rows, Index cols) {
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  Dense m(rows, cols);
  for (Index i = 0; i < rows; ++i)
    for (Index j = 0; j < cols; ++j)
      m(i, j) = u(rng);
  return m;
}

/// `undrained`: the potentials couple to the displacements and the multiplier to the fluxes
/// (without: the drained part is the whole Schur complement, and the multiplier stands alone).
TwoCells make_two_cells(bool undrained = true) {
  std::mt19937 rng(7);
  TwoCells s;
  // flux equations: node, component, field; node 0's z component of the fluid flux prescribed
  Eigen::Array<Index, Eigen::Dynamic, 1> flux_eq =
      Eigen::Array<Index, Eigen::Dynamic, 1>::Constant(9 * TwoCells::kNodes, -1);
  for (Index i = 0; i < 9 * TwoCells::kNodes; ++i)
    if (i != 2 * 3 + 0) // (node 0, component 2, field 0)
      flux_eq[i] = TwoCells::kDisplacements + s.fluxes++;
  const Index first_potential = TwoCells::kDisplacements + s.fluxes;
  s.potentials = 5;
  const Index n = first_potential + s.potentials;
  for (Index i = 0; i < n; ++i)
    (i < TwoCells::kDisplacements ? s.split.displacement
     : i < first_potential        ? s.split.flux
                                  : s.split.potential)
        .push_back(i);

  for (int c = 0; c < 2; ++c) {
    TransportCell cell;
    cell.potential = {first_potential + 2 * c, first_potential + 2 * c + 1};
    cell.coupling = random_matrix(rng, 2, 3);
    const Dense f = random_matrix(rng, 3, 3);
    cell.friction = f * f.transpose() + 3.0 * Dense::Identity(3, 3);
    cell.gamma = random_matrix(rng, 3, 3); // unsymmetric, as the mixture's
    Eigen::Matrix<Real, 8, 3> area = random_matrix(rng, 8, 3);
    area.rowwise() -= area.colwise().mean(); // Σ_a g_a = 0
    cell.lumped_mass = (random_matrix(rng, 8, 1).array() + 2.0).matrix();
    cell.divergence.setZero();
    for (int a = 0; a < 8; ++a) {
      cell.node[a] = 4 * c + a;
      for (int k = 0; k < 3; ++k)
        cell.divergence.row(3 * a + k).setConstant(area(a, k));
      for (int k = 0; k < 3; ++k)
        for (int f = 0; f < 3; ++f)
          cell.flux_equation(3 * a + k, f) = flux_eq[9 * cell.node[a] + 3 * k + f];
    }
    s.cells.push_back(cell);
  }

  // the Jacobian, dense: K, F = D + Gᵀ Γ G, the couplings
  Dense J = Dense::Zero(n, n);
  const Dense k = random_matrix(rng, TwoCells::kDisplacements, TwoCells::kDisplacements);
  J.topLeftCorner(TwoCells::kDisplacements, TwoCells::kDisplacements) =
      k * k.transpose() +
      40.0 * Dense::Identity(TwoCells::kDisplacements, TwoCells::kDisplacements);
  for (const TransportCell& c : s.cells)
    for (int a = 0; a < 8; ++a)
      for (int kk = 0; kk < 3; ++kk)
        for (int f = 0; f < 3; ++f)
          for (int h = 0; h < 3; ++h) {
            const Index i = c.flux_equation(3 * a + kk, f), j = c.flux_equation(3 * a + kk, h);
            if (i >= 0 && j >= 0)
              J(i, j) += c.lumped_mass[a] * c.friction(f, h);
          }
  for (const TransportCell& c : s.cells)
    for (int a = 0; a < 8; ++a)
      for (int b = 0; b < 8; ++b)
        for (int ka = 0; ka < 3; ++ka)
          for (int kb = 0; kb < 3; ++kb)
            for (int f = 0; f < 3; ++f)
              for (int h = 0; h < 3; ++h) {
                const Index i = c.flux_equation(3 * a + ka, f), j = c.flux_equation(3 * b + kb, h);
                if (i >= 0 && j >= 0)
                  J(i, j) +=
                      c.divergence(3 * a + ka, f) * c.gamma(f, h) * c.divergence(3 * b + kb, h);
              }
  for (const TransportCell& c : s.cells)
    for (int r = 0; r < 2; ++r)
      for (int a = 0; a < 8; ++a)
        for (int kk = 0; kk < 3; ++kk)
          for (int f = 0; f < 3; ++f)
            if (const Index eq = c.flux_equation(3 * a + kk, f); eq >= 0) {
              J(c.potential[r], eq) += c.coupling(r, f) * c.divergence(3 * a + kk, f);
              J(eq, c.potential[r]) += c.coupling(r, f) * c.divergence(3 * a + kk, f);
            }
  const Index p0 = first_potential, nu = TwoCells::kDisplacements;
  if (undrained) {
    J.block(p0, 0, s.potentials, nu) = random_matrix(rng, s.potentials, nu);
    J.block(0, p0, nu, s.potentials) = random_matrix(rng, nu, s.potentials);
    J.block(p0 + 4, nu, 1, s.fluxes) = random_matrix(rng, 1, s.fluxes); // the multiplier
    J.block(nu, p0 + 4, s.fluxes, 1) = random_matrix(rng, s.fluxes, 1);
  }
  J(p0 + 4, p0 + 4) = 0.3;
  s.A = J.sparseView();

  // expected: −A_ππ + A_πu diag(K)⁻¹ A_uπ + A_πf F⁻¹ A_fπ between cell potentials, + the
  // diagonal approximation A_πf diag(F)⁻¹ A_fπ where the multiplier is involved
  const Dense App = J.block(p0, p0, s.potentials, s.potentials);
  const Dense Apu = J.block(p0, 0, s.potentials, nu), Aup = J.block(0, p0, nu, s.potentials);
  const Dense Apf = J.block(p0, nu, s.potentials, s.fluxes);
  const Dense Afp = J.block(nu, p0, s.fluxes, s.potentials);
  const Dense F = J.block(nu, nu, s.fluxes, s.fluxes);
  const Eigen::VectorXd du = J.diagonal().head(nu), df = J.diagonal().segment(nu, s.fluxes);
  s.expected = -App + Apu * du.cwiseInverse().asDiagonal() * Aup;
  // the filtered fixed-stress term on the pressures (positions 0 and 2): nodes 0-3 and 8-11 in
  // one cell, nodes 4-7 in both
  const Real beta[2] = {s.expected(0, 0), s.expected(2, 2)};
  for (int c = 0; c < 2; ++c)
    s.expected(2 * c, 2 * c) += 4 * beta[c] / 8.0; // four nodes of its own, n = 1
  for (int c = 0; c < 2; ++c)
    for (int d = 0; d < 2; ++d) // four shared nodes, n = 2, mean of the two β
      s.expected(2 * c, 2 * d) += 4 * (beta[0] + beta[1]) / 2.0 / 16.0;
  const Dense exact = Apf * F.lu().solve(Afp);
  const Dense diagonal = Apf * df.cwiseInverse().asDiagonal() * Afp;
  for (Index i = 0; i < s.potentials; ++i)
    for (Index j = 0; j < s.potentials; ++j)
      s.expected(i, j) += (i == 4 || j == 4) ? diagonal(i, j) : exact(i, j);
  return s;
}

} // namespace

TEST(DrainedSchur, TheAugmentedSystemGivesTheSchurComplementOfALumpedFluxBlock) {
  const TwoCells s = make_two_cells();
  const Dense M = drained_schur_system(s.A, s.split, s.cells);
  const Index P = s.potentials;
  ASSERT_EQ(M.rows(), P + 6);
  const Index Z = M.rows() - P;
  const Dense schur =
      M.topLeftCorner(P, P) -
      M.topRightCorner(P, Z) * M.bottomRightCorner(Z, Z).lu().solve(M.bottomLeftCorner(Z, P));
  const Real scale = s.expected.cwiseAbs().maxCoeff();
  EXPECT_LT((schur - s.expected).cwiseAbs().maxCoeff(), 1e-12 * scale)
      << "Schur complement of the augmented system\n"
      << schur << "\nexpected\n"
      << s.expected;
  // the drained part is a large part of it: the test would see it missing
  const Dense undrained = M.topLeftCorner(P, P);
  EXPECT_GT((undrained - s.expected).cwiseAbs().maxCoeff(), 1e-2 * scale);
}

TEST(DrainedSchur, CellsWithoutAFieldGetIdentityRows) {
  TwoCells s = make_two_cells();
  for (TransportCell& c : s.cells) { // a biphasic model's cells: the fluid flux only
    c.flux_equation.rightCols(2).setConstant(-1);
    c.coupling.rightCols(2).setZero();
    c.coupling.row(1).setZero();
    c.gamma.setZero();
  }
  const Dense M = drained_schur_system(s.A, s.split, s.cells);
  const Index P = s.potentials;
  for (int c = 0; c < 2; ++c)
    for (int f = 1; f < 3; ++f) {
      const Index z = P + 3 * c + f;
      EXPECT_DOUBLE_EQ(M(z, z), 1.0);
      EXPECT_DOUBLE_EQ(M.row(z).cwiseAbs().sum(), 1.0);
    }
}

namespace {

/// FGMRES iterations of the Krylov backend ("lu" blocks, Schur approximation `schur`) on the
/// two cells' system to 1e-10; the relative residual reached in `residual`.
int krylov_iterations(const TwoCells& s, SchurApproximation schur, Real& residual) {
  auto solver = make_linear_solver({.kind = LinearSolverKind::krylov, .schur = schur});
  std::vector<int> fields;
  for (Index i = 0; i < s.A.rows(); ++i)
    fields.push_back(i < TwoCells::kDisplacements              ? 0
                     : i < TwoCells::kDisplacements + s.fluxes ? 1
                                                               : 2);
  solver->set_hints(
      {fields, {FieldRole::displacement, FieldRole::flux, FieldRole::potential}, {}, {}});
  EXPECT_EQ(solver->wants_transport_cells(), schur == SchurApproximation::drained);
  solver->analyze_pattern(s.A);
  solver->set_transport_cells(s.cells);
  EXPECT_TRUE(solver->factorize(s.A)) << solver->failure().reason;
  const Vector b = Vector::LinSpaced(s.A.rows(), 1.0, 2.0);
  Vector x;
  EXPECT_TRUE(solver->solve(b, x)) << solver->failure().reason;
  residual = (s.A * x - b).norm() / b.norm();
  return solver->last_iterations();
}

} // namespace

TEST(DrainedSchur, MakesTheKrylovBackendsFactorizationExactForALumpedFluxBlock) {
  // without the undrained coupling the drained part is the whole Schur complement: with it
  // exact, the full block factorization is the inverse and FGMRES converges at once
  const TwoCells s = make_two_cells(false);
  Real residual = 1.0;
  EXPECT_LE(krylov_iterations(s, SchurApproximation::drained, residual), 2);
  EXPECT_LT(residual, 1e-9);
  EXPECT_GE(krylov_iterations(s, SchurApproximation::selfp, residual),
            5); // the diagonal approximation
  EXPECT_LT(residual, 1e-9);
  // with the undrained coupling (its diagonal approximation) it still solves
  EXPECT_LE(krylov_iterations(make_two_cells(true), SchurApproximation::drained, residual), 100);
  EXPECT_LT(residual, 1e-9);
}

TEST(DrainedSchur, OptionsOfItsSolverAreReadAndCheckedWithTheKrylovBackend) {
  EXPECT_NO_THROW(
      make_linear_solver({.kind = LinearSolverKind::krylov,
                          .petsc_options = "-drained_schur_pc_factor_mat_solver_type mumps",
                          .schur = SchurApproximation::drained}));
  try { // not read without the drained approximation
    make_linear_solver({.kind = LinearSolverKind::krylov,
                        .petsc_options = "-drained_schur_pc_factor_mat_solver_type mumps"});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("-drained_schur_pc_factor_mat_solver_type"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(make_linear_solver({.kind = LinearSolverKind::krylov,
                                   .petsc_options = "-drained_schur_pc_type no_such_type",
                                   .schur = SchurApproximation::drained}),
               InputError);
}
