// SPDX-License-Identifier: MIT
// The `run` and `check` commands.
#pragma once

#include "trifem/io/case_spec.hpp"

#include <filesystem>

namespace trifem::app {

/// Process exit codes (documented in docs/cli.md).
enum ExitCode : int {
  kSuccess = 0,        ///< the analysis completed
  kUsage = 1,          ///< bad command line
  kInvalidInput = 2,   ///< the case file, mesh or parameters are invalid; nothing was run
  kAnalysisFailed = 3, ///< the analysis stopped early (results written so far are kept)
  kInternalError = 4,  ///< a bug in trifem
};

/// Runs a case; results go to `output_dir`. Returns an ExitCode.
int run_case(const io::CaseSpec& spec, const std::filesystem::path& output_dir);

/// Validates a case (file, mesh, sets, materials) without solving; prints a summary.
int check_case(const io::CaseSpec& spec);

} // namespace trifem::app
