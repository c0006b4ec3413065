// SPDX-License-Identifier: MIT
// Two runs of one problem (or of two inputs that build the same one): on one process they give
// the same bits; on several, MUMPS schedules its work dynamically, so their round-off may
// differ from run to run and they agree to round-off of the answer's scale instead.
#pragma once

#include "trifem/core/types.hpp"
#include "trifem/parallel/communicator.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace trifem::test {

/// Relative agreement of two runs on several processes (measured: 2.3e-16).
inline constexpr Real kRunToRunTolerance = 1e-12;

/// `a` and `b` are the same bits on one process, within kRunToRunTolerance of `scale` on
/// several.
inline testing::AssertionResult same_run_to_run(Real a, Real b, Real scale) {
  const bool same = parallel::size() <= 1 ? a == b : std::abs(a - b) <= kRunToRunTolerance * scale;
  if (same)
    return testing::AssertionSuccess();
  return testing::AssertionFailure()
         << a << " and " << b << " differ by " << std::abs(a - b) << " (scale " << scale << ", "
         << parallel::size() << " processes)";
}

/// Two states: the same bits on one process, within kRunToRunTolerance of the larger's
/// largest magnitude on several.
inline testing::AssertionResult same_run_to_run(const Vector& a, const Vector& b) {
  if (a.size() != b.size())
    return testing::AssertionFailure() << "sizes " << a.size() << " and " << b.size();
  const Real scale = std::max(a.lpNorm<Eigen::Infinity>(), b.lpNorm<Eigen::Infinity>());
  for (Index i = 0; i < a.size(); ++i)
    if (auto r = same_run_to_run(a[i], b[i], scale); !r)
      return r << " at entry " << i;
  return testing::AssertionSuccess();
}

} // namespace trifem::test
