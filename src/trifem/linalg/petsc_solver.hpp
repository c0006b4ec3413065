// SPDX-License-Identifier: MIT
// PETSc backends: "mumps" (MUMPS sparse direct LU through PETSc; nested-dissection or
// automatic ordering, symbolic analysis reused while the pattern is unchanged).
#pragma once

#include "trifem/linalg/linear_solver.hpp"

#include <string>

namespace trifem::linalg {

/// MUMPS through PETSc. `petsc_options` ("-mat_mumps_icntl_14 50 ...") go into PETSc's options
/// database; an option that no PETSc object reads is an InputError (checked here on a small
/// system, so a typo fails before the run).
std::unique_ptr<LinearSolver> make_mumps_solver(const std::string& petsc_options = "");

} // namespace trifem::linalg
