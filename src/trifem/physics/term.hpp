// SPDX-License-Identifier: MIT
// A weak-form term: residual and Jacobian contributions of a list of "elements" (cells,
// facets, contact pairs, ...). Assembly loops over terms without knowing what they are.
#pragma once

#include "trifem/core/types.hpp"

#include <Eigen/Dense>

#include <array>
#include <string>
#include <vector>

namespace trifem::dofs {
class DofMap;
}

namespace trifem::physics {

/// The state seen by terms during one evaluation. Vectors hold all DOFs.
struct EvalState {
  const Vector& x;     ///< current iterate (prescribed values included)
  const Vector& x_old; ///< converged state at the start of the step
  Real time = 0.0;     ///< end time of the step [s]
  Real dt = 0.0;       ///< step size [s]
  /// The DOFs with the constraints of the current step (null: those a term was built with).
  const dofs::DofMap* dofs = nullptr;
};

using LocalVector = Eigen::VectorXd;
using LocalMatrix = Eigen::MatrixXd;

/// What a Schur approximation of the drained part needs of one hex8 mixture cell, in the scaled
/// rows and unknowns of the assembled system (docs/theory/solvers.md §4). Over the fields
/// (fluid, cation, anion flux) and the components, the cell's flux block is
///
///     F_e = m_ab ⊗ friction + (g_a ⊗ g_b) gamma      (plus terms proportional to the fluxes)
///
/// and its potential rows (p, η) are coupling · (Σ_a g_a·w_a, Σ_a g_a·ĵ+_a, Σ_a g_a·ĵ−_a).
struct CellTransport {
  std::array<Index, 2> potential{-1, -1}; ///< DOFs of p and η (−1: none)
  Eigen::Matrix<Real, 2, 3> coupling;     ///< rows (p, η), columns: fields
  Eigen::Matrix3d friction;               ///< per unit mass (fields x fields)
  Eigen::Matrix3d gamma;                  ///< of the divergences (fields x fields)
  /// Row 3a + k, column 3 field + field': the flux equation's derivative by the divergence of
  /// field' beyond g_a[k] gamma (proportional to the fluxes; global components)
  Eigen::Matrix<Real, 24, 9> flux_rate;
  std::array<Index, 8> node{};           ///< mesh nodes of the flux fields
  Eigen::Matrix<Real, 8, 3> area;        ///< g_a (rows: nodes)
  Eigen::Matrix<Real, 8, 1> lumped_mass; ///< Σ_b m_ab
  Eigen::Matrix<Index, 24, 3> flux_dof;  ///< row 3a + k, column field: DOF or −1
};

/// Residual R = f_int - f_ext and dR/dx of a set of elements. Implementations hold only
/// immutable data; history variables live in the state vectors or in explicit state arrays.
class Term {
public:
  virtual ~Term() = default;
  virtual std::string name() const = 0;
  /// True for a term that couples separate bodies (contact): a parallel run partitions the
  /// model by the couplings of the other terms, so that bodies may be cut at their interfaces.
  virtual bool joins_bodies() const { return false; }
  virtual Index num_elements() const = 0;
  /// Global DOFs of element e; fixed for the whole run (defines the sparsity pattern).
  virtual void element_dofs(Index e, std::vector<Index>& dofs) const = 0;
  /// Residual (and, if K is given, Jacobian) of element e, ordered as element_dofs.
  /// Returns false if the state is inadmissible (e.g. J <= 0): nothing else is then used.
  virtual bool evaluate(Index e, const EvalState& state, LocalVector& r, LocalMatrix* K) const = 0;
  /// Called once per converged step with the converged state: history variables advance.
  virtual void commit(const EvalState& /*state*/) {}
  /// Called before every evaluation of the whole system (e.g. contact search and projection).
  /// Returns true if element_dofs() changed: the sparsity pattern is then rebuilt.
  virtual bool prepare(const EvalState& /*state*/) { return false; }
  /// Called when a step is abandoned (before it is retried with a smaller size): state kept by
  /// the term during the step (e.g. a contact active set) returns to the last commit().
  virtual void reject() {}
  /// Called once Newton has converged, before commit(): a non-empty reason rejects the step
  /// (the time loop cuts it back and logs the reason), e.g. a contact status that has not
  /// settled. `state` is the converged state.
  virtual std::string step_rejection(const EvalState& /*state*/) const { return {}; }
  /// Called after step_rejection() found nothing: a non-empty reason is a concern a smaller step
  /// may remove but that does not make the converged state wrong (e.g. a loaded contact node
  /// sliding off the edge of its master surface). The time loop cuts the step back while it
  /// can and accepts it at the minimum step size, with the reason in a warning.
  virtual std::string step_caution(const EvalState& /*state*/) const { return {}; }
  /// The committed history the term keeps outside the state vectors (element histories, a
  /// contact active set), as numbers: what a restart file stores. Empty for stateless terms.
  virtual std::vector<double> history() const { return {}; }
  /// Sets the committed history back from history() of a term of the same model; throws
  /// InputError if `values` do not fit.
  virtual void restore_history(const std::vector<double>& /*values*/) {}
  /// Appends the CellTransport of every mixture cell of the term at `state`, in a fixed order
  /// (terms without mixture cells append nothing).
  virtual void transport_cells(const EvalState& /*state*/,
                               std::vector<CellTransport>& /*out*/) const {}
};

} // namespace trifem::physics
