// SPDX-License-Identifier: MIT
// FEBio input file (.feb, XML format 4.0 and 3.0) -> the CaseSpec of the same physics
// (supported subset, mapping and differences in docs/feb.md).
#pragma once

#include "trifem/io/case_spec.hpp"

#include <filesystem>
#include <string_view>

namespace trifem::feb {

/// Reads a .feb file into a case: its mesh as an inline mesh, its materials, load curves,
/// boundary conditions, loads, steps and logfile outputs mapped to trifem's, and FEBio's
/// natural boundary condition of mixtures (faces without a condition are impermeable) written
/// out as impermeable surfaces. Every unsupported or invalid input is one InputError
/// "<file>:<line>: <XML path>: <what>" (a syntax error: "<file>:<line>: XML syntax error: ...").
/// Notes on what is ignored are logged and returned in CaseSpec::warnings.
io::CaseSpec read_feb(const std::filesystem::path& file);

/// Same as read_feb for text already in memory (`file` names it in messages).
io::CaseSpec parse_feb(std::string_view text, const std::filesystem::path& file);

/// True if `file` has the extension .feb (any case).
bool is_feb_file(const std::filesystem::path& file);

} // namespace trifem::feb
