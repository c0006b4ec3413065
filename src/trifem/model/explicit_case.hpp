// SPDX-License-Identifier: MIT
// Builds the model of a dynamic-explicit case: the mesh, the material of every cell, the fixed
// displacements and surface loads (explicit_dynamics::ExplicitModel), the solver settings and
// the history outputs.
#pragma once

#include "trifem/explicit/explicit_model.hpp"
#include "trifem/explicit/settings.hpp"
#include "trifem/io/case_spec.hpp"
#include "trifem/model/model.hpp"

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace trifem::model {

/// An [[output.reaction]] of an explicit model: the DOFs 3 a + k of a node set, per component k.
struct ExplicitReaction {
  std::string name;
  std::array<std::vector<Index>, 3> dofs;
};

/// An [[output.probe]] of an explicit model: the node nearest to the probe's point.
struct ExplicitProbe {
  std::string name;
  bool position = false; ///< X + u instead of u
  Index node = -1;
};

/// A dynamic-explicit case ready to run.
struct ExplicitCase {
  std::unique_ptr<explicit_dynamics::ExplicitModel> model;
  explicit_dynamics::ExplicitSettings settings;
  std::vector<ExplicitReaction> reactions;
  std::vector<ExplicitProbe> probes;
  std::vector<std::string> material_names; ///< name of each model material, by index
};

/// The solver settings of a case: [explicit] and time.dt (validated; InputError names the key).
explicit_dynamics::ExplicitSettings explicit_settings(const io::CaseSpec& spec);

/// Builds the model of a dynamic-explicit case. InputErrors name the case key (node sets,
/// surfaces, cell blocks); the case must have been read by io::read_case.
ExplicitCase build_explicit_case(const io::CaseSpec& spec);

/// The quasi-static part of a mixed case (spec.has_explicit_step()): its steps before the
/// dynamic-explicit one, the run ending where that step starts.
io::CaseSpec quasi_static_part(const io::CaseSpec& spec);

/// The dynamic-explicit last step of a mixed case as a dynamic-explicit case: the case-level
/// conditions and loads plus those of the step (the others are released), the step's end_time
/// and dt. Its mesh is built like the quasi-static model's (build_mesh: same nodes, same order).
io::CaseSpec explicit_step_part(const io::CaseSpec& spec);

} // namespace trifem::model
