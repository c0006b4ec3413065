// SPDX-License-Identifier: MIT
#include "mutator.hpp"

#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace trifem::fuzz {
namespace {

bool is_word_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '.';
}

bool is_number_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '.' || c == '+' ||
         c == '-';
}

/// True if a number literal starts at text[i] (a digit, a signed digit, inf or nan).
bool number_starts(const std::string& text, std::size_t i) {
  if (i > 0 && is_word_char(text[i - 1]))
    return false;
  std::size_t j = i;
  if (text[j] == '+' || text[j] == '-')
    ++j;
  if (j >= text.size())
    return false;
  if (std::isdigit(static_cast<unsigned char>(text[j])) != 0)
    return true;
  const std::string_view rest = std::string_view(text).substr(j, 3);
  return rest == "inf" || rest == "nan";
}

/// End of the string literal that starts at text[i] (a quote), or npos if it is not closed on
/// its line.
std::size_t string_end(const std::string& text, std::size_t i) {
  const char quote = text[i];
  for (std::size_t j = i + 1; j < text.size() && text[j] != '\n'; ++j) {
    if (quote == '"' && text[j] == '\\') {
      ++j;
      continue;
    }
    if (text[j] == quote)
      return j + 1;
  }
  return std::string::npos;
}

/// Scanner state: the bracket depth of multi-line arrays, carried from line to line.
struct LineScan {
  const std::string& text;
  TomlSpans& spans;
  int depth = 0;

  /// Scans the value part [i, end) of a line; returns the end of the value's last token.
  std::size_t value(std::size_t i, std::size_t end) {
    std::size_t last = i;
    while (i < end && text[i] != '#') {
      const char c = text[i];
      if (c == '"' || c == '\'') {
        const std::size_t close = string_end(text, i);
        const std::size_t stop = close == std::string::npos ? end : close;
        spans.strings.push_back({i, stop});
        i = last = stop;
        continue;
      }
      if (number_starts(text, i)) {
        std::size_t j = i + 1;
        while (j < end && is_number_char(text[j]))
          ++j;
        spans.numbers.push_back({i, j});
        i = last = j;
        continue;
      }
      depth += c == '[' || c == '{' ? 1 : c == ']' || c == '}' ? -1 : 0;
      if (c != ' ' && c != '\t' && c != '\r')
        last = i + 1;
      ++i;
    }
    return last;
  }

  void line(std::size_t begin, std::size_t end) {
    std::size_t i = begin;
    while (i < end && (text[i] == ' ' || text[i] == '\t'))
      ++i;
    if (i >= end || text[i] == '#')
      return;
    if (depth > 0) { // continuation of a multi-line array
      value(i, end);
      return;
    }
    if (text[i] == '[')
      return; // a table header
    const std::size_t eq = text.find('=', i);
    if (eq == std::string::npos || eq >= end)
      return;
    std::size_t k = i;
    while (k < eq && (std::isalnum(static_cast<unsigned char>(text[k])) != 0 || text[k] == '_'))
      ++k;
    if (k > i)
      spans.keys.push_back({i, k});
    std::size_t v = eq + 1;
    while (v < end && (text[v] == ' ' || text[v] == '\t'))
      ++v;
    const std::size_t stop = value(v, end);
    if (depth == 0 && stop > v)
      spans.values.push_back({v, stop});
  }
};

std::string replace(const std::string& text, Span s, const std::string& by) {
  return text.substr(0, s.begin) + by + text.substr(s.end);
}

std::string slice(const std::string& text, Span s) {
  return text.substr(s.begin, s.end - s.begin);
}

/// The line spans of `text` (without newlines).
std::vector<Span> lines_of(const std::string& text) {
  std::vector<Span> lines;
  std::size_t begin = 0;
  while (begin < text.size()) {
    std::size_t end = text.find('\n', begin);
    end = end == std::string::npos ? text.size() : end;
    lines.push_back({begin, end});
    begin = end + 1;
  }
  return lines;
}

/// The whitespace-separated fields of `text` that read as numbers (Gmsh files).
std::vector<Span> msh_numbers(const std::string& text) {
  std::vector<Span> numbers;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i])) != 0)
      ++i;
    std::size_t j = i;
    while (j < text.size() && std::isspace(static_cast<unsigned char>(text[j])) == 0)
      ++j;
    const std::string field = text.substr(i, j - i);
    char* end = nullptr;
    if (!field.empty()) {
      std::strtod(field.c_str(), &end);
      if (end == field.c_str() + field.size())
        numbers.push_back({i, j});
    }
    i = j;
  }
  return numbers;
}

std::string format_real(double v) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  std::string s = buffer;
  if (s.find_first_of(".eEn") == std::string::npos) // keep it a float literal
    s += ".0";
  return s;
}

} // namespace

TomlSpans scan_toml(const std::string& text) {
  TomlSpans spans;
  spans.lines = lines_of(text);
  LineScan scan{text, spans};
  for (const Span& line : spans.lines)
    scan.line(line.begin, line.end);
  return spans;
}

std::size_t Mutator::below(std::size_t n) {
  return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng_);
}

std::string Mutator::new_number(const std::string& old, bool msh) {
  std::string clean = old;
  std::erase(clean, '_');
  const double v = std::strtod(clean.c_str(), nullptr);
  static const std::array<const char*, 20> fixed = {"0",
                                                    "0.0",
                                                    "-0.0",
                                                    "nan",
                                                    "inf",
                                                    "-inf",
                                                    "+nan",
                                                    "1e-320",
                                                    "1e308",
                                                    "4.9e-324",
                                                    "2147483647",
                                                    "2147483648",
                                                    "-2147483649",
                                                    "9223372036854775807",
                                                    "-9223372036854775808",
                                                    "99999999999999999999",
                                                    "1e999",
                                                    "3000000000",
                                                    "1_000_000_000",
                                                    "0x7FFFFFFF"};
  switch (below(8)) {
  case 0:
    return old.starts_with('-') ? old.substr(1) : "-" + old;
  case 1:
    return format_real(v * 1e300);
  case 2:
    return format_real(v * 1e-300);
  case 3:
    return msh ? std::to_string(static_cast<long long>(v) + (below(2) == 0 ? 1 : -1))
               : format_real(v * 10.0);
  case 4:
    return old.find_first_of(".eE") == std::string::npos ? old + ".0"
                                                         : std::to_string(std::llround(v));
  default:
    return fixed[below(fixed.size())];
  }
}

std::string Mutator::new_string(const std::string& text, const TomlSpans& spans) {
  switch (below(7)) {
  case 0:
    return slice(text, spans.strings[below(spans.strings.size())]);
  case 1:
    return "\"\"";
  case 2:
    return "\"x\"";
  case 3:
    return "\"" + std::string(5000, 'a') + "\"";
  case 4:
    return "\"../../\"";
  case 5:
    return "\"\\u00e9\\u0000\"";
  default: {
    std::string quoted(1, '"');
    quoted += garbage();
    quoted += '"';
    return quoted;
  }
  }
}

std::string Mutator::new_value() {
  static const std::array<const char*, 14> values = {
      "\"text\"",     "1.5",           "-3",         "[1.0, 2.0]", "[]",        "true",
      "{}",           "[[1, 2], [3]]", "1979-05-27", "[\"x\", 1]", "{ a = 1 }", "\"1.0\"",
      "[[0.0, 0.0]]", "[1, 2, 3, 4]"};
  return values[below(values.size())];
}

std::string Mutator::garbage() {
  std::string bytes;
  const std::size_t n = 1 + below(8);
  for (std::size_t k = 0; k < n; ++k)
    bytes += static_cast<char>(below(256));
  return bytes;
}

/// One mutation of a case: keys, strings, values and numbers, else a line or byte operation.
void Mutator::case_step(Mutant& m) {
  const TomlSpans spans = scan_toml(m.text);
  const std::size_t kind = below(10);
  if (kind == 0 && !spans.keys.empty()) {
    const Span key = spans.keys[below(spans.keys.size())];
    const std::string other = slice(m.text, spans.keys[below(spans.keys.size())]);
    const std::string by = below(3) == 0 ? slice(m.text, key).substr(1) : other;
    m.description += "key '" + slice(m.text, key) + "' -> '" + by + "'; ";
    m.text = replace(m.text, key, by);
  } else if (kind == 1 && !spans.strings.empty()) {
    const Span s = spans.strings[below(spans.strings.size())];
    const std::string by = new_string(m.text, spans);
    m.description += "string " + slice(m.text, s) + " -> " + by.substr(0, 40) + "; ";
    m.text = replace(m.text, s, by);
  } else if (kind == 2 && !spans.values.empty()) {
    const Span v = spans.values[below(spans.values.size())];
    const std::string by = new_value();
    m.description += "value '" + slice(m.text, v) + "' -> " + by + "; ";
    m.text = replace(m.text, v, by);
  } else if ((kind == 3 || kind == 4 || kind == 5) && !spans.numbers.empty()) {
    const Span n = spans.numbers[below(spans.numbers.size())];
    const std::string by = new_number(slice(m.text, n), false);
    m.description += "number " + slice(m.text, n) + " -> " + by + "; ";
    m.text = replace(m.text, n, by);
  } else {
    msh_step(m); // the operations on lines and bytes
  }
}

/// One mutation on lines, bytes or number fields (Gmsh files; also the fallback of cases).
void Mutator::msh_step(Mutant& m) {
  const std::vector<Span> lines = lines_of(m.text);
  const std::vector<Span> numbers = msh_numbers(m.text);
  const std::size_t kind = below(6);
  if (lines.empty())
    return;
  const std::size_t line_no = below(lines.size()) + 1;
  const Span line = lines[line_no - 1];
  if (kind == 0) {
    m.description += "delete line " + std::to_string(line_no) + "; ";
    m.text = replace(m.text, {line.begin, std::min(line.end + 1, m.text.size())}, "");
  } else if (kind == 1) {
    m.description += "duplicate line " + std::to_string(line_no) + "; ";
    m.text.insert(line.begin, slice(m.text, line) + "\n");
  } else if (kind == 2) {
    const std::size_t at = below(m.text.size() + 1);
    m.description += "truncate at byte " + std::to_string(at) + "; ";
    m.text.resize(at);
  } else if (kind == 3) {
    const std::size_t at = below(m.text.size() + 1);
    m.description += "garbage at byte " + std::to_string(at) + "; ";
    m.text.insert(at, garbage());
  } else if (kind == 4 && line_no < lines.size()) {
    const Span next = lines[line_no];
    m.description +=
        "swap lines " + std::to_string(line_no) + ", " + std::to_string(line_no + 1) + "; ";
    m.text = m.text.substr(0, line.begin) + slice(m.text, next) + "\n" + slice(m.text, line) +
             m.text.substr(next.end);
  } else if (!numbers.empty()) {
    const Span n = numbers[below(numbers.size())];
    const std::string by = new_number(slice(m.text, n), true);
    m.description += "number " + slice(m.text, n) + " -> " + by + "; ";
    m.text = replace(m.text, n, by);
  }
}

Mutant Mutator::mutate_case(const std::string& text) {
  Mutant m{text, ""};
  const std::size_t steps = below(5) == 0 ? 2 : 1;
  for (std::size_t k = 0; k < steps; ++k)
    case_step(m);
  return m;
}

Mutant Mutator::mutate_msh(const std::string& text) {
  Mutant m{text, ""};
  const std::size_t steps = below(5) == 0 ? 2 : 1;
  for (std::size_t k = 0; k < steps; ++k)
    msh_step(m);
  return m;
}

} // namespace trifem::fuzz
