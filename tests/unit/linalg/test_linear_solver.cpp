// SPDX-License-Identifier: MIT
// The sparse direct solvers on an unsymmetric saddle-point system (the structure of the mixed
// and contact tangents: a zero diagonal block), and the size rule of the "auto" backend.
#include "trifem/core/error.hpp"
#include "trifem/linalg/auto_solver.hpp"
#include "trifem/linalg/linear_solver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace trifem;

namespace {

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
Real solve_residual(const std::string& name, const SparseMatrix& S, std::string* chosen) {
  auto solver = linalg::make_linear_solver(name);
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

} // namespace

TEST(LinearSolver, EveryBackendSolvesAnUnsymmetricSaddlePointSystem) {
  const SparseMatrix S = saddle_point(600, 3);
  for (const std::string& name : linalg::available_linear_solvers()) {
    SCOPED_TRACE(name);
    EXPECT_LT(solve_residual(name, S, nullptr), 1e-13);
  }
}

TEST(LinearSolver, AutoTakesSparseLuForSmallAndUmfpackForLargeSystems) {
  std::string chosen;
  const Index below = linalg::kAutoSparseLuLimit - 1000, above = linalg::kAutoSparseLuLimit;
  EXPECT_LT(solve_residual("auto", saddle_point(below - below / 5, 4), &chosen), 1e-13);
  EXPECT_EQ(chosen, "auto (sparselu)");
  EXPECT_LT(solve_residual("auto", saddle_point(above, 4), &chosen), 1e-13);
  EXPECT_EQ(chosen, "auto (umfpack)");
}

TEST(LinearSolver, UnknownBackendIsNamedWithTheChoices) {
  try {
    linalg::make_linear_solver("mumps");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "unknown linear solver 'mumps' (expected auto, umfpack or sparselu)");
  }
}
