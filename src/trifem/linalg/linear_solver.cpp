// SPDX-License-Identifier: MIT
#include "trifem/linalg/linear_solver.hpp"

#include "trifem/core/error.hpp"
#include "trifem/linalg/auto_solver.hpp"
#include "trifem/linalg/krylov_solver.hpp"
#include "trifem/linalg/petsc_solver.hpp"
#include "trifem/linalg/sparse_lu_solver.hpp"
#include "trifem/linalg/umfpack_solver.hpp"
#include "trifem/parallel/communicator.hpp"

namespace trifem::linalg {

void LinearSolver::set_hints(const SystemHints& hints) {
  if (!hints.equation_owner.empty())
    throw InputError(fmt::format("the linear solver '{}' runs on one process only", name()));
}

Index empty_column(const SparseMatrix& A) {
  for (Index c = 0; c < A.outerSize(); ++c) {
    bool nonzero = false;
    for (SparseMatrix::InnerIterator it(A, c); it && !nonzero; ++it)
      nonzero = it.value() != 0.0;
    if (!nonzero)
      return c;
  }
  return -1;
}

std::unique_ptr<LinearSolver> make_linear_solver(const LinearSolverChoice& c) {
  using enum LinearSolverKind;
  if (parallel::active()) { // on several processes MUMPS stands in for every direct backend
    if (c.kind == krylov)
      throw InputError(fmt::format("linear_solver = 'krylov' runs on one process only; on {} "
                                   "processes use 'mumps' or 'auto' (the distributed MUMPS)",
                                   parallel::size()));
    return make_mumps_solver(c.petsc_options, c.reuse_factorization, c.precision);
  }
  switch (c.kind) {
  case automatic:
    return make_auto_solver(c.precision);
  case umfpack:
    return make_umfpack_solver();
  case sparselu:
    return make_sparse_lu_solver();
  case mumps:
    return make_mumps_solver(c.petsc_options, c.reuse_factorization, c.precision);
  case krylov:
    return make_krylov_solver(c.petsc_options,
                              {.preconditioner = c.preconditioner, .schur = c.schur});
  }
  TRIFEM_VERIFY(false, "unknown linear solver kind {}", static_cast<int>(c.kind));
  return nullptr;
}

} // namespace trifem::linalg
