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

/// A follower force F₀ at the reference point X (arm S = X − X_c) and a follower moment M₀,
/// both given in the reference configuration, times curve(t).
struct RigidFollowerLoad {
  std::array<Index, 3> translation{}; ///< DOFs of the body's center
  std::array<Index, 3> rotation{};    ///< DOFs of its rotation vector
  Vec3 arm = Vec3::Zero();            ///< S [mm]
  Vec3 force = Vec3::Zero();          ///< F₀ [N]
  Vec3 moment = Vec3::Zero();         ///< M₀ [N mm]
  dofs::LoadCurve curve = dofs::LoadCurve::constant(1.0);
};

/// Follower loads on rigid bodies (one element per load).
class RigidFollowerTerm final : public Term {
public:
  explicit RigidFollowerTerm(std::vector<RigidFollowerLoad> loads) : loads_(std::move(loads)) {}
  std::string name() const override { return "rigid body follower load"; }
  Index num_elements() const override { return static_cast<Index>(loads_.size()); }
  void element_dofs(Index e, std::vector<Index>& dofs) const override;
  bool evaluate(Index e, const EvalState& state, LocalVector& r, LocalMatrix* K) const override;

private:
  std::vector<RigidFollowerLoad> loads_;
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
