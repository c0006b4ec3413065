// SPDX-License-Identifier: MIT
#include "trifem/material/schema.hpp"

#include "trifem/core/error.hpp"

#include <cmath>
#include <fmt/format.h>

namespace trifem::material {
namespace {

std::string bound(Real v) {
  if (v >= 1e300)
    return "inf";
  if (v <= -1e300)
    return "-inf";
  return fmt::format("{}", v);
}

std::string known_keys(const std::vector<ParameterSchema>& schema) {
  std::string keys;
  for (const auto& p : schema)
    keys += (keys.empty() ? "" : ", ") + p.key;
  return keys;
}

} // namespace

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

ParameterValues validate_parameters(const std::vector<ParameterSchema>& schema,
                                    const ParameterValues& values, const std::string& context) {
  for (const auto& [key, value] : values) {
    bool known = false;
    for (const auto& p : schema)
      known = known || p.key == key;
    TRIFEM_CHECK(known, "{}.{}: unknown parameter (expected one of: {})", context, key,
                 known_keys(schema));
  }
  ParameterValues checked;
  for (const auto& p : schema) {
    const auto it = values.find(p.key);
    if (it == values.end()) {
      TRIFEM_CHECK(p.default_value.has_value(), "{}.{}: missing required parameter ({}{}{})",
                   context, p.key, p.doc, p.unit.empty() ? "" : ", ", p.unit);
      checked[p.key] = *p.default_value;
      continue;
    }
    TRIFEM_CHECK(p.range.contains(it->second), "{}.{} = {}: out of range, expected a value in {}{}",
                 context, p.key, it->second, p.range.describe(),
                 p.unit.empty() ? "" : " " + p.unit);
    checked[p.key] = it->second;
  }
  return checked;
}

} // namespace trifem::material
