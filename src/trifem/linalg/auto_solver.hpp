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

/// Below kAutoSparseLuLimit, SparseLU's first factorization decides: from this many equations,
/// factors with at least kAutoFillRatio times the matrix's nonzeros (a 2-D or 3-D model) hand
/// the system to MUMPS reusing its factorizations for the rest of the run. Measured fill and
/// whole-run times (SparseLU / MUMPS): 1-D columns of 900 and 2 700 equations, fill 1.4 and
/// 1.1, 0.62 / 1.12 s and 1.69 / 2.70 s; the 2-D sliding_layers example, 3 149 equations, fill
/// 3.4, 76 / 43 s (29 s reusing factorizations, what "auto" now takes); a triphasic block of
/// 4 205 equations, fill 7.3, 2.9 / 1.0 s (1.6 s for "auto", after one SparseLU factorization).
constexpr Index kAutoFillCheckRows = 2000;
constexpr Real kAutoFillRatio = 3.0;

/// Chooses the backend in analyze_pattern from the number of rows (again for every new
/// pattern), and from SparseLU's fill after its first factorization; name() is
/// "auto (sparselu)" or "auto (mumps)" once chosen. `precision`: of MUMPS's factorizations.
std::unique_ptr<LinearSolver> make_auto_solver(FactorPrecision precision = FactorPrecision::single);

} // namespace trifem::linalg
