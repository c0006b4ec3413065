// SPDX-License-Identifier: MIT
#include "trifem/dofs/load_curve.hpp"

#include "trifem/core/error.hpp"

#include <algorithm>
#include <cmath>

namespace trifem::dofs {

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
