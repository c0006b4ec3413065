// SPDX-License-Identifier: MIT
// Typed, path-aware access to TOML values for the case reader (see toml_table.hpp).
#include "trifem/io/toml_table.hpp"

#include "trifem/core/error.hpp"

#include <climits>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>

namespace trifem::io::detail {
namespace {

bool is_name_char(char c, bool allow_dash) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
         (allow_dash && c == '-');
}

char lower(char c) {
  return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
}

template <class T, std::size_t N>
std::array<T, N> fixed_array(const toml::node& n, std::string_view path, std::string_view what) {
  const toml::array& a = array_of(n, path, what, N);
  std::array<T, N> out{};
  for (std::size_t i = 0; i < N; ++i)
    out[i] = convert(a[i], element_path(path, i), Tag<T>{});
  return out;
}

} // namespace

// ---------------------------------------------------------------------------------------------
// Messages

bool is_name(std::string_view s, bool allow_dash) {
  return !s.empty() &&
         std::all_of(s.begin(), s.end(), [&](char c) { return is_name_char(c, allow_dash); });
}

std::string join_path(std::string_view parent, std::string_view key) {
  const std::string k = is_name(key, true) ? std::string(key) : fmt::format("\"{}\"", key);
  return parent.empty() ? k : fmt::format("{}.{}", parent, k);
}

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

void fail(const toml::node* where, std::string_view path, std::string_view message) {
  const auto line = where ? where->source().begin.line : 0;
  throw InputError(line > 0 ? fmt::format("{}: {} (line {})", path, message, line)
                            : fmt::format("{}: {}", path, message));
}

void wrong_type(const toml::node& n, std::string_view path, std::string_view what) {
  fail(&n, path, fmt::format("expected {}, got {}", what, type_name(n)));
}

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

std::string range_text(const Range& range, std::string_view unit) {
  return unit.empty() ? range.describe() : fmt::format("{} {}", range.describe(), unit);
}

/// What was expected of `v`, with the unit: "a value in (0, inf) mm".
std::string range_text(const Range& range, Real v, std::string_view unit) {
  return unit.empty() ? range.expected(v) : fmt::format("{} {}", range.expected(v), unit);
}

// ---------------------------------------------------------------------------------------------
// Conversions

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
std::string_view expected(Tag<std::vector<std::string>>) {
  return "an array of strings";
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
  if (std::fpclassify(v) == FP_SUBNORMAL)
    fail(&n, path,
         fmt::format("expected 0 or a number of magnitude at least {:g} (the smallest normal "
                     "double), got {}",
                     std::numeric_limits<Real>::min(), v));
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

const toml::array& array_of(const toml::node& n, std::string_view path, std::string_view what,
                            std::size_t size) {
  const auto* a = n.as_array();
  if (!a)
    wrong_type(n, path, what);
  if (size != 0 && a->size() != size)
    fail(&n, path, fmt::format("expected {}, got an array of {} element(s)", what, a->size()));
  return *a;
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

// ---------------------------------------------------------------------------------------------
// Tables

void check_range(const toml::node* n, std::string_view path, Real v, const NumberRule& rule) {
  if (rule.range.contains(v))
    return;
  const std::string hint = rule.hint.empty() ? "" : fmt::format(" ({})", rule.hint);
  fail(n, fmt::format("{} = {}", path, v),
       fmt::format("out of range, expected {}{}", range_text(rule.range, v, rule.unit), hint));
}

void Table::allow(const std::vector<std::string_view>& allowed) const {
  const auto [key, node] = first_key([&](std::string_view k) {
    return std::find(allowed.begin(), allowed.end(), k) == allowed.end();
  });
  if (node)
    fail(node, path(key),
         fmt::format("unknown key (expected one of: {}){}", join(allowed),
                     did_you_mean(key, allowed)));
}

void Table::allow(const std::vector<std::string_view>& allowed,
                  const std::vector<std::string_view>& also) const {
  std::vector<std::string_view> all = allowed;
  all.insert(all.end(), also.begin(), also.end());
  const auto [key, node] = first_key(
      [&](std::string_view k) { return std::find(all.begin(), all.end(), k) == all.end(); });
  if (!node)
    return;
  std::string extra;
  for (const std::string_view k : also)
    extra += fmt::format(" or '{}'", k);
  fail(node, path(key),
       fmt::format("unknown key (expected one of: {}){}{}", join(allowed), extra,
                   did_you_mean(key, all)));
}

void Table::missing(std::string_view key, std::string_view what) const {
  fail(where(), path(key), fmt::format("missing required key (expected {})", what));
}

Real Table::number(std::string_view key, const NumberRule& rule) const {
  const toml::node* n = find(key);
  if (!n && rule.fallback)
    return *rule.fallback;
  if (!n)
    missing(key, fmt::format("a number in {}", range_text(rule.range, rule.unit)));
  const Real v = convert(*n, path(key), Tag<Real>{});
  check_range(n, path(key), v, rule);
  check_plausible(n, path(key), v, rule);
  return v;
}

bool Table::check_plausible(const toml::node* n, std::string_view key_path, Real value,
                            const NumberRule& rule) const {
  if (rule.plausible == nullptr || warnings_ == nullptr)
    return true;
  const std::string why = material::implausibility(*rule.plausible, value, rule.unit);
  if (why.empty())
    return true;
  const auto line = n ? n->source().begin.line : 0;
  warnings_->push_back(line > 0 ? fmt::format("{} {} (line {})", key_path, why, line)
                                : fmt::format("{} {}", key_path, why));
  return false;
}

Vec3 Table::vec3(std::string_view key, const NumberRule& rule, std::optional<Vec3> fallback) const {
  const toml::node* n = find(key);
  if (!n && fallback)
    return *fallback;
  const Vec3 v = required<Vec3>(key);
  const toml::array& a = *n->as_array();
  for (std::size_t d = 0; d < 3; ++d)
    check_range(&a[d], element_path(path(key), d), v[static_cast<Eigen::Index>(d)], rule);
  for (std::size_t d = 0; d < 3; ++d) // one warning at most: the first implausible element
    if (!check_plausible(&a[d], element_path(path(key), d), v[static_cast<Eigen::Index>(d)], rule))
      break;
  return v;
}

int Table::integer(std::string_view key, int min, int fallback, int max) const {
  const toml::node* n = find(key);
  if (!n)
    return fallback;
  const int v = convert(*n, path(key), Tag<int>{});
  if (v < min || v > max)
    fail(n, fmt::format("{} = {}", path(key), v),
         max == INT_MAX
             ? fmt::format("out of range, expected an integer >= {}", min)
             : fmt::format("out of range, expected an integer >= {} and <= {}", min, max));
  return v;
}

std::string Table::name(std::string_view key, bool required) const {
  const toml::node* n = find(key);
  if (!n && required)
    missing(key, "a non-empty string");
  const std::string s = n ? convert(*n, path(key), Tag<std::string>{}) : std::string();
  if (n && s.empty())
    fail(n, path(key), "expected a non-empty string, got \"\"");
  return s;
}

std::optional<Table> Table::table(std::string_view key) const {
  const toml::node* n = find(key);
  if (!n)
    return std::nullopt;
  if (!n->is_table())
    wrong_type(*n, path(key), fmt::format("a table [{}]", path(key)));
  return Table(*n->as_table(), path(key), warnings_);
}

std::vector<Table> Table::tables(std::string_view key) const {
  const toml::node* n = find(key);
  if (!n)
    return {};
  const std::string what = fmt::format("an array of tables (one [[{}]] per entry)", path(key));
  const toml::array& a = array_of(*n, path(key), what);
  std::vector<Table> out;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!a[i].is_table())
      wrong_type(a[i], element_path(path(key), i), "a table");
    out.emplace_back(*a[i].as_table(), element_path(path(key), i), warnings_);
  }
  return out;
}

std::vector<std::pair<std::string, Table>> Table::named_tables() const {
  std::vector<std::pair<std::string, Table>> out;
  for (const auto& [key, node] : *table_) {
    if (!node.is_table())
      wrong_type(node, path(key.str()), fmt::format("a table [{}]", path(key.str())));
    out.emplace_back(std::string(key.str()), Table(*node.as_table(), path(key.str()), warnings_));
  }
  return out;
}

// ---------------------------------------------------------------------------------------------
// Shared checks

std::string read_curve_reference(const Table& t, const CaseSpec& spec) {
  std::string curve = t.name("curve", false);
  if (!curve.empty())
    check_reference(t, "curve", curve, spec.curves, "curve", "curves");
  return curve;
}

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

Component component_of(const toml::node& n, const std::string& path) {
  const std::string s = convert(n, path, Tag<std::string>{});
  for (const auto& [name, c] : component_options())
    if (name == s)
      return c;
  fail(&n, fmt::format("{} = '{}'", path, s),
       fmt::format("unknown component (expected one of: x, y, z){}", did_you_mean(s, kAxis)));
}

} // namespace trifem::io::detail
