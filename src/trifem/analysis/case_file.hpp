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

/// Refinement of a case for convergence studies (`trifem run --refine-mesh N --refine-time M`).
struct Refinement {
  int mesh_levels = 0; ///< more levels of uniform mesh refinement (each: cells x 8)
  int time_levels = 0; ///< halvings of the time steps (each: steps x 2)
};

/// Refines `spec` in place: `mesh_levels` added to its [mesh] refine; the initial, smallest and
/// largest time step of [time] and of every [[step]] divided by 2^time_levels (output times,
/// step ends and load curves are unchanged). InputError for negative levels, for a mesh refined
/// beyond io::kMaxMeshRefinement levels, or for more than io::kMaxSteps steps.
void refine_case(io::CaseSpec& spec, const Refinement& refinement);

/// Converts the case `input` (read by read_case_file) to the TOML case `output`, its inline mesh
/// next to it as a Gmsh file (io::write_case); existing files are overwritten. Returns the files
/// written, `output` first. InputError for an unreadable input, an output that is the input
/// itself, or what the TOML writer does not support.
std::vector<std::filesystem::path> convert_case(const std::filesystem::path& input,
                                                const std::filesystem::path& output);

} // namespace trifem::analysis
