// SPDX-License-Identifier: MIT
// A dynamic-explicit case (or the dynamic-explicit step of a mixed case) ready to run: the
// explicit model of the shared model's current step, the solver settings and the history
// outputs.
#pragma once

#include "trifem/explicit/explicit_model.hpp"
#include "trifem/explicit/settings.hpp"
#include "trifem/io/case_spec.hpp"
#include "trifem/model/model.hpp"

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace trifem::analysis {

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
  std::unique_ptr<explicit_dynamics::ExplicitModel> model; ///< null until build_explicit_model
  explicit_dynamics::ExplicitSettings settings;
  std::vector<explicit_dynamics::SurfaceLoad> loads;
  std::vector<ExplicitReaction> reactions;
  std::vector<ExplicitProbe> probes;
  std::vector<std::string> material_names; ///< name of each model material, by index
};

/// The settings, surface loads and history outputs of `spec` (a dynamic-explicit case, or
/// explicit_step_part of a mixed case) on `mesh`, validated (InputErrors name the case key);
/// no model yet.
ExplicitCase explicit_case(const io::CaseSpec& spec, const mesh::Mesh& mesh);

/// Gives `c` the explicit model of `model` (built by model::build_model from the same case) in
/// its current step.
void build_explicit_model(ExplicitCase& c, const model::Model& model);

/// The quasi-static part of a mixed case (spec.has_explicit_step()): its steps before the
/// dynamic-explicit one, the run ending where that step starts.
io::CaseSpec quasi_static_part(const io::CaseSpec& spec);

/// The dynamic-explicit last step of a mixed case as a dynamic-explicit case: the case-level
/// loads plus those of the step, its end_time and dt, the case's outputs.
io::CaseSpec explicit_step_part(const io::CaseSpec& spec);

} // namespace trifem::analysis
