// SPDX-License-Identifier: MIT
// [[connector]]: joints and links between rotating rigid bodies (a helper of rigid_bodies).
#pragma once

#include "trifem/dofs/rigid_map.hpp"
#include "trifem/model/model.hpp"
#include "trifem/physics/rigid_connector_term.hpp"

namespace trifem::model {

/// The connectors of `spec` between the rotating bodies `rotating` (by their index in
/// model.rigid_bodies[i].rotating); adds the fields of their multipliers (model.joint_forces,
/// model.joint_moments) and sets model.connectors. Null without connectors.
///
/// Constraints that repeat others where the bodies can move (e.g. the out-of-plane components
/// of spherical joints in a planar mechanism, or a joint between two held bodies) would leave
/// their multipliers undetermined: they are found in the reference configuration (a rank-
/// revealing QR of the constraints' gradients by the free body unknowns, `conditions` holding
/// the prescribed ones) and their multipliers held at 0 (a condition added to `conditions`).
std::unique_ptr<physics::RigidConnectorTerm>
rigid_connectors(const io::CaseSpec& spec, Model& model,
                 const std::vector<dofs::RigidBodyDofs>& rotating,
                 std::vector<dofs::DirichletCondition>& conditions);

} // namespace trifem::model
