// SPDX-License-Identifier: MIT
// Dead moments on rotating rigid bodies (docs/theory/rigid.md): the virtual work M · (T δΘ)
// of a moment M(t) on a body whose rotation vector is Θ gives R_Θ −= T(Θ)ᵀ M and the
// stiffness −H(Θ, M) = −∂(TᵀM)/∂Θ.
#pragma once

#include "trifem/dofs/load_curve.hpp"
#include "trifem/physics/term.hpp"
#include "trifem/tensor/tensor.hpp"

namespace trifem::physics {

/// A moment M = moment · curve(t) [N mm] on the rotation DOFs of one body.
struct RigidMoment {
  std::array<Index, 3> rotation{}; ///< DOFs of the body's rotation vector
  Vec3 moment = Vec3::Zero();
  dofs::LoadCurve curve = dofs::LoadCurve::constant(1.0);
};

/// Dead moments on rigid bodies (one element per moment).
class RigidMomentTerm final : public Term {
public:
  explicit RigidMomentTerm(std::vector<RigidMoment> moments) : moments_(std::move(moments)) {}
  std::string name() const override { return "rigid body moment"; }
  Index num_elements() const override { return static_cast<Index>(moments_.size()); }
  void element_dofs(Index e, std::vector<Index>& dofs) const override;
  bool evaluate(Index e, const EvalState& state, LocalVector& r, LocalMatrix* K) const override;
  const std::vector<RigidMoment>& moments() const { return moments_; }

private:
  std::vector<RigidMoment> moments_;
};

} // namespace trifem::physics
