// SPDX-License-Identifier: MIT
// Linear equations between DOFs imposed exactly with Lagrange multipliers: symmetry planes,
// fixed normal displacements, linear constraints (docs/theory/constraints.md §1).
#pragma once

#include "trifem/dofs/load_curve.hpp"
#include "trifem/physics/term.hpp"

#include <utility>

namespace trifem::physics {

/// One equation g(x) = Σ_j c_j x_{d_j} − value · curve(t) = 0 and the DOF of its multiplier λ.
struct LinearConstraint {
  std::vector<std::pair<Index, Real>> coefficients; ///< (DOF d_j, c_j), distinct DOFs
  Index multiplier = -1;                            ///< DOF of λ
  Real value = 0.0;
  dofs::LoadCurve curve = dofs::LoadCurve::constant(1.0);

  Real rhs(Real t) const { return value * curve(t); }
};

/// Residual contributions (one element per equation, DOFs: the d_j, then λ):
///   R_{d_j} += λ c_j,    R_λ = g(x),
/// a symmetric saddle point whose tangent is constant. The constraint's force on the DOF d_j is
/// −λ c_j (R = f_int − f_ext).
class LinearConstraintTerm final : public Term {
public:
  /// Throws InputError for an equation without coefficients, with a repeated or negative DOF,
  /// a zero coefficient or no multiplier.
  explicit LinearConstraintTerm(std::vector<LinearConstraint> constraints);
  std::string name() const override { return "linear constraints"; }
  Index num_elements() const override { return static_cast<Index>(constraints_.size()); }
  void element_dofs(Index e, std::vector<Index>& dofs) const override;
  bool evaluate(Index e, const EvalState& state, LocalVector& r, LocalMatrix* K) const override;
  const std::vector<LinearConstraint>& constraints() const { return constraints_; }

private:
  std::vector<LinearConstraint> constraints_;
};

} // namespace trifem::physics
