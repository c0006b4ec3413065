// SPDX-License-Identifier: MIT
// A sequential PETSc AIJ (compressed-row) copy of a column-major Eigen matrix whose values can
// be refreshed in place while the pattern is unchanged.
#pragma once

#include "trifem/core/types.hpp"

#include <petscmat.h>

#include <vector>

namespace trifem::linalg::petsc {

/// The pattern of a column-major matrix in compressed rows, optionally symmetrically permuted
/// (row and column `order[i]` of A become row and column i), and, per CSR entry, the position
/// of its value in the column-major storage.
struct CsrPattern {
  std::vector<PetscInt> row_start, column;
  std::vector<Index> source; ///< csr entry k holds A.valuePtr()[source[k]]

  explicit CsrPattern(const SparseMatrix& A, const std::vector<Index>& order = {});
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
  /// PETSc matrix) by row_sign[i] when row_sign is not empty.
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
