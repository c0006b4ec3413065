// SPDX-License-Identifier: MIT
// Sparse direct solver interface: analyze the pattern once, factorize per matrix, solve.
#pragma once

#include "trifem/core/types.hpp"

#include <memory>
#include <string>
#include <vector>

namespace trifem::linalg {

/// A sparse direct solver for general (unsymmetric) matrices.
class LinearSolver {
public:
  virtual ~LinearSolver() = default;
  /// Symbolic analysis (ordering); reused while the sparsity pattern is unchanged.
  virtual void analyze_pattern(const SparseMatrix& A) = 0;
  /// Numeric factorization; false if the matrix is singular or the factorization failed.
  virtual bool factorize(const SparseMatrix& A) = 0;
  /// Solves A x = b with the last factorization; false on failure.
  virtual bool solve(const Vector& b, Vector& x) = 0;
  /// Backend name ("umfpack", "sparselu", "auto (sparselu)", ...).
  virtual std::string name() const = 0;
};

/// Names of the available backends.
std::vector<std::string> available_linear_solvers();

/// Creates the backend `name`; InputError listing the available ones otherwise.
std::unique_ptr<LinearSolver> make_linear_solver(const std::string& name);

} // namespace trifem::linalg
