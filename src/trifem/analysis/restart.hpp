// SPDX-License-Identifier: MIT
// Restart files: the converged state of a run at an output time (state vector, the terms'
// histories, the analysis step, the step controller's next step, the velocity of a dynamic step
// and the explicit integrator's state), from which
// `trifem run --restart` continues as if the run had not stopped.
//
// Format version 3 (native byte order; integers int64, reals IEEE double):
//   header   magic "trifem restart" (16 bytes, zero-padded), version = 3, payload bytes,
//            checksum (FNV-1a 64 of the header's first 32 bytes and of the payload)
//   payload  case fingerprint (kCaseParts hashes, restart_fingerprint.hpp); time; dt; steps;
//            state (length, values); active step (-1: none) and, if one is active, its
//            conditions (count; per condition the offsets' length and values) and released
//            reactions (count; per reaction DOF and force); term histories (count; per term
//            length and values); velocity (length 0 or one per DOF, values); explicit
//            integrator state (length, values)
// The reader verifies the header and the checksum before it interprets anything, then the
// fingerprint, then every value against the case (docs/cli.md, "Restart files").
#pragma once

#include "trifem/analysis/step_state.hpp"
#include "trifem/io/case_spec.hpp"
#include "trifem/model/model.hpp"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace trifem::analysis {

/// The restart format this trifem writes and reads.
inline constexpr std::int64_t kRestartFormat = 3;

/// Where a run continues from.
struct Resume {
  Real time = 0.0; ///< the time of the restart state [s]
  Real dt = 0.0;   ///< the step the controller would have proposed next [s]
  int steps = 0;   ///< steps accepted before it (the step count continues)
  /// The velocity of the dynamic step it was written in, at every DOF (global components), with
  /// which a following step starts; empty: at rest.
  Vector velocity = {};
  /// The state of the explicit integrator of the dynamic-explicit step it was written in
  /// (ExplicitStep::state); empty: written in a step solved by Newton's method.
  std::vector<double> integrator = {};
};

/// Writes the current (converged) state of `model` (built from `spec`) in its active analysis
/// `step` at `resume.time` to `file` atomically (a temporary file renamed onto it).
/// OutputError if it cannot be written.
void write_restart(const std::filesystem::path& file, const io::CaseSpec& spec,
                   const model::Model& model, const StepState& step, const Resume& resume);

/// Reads `file` into `model` (built from `spec`, not yet run): state and term histories, and
/// makes the file's analysis step active with its offsets and released reactions (`steps`). Every
/// failure is an InputError whose message starts with the file's path: not a restart file, another
/// format version, truncated or damaged (checksum), written for another case (the parts of the
/// fingerprint that differ are named), values that do not fit the case (time outside the run
/// or the active step, offsets or histories of other lengths, released DOFs out of range), or
/// a state at the end of the run (nothing left to run). The model is only changed once the
/// whole file has been checked.
Resume read_restart(const std::filesystem::path& file, const io::CaseSpec& spec,
                    model::Model& model, StepState& steps);

} // namespace trifem::analysis
