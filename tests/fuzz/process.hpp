// SPDX-License-Identifier: MIT
// Runs a program with a time limit, capturing its exit status, stdout and stderr (fuzz tests).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace trifem::fuzz {

/// How one process run ended.
struct ProcessResult {
  bool timed_out = false; ///< killed (SIGKILL) after the time limit
  int exit_code = -1;     ///< exit status if the process exited normally, else -1
  int signal = 0;         ///< the signal that ended the process (0: it exited)
  double seconds = 0.0;   ///< wall time
  std::string out;        ///< everything written to stdout
  std::string err;        ///< everything written to stderr
};

/// Runs `argv` (argv[0] is the program path) with stdout and stderr sent to files of `scratch`
/// (a directory), waiting at most `timeout_s` seconds before killing it.
ProcessResult run_process(const std::vector<std::string>& argv,
                          const std::filesystem::path& scratch, double timeout_s);

/// The whole content of `file` ("" if it cannot be read).
std::string read_file(const std::filesystem::path& file);

/// Writes `bytes` to `file`, replacing it.
void write_file(const std::filesystem::path& file, const std::string& bytes);

} // namespace trifem::fuzz
