// SPDX-License-Identifier: MIT
// Linear solver interface (direct or iterative): analyze the pattern once, factorize (or set
// up the preconditioner) per matrix, solve.
#pragma once

#include "trifem/core/field_role.hpp"
#include "trifem/core/solver_choice.hpp"
#include "trifem/core/types.hpp"
#include "trifem/linalg/transport_cells.hpp"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace trifem::linalg {

/// What a linear solver may use beyond the matrix (LinearSolver::set_hints); all empty when
/// nothing is known.
struct SystemHints {
  /// The field of every equation (an index into `field_roles`, −1: none) and the role of each
  /// field: block preconditioners split the system by role, direct solvers ignore them.
  std::vector<int> equation_fields;
  std::vector<FieldRole> field_roles;
  /// The near-null space of the displacement block (the solid's rigid-body motions over the
  /// equations): algebraic multigrid uses it, the other backends ignore it.
  std::vector<Vector> near_null_space;
  /// On several processes: the owner of every equation; each process then gives its own part
  /// of the matrix (its elements' couplings) and the whole right-hand side, and receives the
  /// whole solution. Empty: one process.
  std::vector<int> equation_owner;
};

/// Why the last analyze_pattern / factorize / solve failed.
struct LinearSolverFailure {
  std::string reason;     ///< what failed, in words ("" after a success)
  bool permanent = false; ///< a smaller time step cannot cure it (out of memory, size limits)
  Index equation = -1;    ///< an equation whose column of the matrix is empty (-1: none found)
};

/// A linear solver for general (unsymmetric) sparse matrices.
class LinearSolver {
public:
  virtual ~LinearSolver() = default;
  /// Symbolic analysis (ordering); reused while the sparsity pattern is unchanged.
  virtual void analyze_pattern(const SparseMatrix& A) = 0;
  /// Numeric factorization; false if the matrix is singular or the factorization failed.
  /// `A` (same pattern as analysed) must stay alive and unchanged for the following solves.
  virtual bool factorize(const SparseMatrix& A) = 0;
  /// Solves A x = b with the last factorization; false on failure.
  virtual bool solve(const Vector& b, Vector& x) = 0;
  /// What is known of the system beyond its matrix, before analyze_pattern of a new pattern.
  /// The base refuses a partition (the backends that run on one process only).
  virtual void set_hints(const SystemHints& hints);
  /// True if the backend's preconditioner uses the mixture cells' transport data
  /// (set_transport_cells before every factorize); computing them costs a pass over the cells.
  virtual bool wants_transport_cells() const { return false; }
  /// The mixture cells at the state of the next matrix, before its factorize.
  virtual void set_transport_cells(TransportCells cells) { (void)cells; }
  /// The residual reduction asked of the next solves of an iterative backend (Newton's forcing
  /// term; ‖A x − b‖ ≤ tolerance ‖b‖); direct backends ignore it, and a tolerance given as a
  /// PETSc option (-ksp_rtol) wins over it.
  virtual void set_relative_tolerance(Real tolerance) { (void)tolerance; }
  /// Continues the last solve of an iterative backend (same matrix, same `b`) from its result
  /// `x` to the tolerance now set (set_relative_tolerance); false on failure. Direct backends
  /// solve again.
  virtual bool refine(const Vector& b, Vector& x) { return solve(b, x); }
  /// Iterations of the last solve of an iterative backend (0 for a direct one).
  virtual int last_iterations() const { return 0; }
  /// Nonzeros of the factors of the last factorization of a direct backend that reports them
  /// (0 otherwise).
  virtual std::int64_t factor_nonzeros() const { return 0; }
  /// Backend name ("umfpack", "sparselu", "mumps", "auto (sparselu)", ...).
  virtual std::string name() const = 0;
  /// Why the last operation failed (empty reason if it succeeded).
  virtual LinearSolverFailure failure() const { return {}; }
};

/// The first equation whose column of A holds no non-zero value (no term couples that unknown
/// to any equation), -1 if every column has one: the usual cause of a singular matrix at the
/// first iteration, which the backends' own messages do not name (LinearSolverFailure::equation).
Index empty_column(const SparseMatrix& A);

/// Creates the backend of `choice`. `petsc_options` are passed to the PETSc backends
/// (InputError when PETSc does not use one of them); `reuse_factorization` lets one MUMPS
/// factorization serve several Newton iterations (make_mumps_solver). On several processes
/// (parallel::active()) every direct backend gives MUMPS on the distributed matrix, and `krylov`
/// is an InputError.
std::unique_ptr<LinearSolver> make_linear_solver(const LinearSolverChoice& choice);

} // namespace trifem::linalg
