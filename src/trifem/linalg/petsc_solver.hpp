// SPDX-License-Identifier: MIT
// PETSc backends: "mumps" (MUMPS sparse direct LU through PETSc; nested-dissection or
// automatic ordering, symbolic analysis reused while the pattern is unchanged).
#pragma once

#include "trifem/linalg/linear_solver.hpp"

#include <string>

namespace trifem::linalg {

/// MUMPS through PETSc. `petsc_options` ("-mat_mumps_icntl_14 50 ...") go into PETSc's options
/// database; an option that no PETSc object reads is an InputError (checked here on a small
/// system, so a typo fails before the run). With `reuse_factorization`, a factorization
/// preconditions FGMRES (to 1e-10) on the following matrices of the same pattern until a solve
/// takes more than 8 iterations; one that does not converge (in 15 iterations, or at the rate of
/// its first 3) is repeated with a new one. Reused factorizations are in `precision` on one
/// process (SinglePrecisionLu), in double precision on several; where single precision does not
/// serve (a new factorization fails, or FGMRES does not converge with it) the solver turns to
/// double precision for good. The -mat_mumps_* options set the double-precision MUMPS, so with
/// single-precision reuse they are an InputError that says so.
std::unique_ptr<LinearSolver>
make_mumps_solver(const std::string& petsc_options = "", bool reuse_factorization = false,
                  FactorPrecision precision = FactorPrecision::single);

} // namespace trifem::linalg
