// SPDX-License-Identifier: MIT
// UMFPACK (SuiteSparse) backend: unsymmetric multifrontal LU with partial pivoting.
#pragma once

#include "trifem/linalg/linear_solver.hpp"

namespace trifem::linalg {

std::unique_ptr<LinearSolver> make_umfpack_solver();

} // namespace trifem::linalg
