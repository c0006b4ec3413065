// SPDX-License-Identifier: MIT
// Case reader, part 2: typed, path-aware access to TOML values and one reader per section.
// Every message names the key path (e.g. "mesh.box[0].size[2]") and, where known, the line.
#include "trifem/core/error.hpp"
#include "trifem/io/case_reader.hpp"
#include "trifem/material/registry.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <fmt/format.h>
#include <numeric>
#include <toml++/toml.h>

namespace trifem::io::detail {
void read_sections(const toml::table& root, CaseSpec& spec);
} // namespace trifem::io::detail

namespace trifem::io {
namespace {

using material::Range;
using Point = std::pair<Real, Real>;

constexpr Real kUnbounded = 1e300; ///< Range's convention for "no bound"

// ---------------------------------------------------------------------------------------------
// Messages

bool is_name_char(char c, bool allow_dash) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
         (allow_dash && c == '-');
}

bool is_name(std::string_view s, bool allow_dash) {
  return !s.empty() &&
         std::all_of(s.begin(), s.end(), [&](char c) { return is_name_char(c, allow_dash); });
}

/// `parent.key`, quoting keys that are not bare TOML keys.
std::string join_path(std::string_view parent, std::string_view key) {
  const std::string k = is_name(key, true) ? std::string(key) : fmt::format("\"{}\"", key);
  return parent.empty() ? k : fmt::format("{}.{}", parent, k);
}

/// `path[i + 1]`: messages count array elements from 1, like the rest of trifem.
std::string element_path(std::string_view path, std::size_t i) {
  return fmt::format("{}[{}]", path, i + 1);
}

std::string type_name(const toml::node& n) {
  switch (n.type()) {
  case toml::node_type::string:
    return "a string";
  case toml::node_type::integer:
    return "an integer";
  case toml::node_type::floating_point:
    return "a floating-point number";
  case toml::node_type::boolean:
    return "a boolean";
  case toml::node_type::table:
    return "a table";
  case toml::node_type::array:
    return n.is_array_of_tables() ? "an array of tables" : "an array";
  case toml::node_type::date:
    return "a date";
  case toml::node_type::time:
    return "a time";
  case toml::node_type::date_time:
    return "a date-time";
  default:
    return "nothing";
  }
}

/// Throws "<path>: <message> (line N)"; `where` may be null (no line).
[[noreturn]] void fail(const toml::node* where, std::string_view path, std::string_view message) {
  const auto line = where ? where->source().begin.line : 0;
  throw InputError(line > 0 ? fmt::format("{}: {} (line {})", path, message, line)
                            : fmt::format("{}: {}", path, message));
}

[[noreturn]] void wrong_type(const toml::node& n, std::string_view path, std::string_view what) {
  fail(&n, path, fmt::format("expected {}, got {}", what, type_name(n)));
}

char lower(char c) {
  return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
}

/// Case-insensitive Levenshtein distance.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), std::size_t{0});
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      const std::size_t change = lower(a[i - 1]) == lower(b[j - 1]) ? 0 : 1;
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + change});
      diagonal = up;
    }
  }
  return row[b.size()];
}

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

template <class Names>
std::string join(const Names& names) {
  std::string out;
  for (const auto& n : names)
    out += (out.empty() ? "" : ", ") + std::string(n);
  return out;
}

std::string range_text(const Range& range, std::string_view unit) {
  return unit.empty() ? range.describe() : fmt::format("{} {}", range.describe(), unit);
}

// ---------------------------------------------------------------------------------------------
// Conversions of one TOML value (the Tag selects the C++ type)

template <class T>
struct Tag {};

std::string_view expected(Tag<Real>) {
  return "a number";
}
std::string_view expected(Tag<int>) {
  return "an integer";
}
std::string_view expected(Tag<bool>) {
  return "a boolean (true or false)";
}
std::string_view expected(Tag<std::string>) {
  return "a string";
}
std::string_view expected(Tag<Vec3>) {
  return "an array of 3 numbers";
}
std::string_view expected(Tag<std::array<int, 3>>) {
  return "an array of 3 integers";
}
std::string_view expected(Tag<Point>) {
  return "a [t, value] pair of numbers";
}
std::string_view expected(Tag<std::vector<Real>>) {
  return "an array of numbers";
}
std::string_view expected(Tag<std::vector<Point>>) {
  return "an array of [t, value] pairs";
}

Real convert(const toml::node& n, std::string_view path, Tag<Real>) {
  Real v = 0.0;
  if (const auto* i = n.as_integer())
    v = static_cast<Real>(i->get());
  else if (const auto* f = n.as_floating_point())
    v = f->get();
  else
    wrong_type(n, path, expected(Tag<Real>{}));
  if (!std::isfinite(v))
    fail(&n, path, fmt::format("expected a finite number, got {}", v));
  return v;
}

int convert(const toml::node& n, std::string_view path, Tag<int>) {
  const auto* i = n.as_integer();
  if (!i)
    wrong_type(n, path, expected(Tag<int>{}));
  const std::int64_t v = i->get();
  if (v < INT_MIN || v > INT_MAX)
    fail(&n, path, fmt::format("{} is out of range for an integer", v));
  return static_cast<int>(v);
}

bool convert(const toml::node& n, std::string_view path, Tag<bool>) {
  const auto* b = n.as_boolean();
  if (!b)
    wrong_type(n, path, expected(Tag<bool>{}));
  return b->get();
}

std::string convert(const toml::node& n, std::string_view path, Tag<std::string>) {
  const auto* s = n.as_string();
  if (!s)
    wrong_type(n, path, expected(Tag<std::string>{}));
  return s->get();
}

/// The array `n` (of exactly `size` elements unless size is 0).
const toml::array& array_of(const toml::node& n, std::string_view path, std::string_view what,
                            std::size_t size = 0) {
  const auto* a = n.as_array();
  if (!a)
    wrong_type(n, path, what);
  if (size != 0 && a->size() != size)
    fail(&n, path, fmt::format("expected {}, got an array of {} element(s)", what, a->size()));
  return *a;
}

template <class T, std::size_t N>
std::array<T, N> fixed_array(const toml::node& n, std::string_view path, std::string_view what) {
  const toml::array& a = array_of(n, path, what, N);
  std::array<T, N> out{};
  for (std::size_t i = 0; i < N; ++i)
    out[i] = convert(a[i], element_path(path, i), Tag<T>{});
  return out;
}

Vec3 convert(const toml::node& n, std::string_view path, Tag<Vec3>) {
  const auto a = fixed_array<Real, 3>(n, path, expected(Tag<Vec3>{}));
  return Vec3(a[0], a[1], a[2]);
}

std::array<int, 3> convert(const toml::node& n, std::string_view path, Tag<std::array<int, 3>>) {
  return fixed_array<int, 3>(n, path, expected(Tag<std::array<int, 3>>{}));
}

Point convert(const toml::node& n, std::string_view path, Tag<Point>) {
  const auto a = fixed_array<Real, 2>(n, path, expected(Tag<Point>{}));
  return {a[0], a[1]};
}

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

/// How a number is checked: valid range, default (absent: required), unit and a hint.
struct NumberRule {
  Range range{};
  std::optional<Real> fallback{};
  std::string_view unit{};
  std::string_view hint{};
};

/// Throws "<path> = <v>: out of range ..." unless `v` is in `rule.range`.
void check_range(const toml::node* n, std::string_view path, Real v, const NumberRule& rule) {
  if (rule.range.contains(v))
    return;
  const std::string hint = rule.hint.empty() ? "" : fmt::format(" ({})", rule.hint);
  fail(n, fmt::format("{} = {}", path, v),
       fmt::format("out of range, expected a value in {}{}", range_text(rule.range, rule.unit),
                   hint));
}

template <class E>
using Options = std::vector<std::pair<std::string_view, E>>;

/// A TOML table being read: the table, its key path for messages and typed accessors.
class Table {
public:
  Table(const toml::table& table, std::string path) : table_(&table), path_(std::move(path)) {}

  const std::string& path() const { return path_; }
  std::string path(std::string_view key) const { return join_path(path_, key); }
  const toml::table& raw() const { return *table_; }
  const toml::node* find(std::string_view key) const { return table_->get(key); }
  /// The table's node for line numbers (none for the document root).
  const toml::node* where() const { return path_.empty() ? nullptr : table_; }

  /// Throws on the key that is not in `allowed` and comes first in the file, if any.
  void allow(const std::vector<std::string_view>& allowed) const {
    const toml::node* first = nullptr;
    std::string_view first_key;
    for (const auto& [key, node] : *table_) {
      const bool known = std::find(allowed.begin(), allowed.end(), key.str()) != allowed.end();
      if (!known && (!first || node.source().begin < first->source().begin)) {
        first = &node;
        first_key = key.str();
      }
    }
    if (first)
      fail(first, path(first_key),
           fmt::format("unknown key (expected one of: {}){}", join(allowed),
                       did_you_mean(first_key, allowed)));
  }

  [[noreturn]] void missing(std::string_view key, std::string_view what) const {
    fail(where(), path(key), fmt::format("missing required key (expected {})", what));
  }

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
  Real number(std::string_view key, const NumberRule& rule) const {
    const toml::node* n = find(key);
    if (!n && rule.fallback)
      return *rule.fallback;
    if (!n)
      missing(key, fmt::format("a number in {}", range_text(rule.range, rule.unit)));
    const Real v = convert(*n, path(key), Tag<Real>{});
    check_range(n, path(key), v, rule);
    return v;
  }

  /// Three numbers, each checked against `rule` (rule.fallback is ignored).
  Vec3 vec3(std::string_view key, const NumberRule& rule, std::optional<Vec3> fallback) const {
    const toml::node* n = find(key);
    if (!n && fallback)
      return *fallback;
    const Vec3 v = required<Vec3>(key);
    const toml::array& a = *n->as_array();
    for (std::size_t d = 0; d < 3; ++d)
      check_range(&a[d], element_path(path(key), d), v[static_cast<Eigen::Index>(d)], rule);
    return v;
  }

  /// An integer >= `min`, `fallback` if absent.
  int integer(std::string_view key, int min, int fallback) const {
    const toml::node* n = find(key);
    if (!n)
      return fallback;
    const int v = convert(*n, path(key), Tag<int>{});
    if (v < min)
      fail(n, fmt::format("{} = {}", path(key), v),
           fmt::format("out of range, expected an integer >= {}", min));
    return v;
  }

  /// A non-empty string; "" if absent and not `required`.
  std::string name(std::string_view key, bool required = true) const {
    const toml::node* n = find(key);
    if (!n && required)
      missing(key, "a non-empty string");
    const std::string s = n ? convert(*n, path(key), Tag<std::string>{}) : std::string();
    if (n && s.empty())
      fail(n, path(key), "expected a non-empty string, got \"\"");
    return s;
  }

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
  std::optional<Table> table(std::string_view key) const {
    const toml::node* n = find(key);
    if (!n)
      return std::nullopt;
    if (!n->is_table())
      wrong_type(*n, path(key), fmt::format("a table [{}]", path(key)));
    return Table(*n->as_table(), path(key));
  }

  /// The elements of the array of tables `key` ([[key]]); empty if absent.
  std::vector<Table> tables(std::string_view key) const {
    const toml::node* n = find(key);
    if (!n)
      return {};
    const std::string what = fmt::format("an array of tables (one [[{}]] per entry)", path(key));
    const toml::array& a = array_of(*n, path(key), what);
    std::vector<Table> out;
    for (std::size_t i = 0; i < a.size(); ++i) {
      if (!a[i].is_table())
        wrong_type(a[i], element_path(path(key), i), "a table");
      out.emplace_back(*a[i].as_table(), element_path(path(key), i));
    }
    return out;
  }

  /// Every entry of this table, each of which must itself be a table ([<path>.<name>]).
  std::vector<std::pair<std::string, Table>> named_tables() const {
    std::vector<std::pair<std::string, Table>> out;
    for (const auto& [key, node] : *table_) {
      if (!node.is_table())
        wrong_type(node, path(key.str()), fmt::format("a table [{}]", path(key.str())));
      out.emplace_back(std::string(key.str()), Table(*node.as_table(), path(key.str())));
    }
    return out;
  }

private:
  const toml::table* table_;
  std::string path_;
};

// ---------------------------------------------------------------------------------------------
// Shared checks

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
std::string read_curve_reference(const Table& t, const CaseSpec& spec) {
  std::string curve = t.name("curve", false);
  if (!curve.empty())
    check_reference(t, "curve", curve, spec.curves, "curve", "curves");
  return curve;
}

/// The `key` string of `t`: letters, digits, '_' (and '-' if `allow_dash`).
std::string read_identifier(const Table& t, std::string_view key, bool allow_dash) {
  std::string s = t.name(key);
  if (!is_name(s, allow_dash))
    fail(t.find(key), fmt::format("{} = '{}'", t.path(key), s),
         fmt::format("invalid name (use only letters, digits{} and '_')",
                     allow_dash ? ", '-'" : ""));
  return s;
}

const Options<Component>& component_options() {
  static const Options<Component> options = {{"x", 0}, {"y", 1}, {"z", 2}};
  return options;
}

constexpr std::string_view kAxis[3] = {"x", "y", "z"};

Component component_of(const toml::node& n, const std::string& path) {
  const std::string s = convert(n, path, Tag<std::string>{});
  for (const auto& [name, c] : component_options())
    if (name == s)
      return c;
  fail(&n, fmt::format("{} = '{}'", path, s),
       fmt::format("unknown component (expected one of: x, y, z){}", did_you_mean(s, kAxis)));
}

// ---------------------------------------------------------------------------------------------
// [materials.<name>] and [curves.<name>]

MaterialSpec read_material(const Table& t) {
  std::vector<std::pair<std::string_view, const material::LawEntry*>> laws;
  for (const auto& law : material::registered_laws())
    laws.emplace_back(law.type, &law);
  const material::LawEntry& law =
      *t.choice<const material::LawEntry*>("type", laws, std::nullopt, "material type");
  std::vector<std::string_view> keys = {"type"};
  for (const auto& p : *law.parameters)
    keys.push_back(p.key);
  t.allow(keys);
  material::ParameterValues values;
  for (const auto& p : *law.parameters)
    if (t.find(p.key) != nullptr)
      values[p.key] = t.number(p.key, {.range = p.range, .unit = p.unit});
  MaterialSpec m{law.type, material::validate_parameters(*law.parameters, values, t.path())};
  material::create_law(m.type, m.parameters, t.path()); // the law's own checks, if any
  return m;
}

CurveSpec read_curve(const Table& t) {
  t.allow({"interpolation", "points"});
  static const Options<dofs::Interpolation> kinds = {{"linear", dofs::Interpolation::Linear},
                                                     {"step", dofs::Interpolation::Step},
                                                     {"smooth", dofs::Interpolation::Smooth}};
  CurveSpec c;
  c.interpolation = t.choice("interpolation", kinds, std::optional(c.interpolation));
  c.points = t.required<std::vector<Point>>("points");
  const dofs::LoadCurve check(c.points, c.interpolation, t.path("points"));
  return c;
}

void read_materials_and_curves(const Table& root, CaseSpec& spec) {
  if (const auto materials = root.table("materials"))
    for (const auto& [name, t] : materials->named_tables())
      spec.materials.emplace(name, read_material(t));
  if (const auto curves = root.table("curves"))
    for (const auto& [name, t] : curves->named_tables())
      spec.curves.emplace(name, read_curve(t));
}

// ---------------------------------------------------------------------------------------------
// [time], [solver]

void read_time(const Table& root, CaseSpec& spec) {
  const auto t = root.table("time");
  if (!t)
    fail(nullptr, "time", "missing required table [time] (with at least end_time and dt)");
  t->allow({"end_time", "dt", "dt_min", "dt_max", "target_iterations", "growth", "cutback"});
  TimeSpec& s = spec.time; // holds the defaults until overwritten
  s.end_time = t->number("end_time", {.range = Range::positive(), .unit = "s"});
  s.dt = t->number(
      "dt",
      {.range = {0.0, s.end_time, true, false}, .unit = "s", .hint = "at most time.end_time"});
  s.dt_min = t->number("dt_min", {.range = {0.0, s.dt, true, false},
                                  .fallback = s.dt * 1e-6,
                                  .unit = "s",
                                  .hint = "at most time.dt"});
  s.dt_max = t->number("dt_max", {.range = {s.dt, kUnbounded, false, false},
                                  .fallback = s.dt,
                                  .unit = "s",
                                  .hint = "at least time.dt"});
  s.target_iterations = t->integer("target_iterations", 1, s.target_iterations);
  s.growth = t->number("growth", {.range = {1.0, kUnbounded}, .fallback = s.growth});
  s.cutback = t->number("cutback", {.range = Range::open(0.0, 1.0), .fallback = s.cutback});
}

void read_solver(const Table& root, CaseSpec& spec) {
  const auto t = root.table("solver");
  if (!t)
    return;
  t->allow({"max_iterations", "residual_tolerance", "increment_tolerance", "line_search",
            "linear_solver"});
  static const Options<std::string_view> solvers = {{"umfpack", "umfpack"},
                                                    {"sparselu", "sparselu"}};
  SolverSpec& s = spec.solver;
  s.max_iterations = t->integer("max_iterations", 1, s.max_iterations);
  s.residual_tolerance = t->number(
      "residual_tolerance", {.range = Range::open(0.0, 1.0), .fallback = s.residual_tolerance});
  s.increment_tolerance = t->number(
      "increment_tolerance", {.range = Range::open(0.0, 1.0), .fallback = s.increment_tolerance});
  s.line_search = t->get<bool>("line_search").value_or(s.line_search);
  s.linear_solver = std::string(
      t->choice("linear_solver", solvers, std::optional<std::string_view>(s.linear_solver)));
}

// ---------------------------------------------------------------------------------------------
// [[mesh.box]], [[mesh.gmsh]]

void check_node_count(const Table& t, const std::array<int, 3>& n) {
  const std::int64_t nodes =
      (std::int64_t{n[0]} + 1) * (std::int64_t{n[1]} + 1) * (std::int64_t{n[2]} + 1);
  if (nodes > INT_MAX)
    fail(t.find("divisions"), t.path("divisions"),
         fmt::format("{} x {} x {} cells need {} nodes, more than the {} a mesh can hold", n[0],
                     n[1], n[2], nodes, INT_MAX));
}

BoxMeshSpec read_box(const Table& t, const CaseSpec& spec) {
  t.allow({"name", "origin", "size", "divisions", "grading", "material"});
  BoxMeshSpec b;
  b.box.name = read_identifier(t, "name", true);
  for (std::size_t i = 0; i < spec.boxes.size(); ++i)
    if (spec.boxes[i].box.name == b.box.name)
      fail(t.find("name"), fmt::format("{} = '{}'", t.path("name"), b.box.name),
           fmt::format("duplicate box name (already used by {})", element_path("mesh.box", i)));
  b.box.origin = t.vec3("origin", {.unit = "mm"}, Vec3::Zero());
  b.box.size = t.vec3("size", {.range = Range::positive(), .unit = "mm"}, std::nullopt);
  b.box.divisions = t.required<std::array<int, 3>>("divisions");
  for (std::size_t d = 0; d < 3; ++d)
    if (b.box.divisions[d] < 1)
      fail(&(*t.find("divisions")->as_array())[d],
           fmt::format("{} = {}", element_path(t.path("divisions"), d), b.box.divisions[d]),
           "out of range, expected an integer >= 1");
  check_node_count(t, b.box.divisions);
  b.box.grading = t.vec3("grading", {.range = Range::positive()}, Vec3::Ones());
  b.material = t.name("material");
  check_reference(t, "material", b.material, spec.materials, "material", "materials");
  return b;
}

GmshMeshSpec read_gmsh(const Table& t, const CaseSpec& spec) {
  t.allow({"file", "materials"});
  GmshMeshSpec g;
  const std::string file = t.name("file");
  std::error_code ec;
  g.file = std::filesystem::absolute(spec.file.parent_path() / file, ec).lexically_normal();
  if (!std::filesystem::is_regular_file(g.file, ec))
    fail(t.find("file"), fmt::format("{} = '{}'", t.path("file"), file),
         fmt::format("{} (looked for '{}')",
                     std::filesystem::exists(g.file, ec) ? "not a regular file" : "file not found",
                     g.file.string()));
  const auto volumes = t.table("materials");
  if (!volumes)
    t.missing("materials", "a table { <physical volume name> = \"<material>\", ... }");
  if (volumes->raw().empty())
    fail(t.find("materials"), t.path("materials"),
         "expected at least one <physical volume name> = \"<material>\" entry");
  for (const auto& [key, node] : volumes->raw()) {
    const std::string volume(key.str());
    const std::string material = volumes->name(volume);
    check_reference(*volumes, volume, material, spec.materials, "material", "materials");
    g.materials.emplace(volume, material);
  }
  return g;
}

void read_mesh(const Table& root, CaseSpec& spec) {
  if (const auto mesh = root.table("mesh")) {
    mesh->allow({"box", "gmsh"});
    for (const Table& t : mesh->tables("box"))
      spec.boxes.push_back(read_box(t, spec));
    for (const Table& t : mesh->tables("gmsh"))
      spec.gmsh.push_back(read_gmsh(t, spec));
  }
  if (spec.boxes.empty() && spec.gmsh.empty())
    fail(nullptr, "mesh", "no mesh defined (expected at least one [[mesh.box]] or [[mesh.gmsh]])");
}

// ---------------------------------------------------------------------------------------------
// [[boundary.fixed]], [[boundary.prescribed]], [[loads.pressure]], [[loads.traction]]

FixedSpec read_fixed(const Table& t) {
  t.allow({"set", "components"});
  FixedSpec f{t.name("set"), {}};
  const toml::node* n = t.find("components");
  if (!n)
    return {f.set, {0, 1, 2}};
  const toml::array& a = array_of(*n, t.path("components"), "an array of components");
  if (a.empty())
    fail(n, t.path("components"), "expected at least one of \"x\", \"y\", \"z\", got []");
  for (std::size_t i = 0; i < a.size(); ++i) {
    const std::string path = element_path(t.path("components"), i);
    const Component c = component_of(a[i], path);
    if (std::find(f.components.begin(), f.components.end(), c) != f.components.end())
      fail(&a[i], fmt::format("{} = '{}'", path, kAxis[c]), "duplicate component");
    f.components.push_back(c);
  }
  return f;
}

/// Rejects a second constraint on the same (node set, component).
void check_unconstrained(const Table& t, const PrescribedSpec& p, const CaseSpec& spec) {
  const auto conflict = [&](std::string_view by, std::size_t i) {
    fail(t.where(), t.path(),
         fmt::format("component {} of node set '{}' is already constrained by {}",
                     kAxis[p.component], p.set, element_path(by, i)));
  };
  for (std::size_t i = 0; i < spec.fixed.size(); ++i) {
    const auto& c = spec.fixed[i].components;
    if (spec.fixed[i].set == p.set && std::find(c.begin(), c.end(), p.component) != c.end())
      conflict("boundary.fixed", i);
  }
  for (std::size_t i = 0; i < spec.prescribed.size(); ++i)
    if (spec.prescribed[i].set == p.set && spec.prescribed[i].component == p.component)
      conflict("boundary.prescribed", i);
}

PrescribedSpec read_prescribed(const Table& t, const CaseSpec& spec) {
  t.allow({"set", "component", "value", "curve"});
  PrescribedSpec p;
  p.set = t.name("set");
  p.component = t.choice("component", component_options(), std::optional<Component>(), "component");
  p.value = t.number("value", {.unit = "mm"});
  p.curve = read_curve_reference(t, spec);
  check_unconstrained(t, p, spec);
  return p;
}

void read_boundary(const Table& root, CaseSpec& spec) {
  const auto boundary = root.table("boundary");
  if (!boundary)
    return;
  boundary->allow({"fixed", "prescribed"});
  for (const Table& t : boundary->tables("fixed"))
    spec.fixed.push_back(read_fixed(t));
  for (const Table& t : boundary->tables("prescribed"))
    spec.prescribed.push_back(read_prescribed(t, spec));
}

void read_loads(const Table& root, CaseSpec& spec) {
  const auto loads = root.table("loads");
  if (!loads)
    return;
  loads->allow({"pressure", "traction"});
  for (const Table& t : loads->tables("pressure")) {
    t.allow({"surface", "value", "curve"});
    spec.pressures.push_back(
        {t.name("surface"), t.number("value", {.unit = "MPa"}), read_curve_reference(t, spec)});
  }
  for (const Table& t : loads->tables("traction")) {
    t.allow({"surface", "value", "curve"});
    spec.tractions.push_back({t.name("surface"), t.vec3("value", {.unit = "MPa"}, std::nullopt),
                              read_curve_reference(t, spec)});
  }
}

// ---------------------------------------------------------------------------------------------
// [output], [[output.reaction]], [[output.probe]]

std::vector<Real> read_output_times(const Table& t, Real end_time) {
  const toml::node* n = t.find("times");
  if (!n)
    return {};
  std::vector<Real> times = t.required<std::vector<Real>>("times");
  const NumberRule rule{
      .range = Range::closed(0.0, end_time), .unit = "s", .hint = "between 0 and time.end_time"};
  for (std::size_t i = 0; i < times.size(); ++i)
    check_range(&(*n->as_array())[i], element_path(t.path("times"), i), times[i], rule);
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  return times;
}

ProbeSpec read_probe(const Table& t, const std::vector<ProbeSpec>& earlier) {
  t.allow({"name", "quantity", "point"});
  static const Options<std::string_view> quantities = {{"displacement", "displacement"},
                                                       {"position", "position"}};
  ProbeSpec p;
  p.name = read_identifier(t, "name", false);
  for (std::size_t i = 0; i < earlier.size(); ++i)
    if (earlier[i].name == p.name)
      fail(t.find("name"), fmt::format("{} = '{}'", t.path("name"), p.name),
           fmt::format("duplicate probe name (already used by {})",
                       element_path("output.probe", i)));
  p.quantity = std::string(
      t.choice("quantity", quantities, std::optional<std::string_view>(p.quantity), "quantity"));
  p.point = t.vec3("point", {.unit = "mm"}, std::nullopt);
  return p;
}

ReactionSpec read_reaction(const Table& t, const std::vector<ReactionSpec>& earlier) {
  t.allow({"set"});
  ReactionSpec r{t.name("set")};
  for (std::size_t i = 0; i < earlier.size(); ++i)
    if (earlier[i].set == r.set)
      fail(t.find("set"), fmt::format("{} = '{}'", t.path("set"), r.set),
           fmt::format("node set already listed in {}", element_path("output.reaction", i)));
  return r;
}

void read_output(const Table& root, CaseSpec& spec) {
  const auto t = root.table("output");
  if (!t)
    return;
  t->allow({"interval", "times", "vtu", "reaction", "probe"});
  OutputSpec& s = spec.output;
  s.interval =
      t->number("interval", {.range = Range::non_negative(), .fallback = s.interval, .unit = "s"});
  s.times = read_output_times(*t, spec.time.end_time);
  s.vtu = t->get<bool>("vtu").value_or(s.vtu);
  for (const Table& r : t->tables("reaction"))
    s.reactions.push_back(read_reaction(r, s.reactions));
  for (const Table& p : t->tables("probe"))
    s.probes.push_back(read_probe(p, s.probes));
}

} // namespace

void detail::read_sections(const toml::table& document, CaseSpec& spec) {
  const Table root(document, "");
  root.allow(
      {"title", "mesh", "materials", "curves", "boundary", "loads", "time", "solver", "output"});
  spec.title = root.get<std::string>("title").value_or("");
  read_materials_and_curves(root, spec);
  read_time(root, spec);
  read_mesh(root, spec);
  read_boundary(root, spec);
  read_loads(root, spec);
  read_solver(root, spec);
  read_output(root, spec);
}

} // namespace trifem::io
