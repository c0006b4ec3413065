// SPDX-License-Identifier: MIT
// What the Newton solver sees of a discretised problem (it knows nothing of elements).
#pragma once

#include "trifem/core/types.hpp"
#include "trifem/linalg/transport_cells.hpp"

#include <string>
#include <vector>

namespace trifem::solver {

/// Outcome of a numerical operation; failures make the step controller cut the step back.
enum class SolveStatus {
  Converged,
  Inadmissible,        ///< a trial state is unphysical (J <= 0, ...), never evaluated further
  Diverged,            ///< residual grows or becomes non-finite
  MaxIterations,       ///< Newton did not converge in the allowed iterations
  FactorizationFailed, ///< singular or failed LU factorization
  Rejected,            ///< converged, but a term rejected the state (e.g. contact not settled)
  Unrecoverable,       ///< a failure no smaller step can cure (e.g. out of memory): stop at once
  Interrupted,         ///< a stop was requested (interrupt::requested) during the solve
};

/// Human-readable status.
const char* to_string(SolveStatus status);

/// Characteristic scales of one field, for unit-independent convergence tests.
struct FieldScale {
  std::string name;
  Real residual = 1.0; ///< characteristic residual (e.g. modulus * length^2 for forces)
  Real size = 1.0;     ///< characteristic size of the unknown (e.g. model length)
};

/// The linearisation of the problem at its current state.
struct Linearization {
  Vector residual;       ///< R at free equations
  Vector constraint_rhs; ///< K_fc * (pending increment of constrained DOFs)
  SparseMatrix jacobian; ///< dR/dx at free equations (pattern fixed while pattern_id is)
  /// The problem whose assembly storage `jacobian` holds (it takes the storage back at its
  /// next linearize instead of keeping a copy), and that problem's pattern_id then.
  const void* lender = nullptr;
  int lent_pattern = -1;
};

/// A nonlinear system R(x) = 0 over free equations, with prescribed DOFs that may still have
/// a pending increment towards their target (applied together with the Newton update).
class NonlinearProblem {
public:
  virtual ~NonlinearProblem() = default;
  virtual Index num_equations() const = 0;
  /// Field index of every equation, and the scales and the role of each field (no roles: all
  /// count as displacements).
  virtual const std::vector<int>& equation_fields() const = 0;
  virtual const std::vector<FieldScale>& field_scales() const = 0;
  virtual std::vector<FieldRole> field_roles() const { return {}; }
  /// What equation `eq` is, in the user's terms (field, node or entity, component), for
  /// messages; empty if the problem cannot say.
  virtual std::string equation_name(Index /*eq*/) const { return {}; }
  /// Changes whenever the sparsity pattern of the Jacobian changes (symbolic re-analysis).
  virtual int pattern_id() const = 0;
  /// On several processes: the process that owns each equation (the linear solver's rows);
  /// the Jacobian of linearize() then holds this process's part only. Empty on one process.
  virtual const std::vector<int>& equation_owners() const {
    static const std::vector<int> none;
    return none;
  }
  /// The rigid-body motions of the solid (three translations, three rotations) as vectors over
  /// the equations, zero on equations that are not displacements: the near-null space of the
  /// displacement block, for algebraic multigrid. Empty when unknown.
  virtual std::vector<Vector> rigid_body_modes() const { return {}; }
  /// The mixture cells' flux-block data at the current state, over the equations (for the
  /// preconditioners that ask for them, linalg::LinearSolver::wants_transport_cells). Empty when
  /// the problem has none or they would not describe the Jacobian.
  virtual linalg::TransportCells transport_cells() const { return {}; }
  /// Evaluates residual and, if `with_jacobian`, Jacobian and constraint_rhs at the current
  /// state. Returns Inadmissible if the state cannot be evaluated.
  virtual SolveStatus linearize(Linearization& lin, bool with_jacobian) = 0;
  /// Moves the state by step * dx on free equations and step * (pending increment) on
  /// constrained DOFs. Returns Inadmissible (state unchanged) if the trial state is unphysical.
  virtual SolveStatus update(const Vector& dx, Real step) = 0;
  /// Largest magnitude of the current unknowns of each field (the scale of their round-off).
  virtual std::vector<Real> field_magnitudes() const { return {}; }
  /// True once all constrained DOFs have reached their targets.
  virtual bool constraints_satisfied() const = 0;
  /// Saves / restores the iterate (for line search).
  virtual void save_iterate() = 0;
  virtual void restore_iterate() = 0;
};

/// A problem advanced in time by steps (hooks used by the time loop).
class TransientProblem : public NonlinearProblem {
public:
  /// Sets loads and prescribed targets for the step ending at `time` with size `dt`.
  virtual void begin_step(Real time, Real dt) = 0;
  /// Called after Newton converged: a non-empty reason rejects the step (it is cut back).
  virtual std::string step_rejection() const { return {}; }
  /// Called after step_rejection() found nothing: a non-empty reason cuts the step back while
  /// it is above the minimum size; at the minimum size the step is accepted with a warning.
  virtual std::string step_caution() const { return {}; }
  /// Accepts the converged step (history variables become the new old state).
  virtual void commit_step() = 0;
  /// Returns to the state at the beginning of the step (after a failure).
  virtual void reject_step() = 0;
  /// Per field (as field_scales()), the largest change of an unknown since the last commit.
  virtual std::vector<Real> step_change() const = 0;
  /// Remembers the committed state (unknowns, time and history), for a step made of several
  /// committed sub-steps (a steady-state step) that must be undone as a whole if one fails.
  virtual void mark_committed() = 0;
  /// Returns to the state remembered by mark_committed() (as committed state).
  virtual void return_to_mark() = 0;
};

} // namespace trifem::solver
