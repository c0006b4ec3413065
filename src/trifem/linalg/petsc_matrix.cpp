// SPDX-License-Identifier: MIT
#include "trifem/linalg/petsc_matrix.hpp"

#include "trifem/linalg/petsc_session.hpp"

#include <algorithm>

namespace trifem::linalg::petsc {

CsrPattern::CsrPattern(const SparseMatrix& A, const std::vector<Index>& new_to_old)
    : order(new_to_old) {
  const Index n = static_cast<Index>(A.rows());
  if (!order.empty()) {
    position.resize(n);
    for (Index i = 0; i < n; ++i)
      position[order[i]] = i;
  }
  auto to_new = [&](Index old) { return position.empty() ? old : position[old]; };
  row_start.assign(n + 1, 0);
  for (Index k = 0; k < A.nonZeros(); ++k)
    ++row_start[to_new(A.innerIndexPtr()[k]) + 1];
  for (Index i = 0; i < n; ++i)
    row_start[i + 1] += row_start[i];
  column.resize(A.nonZeros());
  std::vector<PetscInt> next(row_start.begin(), row_start.end() - 1);
  for (Index j = 0; j < A.cols(); ++j) { // new columns in order: each row's come sorted
    const Index old = order.empty() ? j : order[j];
    for (Index k = A.outerIndexPtr()[old]; k < A.outerIndexPtr()[old + 1]; ++k)
      column[next[to_new(A.innerIndexPtr()[k])]++] = static_cast<PetscInt>(j);
  }
}

void CsrPattern::scatter(const SparseMatrix& A, PetscScalar* to,
                         const std::vector<Real>& row_factor) const {
  const Index n = static_cast<Index>(row_start.size()) - 1;
  const Real* v = A.valuePtr();
  std::vector<PetscInt> next(row_start.begin(), row_start.end() - 1);
  for (Index j = 0; j < n; ++j) { // the order in which the pattern was built
    const Index old = order.empty() ? j : order[j];
    for (Index k = A.outerIndexPtr()[old]; k < A.outerIndexPtr()[old + 1]; ++k) {
      const Index row = position.empty() ? A.innerIndexPtr()[k] : position[A.innerIndexPtr()[k]];
      to[next[row]++] = (row_factor.empty() ? 1.0 : row_factor[row]) * v[k];
    }
  }
}

SeqAijMatrix::SeqAijMatrix(const SparseMatrix& A, const std::vector<Index>& order)
    : pattern_(A, order), values_(A.nonZeros(), 0.0) {
  pattern_.scatter(A, values_.data());
  check(MatCreateSeqAIJWithArrays(PETSC_COMM_SELF, static_cast<PetscInt>(A.rows()),
                                  static_cast<PetscInt>(A.cols()), pattern_.row_start.data(),
                                  pattern_.column.data(), values_.data(), &matrix_),
        "PETSc matrix");
}

SeqAijMatrix::~SeqAijMatrix() {
  if (matrix_)
    MatDestroy(&matrix_);
}

void SeqAijMatrix::update(const SparseMatrix& A, const std::vector<Real>& row_sign) {
  // through Get/RestoreArray, so PETSc knows the values changed
  PetscScalar* to = nullptr;
  check(MatSeqAIJGetArray(matrix_, &to), "PETSc matrix");
  pattern_.scatter(A, to, row_sign);
  check(MatSeqAIJRestoreArray(matrix_, &to), "PETSc matrix");
}

void set_vector(Vec v, const Vector& b, const std::vector<Index>& order,
                const std::vector<Real>& sign) {
  PetscScalar* data = nullptr;
  check(VecGetArray(v, &data), "PETSc vector");
  for (Index i = 0; i < static_cast<Index>(b.size()); ++i)
    data[i] = (sign.empty() ? 1.0 : sign[i]) * b[order.empty() ? i : order[i]];
  check(VecRestoreArray(v, &data), "PETSc vector");
}

void get_vector(Vec v, Vector& x, const std::vector<Index>& order) {
  PetscInt n = 0;
  check(VecGetLocalSize(v, &n), "PETSc vector");
  x.resize(n);
  const PetscScalar* data = nullptr;
  check(VecGetArrayRead(v, &data), "PETSc vector");
  for (Index i = 0; i < static_cast<Index>(n); ++i)
    x[order.empty() ? i : order[i]] = data[i];
  check(VecRestoreArrayRead(v, &data), "PETSc vector");
}

void SeqAijMatrix::assign_values(const SeqAijMatrix& other) {
  PetscScalar* to = nullptr;
  check(MatSeqAIJGetArray(matrix_, &to), "PETSc matrix");
  std::copy(other.values_.begin(), other.values_.end(), to);
  check(MatSeqAIJRestoreArray(matrix_, &to), "PETSc matrix");
}

} // namespace trifem::linalg::petsc
