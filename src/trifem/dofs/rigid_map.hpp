// SPDX-License-Identifier: MIT
// Rigid bodies that translate and rotate: each body has six unknowns, the displacement u_c of
// its centre X_c and its total rotation vector Θ, and the displacement DOFs of its nodes follow
// them (docs/theory/rigid.md):
//
//     u_a = u_c + (R(Θ) − I) S_a,   S_a = X_a − X_c,   δu_a = δu_c − [s_a]× T(Θ) δΘ,   s_a = R S_a
//
// The follower DOFs have no equation of their own: an element's residual and Jacobian on them
// are condensed onto the body's unknowns (Λᵀr, ΛᵀKΛ plus the geometric stiffness of the
// rotation) when it is assembled.
#pragma once

#include "trifem/dofs/dof_map.hpp"
#include "trifem/tensor/tensor.hpp"

#include <array>
#include <span>
#include <vector>

namespace trifem::dofs {

/// The unknowns of one rigid body and the displacement DOFs that follow it.
struct RigidBodyDofs {
  std::array<Index, 3> translation{};          ///< DOFs of u_c
  std::array<Index, 3> rotation{};             ///< DOFs of Θ
  Vec3 centre = Vec3::Zero();                  ///< X_c (reference configuration)
  std::vector<std::array<Index, 3>> followers; ///< displacement DOFs of each node it carries
  std::vector<Vec3> arms;                      ///< S_a = X_a − X_c of each node
};

/// An element's contribution after condensation onto the bodies' unknowns.
struct CondensedElement {
  std::vector<Index> dofs;  ///< the element's DOFs that follow no body, then 6 per body
  Index first_body_dof = 0; ///< position in `dofs` of the first body unknown
  Eigen::VectorXd residual; ///< Λᵀ r
  Eigen::MatrixXd jacobian; ///< ΛᵀKΛ + geometric stiffness
  Eigen::MatrixXd lambda;   ///< Λ (element DOFs x condensed DOFs)
};

/// The rigid bodies of a model and the condensation of element contributions onto them.
class RigidMap {
public:
  RigidMap() = default;
  /// `num_dofs`: the size of the DOF map. A DOF may follow one body only.
  RigidMap(std::vector<RigidBodyDofs> bodies, Index num_dofs);

  bool empty() const { return bodies_.empty(); }
  const std::vector<RigidBodyDofs>& bodies() const { return bodies_; }
  /// The body whose motion DOF `dof` follows, or −1.
  int body_of(Index dof) const { return dof < Index(body_of_.size()) ? body_of_[dof] : -1; }

  /// Sets the follower DOFs of `x` (every DOF) from the bodies' unknowns in `x`.
  void apply(Vector& x) const;
  /// Sets the follower DOFs of `v` (every DOF) to Λ times the bodies' DOFs of `v`: the
  /// variation (or velocity, acceleration) of the nodes for a variation of the bodies' unknowns
  /// at the state `x`, δu_a = δu_c − [s_a]× T(Θ) δΘ.
  void spread(const Vector& x, Vector& v) const;
  /// Adds Λᵀ f, the follower DOFs' values of `f` condensed at the state `x`, to the bodies'
  /// DOFs of `out` (force Σ f_a and Tᵀ Σ s_a × f_a): generalized forces of nodal forces.
  void add_condensed(const Vector& x, const Vector& f, Vector& out) const;
  /// Replaces a rotation vector Θ longer than π by the equivalent Θ (1 − 2π/θ), shorter than π,
  /// in each body whose three rotation DOFs are free in `map`: T(Θ) is singular at θ = 2π, so
  /// a body that keeps turning needs this between steps. True if any changed (the followers
  /// do not: the rotation is the same).
  bool wrap_rotations(Vector& x, const DofMap& map) const;
  /// The DOFs of an element on `dofs` after condensation: those that follow no body, in their
  /// order, then translation and rotation of each body the element touches, by body.
  void expand(std::span<const Index> dofs, std::vector<Index>& out) const;
  /// Condenses the residual `r` (and, if given, the Jacobian `K`) of an element on `dofs` at
  /// the state `x` (every DOF). False, and `out` untouched, if the element touches no body.
  bool condense(std::span<const Index> dofs, const Vector& x, const Eigen::VectorXd& r,
                const Eigen::MatrixXd* K, CondensedElement& out) const;

private:
  std::vector<RigidBodyDofs> bodies_;
  std::vector<int> body_of_;       ///< per DOF (empty without bodies)
  std::vector<Index> follower_of_; ///< per DOF: 3 × follower + component
};

} // namespace trifem::dofs
