// SPDX-License-Identifier: MIT
// Case reader, part 1: file and text checks, TOML syntax errors, the "<file>: " message prefix.
// The sections themselves are read in case_reader_sections.cpp and case_reader_physics.cpp.
#include "trifem/io/case_reader.hpp"

#include "trifem/core/error.hpp"
#include "trifem/core/log.hpp"
#include "trifem/io/toml_table.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <fmt/format.h>
#include <memory>
#include <string>
#include <system_error>
#include <toml++/toml.h>

namespace trifem::io {
namespace {

/// How much of the text is inspected for binary data.
constexpr std::size_t kSniffBytes = 4096;
/// Largest case file read: a case is text written by hand or by a converter.
constexpr std::size_t kMaxCaseBytes = std::size_t{64} << 20;
/// Most levels of a dotted key.
constexpr std::size_t kMaxKeyDepth = 64;
/// Longest source line quoted under a syntax error.
constexpr std::size_t kMaxQuotedLine = 160;

std::string display_name(const std::filesystem::path& file) {
  return file.empty() ? std::string("<case>") : file.string();
}

[[noreturn]] void fail(const std::string& file, std::string_view message) {
  throw InputError(fmt::format("{}: {}", file, message));
}

/// Length of the UTF-8 sequence introduced by `lead` (0: not a valid lead byte).
std::size_t sequence_length(unsigned char lead) {
  if (lead < 0x80)
    return 1;
  if ((lead & 0xE0) == 0xC0)
    return 2;
  if ((lead & 0xF0) == 0xE0)
    return 3;
  if ((lead & 0xF8) == 0xF0)
    return 4;
  return 0;
}

/// True if `seq` (2 to 4 bytes) is a well-formed, shortest-form UTF-8 scalar value.
bool valid_sequence(std::string_view seq) {
  static constexpr char32_t kMinimum[5] = {0, 0, 0x80, 0x800, 0x10000};
  char32_t cp = static_cast<unsigned char>(seq[0]) & (0x7F >> seq.size());
  for (std::size_t k = 1; k < seq.size(); ++k) {
    const auto c = static_cast<unsigned char>(seq[k]);
    if ((c & 0xC0) != 0x80)
      return false;
    cp = (cp << 6) | (c & 0x3F);
  }
  const bool surrogate = cp >= 0xD800 && cp <= 0xDFFF;
  return cp >= kMinimum[seq.size()] && cp <= 0x10FFFF && !surrogate;
}

/// Offset of the first NUL byte or malformed UTF-8 sequence starting in the first kSniffBytes of
/// `text`, or npos if there is none.
std::size_t find_binary(std::string_view text) {
  const std::size_t n = std::min(text.size(), kSniffBytes);
  for (std::size_t i = 0; i < n;) {
    const auto lead = static_cast<unsigned char>(text[i]);
    const std::size_t len = sequence_length(lead);
    if (lead == 0 || len == 0 || i + len > text.size())
      return i;
    if (len > 1 && !valid_sequence(text.substr(i, len)))
      return i;
    i += len;
  }
  return std::string_view::npos;
}

void check_not_binary(std::string_view text, const std::string& name) {
  if (const std::size_t at = find_binary(text); at != std::string_view::npos)
    fail(name, fmt::format("not a text file (binary data found at byte {}); expected a TOML case "
                           "file",
                           at));
}

void check_text(std::string_view text, const std::string& name) {
  if (text.find_first_not_of(" \t\r\n") == std::string_view::npos)
    fail(name, "the case file is empty");
  check_not_binary(text, name);
}

/// The source line `line` (1-based) with a caret under `column` (1-based, in code points), or ""
/// if the line does not exist or is too long to quote.
std::string quote_line(std::string_view text, std::size_t line, std::size_t column) {
  std::size_t start = 0;
  for (std::size_t l = 1; l < line && start != std::string_view::npos; ++l) {
    start = text.find('\n', start);
    start = start == std::string_view::npos ? start : start + 1;
  }
  if (line == 0 || start == std::string_view::npos)
    return {};
  std::string_view row = text.substr(start, text.find('\n', start) - start);
  if (!row.empty() && row.back() == '\r')
    row.remove_suffix(1);
  if (row.size() > kMaxQuotedLine)
    return {};
  std::string pad;
  std::size_t col = 1;
  for (std::size_t i = 0; i < row.size() && col < column; ++i) {
    if ((static_cast<unsigned char>(row[i]) & 0xC0) == 0x80)
      continue; // continuation byte: same code point
    pad += row[i] == '\t' ? '\t' : ' ';
    ++col;
  }
  return fmt::format("\n{:>6} | {}\n{:>6} | {}^", line, row, "", pad);
}

/// The most dots in one chain of key segments (bare words or quoted strings joined by dots,
/// blanks allowed around them) on `line`: a dotted key's depth minus one. Numbers count as
/// segments too, but a value holds no chain longer than a float's one dot.
std::size_t key_dots(std::string_view line) {
  std::size_t most = 0, chain = 0;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (c == '"' || c == '\'') { // a quoted segment: skip to its closing quote
      for (++i; i < line.size() && line[i] != c; ++i)
        i += c == '"' && line[i] == '\\' ? 1 : 0;
    } else if (c == '.') {
      most = std::max(most, ++chain);
    } else if (c == '#') {
      break;
    } else if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '+' ||
                 c == ' ' || c == '\t')) {
      chain = 0; // '=', ',', brackets, braces: the chain ends
    }
  }
  return most;
}

/// Refuses keys nested deeper than kMaxKeyDepth levels (a.b.c... = 1 or [a.b.c...]) before the
/// parser builds them: the TOML library recurses through nested tables (a stack overflow at
/// tens of thousands of levels), and no case nests deeper than a few.
void check_key_depth(std::string_view text, const std::string& name) {
  std::size_t line = 1;
  for (std::size_t start = 0; start < text.size(); ++line) {
    std::size_t end = text.find('\n', start);
    end = end == std::string_view::npos ? text.size() : end;
    if (key_dots(text.substr(start, end - start)) >= kMaxKeyDepth)
      fail(name, fmt::format("line {}: a dotted key nested more than {} levels deep (a case file "
                             "nests at most a few)",
                             line, kMaxKeyDepth));
    start = end + 1;
  }
}

toml::table parse_toml(std::string_view text, const std::string& name) {
  check_key_depth(text, name);
  try {
    return toml::parse(text, name);
  } catch (const toml::parse_error& e) {
    const auto& where = e.source().begin;
    fail(name, fmt::format("line {}, column {}: TOML syntax error: {}{}", where.line, where.column,
                           e.description(), quote_line(text, where.line, where.column)));
  }
}

/// Closes a C stream.
struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};

std::string read_text(const std::filesystem::path& file) {
  const std::string name = display_name(file);
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec))
    fail(name, "cannot open the case file (it is a directory)");
  errno = 0;
  const std::unique_ptr<std::FILE, FileCloser> stream(std::fopen(file.c_str(), "rb"));
  if (!stream) {
    const int err = errno != 0 ? errno : ENOENT;
    fail(name, fmt::format("cannot open the case file ({})",
                           std::error_code(err, std::generic_category()).message()));
  }
  std::string text;
  char buffer[1 << 14];
  std::size_t got = 0;
  while ((got = std::fread(buffer, 1, sizeof buffer, stream.get())) > 0) {
    text.append(buffer, got);
    if (text.size() == got) // the first block: a device or binary file is refused at once
      check_not_binary(text, name);
    if (text.size() > kMaxCaseBytes)
      fail(name, fmt::format("the case file is larger than {} MB; a case file describes the "
                             "model (its meshes belong in Gmsh files, [[mesh.gmsh]])",
                             kMaxCaseBytes >> 20));
  }
  if (std::ferror(stream.get()))
    fail(name, "cannot read the case file (read error)");
  return text;
}

} // namespace

CaseSpec read_case(const std::filesystem::path& file) {
  return parse_case(read_text(file), file);
}

CaseSpec parse_case(std::string_view text, const std::filesystem::path& file) {
  const std::string name = display_name(file);
  check_text(text, name);
  const toml::table root = parse_toml(text, name);
  if (root.empty())
    fail(name, "the case file is empty (it contains only comments)");
  CaseSpec spec;
  spec.file = file;
  try {
    detail::read_sections(root, spec);
  } catch (const InputError& e) {
    fail(name, e.what());
  }
  for (const std::string& warning : spec.warnings)
    log::warn("warning: {}: {}", name, warning);
  return spec;
}

void check_limits(const CaseSpec& spec) {
  try {
    detail::check_time_limits(nullptr, spec);
    detail::check_model_size(nullptr, spec);
  } catch (const InputError& e) {
    fail(display_name(spec.file), e.what());
  }
}

} // namespace trifem::io
