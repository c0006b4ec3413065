// SPDX-License-Identifier: MIT
#include "trifem/physics/rigid_moment_term.hpp"

#include "trifem/tensor/rotation.hpp"

namespace trifem::physics {

void RigidMomentTerm::element_dofs(Index e, std::vector<Index>& dofs) const {
  dofs.assign(moments_[e].rotation.begin(), moments_[e].rotation.end());
}

bool RigidMomentTerm::evaluate(Index e, const EvalState& state, LocalVector& r,
                               LocalMatrix* K) const {
  const RigidMoment& m = moments_[e];
  const Vec3 theta(state.x[m.rotation[0]], state.x[m.rotation[1]], state.x[m.rotation[2]]);
  const Vec3 moment = m.curve(state.time) * m.moment;
  r = -rotation::tangent(theta).transpose() * moment;
  if (K)
    *K = -rotation::tangent_derivative(theta, moment);
  return true;
}

} // namespace trifem::physics
