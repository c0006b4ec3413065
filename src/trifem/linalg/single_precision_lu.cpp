// SPDX-License-Identifier: MIT
#include "trifem/linalg/single_precision_lu.hpp"

#include <mpi.h>
#include <smumps_c.h>

#include <algorithm>
#include <type_traits>

namespace trifem::linalg {
namespace {

static_assert(std::is_same_v<MUMPS_INT, int>, "MUMPS built with 32-bit integers expected");

constexpr int kInitialize = -1, kTerminate = -2, kAnalyze = 1, kFactorize = 2, kSolve = 3;
constexpr int kMaxSmumpsWorkspaceRetries = 4;

/// INFOG(1) of a workspace estimate too small (pivots delayed beyond what the analysis foresaw).
bool smumps_workspace_too_small(int infog1) {
  return infog1 == -8 || infog1 == -9 || infog1 == -14 || infog1 == -15 || infog1 == -17 ||
         infog1 == -20;
}

} // namespace

struct SinglePrecisionLu::Instance {
  SMUMPS_STRUC_C id{};
  int& icntl(int i) { return id.icntl[i - 1]; } // MUMPS numbers its controls from 1
  int infog(int i) const { return id.infog[i - 1]; }
};

SinglePrecisionLu::SinglePrecisionLu() : mumps_(std::make_unique<Instance>()) {
  SMUMPS_STRUC_C& id = mumps_->id;
  id.par = 1; // the host works
  id.sym = 0; // unsymmetric
  id.comm_fortran = static_cast<MUMPS_INT>(MPI_Comm_c2f(MPI_COMM_SELF));
  call(kInitialize);
  mumps_->icntl(1) = -1; // no messages: failures are reported through INFOG
  mumps_->icntl(2) = -1;
  mumps_->icntl(3) = -1;
  mumps_->icntl(4) = 0;
}

SinglePrecisionLu::~SinglePrecisionLu() {
  mumps_->id.job = kTerminate;
  smumps_c(&mumps_->id);
}

bool SinglePrecisionLu::call(int job) {
  mumps_->id.job = job;
  smumps_c(&mumps_->id);
  infog1_ = mumps_->infog(1);
  infog2_ = mumps_->infog(2);
  return infog1_ >= 0;
}

bool SinglePrecisionLu::analyze(PetscInt n, const PetscInt* row_start, const PetscInt* column,
                                const PetscScalar* values) {
  n_ = n;
  const PetscInt entries = row_start[n];
  row_.resize(entries);
  column_.resize(entries);
  values_.resize(entries);
  for (PetscInt i = 0; i < n; ++i)
    for (PetscInt k = row_start[i]; k < row_start[i + 1]; ++k) {
      row_[k] = static_cast<int>(i + 1);
      column_[k] = static_cast<int>(column[k] + 1);
    }
  std::transform(values, values + entries, values_.begin(),
                 [](PetscScalar v) { return static_cast<float>(v); });
  perm_in_.resize(n);
  for (PetscInt i = 0; i < n; ++i)
    perm_in_[i] = static_cast<int>(i + 1); // the pivots in the order given
  rhs_.resize(n);
  SMUMPS_STRUC_C& id = mumps_->id;
  id.n = static_cast<MUMPS_INT>(n);
  id.nnz = entries;
  id.irn = row_.data();
  id.jcn = column_.data();
  id.a = values_.data();
  id.perm_in = perm_in_.data();
  mumps_->icntl(7) = 1; // the ordering given in perm_in
  return call(kAnalyze);
}

bool SinglePrecisionLu::factorize(const PetscScalar* values) {
  std::transform(values, values + values_.size(), values_.begin(),
                 [](PetscScalar v) { return static_cast<float>(v); });
  const int relaxation = mumps_->icntl(14);
  for (int retry = 0;; ++retry) {
    if (call(kFactorize)) {
      mumps_->icntl(14) = relaxation;
      return true;
    }
    if (!smumps_workspace_too_small(infog1_) || retry == kMaxSmumpsWorkspaceRetries) {
      mumps_->icntl(14) = relaxation;
      return false;
    }
    mumps_->icntl(14) = std::max(50, 2 * mumps_->icntl(14));
  }
}

bool SinglePrecisionLu::solve(const PetscScalar* b, PetscScalar* x) {
  std::transform(b, b + n_, rhs_.begin(), [](PetscScalar v) { return static_cast<float>(v); });
  SMUMPS_STRUC_C& id = mumps_->id;
  id.rhs = rhs_.data();
  id.nrhs = 1;
  id.lrhs = static_cast<MUMPS_INT>(n_);
  if (!call(kSolve))
    return false;
  std::transform(rhs_.begin(), rhs_.end(), x, [](float v) { return static_cast<PetscScalar>(v); });
  return true;
}

} // namespace trifem::linalg
