// SPDX-License-Identifier: MIT
#include "trifem/contact/rigid_wall_term.hpp"

#include "trifem/core/error.hpp"

#include <cmath>

namespace trifem::contact {
namespace {

ActiveSetSettings active_set_settings(const RigidWallSettings& s) {
  ActiveSetSettings a;
  a.release_threshold = s.release_threshold;
  a.gap_tolerance = s.gap_tolerance;
  a.max_updates = s.max_active_set_updates;
  a.max_resolves = s.max_active_set_resolves;
  return a;
}

} // namespace

RigidWallTerm::RigidWallTerm(const mesh::Mesh& mesh, const dofs::DofMap& dofs,
                             dofs::FieldId displacement, dofs::FieldId multiplier,
                             std::vector<Index> nodes, RigidWallSettings settings)
    : mesh_(mesh), dofs_(dofs), u_(displacement), lambda_(multiplier), nodes_(std::move(nodes)),
      settings_(std::move(settings)),
      active_(static_cast<Index>(nodes_.size()), active_set_settings(settings_)),
      committed_(active_) {
  TRIFEM_CHECK(!nodes_.empty(), "the rigid wall's surface has no node");
  TRIFEM_CHECK(std::abs(settings_.normal.norm() - 1.0) < 1e-12,
               "the rigid wall's normal must be a unit vector");
  TRIFEM_CHECK(settings_.scale > 0.0 && settings_.gap_tolerance > 0.0,
               "the rigid wall needs a positive scale and gap tolerance");
  TRIFEM_CHECK(dofs_.field(lambda_).num_entities == static_cast<Index>(nodes_.size()) &&
                   dofs_.field(lambda_).components == 1,
               "the rigid wall's multiplier field must have one entity per node and one "
               "component");
}

void RigidWallTerm::element_dofs(Index e, std::vector<Index>& dofs) const {
  dofs = {u_dof(e, 0), u_dof(e, 1), u_dof(e, 2), multiplier_dof(e)};
}

Real RigidWallTerm::gap(Index k, const Vector& x, Real t) const {
  const Vec3 position =
      mesh_.node(nodes_[k]) + Vec3(x[u_dof(k, 0)], x[u_dof(k, 1)], x[u_dof(k, 2)]);
  return settings_.normal.dot(position - settings_.point) - settings_.offset * settings_.curve(t);
}

bool RigidWallTerm::evaluate(Index e, const physics::EvalState& state, physics::LocalVector& r,
                             physics::LocalMatrix* K) const {
  const Vec3& n = settings_.normal;
  const Real lambda = state.x[multiplier_dof(e)];
  const bool active = active_.active(e);
  r.resize(4);
  r.head<3>() = lambda * n;
  r[3] = active ? gap(e, state.x, state.time) : lambda / settings_.scale;
  if (K) {
    K->setZero(4, 4);
    K->block<3, 1>(0, 3) = n;
    if (active)
      K->block<1, 3>(3, 0) = n.transpose();
    else
      (*K)(3, 3) = 1.0 / settings_.scale;
  }
  return true;
}

bool RigidWallTerm::prepare(const physics::EvalState& state) {
  std::vector<NodeStatus> status(nodes_.size());
  for (Index k = 0; k < num_elements(); ++k) {
    const Real g = gap(k, state.x, state.time);
    status[k] = {true, g, state.x[multiplier_dof(k)] + settings_.scale * g, false};
  }
  active_.update(state.time, status);
  return false;
}

void RigidWallTerm::commit(const physics::EvalState& /*state*/) {
  active_.commit();
  committed_ = active_;
}

std::string RigidWallTerm::step_rejection(const physics::EvalState& /*state*/) const {
  if (active_.pending() > 0)
    return fmt::format("the contact status of {} node(s) with the rigid wall did not settle "
                       "within the step",
                       active_.pending());
  return {};
}

std::vector<double> RigidWallTerm::history() const {
  const std::vector<char>& flags = committed_.flags();
  return {flags.begin(), flags.end()};
}

void RigidWallTerm::restore_history(const std::vector<double>& values) {
  TRIFEM_CHECK(values.size() == nodes_.size(),
               "the restart file holds {} rigid wall contact flags, this wall has {} nodes",
               values.size(), nodes_.size());
  std::vector<char> flags(values.size());
  for (std::size_t k = 0; k < values.size(); ++k) {
    TRIFEM_CHECK(values[k] == 0 || values[k] == 1,
                 "the restart file holds an invalid rigid wall contact flag {} at node {}",
                 values[k], k);
    flags[k] = static_cast<char>(values[k]);
  }
  active_.assign(flags);
  active_.commit();
  committed_ = active_;
}

Vec3 RigidWallTerm::force(const Vector& x) const {
  Real sum = 0.0;
  for (Index k = 0; k < num_elements(); ++k)
    sum += x[multiplier_dof(k)];
  return -sum * settings_.normal;
}

} // namespace trifem::contact
