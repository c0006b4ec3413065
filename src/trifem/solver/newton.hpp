// SPDX-License-Identifier: MIT
// Newton-Raphson with backtracking line search and per-field scaled convergence tests.
#pragma once

#include "trifem/linalg/linear_solver.hpp"
#include "trifem/solver/nonlinear_problem.hpp"

#include <array>
#include <chrono>
#include <memory>
#include <vector>

namespace trifem::solver {

/// Newton settings.
struct NewtonSettings {
  int max_iterations = 20;
  Real residual_tolerance = 1e-8;  ///< ||R_f|| <= tol * max(||R_f^0||, eps_abs R_char_f)
  Real increment_tolerance = 1e-8; ///< ||dx_f||_inf <= tol * size_f
  Real absolute_floor = 1e-13;     ///< ||R_f|| <= floor * R_char_f counts as converged
  bool line_search = true;
  Real line_search_tolerance = 0.9; ///< accept s when |dx.R(s)| <= tol |dx.R(0)|
  int max_backtracks = 8;
  /// Inexact Newton for iterative linear solvers: the relative tolerance of each linear solve
  /// follows the convergence of the residual (the forcing term of Eisenstat & Walker, SIAM J.
  /// Sci. Comput. 17 (1996) 16-32, choice 2), between linear_tolerance_max and
  /// linear_tolerance_min; false: linear_tolerance_min for every solve.
  bool adaptive_linear_tolerance = true;
  Real linear_tolerance_max = 1e-4;
  Real linear_tolerance_min = 1e-10;
};

/// Wall-clock time spent per phase [s].
struct PhaseTimes {
  double assembly = 0.0;
  double factorization = 0.0;
  double solve = 0.0;
};

/// What one Newton solve did.
struct NewtonReport {
  SolveStatus status = SolveStatus::MaxIterations;
  int iterations = 0;
  int linear_iterations = 0; ///< iterations of an iterative linear solver, summed (0: direct)
  std::vector<Real> residual_history; ///< scaled residual norm at each evaluation
  Real final_residual = 0.0;
  std::string failure_reason;
  /// Converged by reaching the round-off floor rather than the residual tolerance.
  bool at_roundoff_floor = false;
};

/// Newton solver. Owns the linear solver and reuses its symbolic analysis across calls while
/// the problem's pattern_id is unchanged.
class NewtonSolver {
public:
  NewtonSolver(NewtonSettings settings, std::unique_ptr<linalg::LinearSolver> linear_solver);
  NewtonReport solve(NonlinearProblem& problem);
  /// As solve, with the reference residual of each field at least `reference` (the load scale
  /// of an earlier solve under the same loads, e.g. reference() after it): a start already
  /// within the tolerance of that scale converges without an iteration.
  NewtonReport solve(NonlinearProblem& problem, const std::vector<Real>& reference);
  /// The per-field reference residual of the last solve (the largest residual it saw).
  const std::vector<Real>& reference() const { return reference_; }
  const PhaseTimes& times() const { return times_; }
  const NewtonSettings& settings() const { return settings_; }

private:
  /// Max over fields of ||R_f||_2 / max(R0_f, floor R_char_f): 1 means "at tolerance scale".
  Real scaled_residual(const NonlinearProblem& problem, const Vector& r) const;
  std::vector<Real> field_norms(const NonlinearProblem& problem, const Vector& v, bool inf) const;
  bool residual_converged(const NonlinearProblem& problem, const Vector& r) const;
  /// 1 over what convergence asks of field f's residual norm: the larger of the relative
  /// tolerance times its reference and the absolute floor.
  Real convergence_weight(const NonlinearProblem& problem, std::size_t f) const;
  /// sqrt of the sum over fields of (‖r_f‖ convergence_weight)²: about 1 at convergence.
  Real convergence_norm(const NonlinearProblem& problem, const Vector& r) const;
  bool increment_converged(const NonlinearProblem& problem, const Vector& dx, Real step) const;
  /// The round-off floor of the discrete system: the residual stalls (not halved in two
  /// iterations) while the Newton increments change every field by less than 1e4 eps of the
  /// magnitude of its unknowns. The state is then as converged as double arithmetic allows
  /// (strongly graded meshes: a stiff tiny cell turns the round-off of the unknowns into a
  /// residual above the tolerance), and the solve is accepted.
  bool at_roundoff_floor(const NonlinearProblem& problem, const Vector& dx, Real step,
                         const std::vector<Real>& history) const;
  /// The reduction of the convergence norm asked of the next linear solve (the forcing term),
  /// from the convergence norms of the residuals of this solve so far.
  Real linear_reduction(const std::vector<Real>& history) const;
  /// The relative tolerance of an iterative solve of J dx = rhs (in the 2-norm) that reduces
  /// the convergence norm by at least `reduction`, whatever the
  /// residual's distribution over the fields (for distributed solves, which cannot check).
  Real in_linear_norm(const NonlinearProblem& problem, const Vector& rhs, Real reduction) const;
  /// Solves J dx = rhs after the factorization; an iterative solve until the convergence norm
  /// of its residual has fallen by `reduction` (checked after the solve, and the solve continued
  /// to a tighter tolerance if needed). Sets linear_iterations_.
  bool solve_to(const NonlinearProblem& problem, const SparseMatrix& jacobian, const Vector& rhs,
                Vector& dx, Real reduction, bool first);
  /// Factorizes and solves (solve_to).
  SolveStatus factor_and_solve(NonlinearProblem& problem, Linearization& lin, Vector& dx,
                               Real reduction, bool first);
  /// FactorizationFailed, or Unrecoverable if the linear solver says no step can cure it.
  SolveStatus linear_failure_status() const;
  SolveStatus line_search(NonlinearProblem& problem, const Vector& dx, const Vector& r0, Real& step,
                          Linearization& lin);

  NewtonSettings settings_;
  std::unique_ptr<linalg::LinearSolver> linear_;
  Linearization lin_; ///< the linearization of the current solve (kept: see Linearization)
  int analyzed_pattern_ = -1;
  std::vector<Real> reference_; ///< per-field reference residual (running maximum)
  /// The reduction of the convergence norm over the 2-norm tolerance, at the last iterative solve
  /// (how much weaker Newton's norm converged than the solver's), for the first iteration of a
  /// solve and for the later ones; guides the next tolerance.
  std::array<Real, 2> amplification_{1.0, 1.0};
  int linear_iterations_ = 0; ///< of the last solve_to (0: a direct solve)
  PhaseTimes times_;
};

} // namespace trifem::solver
