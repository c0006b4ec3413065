// SPDX-License-Identifier: MIT
#include "trifem/analysis/case_file.hpp"

#include "trifem/feb/feb_reader.hpp"
#include "trifem/io/case_reader.hpp"

namespace trifem::analysis {

io::CaseSpec read_case_file(const std::filesystem::path& file) {
  return feb::is_feb_file(file) ? feb::read_feb(file) : io::read_case(file);
}

} // namespace trifem::analysis
