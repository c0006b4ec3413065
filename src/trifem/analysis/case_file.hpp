// SPDX-License-Identifier: MIT
// Reading a case in any input format the command accepts (TOML case, FEBio .feb), and
// converting it to a TOML case.
#pragma once

#include "trifem/io/case_spec.hpp"

#include <filesystem>
#include <vector>

namespace trifem::analysis {

/// Reads the case of `file`: an FEBio input file (extension .feb) through feb::read_feb, any
/// other file as a TOML case through io::read_case. Errors are those readers' InputErrors.
io::CaseSpec read_case_file(const std::filesystem::path& file);

/// Converts the case `input` (read by read_case_file) to the TOML case `output`, its inline mesh
/// next to it as a Gmsh file (io::write_case); existing files are overwritten. Returns the files
/// written, `output` first. InputError for an unreadable input, an output that is the input
/// itself, or what the TOML writer does not support.
std::vector<std::filesystem::path> convert_case(const std::filesystem::path& input,
                                                const std::filesystem::path& output);

} // namespace trifem::analysis
