// SPDX-License-Identifier: MIT
// [[rigid_body]]: node sets that move with one rigid translation, or translate and rotate
// (helpers of build_model).
#pragma once

#include "trifem/model/model.hpp"
#include "trifem/physics/cell_mass.hpp"

namespace trifem::model {

/// What the rigid bodies add to the problem.
struct RigidBodyParts {
  std::vector<std::unique_ptr<physics::Term>> loads; ///< their forces, moments and connectors
  dofs::RigidMap map;                                ///< the rotating bodies
};

/// Builds every [[rigid_body]] and fills model.rigid_bodies. A body that only translates ties
/// the displacement DOFs of its nodes (free and force-driven components share one unknown, the
/// body's translation); a rotating one adds its six unknowns (fields model.rigid_translation
/// and model.rigid_rotation) and makes its nodes' displacements follow them. Prescribed
/// components are added to `conditions`. Must run after every other condition has been added to
/// `conditions` (a component may not be constrained twice) and before the DOF map is finalized.
RigidBodyParts rigid_bodies(const io::CaseSpec& spec, Model& model,
                            std::vector<dofs::DirichletCondition>& conditions);

/// The shells of the rigid bodies with a shell_thickness t and a density ρ: the facets of their
/// surface meshes as mass elements of ρ t per reference area (none without a density).
std::vector<physics::MassElement> rigid_shell_masses(const io::CaseSpec& spec, const Model& model);

/// The velocity of every DOF at the start of the analysis: of the nodes (and unknowns) of the
/// rigid bodies with a velocity or angular velocity, v_a = v + ω × S_a. Empty if none has one.
/// Call once the problem exists.
Vector initial_rigid_velocity(const io::CaseSpec& spec, const Model& model);

/// Throws InputError if a node carried by a rotating body has a flux DOF in a rotated nodal
/// frame (an impermeable surface): the frame is fixed in space and would not turn with it.
void check_frames_of_rotating_bodies(const io::CaseSpec& spec, const Model& model,
                                     const dofs::NodalFrames& frames);

/// The force rigid body `b` applies to the tissue [N]: the resultant of the internal forces
/// at its nodes (sum of the residual over its DOFs plus the applied force). Equals the applied
/// force of force-driven components at equilibrium and is the reaction of displacement-driven
/// ones (the same sign convention as [[output.reaction]]).
Vec3 rigid_body_force(const Model& model, const RigidBody& b, Real time);
/// rigid_body_force with the residual `R` of every DOF (e.g. an explicit step's reactions).
Vec3 rigid_body_force(const RigidBody& b, Real time, const Vector& R);

/// The translation of rigid body `b` [mm] (of its center if it rotates; 0 in the components
/// it does not tie).
Vec3 rigid_body_displacement(const Model& model, const RigidBody& b);

/// The rotation vector of a rotating rigid body [rad].
Vec3 rigid_body_rotation(const Model& model, const RigidBody& b);

/// The moment a rotating rigid body applies to the tissue about its current center [N mm]:
/// Σ (x_a − x_c) × R_a over its nodes (the sign convention of rigid_body_force).
Vec3 rigid_body_moment(const Model& model, const RigidBody& b);
/// rigid_body_moment with the residual `R` of every DOF.
Vec3 rigid_body_moment(const Model& model, const RigidBody& b, const Vector& R);

} // namespace trifem::model
