// SPDX-License-Identifier: MIT
// A PETSc matrix and vectors distributed over the processes of a run: each process holds the
// rows of the equations it owns, adds its elements' contributions to any row, and receives the
// whole solution.
#pragma once

#include "trifem/core/types.hpp"

#include <petscmat.h>

#include <cstdint>
#include <vector>

namespace trifem::linalg::petsc {

/// The PETSc numbering of the equations on several processes: process r holds rows
/// [start[r], start[r + 1]), its own equations in ascending order.
struct RowLayout {
  std::vector<PetscInt> row;   ///< PETSc row of each equation
  std::vector<PetscInt> start; ///< first row of each process, and the row count at the end
  int rank = 0;

  /// From the owner of each equation (values 0 .. processes - 1).
  RowLayout(const std::vector<int>& equation_owner, int rank, int processes);
  PetscInt local_rows() const { return start[rank + 1] - start[rank]; }
  PetscInt rows() const { return start.back(); }
};

/// An MPIAIJ matrix whose pattern is the union of the processes' parts. Each process gives
/// its own part, a column-major matrix over all equations holding its elements' couplings.
class MpiAijMatrix {
public:
  /// Creates the matrix (PETSC_COMM_WORLD, collective) with the union of the parts' patterns
  /// and the sum of their values.
  MpiAijMatrix(const SparseMatrix& part, const RowLayout& layout);
  ~MpiAijMatrix();
  MpiAijMatrix(const MpiAijMatrix&) = delete;
  MpiAijMatrix& operator=(const MpiAijMatrix&) = delete;

  /// Sets the values to the sum of the parts (each of the pattern given at construction);
  /// collective.
  void update(const SparseMatrix& part);
  /// Copies the values of `other`, a matrix of the same layout and pattern.
  void assign_values(const MpiAijMatrix& other);
  Mat mat() const { return matrix_; }
  /// Stored entries of this process's part, and those of them in rows of other processes
  /// (sent at every assembly).
  std::int64_t entries() const { return static_cast<std::int64_t>(row_of_entry_.size()); }
  std::int64_t sent_entries() const { return sent_entries_; }

private:
  void add_part(Mat target, const SparseMatrix& part) const;

  std::vector<PetscInt> row_of_entry_; ///< PETSc row of every stored entry of the part
  std::vector<PetscInt> column_;       ///< PETSc column of every column of the part
  std::int64_t sent_entries_ = 0;
  Mat matrix_ = nullptr;
};

/// Writes this process's rows of `b` (over all equations, the same on every process) into `v`.
void set_vector(Vec v, const Vector& b, const RowLayout& layout);

/// Gathers a distributed vector into x (over all equations) on every process.
class Gather {
public:
  explicit Gather(Vec like);
  ~Gather();
  Gather(const Gather&) = delete;
  Gather& operator=(const Gather&) = delete;
  void operator()(Vec v, Vector& x, const RowLayout& layout);

private:
  VecScatter scatter_ = nullptr;
  Vec all_ = nullptr;
};

} // namespace trifem::linalg::petsc
