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

void RigidFollowerTerm::element_dofs(Index e, std::vector<Index>& dofs) const {
  dofs.assign(loads_[e].translation.begin(), loads_[e].translation.end());
  dofs.insert(dofs.end(), loads_[e].rotation.begin(), loads_[e].rotation.end());
}

bool RigidFollowerTerm::evaluate(Index e, const EvalState& state, LocalVector& r,
                                 LocalMatrix* K) const {
  const RigidFollowerLoad& load = loads_[e];
  const Vec3 theta(state.x[load.rotation[0]], state.x[load.rotation[1]], state.x[load.rotation[2]]);
  const Real scale = load.curve(state.time);
  const Mat3 R = rotation::matrix(theta), T = rotation::tangent(theta);
  const Vec3 f = scale * (R * load.force);
  const Vec3 m = scale * (R * (load.arm.cross(load.force) + load.moment));
  r.resize(6);
  r.head<3>() = -f;
  r.tail<3>() = -T.transpose() * m;
  if (K) {
    K->setZero(6, 6);
    K->block<3, 3>(0, 3) = rotation::skew(f) * T;
    K->block<3, 3>(3, 3) =
        -rotation::tangent_derivative(theta, m) + T.transpose() * rotation::skew(m) * T;
  }
  return true;
}

} // namespace trifem::physics
