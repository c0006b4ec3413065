// SPDX-License-Identifier: MIT
#include "trifem/material/schema.hpp"

#include "trifem/core/error.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <set>

namespace trifem::material {
namespace {

std::string bound(Real v) {
  if (v >= 1e300)
    return "inf";
  if (v <= -1e300)
    return "-inf";
  return fmt::format("{}", v);
}

/// The keys under which `p` is stored in ParameterValues: its key, or a Vector's three.
std::set<std::string> stored_keys(const ParameterSchema& p) {
  if (p.kind == ParameterKind::Scalar)
    return {p.key};
  const auto keys = vector_keys(p.key);
  return {keys.begin(), keys.end()};
}

std::string known_keys(const std::vector<ParameterSchema>& schema) {
  std::string keys;
  for (const auto& p : schema)
    keys += (keys.empty() ? "" : ", ") + p.key;
  return keys;
}

} // namespace

namespace plausible {

// Typical values: cartilage E 0.3-10 MPa (brain 1e-3, bone 2e4), permeability 1e-3 mm^4/(N s)
// (1e-15 m^4/(N s)), bath 0.15 M = 1.5e-4 mmol/mm^3, fixed charge 0.1-0.3 mEq/mL = 1e-4 to
// 3e-4 mEq/mm^3, ion diffusivities 5e-4 to 2e-3 mm^2/s (5e-10 to 2e-9 m^2/s), water density
// 1e-9 t/mm^3.
const Plausibility& modulus() {
  static const Plausibility p{1e-5, 1e5, {{1e-6, "Pa"}, {1e-3, "kPa"}, {1e3, "GPa"}}};
  return p;
}
const Plausibility& permeability() {
  static const Plausibility p{1e-7, 1e2, {{1e12, "m^4/(N s)"}}};
  return p;
}
const Plausibility& concentration() {
  static const Plausibility p{1e-7, 1e-2, {{1e-3, "M (mol/L)"}, {1e-6, "mM (mmol/L)"}}};
  return p;
}
const Plausibility& fixed_charge() {
  static const Plausibility p{1e-7, 1e-2, {{1e-3, "mEq/mL"}, {1e-6, "mEq/L"}}};
  return p;
}
const Plausibility& diffusivity() {
  static const Plausibility p{1e-7, 1e-1, {{1e6, "m^2/s"}, {1e2, "cm^2/s"}}};
  return p;
}
const Plausibility& length() {
  static const Plausibility p{1e-4, 1e4, {}}; // 1 mm written in m or um is still plausible
  return p;
}
const Plausibility& density() {
  static const Plausibility p{1e-11, 1e-7, {{1e-12, "kg/m^3"}, {1e-9, "g/cm^3"}}};
  return p;
}

} // namespace plausible

const Plausibility* parameter_plausibility(std::string_view key) {
  static const std::map<std::string_view, const Plausibility*> table = {
      {"E", &plausible::modulus()},
      {"permeability", &plausible::permeability()},
      {"fixed_charge", &plausible::fixed_charge()},
      {"d_plus", &plausible::diffusivity()},
      {"d_minus", &plausible::diffusivity()},
  };
  const auto it = table.find(key);
  return it == table.end() ? nullptr : it->second;
}

std::string implausibility(const Plausibility& p, Real value, std::string_view unit) {
  const Real size = std::abs(value);
  if (size == 0.0 || (size >= p.lo && size <= p.hi))
    return {};
  std::string text = fmt::format("= {:g} {} is far outside the range of soft tissues ({:g} to {:g} "
                                 "{})",
                                 value, unit, p.lo, p.hi, unit);
  for (const UnitSlip& slip : p.slips) {
    const Real meant = size * slip.factor;
    if (meant >= p.lo && meant <= p.hi)
      return text +
             fmt::format("; if it is in {}, write {:g}", slip.unit, value < 0 ? -meant : meant);
  }
  return text;
}

bool Range::contains(Real v) const {
  if (!std::isfinite(v))
    return false;
  const bool above = lo_open ? v > lo : v >= lo;
  const bool below = hi_open ? v < hi : v <= hi;
  return above && below;
}

std::string Range::describe() const {
  const bool lo_inf = lo <= -1e300, hi_inf = hi >= 1e300;
  return fmt::format("{}{}, {}{}", lo_open || lo_inf ? "(" : "[", bound(lo), bound(hi),
                     hi_open || hi_inf ? ")" : "]");
}

std::string Range::expected(Real v) const {
  const bool beyond_infinity =
      std::isfinite(v) && ((v < lo && lo <= -1e300) || (v > hi && hi >= 1e300));
  return beyond_infinity ? fmt::format("a value of magnitude at most {:g}", 1e300)
                         : fmt::format("a value in {}", describe());
}

std::array<std::string, 3> vector_keys(std::string_view key) {
  return {fmt::format("{}.x", key), fmt::format("{}.y", key), fmt::format("{}.z", key)};
}

void set_vector(ParameterValues& values, std::string_view key, const Vec3& v) {
  const auto keys = vector_keys(key);
  for (int d = 0; d < 3; ++d)
    values[keys[d]] = v[d];
}

Vec3 fibre_direction(const ParameterValues& values, const std::string& context) {
  const Vec3 a = vector_value(values, "fibre");
  TRIFEM_CHECK(a.norm() > 0.0,
               "{}.fibre = [{}, {}, {}]: the fibre direction must be a nonzero vector", context,
               a.x(), a.y(), a.z());
  return a;
}

Vec3 vector_value(const ParameterValues& values, std::string_view key) {
  const auto keys = vector_keys(key);
  Vec3 v;
  for (int d = 0; d < 3; ++d) {
    const auto it = values.find(keys[d]);
    TRIFEM_VERIFY(it != values.end(), "vector parameter '{}' has no component '{}'", key, keys[d]);
    v[d] = it->second;
  }
  return v;
}

ParameterValues validate_parameters(const std::vector<ParameterSchema>& schema,
                                    const ParameterValues& values, const std::string& context) {
  for (const auto& [key, value] : values) {
    bool known = false;
    for (const auto& p : schema)
      known = known || stored_keys(p).contains(key);
    TRIFEM_CHECK(known, "{}.{}: unknown parameter (expected one of: {})", context, key,
                 known_keys(schema));
  }
  ParameterValues checked;
  for (const auto& p : schema) {
    const std::set<std::string> keys = stored_keys(p);
    const auto given = static_cast<std::size_t>(
        std::count_if(keys.begin(), keys.end(), [&](const auto& k) { return values.contains(k); }));
    if (given == 0) {
      TRIFEM_CHECK(p.default_value.has_value() && p.kind == ParameterKind::Scalar,
                   "{}.{}: missing required parameter ({}{}{})", context, p.key, p.doc,
                   p.unit.empty() ? "" : ", ", p.unit);
      checked[p.key] = *p.default_value;
      continue;
    }
    TRIFEM_CHECK(given == keys.size(), "{}.{}: incomplete vector (expected the 3 components {})",
                 context, p.key, fmt::join(keys, ", "));
    for (const std::string& key : keys) {
      const Real v = values.at(key);
      TRIFEM_CHECK(p.range.contains(v), "{}.{} = {}: out of range, expected {}{}", context, key, v,
                   p.range.expected(v), p.unit.empty() ? "" : " " + p.unit);
      checked[key] = v;
    }
  }
  return checked;
}

} // namespace trifem::material
