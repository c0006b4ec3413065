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

/// How a load curve goes on before its first point t_0 and after its last point t_n (FEBio's
/// `extend`). A repeating curve takes at t the value of the curve at t − kT, T = t_n − t_0, for
/// the whole number k that brings t into the points: into (t_0, t_n] after them and into
/// [t_0, t_n) before them, as FEBio does (the value at t_n + kT is that of t_n, the value at
/// t_0 − kT that of t_0). A curve of one point is constant whatever its extension.
enum class Extension {
  Constant,    ///< the first value before the points, the last one after them
  Repeat,      ///< periodic with period T (FEBio's REPEAT)
  RepeatOffset ///< periodic plus k (v_n − v_0): each period starts where the previous one
               ///< ended (FEBio's REPEAT OFFSET)
};

/// A piecewise function of time through (t_i, v_i), t strictly increasing; constant outside
/// the points or repeating them (Extension).
class LoadCurve {
public:
  /// Throws InputError (naming `context`) if there is no point or times do not increase.
  LoadCurve(std::vector<std::pair<Real, Real>> points, Interpolation interpolation,
            const std::string& context = "load curve", Extension extension = Extension::Constant);
  /// A constant curve (value 1 at every time).
  static LoadCurve constant(Real value = 1.0);

  Real operator()(Real t) const;
  /// Abscissae of the points: step boundaries should land on them (must points). For a
  /// repeating curve these are the ones of one period: see breakpoints(from, to).
  std::vector<Real> breakpoints() const;
  /// The breakpoints in [from, to], ascending: the times of the points, and for a repeating
  /// curve the times of its points shifted by every whole number of periods that lands them in
  /// [from, to] (the end of one period, the start of the next, once). At one of them the curve
  /// takes the value of the shifted point (of t_n at a period boundary, see Extension) without
  /// the round-off of the shift. A repeating curve has about (to − from) / T times its number
  /// of points there: the caller bounds the window (error beyond 1e8 periods).
  std::vector<Real> breakpoints(Real from, Real to) const;

private:
  /// The curve inside its points, constant outside them.
  Real interpolate(Real t) const;
  /// `t` shifted by k whole periods into the points (see Extension), and k.
  std::pair<Real, Real> into_period(Real t) const;
  /// `t` if no point is within `tol` of it, else that point's time.
  Real snap_to_point(Real t, Real tol) const;
  bool repeats() const { return extension_ != Extension::Constant && points_.size() > 1; }

  std::vector<std::pair<Real, Real>> points_;
  Interpolation interpolation_;
  Extension extension_;
};

} // namespace trifem::dofs
