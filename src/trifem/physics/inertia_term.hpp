// SPDX-License-Identifier: MIT
// Inertia of hex8 cells in an implicit dynamic step: the generalized-α method (Chung & Hulbert
// 1993) on M a + g(x, t) = 0, with the Newmark relations for the displacement's velocity and
// acceleration (docs/theory/dynamics.md).
#pragma once

#include "trifem/dofs/dof_map.hpp"
#include "trifem/fe/hex8.hpp"
#include "trifem/mesh/mesh.hpp"
#include "trifem/physics/cell_mass.hpp"
#include "trifem/physics/term.hpp"

namespace trifem::physics {

/// The coefficients of the generalized-α method. The step's equation is
///
///     M a_{n+1-α_m} + (1 - α_f) g(x_{n+1}, t_{n+1}) + α_f g(x_n, t_n) = 0,
///     a_{n+1-α_m} = (1 - α_m) a_{n+1} + α_m a_n,
///
/// with x_{n+1} = x_n + Δt v_n + Δt² ((1/2 - β) a_n + β a_{n+1}) and
/// v_{n+1} = v_n + Δt ((1 - γ) a_n + γ a_{n+1}). g = f_int − f_ext is the residual of the other
/// terms (f_int evaluated at x_{n+1} and averaged: second-order accurate like the evaluation at
/// the intermediate state).
struct GeneralizedAlpha {
  Real alpha_m = 0.5;
  Real alpha_f = 0.5;
  Real beta = 0.25;
  Real gamma = 0.5;

  /// The second-order method whose amplification has spectral radius rho_inf ∈ [0, 1] at
  /// infinite frequency (Chung & Hulbert's optimal family): α_m = (2ρ∞ − 1)/(ρ∞ + 1),
  /// α_f = ρ∞/(ρ∞ + 1), γ = 1/2 − α_m + α_f, β = (1 − α_m + α_f)²/4. ρ∞ = 1 is the
  /// trapezoidal rule (no numerical dissipation), ρ∞ = 0 annihilates the highest frequencies
  /// in one step.
  static GeneralizedAlpha from_spectral_radius(Real rho_inf);
};

/// How the mass of a cell is distributed to its nodes.
enum class MassMatrix {
  Consistent, ///< m_ab = ∫ ρ N_a N_b dV
  Lumped      ///< the row sums, or the scaled diagonal of quadratic cells (lumped_mass())
};

/// The inertia forces M a_{n+1-α_m} of mass elements (hex8 cells of reference density ρ, quad4
/// shells) on the displacement, with the velocity, acceleration and residual history of the
/// displacement DOFs of their nodes (committed with the step; history() for restarts). The
/// acceleration a_{n+1} follows from the state by the Newmark relation, so the unknowns stay
/// the displacements.
class InertiaTerm final : public Term {
public:
  /// `elements`: consistent mass matrices (lumped here if `mass` says so). `massless`: further
  /// DOFs whose motion and residual history the method keeps although no element gives them
  /// mass (the unknowns of rigid bodies, which the inertia of their nodes reaches by
  /// condensation).
  InertiaTerm(const dofs::DofMap& dofs, dofs::FieldId displacement,
              std::vector<MassElement> elements, MassMatrix mass, GeneralizedAlpha method,
              std::vector<Index> massless = {});
  /// Of hex8 cells: `densities[i]` > 0 is the mass per reference volume of `cells[i]`
  /// [t/mm³]. Throws InputError naming the cell if a cell is inverted or degenerate.
  InertiaTerm(const mesh::Mesh& mesh, const dofs::DofMap& dofs, dofs::FieldId displacement,
              const std::vector<Index>& cells, const std::vector<Real>& densities, MassMatrix mass,
              GeneralizedAlpha method, std::vector<Index> massless = {});

  std::string name() const override { return "inertia"; }
  Index num_elements() const override { return static_cast<Index>(elements_.size()); }
  void element_dofs(Index e, std::vector<Index>& dofs) const override;
  /// r = m_e a_{n+1-α_m}, K = (1 − α_m)/(β Δt²) m_e; zero for Δt = 0.
  bool evaluate(Index e, const EvalState& state, LocalVector& r, LocalMatrix* K) const override;
  /// The velocity and acceleration at the converged state become those of step n.
  void commit(const EvalState& state) override;
  /// v, a and g of every DOF of dofs(), in this order.
  std::vector<double> history() const override;
  void restore_history(const std::vector<double>& values) override;

  const GeneralizedAlpha& method() const { return method_; }
  /// The displacement DOFs of the cells' nodes and the massless DOFs, ascending.
  const std::vector<Index>& dofs() const { return dofs_; }
  /// Velocity, acceleration and residual g of step n at dofs() (global components).
  const Vector& velocity() const { return v_; }
  const Vector& acceleration() const { return a_; }
  const Vector& residual_history() const { return g_; }
  /// Sets the motion of step n at dofs() (e.g. at the start of a dynamic step).
  void set_motion(Vector velocity, Vector acceleration);
  /// Sets g(x_n, t_n) at dofs().
  void set_residual_history(Vector g);
  /// M u at every DOF for u given at every DOF (zero outside dofs()).
  Vector mass_times(const Vector& u) const;
  /// The row sums of M at every DOF (zero outside dofs()): the lumped mass (negative at the
  /// corners of tet10 and hex20 cells of a consistent M).
  Vector lumped_mass() const;
  /// The diagonal Σ m_aa of the consistent mass at every DOF (positive where there is mass; the
  /// lumped mass is not at the corners of tet10 and hex20 cells).
  Vector diagonal_mass() const;

private:
  /// The Newmark acceleration a_{n+1} of the entry i of dofs() for the displacements
  /// x_{n+1}, x_n over a step Δt.
  Real acceleration_at(Index i, Real x, Real x_old, Real dt) const;
  /// Entry of dofs() of the DOF `dof`.
  Index slot(Index dof) const;

  const dofs::DofMap& map_;
  dofs::FieldId u_;
  std::vector<MassElement> elements_;
  GeneralizedAlpha method_;
  std::vector<Index> dofs_;
  std::vector<Index> slot_of_dof_; ///< entry of dofs_ by DOF (−1: none)
  Vector v_, a_, g_;
};

} // namespace trifem::physics
