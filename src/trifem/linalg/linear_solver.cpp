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

std::vector<std::string> available_linear_solvers() {
  return {"auto", "umfpack", "sparselu", "mumps", "krylov"};
}

std::unique_ptr<LinearSolver>
make_linear_solver(const std::string& name, const std::string& petsc_options,
                   bool reuse_factorization, const std::string& preconditioner,
                   FactorPrecision precision, const std::string& schur) {
  if (preconditioner != "lu" && name != "krylov")
    throw InputError(fmt::format("solver.preconditioner applies to linear_solver = 'krylov', "
                                 "not to '{}'",
                                 name));
  if (schur != "selfp" && name != "krylov")
    throw InputError(fmt::format("solver.schur_approximation applies to linear_solver = "
                                 "'krylov', not to '{}'",
                                 name));
  if (reuse_factorization && name != "mumps")
    throw InputError(fmt::format("solver.reuse_factorization applies to linear_solver = 'mumps', "
                                 "not to '{}'",
                                 name));
  if (!petsc_options.empty() && name != "mumps" && name != "krylov")
    throw InputError(
        fmt::format("solver.petsc_options applies to the PETSc backends (mumps, krylov), "
                    "not to linear_solver = '{}'",
                    name));
  if (parallel::active()) { // on several processes MUMPS stands in for every direct backend
    if (name == "krylov")
      throw InputError(fmt::format("linear_solver = 'krylov' runs on one process only; on {} "
                                   "processes use 'mumps' or 'auto' (the distributed MUMPS)",
                                   parallel::size()));
    if (name == "auto" || name == "umfpack" || name == "sparselu" || name == "mumps")
      return make_mumps_solver(petsc_options, reuse_factorization, precision);
  }
  if (name == "auto")
    return make_auto_solver(precision);
  if (name == "umfpack")
    return make_umfpack_solver();
  if (name == "sparselu")
    return make_sparse_lu_solver();
  if (name == "mumps")
    return make_mumps_solver(petsc_options, reuse_factorization, precision);
  if (name == "krylov")
    return make_krylov_solver(petsc_options,
                              {.preconditioner = krylov_preconditioner(preconditioner),
                               .schur = schur_approximation(schur)});
  throw InputError(fmt::format(
      "unknown linear solver '{}' (expected auto, umfpack, sparselu, mumps or krylov)", name));
}

} // namespace trifem::linalg
