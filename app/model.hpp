// SPDX-License-Identifier: MIT
// Builds the finite element model (mesh, fields, conditions, terms) described by a case.
#pragma once

#include "trifem/assembly/fe_problem.hpp"
#include "trifem/io/case_spec.hpp"
#include "trifem/material/elastic_law.hpp"
#include "trifem/mesh/mesh.hpp"
#include "trifem/physics/solid_term.hpp"

#include <memory>

namespace trifem::app {

/// A reaction output: DOFs of a node set per component.
struct ReactionSet {
  std::string name;
  std::array<std::vector<Index>, 3> dofs;
};

/// A probe output: one node.
struct Probe {
  std::string name;
  std::string quantity;
  Index node = -1;
};

/// Everything a run needs. Owns the mesh and DOF map the problem refers to.
struct Model {
  mesh::Mesh mesh;
  dofs::DofMap dofs;
  dofs::FieldId displacement;
  const physics::SolidTerm* solid = nullptr; ///< owned by problem
  std::unique_ptr<assembly::FeProblem> problem;
  std::vector<ReactionSet> reactions;
  std::vector<Probe> probes;
  Real length_scale = 1.0;  ///< bounding-box diagonal [mm]
  Real modulus_scale = 1.0; ///< largest P-wave modulus [MPa]
};

/// Builds the mesh of a case (boxes and Gmsh files) with their cell-block -> material map.
mesh::Mesh build_mesh(const io::CaseSpec& spec, std::map<std::string, std::string>& materials);

/// Builds the whole model. InputErrors name the case key of the problem.
std::unique_ptr<Model> build_model(const io::CaseSpec& spec);

} // namespace trifem::app
