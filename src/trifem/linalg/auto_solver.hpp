// SPDX-License-Identifier: MIT
// "auto" backend: Eigen's SparseLU for small systems, UMFPACK for large ones.
#pragma once

#include "trifem/linalg/linear_solver.hpp"

namespace trifem::linalg {

/// Systems with fewer equations than this go to SparseLU, larger ones to UMFPACK. Measured on
/// the examples (146–3 149 equations: SparseLU 1.3–3.7× faster per run) and on triphasic
/// confined blocks (6 383 equations: SparseLU 1.45× faster; 14 383: UMFPACK 1.5× faster).
constexpr Index kAutoSparseLuLimit = 8000;

/// Chooses the backend in analyze_pattern from the number of rows (again for every new
/// pattern); name() is "auto (sparselu)" or "auto (umfpack)" once chosen.
std::unique_ptr<LinearSolver> make_auto_solver();

} // namespace trifem::linalg
