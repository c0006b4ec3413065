// SPDX-License-Identifier: MIT
// MUMPS's LU factorization in single precision (SMUMPS) of a sequential matrix given in compressed
// rows: half the factor memory, about half the factorization time and two thirds the solve time
// of double precision, for use as the preconditioner of a Krylov method iterating in double
// precision.
#pragma once

#include "trifem/core/types.hpp"

#include <petscsys.h>

#include <memory>
#include <vector>

namespace trifem::linalg {

/// SMUMPS on one process. The pattern (analyze) is kept in the pivot order it comes in (the
/// rows and columns are already ordered, e.g. by nested dissection); later factorizations take
/// new values of that pattern.
class SinglePrecisionLu {
public:
  SinglePrecisionLu();
  ~SinglePrecisionLu();
  SinglePrecisionLu(const SinglePrecisionLu&) = delete;
  SinglePrecisionLu& operator=(const SinglePrecisionLu&) = delete;

  /// The symbolic analysis of the n×n pattern in compressed rows (0-based), pivots in the
  /// given order; `values` (row_start[n] of them) guide MUMPS's column permutation and scaling.
  /// False on failure (infog1() says why).
  bool analyze(PetscInt n, const PetscInt* row_start, const PetscInt* column,
               const PetscScalar* values);
  /// A numeric factorization of `values` (the analysed pattern), rounded to single precision;
  /// a workspace estimate found too small is doubled and the factorization repeated.
  bool factorize(const PetscScalar* values);
  /// x = LU⁻¹ b (in single precision; b and x may be the same array). False on failure.
  bool solve(const PetscScalar* b, PetscScalar* x);

  /// INFOG(1), INFOG(2) of the last call (INFOG(1) < 0: it failed; the MUMPS users' guide).
  PetscInt infog1() const { return infog1_; }
  PetscInt infog2() const { return infog2_; }

private:
  bool call(int job);

  struct Instance; // the SMUMPS structure, kept out of this header
  std::unique_ptr<Instance> mumps_;
  PetscInt n_ = 0;
  std::vector<int> row_, column_, perm_in_; // MUMPS_INT, 1-based
  std::vector<float> values_, rhs_;
  PetscInt infog1_ = 0, infog2_ = 0;
};

} // namespace trifem::linalg
