// SPDX-License-Identifier: MIT
// CHOLMOD (SuiteSparse) backend: sparse Cholesky LLᵀ of a symmetric positive definite matrix
// given by its lower triangle.
#pragma once

#include "trifem/linalg/linear_solver.hpp"

namespace trifem::linalg {

/// A LinearSolver for symmetric positive definite matrices that reads only the lower triangle
/// of A (entries above the diagonal may be absent; if present they are ignored). CHOLMOD picks
/// the ordering (AMD or METIS) and a simplicial or supernodal factorization from the flop count
/// of the symbolic factor. factorize is false when A is not positive definite.
std::unique_ptr<LinearSolver> make_cholmod_solver();

} // namespace trifem::linalg
