// SPDX-License-Identifier: MIT
// Line and field reading for the Gmsh reader (internal to the mesh library): a text file read
// line by line, split into blank-separated fields, with "<file>:<line>" locations for errors.
#pragma once

#include "trifem/core/error.hpp"

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

namespace trifem::mesh::detail {

/// Reads a text file line by line and splits each line into blank-separated fields.
class LineReader {
public:
  explicit LineReader(const std::filesystem::path& file) : in_(file), file_(file.string()) {
    TRIFEM_CHECK(in_.is_open(), "{}: cannot open the mesh file", location());
  }

  /// Advances to the next non-blank line; false at the end of the file.
  bool next_line() {
    while (std::getline(in_, line_)) {
      ++line_no_;
      if (!line_.empty() && line_.back() == '\r')
        line_.pop_back();
      pos_ = 0;
      if (!at_line_end())
        return true;
    }
    line_.clear();
    pos_ = 0;
    return false;
  }

  /// Advances to the next non-blank line; InputError at the end of the file.
  void require_line() {
    TRIFEM_CHECK(next_line(), "{}: unexpected end of file: section ${} is truncated (no $End{})",
                 location(), section_, section_);
  }

  /// True if the current line has no fields left.
  bool at_line_end() {
    while (pos_ < line_.size() && is_blank(line_[pos_]))
      ++pos_;
    return pos_ >= line_.size();
  }

  /// Next field of the current line; empty at the end of the line.
  std::string_view field() {
    at_line_end();
    const std::size_t begin = pos_;
    while (pos_ < line_.size() && !is_blank(line_[pos_]))
      ++pos_;
    return std::string_view(line_).substr(begin, pos_ - begin);
  }

  /// The unread rest of the current line without surrounding blanks; consumes it.
  std::string_view rest() {
    at_line_end();
    std::size_t end = line_.size();
    while (end > pos_ && is_blank(line_[end - 1]))
      --end;
    const std::string_view text = std::string_view(line_).substr(pos_, end - pos_);
    pos_ = line_.size();
    return text;
  }

  /// Parses the next field of the current line as a number; `what` names it in errors.
  template <class T>
  T number(std::string_view what) {
    std::string_view text = field();
    if (text.starts_with('+')) // from_chars rejects an explicit plus sign
      text.remove_prefix(1);
    T value{};
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (text.empty() || ec != std::errc() || ptr != end) [[unlikely]]
      bad_field(what, text);
    return value;
  }

  /// Like number(), but continues on the next line when the current one is used up.
  template <class T>
  T number_any_line(std::string_view what) {
    if (at_line_end())
      require_line();
    return number<T>(what);
  }

  /// "<file>:<line>" of the current line.
  std::string location() const { return at(line_no_); }
  const std::string& file() const { return file_; }
  /// "<file>:<line>" of any line.
  std::string at(long line) const { return fmt::format("{}:{}", file_, std::max(line, 1L)); }
  long line() const { return line_no_; }
  const std::string& section() const { return section_; }
  void set_section(std::string_view name) { section_ = name; }

private:
  static bool is_blank(char c) { return c == ' ' || c == '\t'; }

  [[noreturn]] void bad_field(std::string_view what, std::string_view text) const {
    TRIFEM_CHECK(!text.empty(), "{}: expected {}, found the end of the line", location(), what);
    TRIFEM_CHECK(!text.starts_with('$'), "{}: expected {}, found '{}': section ${} is truncated",
                 location(), what, text, section_);
    throw InputError(fmt::format("{}: expected {}, found '{}'", location(), what, text));
  }

  std::ifstream in_;
  std::string file_;
  std::string line_;
  std::size_t pos_ = 0;
  long line_no_ = 0;
  std::string section_ = "MeshFormat";
};

} // namespace trifem::mesh::detail
