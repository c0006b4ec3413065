// SPDX-License-Identifier: MIT
// The sparse direct solvers on an unsymmetric saddle-point system (the structure of the mixed
// and contact tangents: a zero diagonal block), and the size rule of the "auto" backend.
#include "trifem/core/error.hpp"
#include "trifem/linalg/auto_solver.hpp"
#include "trifem/linalg/linear_solver.hpp"

#include <gtest/gtest.h>
#include <spdlog/sinks/ostream_sink.h>
#include <spdlog/spdlog.h>

#include <cmath>
#include <memory>
#include <sstream>
#include <vector>

using namespace trifem;

namespace {

constexpr LinearSolverKind kDirectBackends[] = {
    LinearSolverKind::automatic, LinearSolverKind::umfpack, LinearSolverKind::sparselu,
    LinearSolverKind::mumps};

/// [A B; Cᵀ 0] with A an unsymmetric 1-D convection–diffusion matrix of size n and B, C
/// coupling every k-th unknown to one multiplier (n/k multipliers).
SparseMatrix saddle_point(Index n, Index k) {
  const Index m = n / k;
  std::vector<Eigen::Triplet<Real>> t;
  for (Index i = 0; i < n; ++i) {
    t.emplace_back(i, i, 4.0);
    if (i > 0)
      t.emplace_back(i, i - 1, -1.5);
    if (i + 1 < n)
      t.emplace_back(i, i + 1, -0.5);
  }
  for (Index j = 0; j < m; ++j) {
    t.emplace_back(j * k, n + j, 1.0);       // B
    t.emplace_back(n + j, j * k, 1.0);       // Cᵀ
    t.emplace_back(n + j, j * k + 1, -0.25); // C ≠ B: unsymmetric coupling
  }
  SparseMatrix S(n + m, n + m);
  S.setFromTriplets(t.begin(), t.end());
  return S;
}

Vector right_hand_side(Index size) {
  Vector b(size);
  for (Index i = 0; i < size; ++i)
    b[i] = std::sin(0.37 * i) + 0.1;
  return b;
}

/// Relative residual of solving S x = b with the backend `name`, factorizing twice (the second
/// time with scaled values, as a Newton iteration does on a fixed pattern).
Real solve_residual(LinearSolverKind kind, const SparseMatrix& S, std::string* chosen) {
  auto solver = linalg::make_linear_solver({kind});
  const Vector b = right_hand_side(S.rows());
  solver->analyze_pattern(S);
  EXPECT_TRUE(solver->factorize(S));
  const SparseMatrix S2 = 2.0 * S;
  EXPECT_TRUE(solver->factorize(S2));
  Vector x;
  EXPECT_TRUE(solver->solve(b, x));
  if (chosen)
    *chosen = solver->name();
  return (S2 * x - b).norm() / b.norm();
}

/// R S R_c and R b for the saddle point system S x = b of 600 + 200 unknowns, R and R_c
/// diagonal with powers of two from 2^-40 to 2^40 (exact scalings: x = R_c y solves S x = b
/// when y solves the scaled system).
struct BadlyScaled {
  SparseMatrix S, scaled;
  Vector b, scaled_b, column_scale;
};

BadlyScaled badly_scaled_saddle_point() {
  BadlyScaled p;
  p.S = saddle_point(600, 3);
  p.b = right_hand_side(p.S.rows());
  Vector row(p.S.rows());
  p.column_scale.resize(p.S.cols());
  for (Index i = 0; i < p.S.rows(); ++i) {
    row[i] = std::ldexp(1.0, static_cast<int>(std::lround(40.0 * std::sin(2.3 * i))));
    p.column_scale[i] = std::ldexp(1.0, static_cast<int>(std::lround(40.0 * std::cos(1.1 * i))));
  }
  p.scaled = row.asDiagonal() * p.S * p.column_scale.asDiagonal();
  p.scaled_b = row.asDiagonal() * p.b;
  return p;
}

} // namespace

TEST(LinearSolver, EveryDirectBackendSolvesAnUnsymmetricSaddlePointSystem) {
  const SparseMatrix S = saddle_point(600, 3);
  for (const LinearSolverKind kind : kDirectBackends) {
    SCOPED_TRACE(to_string(kind));
    EXPECT_LT(solve_residual(kind, S, nullptr), 1e-13);
  }
}

// The equations of a mixed model differ in scale by many orders (a steady-state step scales the
// flux rows by its pseudo-time step): every direct backend must solve R S C y = R b, R and C
// diagonal with powers of two from 2^-40 to 2^40 (exact scalings, so x = C y solves S x = b),
// backward stably and close to the solution of S x = b. Measured: UMFPACK and SparseLU to
// round-off (residuals 5e-16, solutions equal to 1e-15); MUMPS (threshold pivoting 0.01 in
// the nested-dissection order) to a residual of 8e-12 and a solution 3e-11 from the unscaled
// one. (An exact power-of-two equilibration of the matrix before MUMPS made this worse, 4e-7.)
TEST(LinearSolver, EveryDirectBackendSolvesABadlyScaledSystem) {
  const auto [S, scaled, b, scaled_b, col] = badly_scaled_saddle_point();
  for (const LinearSolverKind kind : kDirectBackends) {
    SCOPED_TRACE(to_string(kind));
    auto plain = linalg::make_linear_solver({kind});
    auto badly = linalg::make_linear_solver({kind});
    Vector x, y;
    plain->analyze_pattern(S);
    ASSERT_TRUE(plain->factorize(S));
    ASSERT_TRUE(plain->solve(b, x));
    badly->analyze_pattern(scaled);
    ASSERT_TRUE(badly->factorize(scaled)) << badly->failure().reason;
    ASSERT_TRUE(badly->solve(scaled_b, y)) << badly->failure().reason;
    EXPECT_LT((scaled * y - scaled_b).norm(), 1e-10 * scaled_b.norm());
    const Vector x_from_scaled = col.asDiagonal() * y;
    EXPECT_LT((x_from_scaled - x).norm(), 1e-9 * x.norm());
  }
}

TEST(LinearSolver, AutoTakesSparseLuForSmallAndMumpsForLargeSystems) {
  std::string chosen;
  const Index below = linalg::kAutoSparseLuLimit - 1000, above = linalg::kAutoSparseLuLimit;
  EXPECT_LT(
      solve_residual(LinearSolverKind::automatic, saddle_point(below - below / 5, 4), &chosen),
      1e-13);
  EXPECT_EQ(chosen, "auto (sparselu)");
  EXPECT_LT(solve_residual(LinearSolverKind::automatic, saddle_point(above, 4), &chosen), 1e-13);
  EXPECT_EQ(chosen, "auto (mumps)");
}

// A 3-D stencil (the 7-point Laplacian on a 14^3 grid, 2 744 equations) fills SparseLU's
// factors far beyond kAutoFillRatio: "auto" hands it to MUMPS after the first factorization and
// keeps MUMPS for the next pattern of the run; a 1-D system of the same size stays with SparseLU.
TEST(LinearSolver, AutoHandsHighFillSystemsToMumps) {
  const Index n = 14, rows = n * n * n;
  std::vector<Eigen::Triplet<Real>> t;
  const auto at = [&](Index i, Index j, Index k) { return (k * n + j) * n + i; };
  for (Index k = 0; k < n; ++k)
    for (Index j = 0; j < n; ++j)
      for (Index i = 0; i < n; ++i) {
        const Index r = at(i, j, k);
        t.emplace_back(r, r, 6.5);
        if (i > 0)
          t.emplace_back(r, at(i - 1, j, k), -1.0);
        if (i + 1 < n)
          t.emplace_back(r, at(i + 1, j, k), -1.0);
        if (j > 0)
          t.emplace_back(r, at(i, j - 1, k), -1.0);
        if (j + 1 < n)
          t.emplace_back(r, at(i, j + 1, k), -1.0);
        if (k > 0)
          t.emplace_back(r, at(i, j, k - 1), -1.0);
        if (k + 1 < n)
          t.emplace_back(r, at(i, j, k + 1), -1.0);
      }
  SparseMatrix L(rows, rows);
  L.setFromTriplets(t.begin(), t.end());
  ASSERT_GE(rows, linalg::kAutoFillCheckRows);
  std::string chosen;
  EXPECT_LT(solve_residual(LinearSolverKind::automatic, L, &chosen),
            1e-10); // MUMPS reusing: FGMRES to 1e-10
  EXPECT_EQ(chosen, "auto (mumps)");
  EXPECT_LT(solve_residual(LinearSolverKind::automatic, saddle_point(rows, 4), &chosen), 1e-13);
  EXPECT_EQ(chosen, "auto (sparselu)");

  auto solver = linalg::make_linear_solver({LinearSolverKind::automatic});
  solver->analyze_pattern(L);
  ASSERT_TRUE(solver->factorize(L));
  EXPECT_EQ(solver->name(), "auto (mumps)");
  const SparseMatrix S = saddle_point(600, 3); // a later, small pattern of the same run
  solver->analyze_pattern(S);
  ASSERT_TRUE(solver->factorize(S));
  Vector x;
  ASSERT_TRUE(solver->solve(right_hand_side(S.rows()), x));
  EXPECT_EQ(solver->name(), "auto (mumps)");
  EXPECT_LT((S * x - right_hand_side(S.rows())).norm(), 1e-10 * right_hand_side(S.rows()).norm());
}

TEST(LinearSolver, MumpsReanalysesANewPatternAndTakesPetscOptions) {
  // a new pattern (another size) after the first; options that MUMPS reads (AMD ordering,
  // 50 % workspace relaxation) give the same solution to round-off
  auto plain = linalg::make_linear_solver({LinearSolverKind::mumps});
  auto tuned =
      linalg::make_linear_solver({.kind = LinearSolverKind::mumps,
                                  .petsc_options = "-mat_mumps_icntl_7 0 -mat_mumps_icntl_14 50"});
  for (const Index n : {300, 900}) {
    const SparseMatrix S = saddle_point(n, 3);
    const Vector b = right_hand_side(S.rows());
    Vector x1, x2;
    for (auto* solver : {plain.get(), tuned.get()}) {
      solver->analyze_pattern(S);
      ASSERT_TRUE(solver->factorize(S)) << solver->failure().reason;
      ASSERT_TRUE(solver->solve(b, solver == plain.get() ? x1 : x2));
    }
    EXPECT_LT((S * x1 - b).norm(), 1e-13 * b.norm());
    EXPECT_LT((x1 - x2).norm(), 1e-12 * x1.norm());
  }
}

class MumpsReusing : public ::testing::TestWithParam<FactorPrecision> {
protected:
  std::unique_ptr<linalg::LinearSolver> make() const {
    return linalg::make_linear_solver(
        {.kind = LinearSolverKind::mumps, .reuse_factorization = true, .precision = GetParam()});
  }
  /// FGMRES iterations to 1e-10 with a fresh factorization: 1 in double precision (exact to
  /// round-off); in single precision each iteration gains at least 1e-4 on this system.
  int fresh_iterations() const { return GetParam() == FactorPrecision::full ? 1 : 3; }
};

INSTANTIATE_TEST_SUITE_P(Precisions, MumpsReusing,
                         ::testing::Values(FactorPrecision::single, FactorPrecision::full),
                         [](const auto& info) {
                           return info.param == FactorPrecision::full ? "Double" : "Single";
                         });

TEST_P(MumpsReusing, SolvesLaterMatricesToTheKrylovTolerance) {
  // one factorization preconditions the next matrices of the pattern: a nearby one (a Newton
  // iteration later) in a few FGMRES iterations; a far one (every value of the first block
  // row scaled) through a new factorization when the old one does not serve, the hopeless
  // solve stopped after kRateCheckIterations (3), not after 15
  const SparseMatrix S = saddle_point(600, 3);
  const Vector b = right_hand_side(S.rows());
  auto solver = make();
  solver->analyze_pattern(S);
  Vector x;
  ASSERT_TRUE(solver->factorize(S)) << solver->failure().reason;
  ASSERT_TRUE(solver->solve(b, x));
  EXPECT_LT((S * x - b).norm(), 1e-10 * b.norm());
  EXPECT_GE(solver->last_iterations(), 1);
  EXPECT_LE(solver->last_iterations(), fresh_iterations());

  SparseMatrix near = S;
  for (Index k = 0; k < near.nonZeros(); ++k)
    near.valuePtr()[k] *= 1.0 + 0.01 * std::sin(1.7 * k);
  ASSERT_TRUE(solver->factorize(near));
  ASSERT_TRUE(solver->solve(b, x));
  EXPECT_LT((near * x - b).norm(), 1e-9 * b.norm());
  EXPECT_GT(solver->last_iterations(), 1); // the old factorization served
  EXPECT_LE(solver->last_iterations(), 8);

  SparseMatrix far = S;
  for (Index k = 0; k < far.nonZeros(); ++k)
    far.valuePtr()[k] *= 1.0 + 0.9 * std::sin(0.3 * k);
  ASSERT_TRUE(solver->factorize(far));
  ASSERT_TRUE(solver->solve(b, x)) << solver->failure().reason;
  EXPECT_LT((far * x - b).norm(), 1e-9 * b.norm());
  EXPECT_LE(solver->last_iterations(), 3 + fresh_iterations());
}

TEST_P(MumpsReusing, ContinuesASolveToATighterTolerance) {
  // the FGMRES of reuse stops at the tolerance Newton asks for, and continues from its result
  const SparseMatrix S = saddle_point(600, 3);
  const Vector b = right_hand_side(S.rows());
  auto solver = make();
  solver->analyze_pattern(S);
  ASSERT_TRUE(solver->factorize(S)) << solver->failure().reason;
  Vector x;
  ASSERT_TRUE(solver->solve(b, x));
  SparseMatrix near = S;
  for (Index k = 0; k < near.nonZeros(); ++k)
    near.valuePtr()[k] *= 1.0 + 0.01 * std::sin(1.7 * k);
  ASSERT_TRUE(solver->factorize(near));
  solver->set_relative_tolerance(1e-3);
  ASSERT_TRUE(solver->solve(b, x));
  const Real loose = (near * x - b).norm() / b.norm();
  EXPECT_LE(loose, 1e-3);
  EXPECT_GT(loose, 1e-10);
  solver->set_relative_tolerance(1e-10);
  ASSERT_TRUE(solver->refine(b, x)) << solver->failure().reason;
  EXPECT_LE((near * x - b).norm() / b.norm(), 1e-9);
  EXPECT_GE(solver->last_iterations(), 1);
}

TEST(LinearSolver, MumpsReusingSinglePrecisionFactorizationsSolvesABadlyScaledSystem) {
  // the scaling of EveryDirectBackendSolvesABadlyScaledSystem (entries from 2^-80 to 2^80 of
  // the unscaled ones, within single precision's range): MUMPS's own scaling before the
  // single-precision factorization, FGMRES in double precision to 1e-10
  const BadlyScaled system = badly_scaled_saddle_point();
  const SparseMatrix& scaled = system.scaled;
  const Vector& scaled_b = system.scaled_b;
  auto solver =
      linalg::make_linear_solver({.kind = LinearSolverKind::mumps, .reuse_factorization = true});
  Vector y;
  solver->analyze_pattern(scaled);
  ASSERT_TRUE(solver->factorize(scaled)) << solver->failure().reason;
  ASSERT_TRUE(solver->solve(scaled_b, y)) << solver->failure().reason;
  EXPECT_LT((scaled * y - scaled_b).norm(), 1e-10 * scaled_b.norm());
  EXPECT_LE(solver->last_iterations(), 3);
}

namespace {

/// The 1-D Laplacian with zero Neumann ends plus `shift` on the diagonal: eigenvalues from
/// `shift` to 4 + `shift`, nearly singular for a small shift.
SparseMatrix shifted_neumann_laplacian(Index n, Real shift) {
  std::vector<Eigen::Triplet<Real>> t;
  for (Index i = 0; i < n; ++i) {
    t.emplace_back(i, i, (i == 0 || i + 1 == n ? 1.0 : 2.0) + shift);
    if (i > 0)
      t.emplace_back(i, i - 1, -1.0);
    if (i + 1 < n)
      t.emplace_back(i, i + 1, -1.0);
  }
  SparseMatrix A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

} // namespace

TEST(LinearSolver, MumpsReusingFactorizationsTurnsToDoublePrecisionWhereSingleDoesNotServe) {
  // condition number 4e10: the single-precision factors are no preconditioner (or MUMPS finds
  // the matrix singular in single precision); the solve must still succeed, in double precision:
  // a backward error (residual over ‖A‖‖x‖ + ‖b‖, ‖A‖ ≤ 4) of round-off, where single precision
  // leaves 1e-8 at best
  const SparseMatrix A = shifted_neumann_laplacian(400, 1e-10);
  const Vector b = right_hand_side(A.rows());
  std::ostringstream log;
  const auto sink = std::make_shared<spdlog::sinks::ostream_sink_mt>(log);
  spdlog::default_logger()->sinks().push_back(sink);
  auto solver =
      linalg::make_linear_solver({.kind = LinearSolverKind::mumps, .reuse_factorization = true});
  solver->analyze_pattern(A);
  Vector x;
  const bool factorized = solver->factorize(A);
  const bool solved = factorized && solver->solve(b, x);
  spdlog::default_logger()->sinks().pop_back();
  ASSERT_TRUE(solved) << solver->failure().reason;
  EXPECT_LT((A * x - b).norm(), 1e-12 * (4.0 * x.norm() + b.norm()));
  EXPECT_NE(log.str().find("factorizing in double precision from here"), std::string::npos)
      << log.str();
}

TEST(LinearSolver, MumpsOptionsWithSinglePrecisionReuseAreAnInputErrorNamingTheKey) {
  try {
    linalg::make_linear_solver({.kind = LinearSolverKind::mumps,
                                .petsc_options = "-mat_mumps_icntl_14 50",
                                .reuse_factorization = true});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("factorization_precision = \"double\""), std::string::npos)
        << e.what();
  }
  EXPECT_NO_THROW(linalg::make_linear_solver({.kind = LinearSolverKind::mumps,
                                              .petsc_options = "-mat_mumps_icntl_14 50",
                                              .reuse_factorization = true,
                                              .precision = FactorPrecision::full}));
}

TEST(LinearSolver, MumpsReportsASingularMatrixAsCurable) {
  SparseMatrix S = saddle_point(60, 3);
  for (Index k = S.outerIndexPtr()[5]; k < S.outerIndexPtr()[6]; ++k)
    S.valuePtr()[k] = 0.0; // column 5 zero: singular
  auto solver = linalg::make_linear_solver({LinearSolverKind::mumps});
  solver->analyze_pattern(S);
  EXPECT_FALSE(solver->factorize(S));
  EXPECT_NE(solver->failure().reason.find("singular"), std::string::npos)
      << solver->failure().reason;
  EXPECT_FALSE(solver->failure().permanent); // a smaller step may give a regular matrix
}

TEST_P(MumpsReusing, RecoversFromASingularMatrix) {
  // a Newton iteration meets a singular matrix (the old factorization cannot solve it, the new
  // one fails), then the step is cut back and the next matrix is regular: it must be solved,
  // not preconditioned by the failed factorization (MUMPS would refuse the solve, INFOG(1) = -3)
  const SparseMatrix S = saddle_point(60, 3);
  const Vector b = right_hand_side(S.rows());
  SparseMatrix singular = S;
  for (Index k = singular.outerIndexPtr()[5]; k < singular.outerIndexPtr()[6]; ++k)
    singular.valuePtr()[k] = 0.0; // column 5 zero
  auto solver = make();
  solver->analyze_pattern(S);
  Vector x;
  ASSERT_TRUE(solver->factorize(S)) << solver->failure().reason;
  ASSERT_TRUE(solver->solve(b, x));
  EXPECT_TRUE(solver->factorize(singular)); // the old factorization is tried first
  EXPECT_FALSE(solver->solve(b, x));        // it does not serve, and a new one fails
  for (int retry = 0; retry < 3; ++retry) { // every later regular matrix is solved
    ASSERT_TRUE(solver->factorize(S)) << solver->failure().reason;
    ASSERT_TRUE(solver->solve(b, x)) << solver->failure().reason;
    EXPECT_LT((S * x - b).norm(), 1e-10 * b.norm());
  }
}

TEST(LinearSolver, UnusedPetscOptionIsAnInputErrorNamingIt) {
  try {
    linalg::make_linear_solver({.kind = LinearSolverKind::mumps,
                                .petsc_options = "-mat_mumps_icntl_14 50 -mat_mumsp_icntl_7 5"});
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("-mat_mumsp_icntl_7 5"), std::string::npos) << what;
    EXPECT_EQ(what.find("icntl_14"), what.find("icntl_14 50 -mat")) << what; // not as unused
  }
  EXPECT_NO_THROW(linalg::make_linear_solver(
      {.kind = LinearSolverKind::mumps, .petsc_options = "-mat_mumps_icntl_14 60"})); // cleared
}

// A singular matrix with an empty column: the direct solvers' failure names its equation, which
// Newton's message then describes in the user's terms (field, node, component).
TEST(LinearSolver, DirectSolversNameTheEquationOfAnEmptyColumn) {
  const SparseMatrix S = saddle_point(60, 3);
  for (const Index empty : {Index{0}, Index{17}, Index{41}, Index{61}}) {
    std::vector<Eigen::Triplet<Real>> kept;
    for (Index c = 0; c < S.outerSize(); ++c)
      for (SparseMatrix::InnerIterator it(S, c); it; ++it)
        if (it.col() != empty)
          kept.emplace_back(it.row(), it.col(), it.value());
    SparseMatrix A(S.rows(), S.cols());
    A.setFromTriplets(kept.begin(), kept.end());
    for (const auto kind : {LinearSolverKind::sparselu, LinearSolverKind::umfpack}) {
      auto solver = linalg::make_linear_solver({kind});
      solver->analyze_pattern(A);
      EXPECT_FALSE(solver->factorize(A));
      EXPECT_EQ(solver->failure().equation, empty) << solver->failure().reason;
    }
  }
}
