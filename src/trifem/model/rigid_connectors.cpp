// SPDX-License-Identifier: MIT
#include "trifem/model/rigid_connectors.hpp"

#include "trifem/core/log.hpp"
#include "trifem/model/conditions.hpp"
#include "trifem/physics/rigid_joints.hpp"

#include <fmt/ranges.h>

#include <set>

namespace trifem::model {
namespace {

using io::ConnectorKind;
using Bodies = std::array<std::optional<physics::RigidBodyUnknowns>, 2>;

/// The unknowns of the body `name` ("ground": none).
std::optional<physics::RigidBodyUnknowns>
body_unknowns(const io::CaseSpec& spec, const Model& model,
              const std::vector<dofs::RigidBodyDofs>& rotating, const std::string& name) {
  if (name == "ground")
    return std::nullopt;
  for (std::size_t i = 0; i < spec.rigid_bodies.size(); ++i)
    if (spec.rigid_bodies[i].name == name) {
      const dofs::RigidBodyDofs& r = rotating.at(model.rigid_bodies[i].rotating);
      return physics::RigidBodyUnknowns{r.translation, r.rotation, r.centre};
    }
  throw InputError(fmt::format("no rotating rigid body is named '{}'", name));
}

physics::JointDrive joint_drive(const io::CaseSpec& spec, const io::RigidComponentSpec& c) {
  using Kind = physics::JointDrive::Kind;
  const Kind kind = c.drive == io::RigidDrive::Displacement ? Kind::Motion
                    : c.drive == io::RigidDrive::Force      ? Kind::Load
                                                            : Kind::Free;
  return {kind, c.value, make_curve(spec, c.curve)};
}

physics::Connector joint(const io::CaseSpec& spec, const io::ConnectorSpec& c, Bodies bodies) {
  static const std::map<ConnectorKind, physics::JointKind> kinds = {
      {ConnectorKind::Spherical, physics::JointKind::Spherical},
      {ConnectorKind::Revolute, physics::JointKind::Revolute},
      {ConnectorKind::Prismatic, physics::JointKind::Prismatic},
      {ConnectorKind::Cylindrical, physics::JointKind::Cylindrical},
      {ConnectorKind::Planar, physics::JointKind::Planar},
      {ConnectorKind::Lock, physics::JointKind::Lock}};
  physics::JointDefinition j;
  j.name = c.name;
  j.kind = kinds.at(c.kind);
  j.origin = c.origin;
  j.axis = c.axis;
  if (c.transverse)
    j.transverse = *c.transverse;
  j.rotation = joint_drive(spec, c.rotation);
  j.translation = joint_drive(spec, c.translation);
  j.torsion_stiffness = c.torsion_stiffness;
  return physics::make_joint(j, std::move(bodies));
}

physics::Connector link(const io::CaseSpec& spec, const io::ConnectorSpec& c, Bodies bodies) {
  using Kind = physics::LinkDefinition::Kind;
  static const std::map<ConnectorKind, Kind> kinds = {
      {ConnectorKind::Spring, Kind::Spring},
      {ConnectorKind::Cable, Kind::Cable},
      {ConnectorKind::Damper, Kind::Damper},
      {ConnectorKind::Contractile, Kind::Contractile}};
  physics::LinkDefinition l;
  l.name = c.name;
  l.kind = kinds.at(c.kind);
  l.point_a = c.point_a;
  l.point_b = c.point_b;
  l.stiffness = c.stiffness;
  l.free_length = c.free_length.value_or(-1.0);
  l.force = c.force;
  l.curve = make_curve(spec, c.curve);
  return physics::make_link(l, std::move(bodies));
}

/// The constraints of `term` that repeat others where the free body unknowns can move, by
/// multiplier DOF, with the name of the connector of each.
std::vector<std::pair<Index, std::string>>
redundant_constraints(const physics::RigidConnectorTerm& term,
                      const std::vector<dofs::DirichletCondition>& conditions, Index num_dofs) {
  std::vector<char> held(num_dofs, 0);
  for (const auto& c : conditions)
    for (Index d : c.dofs)
      held[d] = 1;
  std::map<Index, Index> column; // free body unknown -> column of G
  std::vector<Index> multipliers;
  std::vector<std::string> names;
  std::vector<Index> dofs;
  for (Index e = 0; e < term.num_elements(); ++e) {
    term.element_dofs(e, dofs);
    const std::size_t bodies = dofs.size() - term.connectors()[e].constraints.size();
    for (std::size_t k = 0; k < bodies; ++k) // (the multipliers follow the body unknowns)
      if (!held[dofs[k]] && bodies < dofs.size())
        column.emplace(dofs[k], static_cast<Index>(column.size()));
  }
  // G: a row per constraint, a column per free body unknown, at the reference state
  const Vector x0 = Vector::Zero(num_dofs);
  std::vector<Eigen::VectorXd> rows;
  for (Index e = 0; e < term.num_elements(); ++e) {
    const physics::Connector& c = term.connectors()[e];
    term.element_dofs(e, dofs);
    const Eigen::MatrixXd g = term.constraint_gradients(e, x0);
    for (Index i = 0; i < g.cols(); ++i) {
      Eigen::VectorXd row = Eigen::VectorXd::Zero(static_cast<Index>(column.size()));
      for (Index k = 0; k < g.rows(); ++k)
        if (const auto it = column.find(dofs[k]); it != column.end())
          row[it->second] = g(k, i);
      rows.push_back(std::move(row));
      multipliers.push_back(c.constraints[i].multiplier);
      names.push_back(c.name);
    }
  }
  Eigen::MatrixXd Gt(static_cast<Index>(column.size()), static_cast<Index>(rows.size()));
  for (std::size_t i = 0; i < rows.size(); ++i)
    Gt.col(static_cast<Index>(i)) = rows[i];
  std::vector<std::pair<Index, std::string>> out;
  if (Gt.rows() == 0) { // no free unknown: every constraint repeats the conditions
    for (std::size_t i = 0; i < rows.size(); ++i)
      out.emplace_back(multipliers[i], names[i]);
    return out;
  }
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(Gt);
  qr.setThreshold(1e-10); // relative to the largest pivot; gradients are of order 1
  for (Index k = qr.rank(); k < Gt.cols(); ++k) {
    const Index i = qr.colsPermutation().indices()[k];
    out.emplace_back(multipliers[i], names[i]);
  }
  return out;
}

} // namespace

std::unique_ptr<physics::RigidConnectorTerm>
rigid_connectors(const io::CaseSpec& spec, Model& model,
                 const std::vector<dofs::RigidBodyDofs>& rotating,
                 std::vector<dofs::DirichletCondition>& conditions) {
  if (spec.connectors.empty())
    return nullptr;
  std::vector<physics::Connector> connectors;
  Index forces = 0, moments = 0;
  for (const io::ConnectorSpec& c : spec.connectors) {
    Bodies bodies = with_context(c.key, [&] {
      return Bodies{body_unknowns(spec, model, rotating, c.body_a),
                    body_unknowns(spec, model, rotating, c.body_b)};
    });
    connectors.push_back(c.kind <= ConnectorKind::Lock ? joint(spec, c, std::move(bodies))
                                                       : link(spec, c, std::move(bodies)));
    for (const physics::ConnectorConstraint& g : connectors.back().constraints)
      ++(g.angular ? moments : forces);
  }
  if (forces > 0)
    model.joint_forces = model.dofs.add_field("joint_forces", FieldRole::multiplier, forces, 1);
  if (moments > 0)
    model.joint_moments = model.dofs.add_field("joint_moments", FieldRole::multiplier, moments, 1);
  Index next_force = 0, next_moment = 0;
  for (physics::Connector& c : connectors)
    for (physics::ConnectorConstraint& g : c.constraints)
      g.multiplier = g.angular ? model.dofs.dof(model.joint_moments, next_moment++, 0)
                               : model.dofs.dof(model.joint_forces, next_force++, 0);
  auto term = std::make_unique<physics::RigidConnectorTerm>(std::move(connectors));
  model.connectors = term.get();
  const auto redundant = redundant_constraints(*term, conditions, model.dofs.num_dofs());
  if (!redundant.empty()) {
    dofs::DirichletCondition held;
    std::set<std::string> names;
    for (const auto& [dof, name] : redundant) {
      held.dofs.push_back(dof);
      names.insert(name);
    }
    conditions.push_back(std::move(held));
    log::info("  connectors: {} constraint(s) repeat others where the bodies can move (of {}); "
              "their multipliers are held at 0",
              redundant.size(), fmt::format("{}", fmt::join(names, ", ")));
  }
  return term;
}

} // namespace trifem::model
