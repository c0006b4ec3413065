// SPDX-License-Identifier: MIT
// "auto" backend: Eigen's SparseLU for small systems, MUMPS (reusing its factorizations) for
// large ones.
#pragma once

#include "trifem/linalg/linear_solver.hpp"

namespace trifem::linalg {

/// Systems with fewer equations than this go to SparseLU, larger ones to MUMPS reusing its
/// factorizations (docs/performance.md). SparseLU against UMFPACK, measured on the examples
/// (146–3 149 equations: SparseLU 1.3–3.7× faster per run) and on triphasic confined blocks
/// (6 383 equations: SparseLU 1.45× faster; 14 383: UMFPACK 1.5× faster); MUMPS with reuse
/// against UMFPACK on 3-D triphasic blocks (17 125 and 44 413 equations: 4.5× and 5.8×) and on
/// the indentation example (16 532, 53 212 and 93 468 equations: 3.5×, 5.1× and 7.7×).
constexpr Index kAutoSparseLuLimit = 8000;

/// Chooses the backend in analyze_pattern from the number of rows (again for every new
/// pattern); name() is "auto (sparselu)" or "auto (mumps)" once chosen.
std::unique_ptr<LinearSolver> make_auto_solver();

} // namespace trifem::linalg
