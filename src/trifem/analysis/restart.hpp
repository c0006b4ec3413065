// SPDX-License-Identifier: MIT
// Restart files: the converged state of a quasi-static run at an output time (state vector,
// the terms' histories, the analysis step and the step controller's next step), from which
// `trifem run --restart` continues as if the run had not stopped.
#pragma once

#include "trifem/model/model.hpp"

#include <filesystem>
#include <vector>

namespace trifem::analysis {

/// Where a run continues from.
struct Resume {
  Real time = 0.0; ///< the time of the restart state [s]
  Real dt = 0.0;   ///< the step the controller would have proposed next [s]
  int steps = 0;   ///< steps accepted before it (the step count continues)
};

/// Writes the current (converged) state of `model` at `resume.time` to `file` atomically
/// (a temporary file renamed onto it). OutputError if it cannot be written.
void write_restart(const std::filesystem::path& file, const model::Model& model,
                   const Resume& resume);

/// Reads `file` into `model` (built from the same case): state, term histories and the active
/// analysis step with its offsets and released reactions. InputError naming the file if it is
/// not a restart file, is truncated or was written for another model.
Resume read_restart(const std::filesystem::path& file, model::Model& model);

} // namespace trifem::analysis
