// SPDX-License-Identifier: MIT
// [[rigid_body]]: node sets that move with one rigid translation (helpers of build_model).
#pragma once

#include "trifem/model/model.hpp"

namespace trifem::model {

/// Ties the displacement DOFs of every [[rigid_body]] (free and force-driven components share
/// one unknown, the body's translation), prescribes its displacement-driven components and
/// returns the term applying its forces (null if there are none). Fills model.rigid_bodies.
/// Must run after every other condition has been added to `conditions` (a component may not
/// be constrained twice) and before the DOF map is finalized.
std::unique_ptr<physics::Term> rigid_bodies(const io::CaseSpec& spec, Model& model,
                                            std::vector<dofs::DirichletCondition>& conditions);

/// The force rigid body `b` applies to the tissue [N]: the resultant of the internal forces
/// at its nodes (sum of the residual over its DOFs plus the applied force). Equals the applied
/// force of force-driven components at equilibrium and is the reaction of displacement-driven
/// ones (the same sign convention as [[output.reaction]]).
Vec3 rigid_body_force(const Model& model, const RigidBody& b, Real time);

/// The translation of rigid body `b` [mm] (0 in the components it does not tie).
Vec3 rigid_body_displacement(const Model& model, const RigidBody& b);

} // namespace trifem::model
