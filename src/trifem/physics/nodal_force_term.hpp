// SPDX-License-Identifier: MIT
// Point forces on single DOFs, e.g. the force that drives a rigid body (whose translation is
// one unknown shared by all its nodes, see DofMap::tie).
#pragma once

#include "trifem/dofs/load_curve.hpp"
#include "trifem/physics/term.hpp"

namespace trifem::physics {

/// A force F(t) = magnitude * curve(t) on one DOF.
struct NodalForce {
  Index dof = -1;
  Real magnitude = 0.0;
  dofs::LoadCurve curve = dofs::LoadCurve::constant(1.0);

  Real value(Real t) const { return magnitude * curve(t); }
};

/// Dead point forces: R_dof -= F(t) (one element per force, no stiffness).
class NodalForceTerm final : public Term {
public:
  explicit NodalForceTerm(std::vector<NodalForce> forces) : forces_(std::move(forces)) {}
  std::string name() const override { return "nodal force"; }
  Index num_elements() const override { return static_cast<Index>(forces_.size()); }
  void element_dofs(Index e, std::vector<Index>& dofs) const override {
    dofs.assign(1, forces_[e].dof);
  }
  bool evaluate(Index e, const EvalState& state, LocalVector& r, LocalMatrix* K) const override {
    r.setConstant(1, -forces_[e].value(state.time));
    if (K)
      K->setZero(1, 1);
    return true;
  }
  const std::vector<NodalForce>& forces() const { return forces_; }

private:
  std::vector<NodalForce> forces_;
};

} // namespace trifem::physics
