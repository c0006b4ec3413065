// SPDX-License-Identifier: MIT
// A sequential PETSc AIJ (compressed-row) copy of a column-major Eigen matrix whose values can
// be refreshed in place while the pattern is unchanged.
#pragma once

#include "trifem/core/types.hpp"

#include <petscmat.h>

#include <vector>

namespace trifem::linalg::petsc {

/// The pattern of a column-major matrix in compressed rows, optionally symmetrically permuted
/// (row and column `order[i]` of A become row and column i).
struct CsrPattern {
  std::vector<PetscInt> row_start, column;
  std::vector<Index> order;    ///< new → old (empty: the identity)
  std::vector<Index> position; ///< old → new (empty: the identity)

  explicit CsrPattern(const SparseMatrix& A, const std::vector<Index>& order = {});
  /// Writes the values of A (this pattern) in compressed-row order into `to`, row i (new)
  /// multiplied by row_factor[i] when row_factor is not empty. A pass over A's columns in the
  /// new order, as the pattern was built: no map per entry is stored.
  void scatter(const SparseMatrix& A, PetscScalar* to,
               const std::vector<Real>& row_factor = {}) const;
};

/// Writes sign[i] · b[order[i]] into `v` (an empty `order` is the identity, an empty `sign` 1).
void set_vector(Vec v, const Vector& b, const std::vector<Index>& order = {},
                const std::vector<Real>& sign = {});
/// Reads `v` into x: x[order[i]] = v[i] (an empty `order` is the identity); x is resized.
void get_vector(Vec v, Vector& x, const std::vector<Index>& order = {});

/// PETSc matrix sharing this object's value storage.
class SeqAijMatrix {
public:
  /// Creates the matrix with the pattern and values of `A`, permuted by `order` if given
  /// (CsrPattern).
  explicit SeqAijMatrix(const SparseMatrix& A, const std::vector<Index>& order = {});
  ~SeqAijMatrix();
  SeqAijMatrix(const SeqAijMatrix&) = delete;
  SeqAijMatrix& operator=(const SeqAijMatrix&) = delete;

  /// Copies the values of `A` (the pattern given at construction), multiplying row i (of the
  /// PETSc matrix) by row_sign[i] when row_sign is not empty (CsrPattern::scatter).
  void update(const SparseMatrix& A, const std::vector<Real>& row_sign = {});
  /// Copies the values of `other`, a matrix of the same pattern.
  void assign_values(const SeqAijMatrix& other);
  Mat mat() const { return matrix_; }
  /// The CSR pattern of the PETSc matrix (for orderings).
  const CsrPattern& pattern() const { return pattern_; }

private:
  CsrPattern pattern_;
  std::vector<PetscScalar> values_;
  Mat matrix_ = nullptr;
};

} // namespace trifem::linalg::petsc
