// SPDX-License-Identifier: MIT
// Shared helpers of the case-reader tests: editing a case text, reading the InputError of a bad
// one, and the parameterised check that the message names the file and the key.
#pragma once

#include "trifem/core/error.hpp"
#include "trifem/io/case_reader.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace trifem::test {

/// The file name the in-memory cases are read as.
inline const std::filesystem::path kMemoryFile = "memory/case.toml";

/// `text` with the first occurrence of `from` replaced by `to` (which must exist).
inline std::string replaced_in(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "'" << from << "' is not in the case";
  if (at != std::string::npos)
    text.replace(at, from.size(), to);
  return text;
}

/// The message of the InputError that reading `text` throws ("" if none).
inline std::string error_of(const std::string& text,
                            const std::filesystem::path& file = kMemoryFile) {
  try {
    io::parse_case(text, file);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

/// A bad case text and the fragments its error message must contain.
struct BadCase {
  std::string name;
  std::string text;
  std::vector<std::string> fragments;
};

inline void PrintTo(const BadCase& c, std::ostream* os) {
  *os << c.name;
}

/// Reading `c.text` fails with a message that starts with the file name and holds every fragment.
inline void expect_fails_naming(const BadCase& c) {
  const std::string m = error_of(c.text);
  ASSERT_FALSE(m.empty()) << "no InputError for " << c.name;
  EXPECT_EQ(m.rfind(kMemoryFile.string() + ": ", 0), 0u) << m;
  for (const auto& fragment : c.fragments)
    EXPECT_NE(m.find(fragment), std::string::npos) << "'" << fragment << "' not in: " << m;
}

/// The test name of a parameter: its `name`.
inline std::string bad_case_name(const testing::TestParamInfo<BadCase>& info) {
  return info.param.name;
}

} // namespace trifem::test
