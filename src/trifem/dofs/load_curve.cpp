// SPDX-License-Identifier: MIT
#include "trifem/dofs/load_curve.hpp"

#include "trifem/core/error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace trifem::dofs {
namespace {

/// The parabola through (a, b, c) at t.
Real parabola(Real t, const std::pair<Real, Real>& a, const std::pair<Real, Real>& b,
              const std::pair<Real, Real>& c) {
  const auto [ta, fa] = a;
  const auto [tb, fb] = b;
  const auto [tc, fc] = c;
  return fa * (t - tb) * (t - tc) / ((ta - tb) * (ta - tc)) +
         fb * (t - ta) * (t - tc) / ((tb - ta) * (tb - tc)) +
         fc * (t - ta) * (t - tb) / ((tc - ta) * (tc - tb));
}

/// FEBio's SMOOTH between points[i] and points[i + 1] (at least three points).
Real quadratic_blend(Real t, const std::vector<std::pair<Real, Real>>& p, std::size_t i) {
  const std::size_t last = p.size() - 1;
  if (i == 0)
    return parabola(t, p[0], p[1], p[2]);
  if (i + 1 == last)
    return parabola(t, p[last - 2], p[last - 1], p[last]);
  const Real w = (t - p[i].first) / (p[i + 1].first - p[i].first);
  const Real left = parabola(t, p[i - 1], p[i], p[i + 1]);
  const Real right = parabola(t, p[i], p[i + 1], p[i + 2]);
  return left + w * (right - left);
}

/// Round-off allowed, relative to the magnitude of the times, when a time shifted by whole
/// periods is compared with the times of the points (a few ulps of t + kT and of t − kT).
constexpr Real kPeriodRoundOff = 64.0 * std::numeric_limits<Real>::epsilon();

/// Most periods breakpoints(from, to) lists (the case readers allow far fewer must points).
constexpr Real kMaxPeriods = 1e8;

} // namespace

LoadCurve::LoadCurve(std::vector<std::pair<Real, Real>> points, Interpolation interpolation,
                     const std::string& context, Extension extension)
    : points_(std::move(points)), interpolation_(interpolation), extension_(extension) {
  TRIFEM_CHECK(!points_.empty(), "{}: needs at least one (time, value) point", context);
  for (std::size_t i = 0; i < points_.size(); ++i) {
    TRIFEM_CHECK(std::isfinite(points_[i].first) && std::isfinite(points_[i].second),
                 "{}: point {} is not finite", context, i + 1);
    TRIFEM_CHECK(i == 0 || points_[i].first > points_[i - 1].first,
                 "{}: times must increase strictly (point {} has t = {} after t = {})", context,
                 i + 1, points_[i].first, points_[i - 1].first);
  }
}

LoadCurve LoadCurve::constant(Real value) {
  return LoadCurve({{0.0, value}}, Interpolation::Step);
}

Real LoadCurve::operator()(Real t) const {
  if (!repeats())
    return interpolate(t);
  const auto [shifted, periods] = into_period(t);
  const Real rise = points_.back().second - points_.front().second;
  return interpolate(shifted) + (extension_ == Extension::RepeatOffset ? periods * rise : 0.0);
}

std::pair<Real, Real> LoadCurve::into_period(Real t) const {
  const Real first = points_.front().first, last = points_.back().first;
  const Real period = last - first;
  const Real tol = kPeriodRoundOff * (std::abs(t) + std::abs(first) + std::abs(last));
  Real k = 0.0; // FEBio: after the points into (t_0, t_n], before them into [t_0, t_n)
  if (t > last + tol)
    k = std::ceil((t - last - tol) / period);
  else if (t < first - tol)
    k = -std::ceil((first - tol - t) / period);
  if (k == 0.0)
    return {t, 0.0};
  return {snap_to_point(t - k * period, tol), k};
}

Real LoadCurve::snap_to_point(Real t, Real tol) const {
  const auto hi = std::lower_bound(points_.begin(), points_.end(), t,
                                   [](const auto& p, Real v) { return p.first < v; });
  if (hi != points_.end() && hi->first - t <= tol)
    return hi->first;
  if (hi != points_.begin() && t - (hi - 1)->first <= tol)
    return (hi - 1)->first;
  return t;
}

Real LoadCurve::interpolate(Real t) const {
  if (t <= points_.front().first)
    return points_.front().second;
  if (t >= points_.back().first)
    return points_.back().second;
  const auto hi = std::upper_bound(points_.begin(), points_.end(), t,
                                   [](Real v, const auto& p) { return v < p.first; });
  const auto lo = hi - 1;
  const Real s = (t - lo->first) / (hi->first - lo->first);
  switch (interpolation_) {
  case Interpolation::Step:
    return lo->second;
  case Interpolation::Next:
    return s > 0.0 ? hi->second : lo->second;
  case Interpolation::Linear:
    return lo->second + s * (hi->second - lo->second);
  case Interpolation::Smooth:
    break;
  case Interpolation::QuadraticBlend:
    if (points_.size() == 2)
      return lo->second + s * (hi->second - lo->second);
    return quadratic_blend(t, points_, static_cast<std::size_t>(lo - points_.begin()));
  }
  const Real h = s * s * (3.0 - 2.0 * s);
  return lo->second + h * (hi->second - lo->second);
}

std::vector<Real> LoadCurve::breakpoints() const {
  std::vector<Real> t;
  for (const auto& p : points_)
    t.push_back(p.first);
  return t;
}

std::vector<Real> LoadCurve::breakpoints(Real from, Real to) const {
  std::vector<Real> t;
  if (!repeats()) {
    for (const auto& p : points_)
      if (p.first >= from && p.first <= to)
        t.push_back(p.first);
    return t;
  }
  const Real first = points_.front().first, period = points_.back().first - first;
  const Real k_begin = std::floor((from - first) / period),
             k_end = std::ceil((to - first) / period);
  TRIFEM_CHECK(k_end - k_begin <= kMaxPeriods,
               "a load curve of period {} s repeats {:.3g} times in [{}, {}], more than the {:.0e} "
               "allowed",
               period, k_end - k_begin, from, to, kMaxPeriods);
  for (Real k = k_begin; k <= k_end; ++k)
    for (std::size_t i = 0; i + 1 < points_.size(); ++i) // t_n + kT is t_0 + (k + 1)T
      if (const Real b = points_[i].first + k * period; b >= from && b <= to)
        t.push_back(b);
  return t;
}

} // namespace trifem::dofs
