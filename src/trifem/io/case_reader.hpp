// SPDX-License-Identifier: MIT
// Case file reader: TOML text -> validated CaseSpec (format documented in docs/input.md).
#pragma once

#include "trifem/io/case_spec.hpp"

#include <filesystem>
#include <string_view>

namespace trifem::io {

/// Reads and validates a case file. Every error is an InputError whose message starts with
/// "<file>: " and names the key path (e.g. "materials.cartilage.E") or the line and column of a
/// TOML syntax error, and says what was expected. Defaults are filled in; relative Gmsh paths
/// are resolved against the directory of `file`.
CaseSpec read_case(const std::filesystem::path& file);

/// Same as read_case for text already in memory; `file` is used for messages and to resolve
/// relative paths (it need not exist).
CaseSpec parse_case(std::string_view text, const std::filesystem::path& file);

/// The limits read_case applies to the work a case implies (steps and cutbacks of [time] and of
/// every [[step]], output times, the size of the model of the boxes), for a spec changed after
/// it was read (e.g. refined by `trifem run --refine-mesh/--refine-time`). InputError starting
/// with "<spec.file>: " if one is exceeded.
void check_limits(const CaseSpec& spec);

} // namespace trifem::io
