// SPDX-License-Identifier: MIT
// Declarative parameter schemas: name, unit, valid range, default, documentation.
#pragma once

#include "trifem/core/types.hpp"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace trifem::material {

/// A typed interval of valid parameter values, e.g. Range::open(-1.0, 0.5).
struct Range {
  Real lo = -1e300;
  Real hi = 1e300;
  bool lo_open = false;
  bool hi_open = false;

  static Range open(Real lo, Real hi) { return {lo, hi, true, true}; }
  static Range closed(Real lo, Real hi) { return {lo, hi, false, false}; }
  static Range half_open(Real lo, Real hi) { return {lo, hi, false, true}; } ///< [lo, hi)
  static Range positive() { return {0.0, 1e300, true, false}; }              ///< (0, inf)
  static Range non_negative() { return {0.0, 1e300, false, false}; }         ///< [0, inf)

  /// True if v is finite and inside the interval.
  bool contains(Real v) const;
  /// Human-readable interval, e.g. "(0, inf)" or "(-1, 0.5)".
  std::string describe() const;
};

/// Schema of one scalar parameter.
struct ParameterSchema {
  std::string key;                   ///< key in the case file
  std::string unit;                  ///< unit in the mm-N-s-MPa system (empty: dimensionless)
  std::string doc;                   ///< one-line description
  Range range;                       ///< valid values
  std::optional<Real> default_value; ///< absent: required
};

/// Parameter values by key, as read from a case file.
using ParameterValues = std::map<std::string, Real>;

/// Validates `values` against `schema`: unknown keys, missing required keys and values outside
/// their range are InputErrors naming `context.key`. Returns the values with defaults filled in.
ParameterValues validate_parameters(const std::vector<ParameterSchema>& schema,
                                    const ParameterValues& values, const std::string& context);

} // namespace trifem::material
