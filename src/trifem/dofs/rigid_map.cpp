// SPDX-License-Identifier: MIT
#include "trifem/dofs/rigid_map.hpp"

#include "trifem/core/error.hpp"
#include "trifem/tensor/rotation.hpp"

#include <algorithm>
#include <numbers>

namespace trifem::dofs {
namespace {

Vec3 values(const Vector& x, const std::array<Index, 3>& dofs) {
  return {x[dofs[0]], x[dofs[1]], x[dofs[2]]};
}

/// The bodies touched by the follower DOFs among `dofs`, ascending.
std::vector<int> touched_bodies(const RigidMap& map, std::span<const Index> dofs) {
  std::vector<int> bodies;
  for (Index d : dofs)
    if (const int b = map.body_of(d); b >= 0)
      bodies.push_back(b);
  std::sort(bodies.begin(), bodies.end());
  bodies.erase(std::unique(bodies.begin(), bodies.end()), bodies.end());
  return bodies;
}

} // namespace

RigidMap::RigidMap(std::vector<RigidBodyDofs> bodies, Index num_dofs) : bodies_(std::move(bodies)) {
  if (bodies_.empty())
    return;
  body_of_.assign(num_dofs, -1);
  follower_of_.assign(num_dofs, -1);
  for (int b = 0; b < static_cast<int>(bodies_.size()); ++b) {
    const RigidBodyDofs& body = bodies_[b];
    TRIFEM_VERIFY(body.followers.size() == body.arms.size(), "one arm per follower of body {}", b);
    for (Index f = 0; f < static_cast<Index>(body.followers.size()); ++f)
      for (int k = 0; k < 3; ++k) {
        const Index d = body.followers[f][k];
        TRIFEM_VERIFY(d >= 0 && d < num_dofs, "follower DOF {} out of range", d);
        TRIFEM_VERIFY(body_of_[d] < 0, "DOF {} follows two rigid bodies", d);
        body_of_[d] = b;
        follower_of_[d] = 3 * f + k;
      }
  }
}

bool RigidMap::wrap_rotations(Vector& x, const DofMap& map) const {
  bool changed = false;
  for (const RigidBodyDofs& b : bodies_) {
    if (std::any_of(b.rotation.begin(), b.rotation.end(),
                    [&](Index d) { return map.is_constrained(d); }))
      continue;
    const Vec3 theta(x[b.rotation[0]], x[b.rotation[1]], x[b.rotation[2]]);
    const Real angle = theta.norm();
    if (angle <= std::numbers::pi)
      continue;
    const Vec3 wrapped = theta * (1.0 - 2.0 * std::numbers::pi / angle);
    for (int k = 0; k < 3; ++k)
      x[b.rotation[k]] = wrapped[k];
    changed = true;
  }
  return changed;
}

void RigidMap::apply(Vector& x) const {
  for (const RigidBodyDofs& body : bodies_) {
    const Vec3 uc = values(x, body.translation);
    const Mat3 R_minus_I = rotation::matrix(values(x, body.rotation)) - Mat3::Identity();
    for (std::size_t f = 0; f < body.followers.size(); ++f) {
      const Vec3 u = uc + R_minus_I * body.arms[f];
      for (int k = 0; k < 3; ++k)
        x[body.followers[f][k]] = u[k];
    }
  }
}

void RigidMap::spread(const Vector& x, Vector& v) const {
  for (const RigidBodyDofs& body : bodies_) {
    const Vec3 theta = values(x, body.rotation);
    const Mat3 R = rotation::matrix(theta);
    const Vec3 turn = rotation::tangent(theta) * values(v, body.rotation); // T δΘ
    const Vec3 shift = values(v, body.translation);
    for (std::size_t f = 0; f < body.followers.size(); ++f) {
      const Vec3 u = shift + turn.cross(R * body.arms[f]);
      for (int k = 0; k < 3; ++k)
        v[body.followers[f][k]] = u[k];
    }
  }
}

void RigidMap::add_condensed(const Vector& x, const Vector& f, Vector& out) const {
  for (const RigidBodyDofs& body : bodies_) {
    const Vec3 theta = values(x, body.rotation);
    const Mat3 R = rotation::matrix(theta);
    Vec3 force = Vec3::Zero(), moment = Vec3::Zero();
    for (std::size_t a = 0; a < body.followers.size(); ++a) {
      const Vec3 fa = values(f, body.followers[a]);
      force += fa;
      moment += (R * body.arms[a]).cross(fa);
    }
    const Vec3 generalized = rotation::tangent(theta).transpose() * moment;
    for (int k = 0; k < 3; ++k) {
      out[body.translation[k]] += force[k];
      out[body.rotation[k]] += generalized[k];
    }
  }
}

void RigidMap::expand(std::span<const Index> dofs, std::vector<Index>& out) const {
  out.clear();
  for (Index d : dofs)
    if (body_of(d) < 0)
      out.push_back(d);
  for (int b : touched_bodies(*this, dofs)) {
    out.insert(out.end(), bodies_[b].translation.begin(), bodies_[b].translation.end());
    out.insert(out.end(), bodies_[b].rotation.begin(), bodies_[b].rotation.end());
  }
}

bool RigidMap::condense(std::span<const Index> dofs, const Vector& x, const Eigen::VectorXd& r,
                        const Eigen::MatrixXd* K, CondensedElement& out) const {
  const std::vector<int> bodies = touched_bodies(*this, dofs);
  if (bodies.empty())
    return false;
  expand(dofs, out.dofs);
  const Index n = static_cast<Index>(dofs.size());
  const Index free = static_cast<Index>(out.dofs.size()) - 6 * Index(bodies.size());
  out.first_body_dof = free;
  // per touched body: R, T, and the sums of the geometric stiffness
  struct Body {
    Vec3 theta;
    Mat3 R, T;
    Mat3 arm_force = Mat3::Zero(); ///< Σ [r_a]×[s_a]×
    Vec3 moment = Vec3::Zero();    ///< Σ s_a × r_a
  };
  std::vector<Body> kin(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    kin[i].theta = values(x, bodies_[bodies[i]].rotation);
    kin[i].R = rotation::matrix(kin[i].theta);
    kin[i].T = rotation::tangent(kin[i].theta);
  }
  out.lambda.setZero(n, static_cast<Index>(out.dofs.size()));
  Index column = 0;
  for (Index i = 0; i < n; ++i) {
    const int b = body_of(dofs[i]);
    if (b < 0) {
      out.lambda(i, column++) = 1.0;
      continue;
    }
    const std::size_t at = std::lower_bound(bodies.begin(), bodies.end(), b) - bodies.begin();
    const Index base = free + 6 * static_cast<Index>(at);
    const Index f = follower_of_[dofs[i]] / 3;
    const int k = static_cast<int>(follower_of_[dofs[i]] % 3);
    const Vec3 s = kin[at].R * bodies_[b].arms[f];
    out.lambda(i, base + k) = 1.0;
    out.lambda.block<1, 3>(i, base + 3) = -(rotation::skew(s) * kin[at].T).row(k);
    const Vec3 force = r[i] * Vec3::Unit(k);
    kin[at].arm_force += rotation::skew(force) * rotation::skew(s);
    kin[at].moment += s.cross(force);
  }
  out.residual = out.lambda.transpose() * r;
  if (!K)
    return true;
  out.jacobian = out.lambda.transpose() * (*K) * out.lambda;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const Index base = free + 6 * static_cast<Index>(i) + 3;
    out.jacobian.block<3, 3>(base, base) +=
        kin[i].T.transpose() * kin[i].arm_force * kin[i].T +
        rotation::tangent_derivative(kin[i].theta, kin[i].moment);
  }
  return true;
}

} // namespace trifem::dofs
