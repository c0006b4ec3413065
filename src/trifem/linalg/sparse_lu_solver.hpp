// SPDX-License-Identifier: MIT
// Eigen SparseLU backend (fallback; slower than UMFPACK for 3-D problems).
#pragma once

#include "trifem/linalg/linear_solver.hpp"

namespace trifem::linalg {

std::unique_ptr<LinearSolver> make_sparse_lu_solver();

} // namespace trifem::linalg
