// SPDX-License-Identifier: MIT
// Load curves: scalar functions of time that scale prescribed values and loads.
#pragma once

#include "trifem/core/types.hpp"

#include <string>
#include <utility>
#include <vector>

namespace trifem::dofs {

/// How a load curve interpolates between its points.
enum class Interpolation {
  Linear, ///< piecewise linear
  Step,   ///< value of the last point at or before t
  Smooth, ///< piecewise cubic Hermite with zero slope at the points (C1, no overshoot)
  Next,   ///< value of the first point at or after t (FEBio's STEP)
  /// FEBio's SMOOTH: between points i and i+1 the linear blend of the parabolas through
  /// (i−1, i, i+1) and (i, i+1, i+2); the one parabola of the first or last three points in
  /// the first and last intervals; linear through two points (C1, passes through the points,
  /// exact for a quadratic)
  QuadraticBlend
};

/// A piecewise function of time through (t_i, v_i), t strictly increasing; constant outside.
class LoadCurve {
public:
  /// Throws InputError (naming `context`) if there is no point or times do not increase.
  LoadCurve(std::vector<std::pair<Real, Real>> points, Interpolation interpolation,
            const std::string& context = "load curve");
  /// A constant curve (value 1 at every time).
  static LoadCurve constant(Real value = 1.0);

  Real operator()(Real t) const;
  /// Abscissae of the points: step boundaries should land on them (must points).
  std::vector<Real> breakpoints() const;

private:
  std::vector<std::pair<Real, Real>> points_;
  Interpolation interpolation_;
};

} // namespace trifem::dofs
