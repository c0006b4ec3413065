// SPDX-License-Identifier: MIT
#include "trifem/analysis/case_file.hpp"

#include "trifem/core/error.hpp"
#include "trifem/feb/feb_reader.hpp"
#include "trifem/io/case_reader.hpp"
#include "trifem/io/case_writer.hpp"

#include <cmath>

namespace trifem::analysis {

io::CaseSpec read_case_file(const std::filesystem::path& file) {
  return feb::is_feb_file(file) ? feb::read_feb(file) : io::read_case(file);
}

void refine_case(io::CaseSpec& spec, const Refinement& refinement) {
  TRIFEM_CHECK(refinement.mesh_levels >= 0 && refinement.time_levels >= 0,
               "refinement levels must be 0 or more (given: mesh {}, time {})",
               refinement.mesh_levels, refinement.time_levels);
  spec.mesh_refinement += refinement.mesh_levels;
  TRIFEM_CHECK(spec.mesh_refinement <= io::kMaxMeshRefinement,
               "--refine-mesh: {} levels of mesh refinement in all, more than the {} allowed "
               "(each level multiplies the cells by eight)",
               spec.mesh_refinement, io::kMaxMeshRefinement);
  if (refinement.mesh_levels == 0 && refinement.time_levels == 0)
    return;
  const Real factor = std::ldexp(1.0, -refinement.time_levels); // 0 once it underflows
  const auto refine = [factor](io::TimeSpec& t) {
    t.dt *= factor;
    t.dt_min *= factor;
    t.dt_max *= factor;
  };
  refine(spec.time);
  for (io::StepSpec& step : spec.steps)
    refine(step.time);
  try {
    io::check_limits(spec); // the refined case must fit the reader's limits too
  } catch (const InputError& e) {
    throw InputError(fmt::format("{} (after --refine-mesh {} --refine-time {})", e.what(),
                                 refinement.mesh_levels, refinement.time_levels));
  }
}

std::vector<std::filesystem::path> convert_case(const std::filesystem::path& input,
                                                const std::filesystem::path& output) {
  const io::CaseSpec spec = read_case_file(input);
  std::error_code ec;
  TRIFEM_CHECK(!std::filesystem::equivalent(input, output, ec),
               "{}: the output is the input file; give another name with -o", output.string());
  return io::write_case(spec, output);
}

} // namespace trifem::analysis
