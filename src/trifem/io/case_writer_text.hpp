// SPDX-License-Identifier: MIT
// TOML text of the case writer: keys, strings and numbers that read back exactly (internal to
// io::case_toml).
#pragma once

#include "trifem/core/types.hpp"
#include "trifem/tensor/tensor.hpp"

#include <fmt/format.h>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace trifem::io {
struct CaseSpec;
} // namespace trifem::io

namespace trifem::io::detail {

/// A TOML document written line by line: table headers and `key = value` lines.
class TomlText {
public:
  /// A key: bare if it is one ([A-Za-z0-9_-]+), else a quoted string.
  static std::string key(std::string_view k);
  /// A basic string with quotes, backslashes and control characters escaped.
  static std::string quoted(std::string_view s);
  /// A float in the shortest form that reads back bitwise (always with '.', 'e', inf or nan).
  static std::string number(Real v);

  /// A table header line, e.g. "[[mesh.gmsh]]" (its keys already formatted), after a blank line.
  void header(std::string_view h) { text_ += fmt::format("\n{}\n", h); }
  /// A comment line.
  void comment(std::string_view c) { text_ += fmt::format("# {}\n", c); }
  /// `key = <value as given>`.
  void raw(std::string_view k, std::string_view value) {
    text_ += fmt::format("{} = {}\n", key(k), value);
  }
  void string(std::string_view k, std::string_view s) { raw(k, quoted(s)); }
  /// `key = "s"` unless s is empty.
  void optional_string(std::string_view k, std::string_view s) {
    if (!s.empty())
      string(k, s);
  }
  void number(std::string_view k, Real v) { raw(k, number(v)); }
  void vector(std::string_view k, const Vec3& v) {
    raw(k, fmt::format("[{}, {}, {}]", number(v[0]), number(v[1]), number(v[2])));
  }
  /// `key = { k1 = v1, ... }` with keys and values already formatted.
  void inline_table(std::string_view k, const std::vector<std::pair<std::string, std::string>>& e);

  const std::string& text() const { return text_; }

private:
  std::string text_;
};

/// The [materials.<name>] tables of `spec` (internal to case_toml).
void write_materials(const CaseSpec& spec, TomlText& t);

} // namespace trifem::io::detail
