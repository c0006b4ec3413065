// SPDX-License-Identifier: MIT
// The linear solver a case asks for ([solver] of a case file): parsed and checked once by the
// reader, built by linalg::make_linear_solver.
#pragma once

#include <string>

namespace trifem {

/// The backend of the linear solves (docs/input.md, [solver] linear_solver).
enum class LinearSolverKind {
  automatic, ///< "auto": sparselu below a size, MUMPS reusing factorizations above
  umfpack,   ///< UMFPACK LU
  sparselu,  ///< Eigen's SparseLU
  mumps,     ///< MUMPS LU through PETSc (the distributed one on several processes)
  krylov     ///< FGMRES with a block (fieldsplit) preconditioner through PETSc
};

/// How the Krylov backend's fieldsplit preconditioner solves its blocks (docs/theory/solvers.md
/// §3).
enum class KrylovPreconditioner {
  lu,  ///< MUMPS LU of the primal block and of the Schur approximation
  amg, ///< primal block: algebraic multigrid (GAMG with the rigid-body modes) on the
       ///< displacement, then ILU(0) on the fluxes; MUMPS LU of the Schur approximation
};

/// How the fieldsplit approximates the potentials' Schur complement (docs/theory/solvers.md §4).
enum class SchurApproximation {
  selfp,   ///< PETSc's selfp: C − B diag(A)⁻¹ Bᵀ, factorized by MUMPS
  drained, ///< the split displacement | transport (fluxes and potentials), the transport block
           ///< solved through the augmented system of drained_schur.hpp (factorized by MUMPS):
           ///< exact flux block up to the lumping of its friction, selfp's undrained part plus
           ///< a fixed-stress term; with contact multipliers the split primal | potential and
           ///< the augmented system for the potentials' Schur complement
};

/// The precision of the factorizations that precondition FGMRES where MUMPS reuses them
/// (reuse_factorization, "auto"): single precision halves the memory of the factors and about
/// the time of a factorization, and cuts that of a solve by a third (measured on a 44 413-equation
/// block); FGMRES still iterates in double precision, to the tolerance Newton asks for.
enum class FactorPrecision { single, full };

/// The linear solver of a case. Settings that do not apply to `kind` are left at their defaults
/// (the reader refuses them).
struct LinearSolverChoice {
  LinearSolverKind kind = LinearSolverKind::automatic;
  std::string petsc_options;        ///< "-key value ..." (mumps, krylov)
  bool reuse_factorization = false; ///< mumps: one factorization for several iterations
  KrylovPreconditioner preconditioner = KrylovPreconditioner::lu; ///< krylov
  SchurApproximation schur = SchurApproximation::selfp;           ///< krylov
  FactorPrecision precision = FactorPrecision::single; ///< of reused factorizations (mumps, auto)
};

/// The names a case file gives them.
constexpr const char* to_string(LinearSolverKind kind) {
  constexpr const char* names[] = {"auto", "umfpack", "sparselu", "mumps", "krylov"};
  return names[static_cast<int>(kind)];
}
constexpr const char* to_string(KrylovPreconditioner p) {
  return p == KrylovPreconditioner::lu ? "lu" : "amg";
}
constexpr const char* to_string(SchurApproximation s) {
  return s == SchurApproximation::selfp ? "selfp" : "drained";
}
constexpr const char* to_string(FactorPrecision p) {
  return p == FactorPrecision::single ? "single" : "double";
}

} // namespace trifem
