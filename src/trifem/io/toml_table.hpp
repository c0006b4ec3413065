// SPDX-License-Identifier: MIT
// Internal to the case reader: typed, path-aware access to TOML values and the message helpers
// and checks shared by the section readers. Every message names the key path and the line.
#pragma once

#include "trifem/io/case_spec.hpp"
#include "trifem/material/material_axes.hpp"
#include "trifem/material/schema.hpp"

#include <algorithm>
#include <array>
#include <climits>
#include <fmt/format.h>
#include <optional>
#include <string>
#include <string_view>
#include <toml++/toml.h>
#include <utility>
#include <vector>

namespace trifem::io::detail {

using material::Range;
using Point = std::pair<Real, Real>;

inline constexpr Real kUnbounded = 1e300; ///< Range's convention for "no bound"

// ---------------------------------------------------------------------------------------------
// Messages

/// True if `s` is non-empty and uses only letters, digits, '_' (and '-' if `allow_dash`).
bool is_name(std::string_view s, bool allow_dash);

/// `parent.key`, quoting keys that are not bare TOML keys.
std::string join_path(std::string_view parent, std::string_view key);

/// `path[i + 1]`: messages count array elements from 1, like the rest of trifem.
std::string element_path(std::string_view path, std::size_t i);

/// "a string", "an integer", ... for messages.
std::string type_name(const toml::node& n);

/// Throws "<path>: <message> (line N)"; `where` may be null (no line).
[[noreturn]] void fail(const toml::node* where, std::string_view path, std::string_view message);

/// Throws "<path>: expected <what>, got <type of n> (line N)".
[[noreturn]] void wrong_type(const toml::node& n, std::string_view path, std::string_view what);

/// Case-insensitive Levenshtein distance.
std::size_t edit_distance(std::string_view a, std::string_view b);

/// "; did you mean 'x'?" for the closest candidate if it is close enough, else "".
template <class Names>
std::string did_you_mean(std::string_view word, const Names& candidates) {
  std::string_view best;
  std::size_t best_distance = std::max<std::size_t>(2, word.size() / 3) + 1;
  for (const auto& c : candidates) {
    const std::size_t d = edit_distance(word, c);
    if (d < best_distance && d < word.size()) {
      best = c;
      best_distance = d;
    }
  }
  return best.empty() ? std::string() : fmt::format("; did you mean '{}'?", best);
}

/// The names separated by ", ".
template <class Names>
std::string join(const Names& names) {
  std::string out;
  for (const auto& n : names)
    out += (out.empty() ? "" : ", ") + std::string(n);
  return out;
}

/// "(0, inf) MPa": the interval and its unit, if any.
std::string range_text(const Range& range, std::string_view unit);

// ---------------------------------------------------------------------------------------------
// Conversions of one TOML value (the Tag selects the C++ type)

template <class T>
struct Tag {};

std::string_view expected(Tag<Real>);
std::string_view expected(Tag<int>);
std::string_view expected(Tag<bool>);
std::string_view expected(Tag<std::string>);
std::string_view expected(Tag<Vec3>);
std::string_view expected(Tag<std::array<int, 3>>);
std::string_view expected(Tag<Point>);
std::string_view expected(Tag<std::vector<Real>>);
std::string_view expected(Tag<std::vector<Point>>);
std::string_view expected(Tag<std::vector<std::string>>);

Real convert(const toml::node& n, std::string_view path, Tag<Real>);
int convert(const toml::node& n, std::string_view path, Tag<int>);
bool convert(const toml::node& n, std::string_view path, Tag<bool>);
std::string convert(const toml::node& n, std::string_view path, Tag<std::string>);
Vec3 convert(const toml::node& n, std::string_view path, Tag<Vec3>);
std::array<int, 3> convert(const toml::node& n, std::string_view path, Tag<std::array<int, 3>>);
Point convert(const toml::node& n, std::string_view path, Tag<Point>);

/// The array `n` (of exactly `size` elements unless size is 0).
const toml::array& array_of(const toml::node& n, std::string_view path, std::string_view what,
                            std::size_t size = 0);

template <class T>
std::vector<T> convert(const toml::node& n, std::string_view path, Tag<std::vector<T>>) {
  const toml::array& a = array_of(n, path, expected(Tag<std::vector<T>>{}));
  std::vector<T> out;
  for (std::size_t i = 0; i < a.size(); ++i)
    out.push_back(convert(a[i], element_path(path, i), Tag<T>{}));
  return out;
}

// ---------------------------------------------------------------------------------------------
// Tables

/// How a number is checked: valid range, default (absent: required), unit and a hint; values
/// outside `plausible` (if set) are kept with a warning (a unit mistake, most likely).
struct NumberRule {
  Range range{};
  std::optional<Real> fallback{};
  std::string_view unit{};
  std::string_view hint{};
  const material::Plausibility* plausible = nullptr;
};

/// Warnings gathered while a case is read (implausible values); each names the key and line.
using Warnings = std::vector<std::string>;

/// Throws "<path> = <v>: out of range ..." unless `v` is in `rule.range`.
void check_range(const toml::node* n, std::string_view path, Real v, const NumberRule& rule);

/// Named choices of a string key, in the order they are listed in messages.
template <class E>
using Options = std::vector<std::pair<std::string_view, E>>;

/// A TOML table being read: the table, its key path for messages and typed accessors.
class Table {
public:
  /// `warnings` (may be null) receives the warnings of this table and of its sub-tables.
  Table(const toml::table& table, std::string path, Warnings* warnings = nullptr)
      : table_(&table), path_(std::move(path)), warnings_(warnings) {}

  const std::string& path() const { return path_; }
  std::string path(std::string_view key) const { return join_path(path_, key); }
  const toml::table& raw() const { return *table_; }
  const toml::node* find(std::string_view key) const { return table_->get(key); }
  /// The table's node for line numbers (none for the document root).
  const toml::node* where() const { return path_.empty() ? nullptr : table_; }

  /// Of the keys for which `pred(key)` holds, the one that comes first in the file, and its
  /// node; {"", nullptr} if there is none.
  template <class Pred>
  std::pair<std::string_view, const toml::node*> first_key(Pred pred) const {
    std::pair<std::string_view, const toml::node*> first{"", nullptr};
    for (const auto& [key, node] : *table_)
      if (pred(key.str()) && (!first.second || node.source().begin < first.second->source().begin))
        first = {key.str(), &node};
    return first;
  }

  /// Throws on the key that is not in `allowed` and comes first in the file, if any.
  void allow(const std::vector<std::string_view>& allowed) const;
  /// As allow(allowed + also); the message lists `also` separately ("expected one of: <allowed>)
  /// or '<also>'"), for keys that are not part of the table's own schema (e.g. a
  /// material-level key next to a law's parameters).
  void allow(const std::vector<std::string_view>& allowed,
             const std::vector<std::string_view>& also) const;

  [[noreturn]] void missing(std::string_view key, std::string_view what) const;

  template <class T>
  std::optional<T> get(std::string_view key) const {
    const toml::node* n = find(key);
    return n ? std::optional<T>(convert(*n, path(key), Tag<T>{})) : std::nullopt;
  }

  template <class T>
  T required(std::string_view key) const {
    auto value = get<T>(key);
    if (!value)
      missing(key, expected(Tag<T>{}));
    return *std::move(value);
  }

  /// A number checked against `rule`.
  Real number(std::string_view key, const NumberRule& rule) const;

  /// Adds a warning (naming `path` and the line of `n`) and returns false if `value` is outside
  /// `rule.plausible`.
  bool check_plausible(const toml::node* n, std::string_view key_path, Real value,
                       const NumberRule& rule) const;

  /// Three numbers, each checked against `rule` (rule.fallback is ignored).
  Vec3 vec3(std::string_view key, const NumberRule& rule, std::optional<Vec3> fallback) const;

  /// An integer in [min, max], `fallback` if absent.
  int integer(std::string_view key, int min, int fallback, int max = INT_MAX) const;

  /// A non-empty string; "" if absent and not `required`.
  std::string name(std::string_view key, bool required = true) const;

  /// One of the named `options`; `fallback` if absent (required if none).
  template <class E>
  E choice(std::string_view key, const Options<E>& options, std::optional<E> fallback,
           std::string_view noun = "value") const {
    std::vector<std::string_view> names;
    for (const auto& option : options)
      names.push_back(option.first);
    const toml::node* n = find(key);
    if (!n && fallback)
      return *fallback;
    if (!n)
      missing(key, fmt::format("one of: {}", join(names)));
    const std::string s = convert(*n, path(key), Tag<std::string>{});
    for (const auto& [option, value] : options)
      if (option == s)
        return value;
    fail(n, fmt::format("{} = '{}'", path(key), s),
         fmt::format("unknown {} (expected one of: {}){}", noun, join(names),
                     did_you_mean(s, names)));
  }

  /// The sub-table `key`, if present.
  std::optional<Table> table(std::string_view key) const;

  /// The elements of the array of tables `key` ([[key]]); empty if absent.
  std::vector<Table> tables(std::string_view key) const;

  /// Every entry of this table, each of which must itself be a table ([<path>.<name>]).
  std::vector<std::pair<std::string, Table>> named_tables() const;

private:
  const toml::table* table_;
  std::string path_;
  Warnings* warnings_;
};

// ---------------------------------------------------------------------------------------------
// Checks shared by the section readers

/// Checks that `name`, the value of `key` in `t`, names an entry of `defined` ([section.<name>]).
template <class Map>
void check_reference(const Table& t, std::string_view key, const std::string& name,
                     const Map& defined, std::string_view noun, std::string_view section) {
  if (defined.count(name) != 0)
    return;
  std::vector<std::string> names;
  for (const auto& entry : defined)
    names.push_back(entry.first);
  const std::string known = names.empty() ? fmt::format("no [{}.<name>] table is defined", section)
                                          : fmt::format("defined: {}", join(names));
  fail(t.find(key), fmt::format("{} = '{}'", t.path(key), name),
       fmt::format("undefined {} ({}){}", noun, known, did_you_mean(name, names)));
}

/// The optional `curve` key: empty or the name of a [curves.<name>] table.
std::string read_curve_reference(const Table& t, const CaseSpec& spec);

/// The `key` string of `t`: letters, digits, '_' (and '-' if `allow_dash`).
std::string read_identifier(const Table& t, std::string_view key, bool allow_dash);

/// "x", "y", "z" -> 0, 1, 2.
const Options<Component>& component_options();

/// Axis names by component.
inline constexpr std::string_view kAxis[3] = {"x", "y", "z"};

/// The component named by the string `n` (at `path`).
Component component_of(const toml::node& n, const std::string& path);

/// The optional `components` key of `t`: distinct "x", "y", "z" (default: all three).
std::vector<Component> read_components(const Table& t);

// ---------------------------------------------------------------------------------------------
// Section readers. Each reads one top-level table of `root` (if present) into `spec`.

/// Every section, in dependency order (case_reader_sections.cpp); implausible values are
/// added to spec.warnings.
void read_sections(const toml::table& document, CaseSpec& spec);

/// Refuses a case whose time settings imply absurd work: more than kMaxSteps steps (end_time
/// over the largest step) or more than kMaxOutputTimes output times and curve points, which are
/// all steps the run must land on (case_reader_limits.cpp; after [time], [curves], [output]).
/// Every [[step]] is checked on its own span. `root` (for line numbers) may be null.
void check_time_limits(const Table* root, const CaseSpec& spec);

/// Refuses a model of [[mesh.box]] cells whose equations overflow the 32-bit index or whose
/// estimated memory exceeds the physical memory of the machine (case_reader_limits.cpp; after
/// the materials and meshes). `root` (for line numbers) may be null.
void check_model_size(const Table* root, const CaseSpec& spec);

/// Most times a failed step may be cut back before the run fails.
inline constexpr Real kMaxCutbacks = 200;
/// Most Newton iterations per step attempt ([solver] max_iterations).
inline constexpr int kMaxNewtonIterations = 1000;
/// Most output times (end_time / output.interval) and must points a run may have.
inline constexpr Real kMaxOutputTimes = 1e6;
/// Shortest time.end_time of a quasi-static analysis [s]: its step control resolves times to
/// 1e-10 s, so a shorter analysis would end before its first step.
inline constexpr Real kMinEndTime = 1e-8;

/// [[boundary.*]] (case_reader_physics.cpp).
void read_boundary(const Table& root, CaseSpec& spec);
/// [[step]] tables (after [boundary], [loads] and [output]); sets spec.time to the span of the
/// steps (case_reader_steps.cpp).
void read_steps(const Table& root, CaseSpec& spec);
/// True if a [[step]] table of `root` says analysis = "dynamic-explicit" (read before the steps:
/// the [explicit] table is allowed then).
bool declares_explicit_step(const Table& root);
/// The time-control keys of `t` into `s` (end_time after `start`; with `allow_duration`,
/// `duration` instead of end_time).
void read_time_keys(const Table& t, TimeSpec& s, Real start, bool allow_duration);
/// [[loads.*]] (case_reader_physics.cpp).
void read_loads(const Table& root, CaseSpec& spec);
/// [[contact]] pairs (after materials).
void read_contacts(const Table& root, CaseSpec& spec);
/// [[rigid_body]] (case_reader_rigid.cpp); after [[boundary.*]] (conflicts are checked).
void read_rigid_bodies(const Table& root, CaseSpec& spec);
/// A driven component of a rigid body or joint: { displacement | force } or, for a rotation,
/// { rotation | moment }, with an optional curve.
RigidComponentSpec read_rigid_component(const Table& t, const CaseSpec& spec, bool rotation);
/// [[connector]] (case_reader_connectors.cpp); after [[rigid_body]].
void read_connectors(const Table& root, CaseSpec& spec);
/// [[constraint]] (case_reader_constraints.cpp); after [curves.<name>] (a constraint's curve).
void read_constraints(const Table& root, CaseSpec& spec);
/// [analysis] (case_reader_physics.cpp).
void read_analysis(const Table& root, CaseSpec& spec);
/// [electrochemistry] (case_reader_physics.cpp).
void read_electrochemistry(const Table& root, CaseSpec& spec);

/// The [<material>.axes] table `t` of a material (case_reader_axes.cpp).
material::AxesSpec read_axes(const Table& t);

/// [analysis] type, before every other section (case_reader_explicit.cpp).
void read_analysis_type(const Table& root, CaseSpec& spec);
/// Rejects the sections of another analysis type: [explicit] unless dynamic-explicit; in
/// dynamic-explicit analyses [solver], [[contact]], [[boundary.prescribed]], ... (the first one).
void check_analysis_sections(const Table& root, const CaseSpec& spec);
/// [time] of a dynamic-explicit analysis (dt optional; quasi-static keys are errors).
void read_explicit_time(const Table& root, CaseSpec& spec);
/// [explicit] (only with [analysis] type = "dynamic-explicit"; after [time]).
void read_explicit(const Table& root, CaseSpec& spec);
/// [dynamic] and the densities of implicit dynamic analyses (after [[step]];
/// case_reader_dynamic.cpp).
void read_dynamic(const Table& root, CaseSpec& spec);

} // namespace trifem::io::detail
