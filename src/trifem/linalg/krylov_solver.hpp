// SPDX-License-Identifier: MIT
// "krylov": FGMRES with a block preconditioner built from the field structure through PETSc's
// fieldsplit (docs/theory/solvers.md): a full Schur-complement factorization between the primal
// unknowns (displacement; fluid and ion fluxes) and the potentials (pressure, electric
// potential, contact multipliers), the Schur complement approximated with the diagonal of the
// primal block ("selfp"). The blocks are solved with MUMPS by default; every part can be
// replaced through PETSc options (AMG, ILU, ...), and a fieldsplit of the primal block chosen
// that way is split into displacement and fluxes.
#pragma once

#include "trifem/linalg/linear_solver.hpp"

#include <string>

namespace trifem::linalg {

/// Settings of the Krylov backend that are not PETSc options.
struct KrylovSettings {
  double relative_tolerance = 1e-10; ///< residual reduction of each solve (-ksp_rtol overrides)
  int max_iterations = 1000;         ///< (-ksp_max_it overrides)
  KrylovPreconditioner preconditioner = KrylovPreconditioner::lu;
  SchurApproximation schur = SchurApproximation::selfp;
};

/// The Krylov backend. `petsc_options` ("-ksp_rtol 1e-9 -fieldsplit_potential_pc_type ilu ...")
/// override the defaults; an option no PETSc object reads is an InputError.
std::unique_ptr<LinearSolver> make_krylov_solver(const std::string& petsc_options = "",
                                                 KrylovSettings settings = {});

} // namespace trifem::linalg
