// SPDX-License-Identifier: MIT
// Test harness of the trifem executable: runs it in a fresh temporary directory and captures
// exit code, stdout and stderr (shared by the CLI test files).
#pragma once

#include "history_csv.hpp"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <map>
#include <ostream>
#include <regex>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace trifem::cli_test {

using test::History;
using test::read_history;

namespace fs = std::filesystem;

inline const fs::path kExe = TRIFEM_EXE;
inline const fs::path kData = TRIFEM_TEST_DATA_DIR;
inline const fs::path kExamples = fs::path(TRIFEM_SOURCE_DIR) / "examples";

/// Exit codes of trifem (mirrors analysis::ExitCode, documented in docs/cli.md).
enum ExitCode : int {
  kSuccess = 0,
  kUsage = 1,
  kInvalidInput = 2,
  kAnalysisFailed = 3,
};

/// What one run of the executable produced.
struct Result {
  std::string command; ///< the shell command that was run
  int exit_code = -1;  ///< exit status, or -1 if the process did not exit normally
  std::string out;     ///< everything written to stdout
  std::string err;     ///< everything written to stderr
};

/// Prints a run for failure messages.
inline std::ostream& operator<<(std::ostream& os, const Result& r) {
  return os << "\n$ " << r.command << "\nexit code " << r.exit_code << "\n--- stdout:\n"
            << r.out << "--- stderr:\n"
            << r.err << "---";
}

/// `text` as one word for /bin/sh (single-quoted, embedded quotes escaped).
inline std::string shell_quoted(std::string_view text) {
  std::string quoted = "'";
  for (const char c : text) {
    if (c == '\'')
      quoted += "'\\''";
    else
      quoted += c;
  }
  return quoted + "'";
}

/// The whole content of `file` ("" if it cannot be read).
inline std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// The non-empty lines of `text`.
inline std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (!line.empty())
      lines.push_back(line);
  return lines;
}

/// The lines of `text` that start with "error:".
inline std::vector<std::string> error_lines(const std::string& text) {
  std::vector<std::string> found = lines_of(text);
  std::erase_if(found, [](const std::string& line) { return !line.starts_with("error:"); });
  return found;
}

/// True if `text` contains `part`.
inline bool contains(std::string_view text, std::string_view part) {
  return text.find(part) != std::string_view::npos;
}

/// Number of occurrences of `part` in `text`.
inline std::size_t count_of(std::string_view text, std::string_view part) {
  std::size_t n = 0;
  for (auto at = text.find(part); at != std::string_view::npos; at = text.find(part, at + 1))
    ++n;
  return n;
}

/// The restart files of a run directory, in order.
inline std::vector<fs::path> restart_files(const fs::path& dir) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().starts_with("restart_"))
      files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

/// The unit of a history column ("top.uz [mm]" -> "mm"; "" if none).
inline std::string unit_of(const std::string& name) {
  const auto open = name.rfind('[');
  return open == std::string::npos ? "" : name.substr(open);
}

/// Largest magnitude of the columns of each unit.
inline std::map<std::string, double> unit_scales(const History& h) {
  std::map<std::string, double> scale;
  for (std::size_t c = 0; c < h.names.size(); ++c)
    for (const double v : h.columns[c])
      scale[unit_of(h.names[c])] = std::max(scale[unit_of(h.names[c])], std::abs(v));
  return scale;
}

/// `other` has the columns and rows of `expected` and the same values to `relative` of the
/// largest magnitude of each unit in `expected` (unit_scales); the columns `skipped` aside.
inline void expect_the_same_history(const History& expected, const History& other, double relative,
                                    std::initializer_list<std::string_view> skipped = {}) {
  ASSERT_EQ(other.names, expected.names);
  const std::map<std::string, double> scale = unit_scales(expected);
  for (std::size_t c = 0; c < expected.names.size(); ++c) {
    if (std::find(skipped.begin(), skipped.end(), expected.names[c]) != skipped.end())
      continue;
    const std::vector<double>& a = expected.columns[c];
    const std::vector<double>& b = other.columns[c];
    ASSERT_EQ(a.size(), b.size()) << expected.names[c] << ": the runs took other steps";
    double diff = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i)
      diff = std::max(diff, std::abs(a[i] - b[i]));
    EXPECT_LE(diff, relative * scale.at(unit_of(expected.names[c]))) << expected.names[c];
  }
}

/// Fixture: every test works in a fresh temporary directory, removed afterwards.
class Cli : public ::testing::Test {
protected:
  void SetUp() override {
    static std::atomic<int> counter{0};
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ =
        fs::temp_directory_path() / ("trifem_test_cli_" + std::string(info->name()) + "_" +
                                     std::to_string(::getpid()) + "_" + std::to_string(counter++));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }

  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

  /// Runs trifem with `args` in the working directory, capturing stdout, stderr and exit code.
  Result trifem(std::initializer_list<std::string> args) const {
    return run(shell_quoted(kExe.string()), args);
  }

  /// Runs `program` (a shell command prefix) with `args` in the working directory.
  Result run(const std::string& program, std::initializer_list<std::string> args) const {
    Result r;
    r.command = program;
    for (const auto& a : args) {
      r.command += ' ';
      r.command += shell_quoted(a);
    }
    const fs::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
    const std::string line = "cd " + shell_quoted(dir_.string()) + " && " + r.command + " >" +
                             shell_quoted(out.string()) + " 2>" + shell_quoted(err.string());
    const int status = std::system(line.c_str());
    r.exit_code = status != -1 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = read_text(out);
    r.err = read_text(err);
    fs::remove(out);
    fs::remove(err);
    return r;
  }

  /// Writes `bytes` to the file `name` of the working directory and returns its path.
  fs::path write_file(const std::string& name, std::string_view bytes) const {
    const fs::path file = dir_ / name;
    std::ofstream(file, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
    return file;
  }

  /// The output directory passed with -o.
  fs::path output() const { return dir_ / "out"; }

  /// Checks that `check` and `run` both reject `case_file` with exit code 2 and exactly one
  /// stderr line "error: ..." containing every one of `parts`, and that `run` wrote nothing.
  void expect_invalid_input(const fs::path& case_file,
                            std::initializer_list<std::string_view> parts) const {
    for (const std::string command : {"check", "run"}) {
      SCOPED_TRACE("trifem " + command);
      const Result r = command == "check"
                           ? trifem({command, case_file.string()})
                           : trifem({command, case_file.string(), "-o", output().string()});
      EXPECT_EQ(r.exit_code, kInvalidInput) << r;
      const std::vector<std::string> lines = lines_of(r.err);
      ASSERT_EQ(lines.size(), 1u) << "expected one stderr line" << r;
      EXPECT_TRUE(lines[0].starts_with("error: ")) << r;
      for (const std::string_view part : parts)
        EXPECT_TRUE(contains(lines[0], part)) << "'" << part << "' is not named" << r;
      EXPECT_TRUE(error_lines(r.out).empty()) << r;
      EXPECT_FALSE(fs::exists(output())) << "an invalid case must not create its output";
    }
  }

  fs::path dir_;
};

} // namespace trifem::cli_test
