// SPDX-License-Identifier: MIT
#include "trifem/analysis/case_file.hpp"

#include "trifem/core/error.hpp"
#include "trifem/feb/feb_reader.hpp"
#include "trifem/io/case_reader.hpp"
#include "trifem/io/case_writer.hpp"

namespace trifem::analysis {

io::CaseSpec read_case_file(const std::filesystem::path& file) {
  return feb::is_feb_file(file) ? feb::read_feb(file) : io::read_case(file);
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
