// SPDX-License-Identifier: MIT
#include "trifem/linalg/petsc_mpi_matrix.hpp"

#include "trifem/linalg/petsc_session.hpp"

namespace trifem::linalg::petsc {

RowLayout::RowLayout(const std::vector<int>& equation_owner, int rank_, int processes)
    : row(equation_owner.size()), start(processes + 1, 0), rank(rank_) {
  for (int owner : equation_owner)
    ++start[owner + 1];
  for (int r = 0; r < processes; ++r)
    start[r + 1] += start[r];
  std::vector<PetscInt> next(start.begin(), start.end() - 1);
  for (std::size_t eq = 0; eq < equation_owner.size(); ++eq)
    row[eq] = next[equation_owner[eq]]++;
}

MpiAijMatrix::MpiAijMatrix(const SparseMatrix& part, const RowLayout& layout)
    : row_of_entry_(part.nonZeros()), column_(part.cols()) {
  const PetscInt first = layout.start[layout.rank], last = layout.start[layout.rank + 1];
  for (Index k = 0; k < part.nonZeros(); ++k) {
    row_of_entry_[k] = layout.row[part.innerIndexPtr()[k]];
    if (row_of_entry_[k] < first || row_of_entry_[k] >= last)
      ++sent_entries_;
  }
  for (Index j = 0; j < part.cols(); ++j)
    column_[j] = layout.row[j];
  const PetscInt local = layout.local_rows(), global = layout.rows();
  Mat counter = nullptr; // records the union of the patterns for the preallocation
  check(MatCreate(PETSC_COMM_WORLD, &counter), "PETSc matrix");
  check(MatSetType(counter, MATPREALLOCATOR), "PETSc matrix");
  check(MatSetSizes(counter, local, local, global, global), "PETSc matrix");
  check(MatSetUp(counter), "PETSc matrix");
  add_part(counter, part);
  check(MatCreate(PETSC_COMM_WORLD, &matrix_), "PETSc matrix");
  check(MatSetType(matrix_, MATAIJ), "PETSc matrix");
  check(MatSetSizes(matrix_, local, local, global, global), "PETSc matrix");
  check(MatPreallocatorPreallocate(counter, PETSC_TRUE, matrix_), "PETSc matrix preallocation");
  MatDestroy(&counter);
  check(MatSetOption(matrix_, MAT_NEW_NONZERO_LOCATION_ERR, PETSC_TRUE), "PETSc matrix");
  check(MatSetOption(matrix_, MAT_SUBSET_OFF_PROC_ENTRIES, PETSC_TRUE), "PETSc matrix");
  update(part);
}

MpiAijMatrix::~MpiAijMatrix() {
  if (matrix_)
    MatDestroy(&matrix_);
}

void MpiAijMatrix::add_part(Mat target, const SparseMatrix& part) const {
  const Index* start = part.outerIndexPtr();
  for (Index j = 0; j < part.cols(); ++j) {
    const PetscInt count = start[j + 1] - start[j];
    if (count > 0) // one column: its values in row-major order are the column's
      check(MatSetValues(target, count, row_of_entry_.data() + start[j], 1, &column_[j],
                         part.valuePtr() + start[j], ADD_VALUES),
            "PETSc matrix values");
  }
  check(MatAssemblyBegin(target, MAT_FINAL_ASSEMBLY), "PETSc matrix assembly");
  check(MatAssemblyEnd(target, MAT_FINAL_ASSEMBLY), "PETSc matrix assembly");
}

void MpiAijMatrix::update(const SparseMatrix& part) {
  check(MatZeroEntries(matrix_), "PETSc matrix");
  add_part(matrix_, part);
}

void MpiAijMatrix::assign_values(const MpiAijMatrix& other) {
  check(MatCopy(other.matrix_, matrix_, SAME_NONZERO_PATTERN), "PETSc matrix copy");
}

void set_vector(Vec v, const Vector& b, const RowLayout& layout) {
  PetscScalar* data = nullptr;
  check(VecGetArray(v, &data), "PETSc vector");
  const PetscInt first = layout.start[layout.rank], last = layout.start[layout.rank + 1];
  for (std::size_t eq = 0; eq < layout.row.size(); ++eq)
    if (const PetscInt r = layout.row[eq]; r >= first && r < last)
      data[r - first] = b[static_cast<Index>(eq)];
  check(VecRestoreArray(v, &data), "PETSc vector");
}

Gather::Gather(Vec like) {
  check(VecScatterCreateToAll(like, &scatter_, &all_), "PETSc scatter");
}

Gather::~Gather() {
  if (scatter_)
    VecScatterDestroy(&scatter_);
  if (all_)
    VecDestroy(&all_);
}

void Gather::operator()(Vec v, Vector& x, const RowLayout& layout) {
  check(VecScatterBegin(scatter_, v, all_, INSERT_VALUES, SCATTER_FORWARD), "PETSc scatter");
  check(VecScatterEnd(scatter_, v, all_, INSERT_VALUES, SCATTER_FORWARD), "PETSc scatter");
  const PetscScalar* data = nullptr;
  check(VecGetArrayRead(all_, &data), "PETSc vector");
  x.resize(static_cast<Index>(layout.row.size()));
  for (std::size_t eq = 0; eq < layout.row.size(); ++eq)
    x[static_cast<Index>(eq)] = data[layout.row[eq]];
  check(VecRestoreArrayRead(all_, &data), "PETSc vector");
}

} // namespace trifem::linalg::petsc
