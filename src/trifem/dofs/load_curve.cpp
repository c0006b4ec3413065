// SPDX-License-Identifier: MIT
#include "trifem/dofs/load_curve.hpp"

#include "trifem/core/error.hpp"

#include <algorithm>
#include <cmath>

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

} // namespace

LoadCurve::LoadCurve(std::vector<std::pair<Real, Real>> points, Interpolation interpolation,
                     const std::string& context)
    : points_(std::move(points)), interpolation_(interpolation) {
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

} // namespace trifem::dofs
