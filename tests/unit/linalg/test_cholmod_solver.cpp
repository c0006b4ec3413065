// SPDX-License-Identifier: MIT
// The Cholesky backend on a symmetric positive definite matrix given by its lower triangle, and
// its refusal of an indefinite one.
#include "trifem/linalg/cholmod_solver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace trifem;

namespace {

/// The 2-D five-point Laplacian on an n × n grid, plus `shift` on the diagonal: SPD for
/// shift > −8 sin²(π/(2(n+1))), indefinite well below. `lower_only` drops the upper triangle.
SparseMatrix laplacian(Index n, Real shift, bool lower_only) {
  std::vector<Eigen::Triplet<Real>> t;
  auto add = [&](Index i, Index j, Real v) {
    if (!lower_only || i >= j)
      t.emplace_back(i, j, v);
  };
  for (Index r = 0; r < n; ++r)
    for (Index c = 0; c < n; ++c) {
      const Index i = r * n + c;
      add(i, i, 4.0 + shift);
      if (c > 0)
        add(i, i - 1, -1.0);
      if (c + 1 < n)
        add(i, i + 1, -1.0);
      if (r > 0)
        add(i, i - n, -1.0);
      if (r + 1 < n)
        add(i, i + n, -1.0);
    }
  SparseMatrix A(n * n, n * n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

} // namespace

TEST(CholmodSolver, SolvesASymmetricPositiveDefiniteSystemFromItsLowerTriangle) {
  const SparseMatrix lower = laplacian(30, 0.01, true);
  const SparseMatrix full = laplacian(30, 0.01, false);
  Vector b(full.rows());
  for (Index i = 0; i < b.size(); ++i)
    b[i] = std::cos(0.7 * i) + 0.2;
  auto solver = linalg::make_cholmod_solver();
  solver->analyze_pattern(lower);
  ASSERT_TRUE(solver->factorize(lower));
  Vector x;
  ASSERT_TRUE(solver->solve(b, x));
  // condition number ≈ 8 / 0.01 · ...: the residual is a few ulps of ‖b‖ times that
  EXPECT_LT((full * x - b).norm(), 1e-10 * b.norm());
  // a second factorization on the same pattern, with the values scaled, halves the solution
  const SparseMatrix doubled = 2.0 * lower;
  ASSERT_TRUE(solver->factorize(doubled));
  Vector y;
  ASSERT_TRUE(solver->solve(b, y));
  EXPECT_LT((2.0 * y - x).norm(), 1e-12 * x.norm());
  EXPECT_EQ(solver->name(), "cholmod");
  EXPECT_TRUE(solver->failure().reason.empty());
}

TEST(CholmodSolver, RefusesAnIndefiniteMatrixWithAReason) {
  const SparseMatrix indefinite = laplacian(10, -4.0, true); // eigenvalues of both signs
  auto solver = linalg::make_cholmod_solver();
  solver->analyze_pattern(indefinite);
  EXPECT_FALSE(solver->factorize(indefinite));
  EXPECT_NE(solver->failure().reason.find("not positive definite"), std::string::npos);
  EXPECT_FALSE(solver->failure().permanent);
  Vector x;
  EXPECT_FALSE(solver->solve(Vector::Ones(indefinite.rows()), x));
}
