// SPDX-License-Identifier: MIT
// Builds the finite element model (mesh, fields, conditions, terms) described by a case.
#pragma once

#include "trifem/assembly/fe_problem.hpp"
#include "trifem/contact/contact_term.hpp"
#include "trifem/contact/rigid_wall_term.hpp"
#include "trifem/io/case_spec.hpp"
#include "trifem/io/probe_quantities.hpp"
#include "trifem/material/mixture.hpp"
#include "trifem/mesh/mesh.hpp"
#include "trifem/physics/mixture_term.hpp"
#include "trifem/physics/nodal_force_term.hpp"
#include "trifem/physics/rigid_connector_term.hpp"
#include "trifem/physics/solid_term.hpp"

#include <memory>

namespace trifem::model {

/// A reaction output: displacement DOFs of a node set per component.
struct ReactionSet {
  std::string name;
  std::array<bool, 3> tied = {false, false, false}; ///< components moving with the body
  std::array<std::vector<Index>, 3> dofs;           ///< of the tied components
};

/// A probe output: a quantity at a point of a cell.
struct Probe {
  std::string name;
  const io::ProbeQuantity* quantity = nullptr;
  Index cell = -1;        ///< the cell containing the point
  Vec3 xi = Vec3::Zero(); ///< natural coordinates of the point in the cell
};

/// An average output: a quantity averaged over the cells of a cell block.
struct Average {
  std::string name;
  const io::ProbeQuantity* quantity = nullptr;
  std::string block;
  std::vector<Index> cells; ///< the cells of the block
};

/// The law of one cell: a solid law, or a mixture (which has its own solid).
struct CellMaterial {
  std::string name; ///< of its [materials.<name>] table (of its body, for a rigid cell)
  std::shared_ptr<const material::ElasticLaw> solid;
  std::shared_ptr<const material::MixtureProperties> mixture;
  physics::SolidElement element = physics::SolidElement::Displacement; ///< of a solid law
  Real density = 0.0; ///< per reference volume [t/mm³] (0: not given)
  /// A cell of a rigid body: no law, no unknowns of its own (its nodes follow the body).
  bool rigid() const { return !solid && !mixture; }
};

/// The element `auto` chooses for a solid law: mean dilatation when its small-strain bulk
/// modulus is at least kNearlyIncompressible times its shear modulus (Poisson's ratio ≥ 0.452),
/// where the displacement element locks; the displacement element otherwise.
inline constexpr Real kNearlyIncompressible = 10.0;
physics::SolidElement solid_element(io::SolidElementSpec requested,
                                    const material::ElasticLaw& law);

/// A [[rigid_body]]: the displacement DOFs of its nodes per component (the first one leads of
/// a body that only translates; a rotating body's nodes follow its own unknowns).
struct RigidBody {
  std::string name;
  std::array<bool, 3> tied = {false, false, false}; ///< components moving with the body
  std::array<std::vector<Index>, 3> dofs;           ///< of the tied components
  std::array<physics::NodalForce, 3> force; ///< applied force per component (magnitude 0: none)
  int rotating = -1; ///< a rotating body: its index among the problem's RigidMap bodies
};

/// A [[constraint]] of type rigid-wall.
struct RigidWall {
  std::string name;
  const contact::RigidWallTerm* term = nullptr; ///< owned by the problem
  dofs::FieldId field;                          ///< its nodal contact forces
};

/// The conditions of one [[step]] (acting in addition to the case's own) and how the conditions
/// it releases are unloaded. Its loads are terms of the problem active during the step only.
/// What a run changes as a step begins (offsets, released reactions) is the analysis'
/// (analysis::StepState).
struct ModelStep {
  std::string name;
  std::string key;                                  ///< "step[i]"
  Real start_time = 0.0;                            ///< end of the previous step [s]
  Real end_time = 0.0;                              ///< [s]
  std::vector<dofs::DirichletCondition> conditions; ///< without the offsets of relative ones
  std::vector<std::string> keys;                    ///< case key of each condition
  std::vector<bool> relative;                       ///< per condition
  Real release_time = 0.0;                          ///< see io::StepSpec
};

/// Everything a run needs. Owns the mesh and the DOF map the terms refer to.
struct Model {
  mesh::Mesh mesh;
  /// The DOFs, constrained by the case's conditions (those of every step); the problem holds
  /// them with the constraints of the current step (problem->dof_map()).
  dofs::DofMap dofs;
  std::vector<CellMaterial> materials; ///< per cell
  /// The material basis Q = [e1 e2 e3] per cell (the identity for cells of materials without
  /// [<name>.axes]); empty if no material has axes.
  std::vector<Mat3> axes;
  physics::MixtureFields fields; ///< u always; w, p with mixtures; j+-, eta with ions
  material::Electrochemistry chem;
  const physics::SolidTerm* solid = nullptr;   ///< pure-solid cells (owned by problem)
  physics::MixtureTerm* mixture = nullptr;     ///< mixture cells (owned by problem)
  std::vector<dofs::FieldId> contact_fields;   ///< contact pressure of each [[contact]] pair
  std::vector<contact::ContactTerm*> contacts; ///< owned by problem
  std::unique_ptr<assembly::FeProblem> problem;
  /// The external loads among the problem's terms (owned by it): the surface loads, body forces
  /// and baths of the case, the forces and moments on the rigid bodies, then the surface loads
  /// of the steps.
  std::vector<const physics::Term*> loads;
  std::vector<ReactionSet> reactions;
  std::vector<Probe> probes;
  std::vector<Average> averages;
  std::vector<RigidBody> rigid_bodies;
  /// The translation and rotation of the rotating rigid bodies (invalid: none).
  dofs::FieldId rigid_translation, rigid_rotation;
  /// The multipliers of the rigid connectors' constraints: forces [N] and moments [N mm].
  dofs::FieldId joint_forces, joint_moments;
  const physics::RigidConnectorTerm* connectors = nullptr; ///< owned by problem; null: none
  /// The multipliers of the constraints' equations ([[constraint]]): forces [N].
  dofs::FieldId constraint_forces;
  std::vector<RigidWall> walls;
  /// The velocity of every DOF (global components) at the start of an analysis that starts
  /// with a dynamic step: that of the rigid bodies given one and of the [[initial_velocity]]
  /// nodes (empty: at rest).
  Vector initial_velocity;
  std::vector<ModelStep> steps; ///< empty: one step with the case's conditions only
  std::vector<dofs::DirichletCondition> case_conditions; ///< the conditions of every step
  Real length_scale = 1.0;                               ///< bounding-box diagonal [mm]
  Real modulus_scale = 1.0;                              ///< largest P-wave modulus [MPa]
  Real permeability_scale = 0.0; ///< largest permeability [mm^4/(N s)] (0: no mixture)

  dofs::FieldId displacement() const { return fields.u; }
};

/// Builds the mesh of a case (boxes, Gmsh files and inline meshes) with their cell-block ->
/// material map.
mesh::Mesh build_mesh(const io::CaseSpec& spec, std::map<std::string, std::string>& materials);

/// Builds the whole model, including its initial state. InputErrors name the case key.
std::unique_ptr<Model> build_model(const io::CaseSpec& spec);

/// On several processes: the process that owns mesh node `node` (the owner of its first
/// displacement equation); -1 if it has none (all displacements prescribed) or on one process.
int node_owner(const Model& model, Index node);

} // namespace trifem::model
