// SPDX-License-Identifier: MIT
// Deterministic mutations of case files (TOML) and Gmsh meshes for the fuzz tests: delete,
// duplicate or swap lines, change numbers (sign, x1e±300, 0, nan/inf, huge integers), swap keys,
// truncate, change strings, change types, insert garbage bytes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace trifem::fuzz {

/// A byte range [begin, end) of a text.
struct Span {
  std::size_t begin = 0;
  std::size_t end = 0;
};

/// The parts of a TOML text that mutations act on (found by a light scan, not a full parser).
struct TomlSpans {
  std::vector<Span> lines;   ///< every line, without its newline
  std::vector<Span> keys;    ///< bare keys before '=' at the start of a line
  std::vector<Span> values;  ///< values that end on their own line (after '=')
  std::vector<Span> numbers; ///< number literals (also inf and nan) in values
  std::vector<Span> strings; ///< basic and literal strings in values, quotes included
};

/// Scans `text` for the spans above.
TomlSpans scan_toml(const std::string& text);

/// A mutated text and what was done to it (for failure reports).
struct Mutant {
  std::string text;
  std::string description;
};

/// Applies one or two random mutations to texts; deterministic for a given seed.
class Mutator {
public:
  explicit Mutator(std::uint64_t seed) : rng_(seed) {}

  /// A mutant of the TOML case `text`.
  Mutant mutate_case(const std::string& text);
  /// A mutant of the ASCII Gmsh file `text`.
  Mutant mutate_msh(const std::string& text);

  /// A uniformly drawn index below n (n > 0).
  std::size_t below(std::size_t n);

private:
  void case_step(Mutant& m);
  void msh_step(Mutant& m);
  std::string new_number(const std::string& old, bool msh);
  std::string new_string(const std::string& text, const TomlSpans& spans);
  std::string new_value();
  std::string garbage();

  std::mt19937_64 rng_;
};

} // namespace trifem::fuzz
