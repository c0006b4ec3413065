// SPDX-License-Identifier: MIT
// Declarative parameter schemas: name, unit, valid range, default, documentation.
#pragma once

#include "trifem/core/types.hpp"
#include "trifem/tensor/tensor.hpp"

#include <array>
#include <map>
#include <optional>
#include <string>
#include <string_view>
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
  /// What was expected of `v`, which is not contained: "a value in (0, inf)", or for a finite
  /// value beyond the ±1e300 that stand for infinity, "a value of magnitude at most 1e+300".
  std::string expected(Real v) const;
};

/// What a parameter holds: one number, or a vector of three numbers (e.g. a fibre direction).
enum class ParameterKind { Scalar, Vector };

/// Schema of one parameter. A Vector parameter `key` is written `key = [x, y, z]` in a case
/// file and stored in ParameterValues as the three numbers of vector_keys(key); `range` applies
/// to each component, and it is always required (no default).
struct ParameterSchema {
  std::string key;                   ///< key in the case file
  std::string unit;                  ///< unit in the mm-N-s-MPa system (empty: dimensionless)
  std::string doc;                   ///< one-line description
  Range range;                       ///< valid values (of each component of a Vector)
  std::optional<Real> default_value; ///< absent: required (always absent for a Vector)
  ParameterKind kind = ParameterKind::Scalar;
};

/// A unit in which values of a quantity are often written by mistake, and the factor that
/// converts a value in that unit to the unit of the key (0.15 M = 0.15 x 1e-3 mmol/mm^3).
struct UnitSlip {
  Real factor;
  std::string unit;
};

/// The magnitudes a quantity takes in soft tissues, widened by one to two orders of magnitude on
/// each side: a value outside was almost surely written in another unit. Such a value is a
/// warning, never an error (the case may model something else).
struct Plausibility {
  Real lo;                     ///< smallest plausible magnitude, in the key's unit
  Real hi;                     ///< largest plausible magnitude
  std::vector<UnitSlip> slips; ///< likely mistakes, tried in order for a suggestion
};

/// Plausible magnitudes of the quantities of a case (mm-N-s-mmol units).
namespace plausible {
const Plausibility& modulus();       ///< [MPa]: Young's moduli of soft tissues to bone
const Plausibility& permeability();  ///< [mm^4/(N s)]: hydraulic permeability
const Plausibility& concentration(); ///< [mmol/mm^3]: NaCl concentration of a bath
const Plausibility& fixed_charge();  ///< [mEq/mm^3]: fixed charge density (0 is uncharged)
const Plausibility& diffusivity();   ///< [mm^2/s]: ion diffusivity
const Plausibility& length();        ///< [mm]: size of a body
const Plausibility& density();       ///< [t/mm^3]: mass density
} // namespace plausible

/// The plausibility of a material parameter by its key (E, permeability, fixed_charge, d_plus,
/// d_minus), or null if the key's values are not checked.
const Plausibility* parameter_plausibility(std::string_view key);

/// "" if `value` is 0 or its magnitude lies within `p`; otherwise a warning text (after the key)
/// saying so in `unit` and, if one of the slips turns it into a plausible value, what was
/// probably meant, e.g. "= 0.15 mmol/mm^3 is far outside the range of soft tissues (1e-07 to
/// 0.01 mmol/mm^3); if it is in M (mol/L), write 0.00015".
std::string implausibility(const Plausibility& p, Real value, std::string_view unit);

/// Parameter values by key, as read from a case file (a Vector parameter as its three
/// component keys, see vector_keys).
using ParameterValues = std::map<std::string, Real>;

/// The keys under which the components of the Vector parameter `key` are stored:
/// "<key>.x", "<key>.y", "<key>.z".
std::array<std::string, 3> vector_keys(std::string_view key);

/// Stores `v` as the Vector parameter `key` of `values`.
void set_vector(ParameterValues& values, std::string_view key, const Vec3& v);

/// The Vector parameter `key` of validated `values` (LogicError if a component is absent).
Vec3 vector_value(const ParameterValues& values, std::string_view key);

/// The fibre direction `fibre` of validated `values`: InputError naming `context.fibre` if it
/// is the zero vector (the check of the fibre laws' parameters).
Vec3 fibre_direction(const ParameterValues& values, const std::string& context);

/// Validates `values` against `schema`: unknown keys, missing required keys (for a Vector, any
/// of its three components) and values outside their range are InputErrors naming
/// `context.key`. Returns the values with defaults filled in.
ParameterValues validate_parameters(const std::vector<ParameterSchema>& schema,
                                    const ParameterValues& values, const std::string& context);

} // namespace trifem::material
