// SPDX-License-Identifier: MIT
// Reading a case in any input format the command accepts (TOML case, FEBio .feb).
#pragma once

#include "trifem/io/case_spec.hpp"

#include <filesystem>

namespace trifem::analysis {

/// Reads the case of `file`: an FEBio input file (extension .feb) through feb::read_feb, any
/// other file as a TOML case through io::read_case. Errors are those readers' InputErrors.
io::CaseSpec read_case_file(const std::filesystem::path& file);

} // namespace trifem::analysis
