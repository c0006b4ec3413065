// SPDX-License-Identifier: MIT
// Wall-clock time of a part of a run, for its timings.
#pragma once

#include <chrono>

namespace trifem {

using WallClock = std::chrono::steady_clock;

/// Seconds since `start`.
inline double seconds_since(WallClock::time_point start) {
  return std::chrono::duration<double>(WallClock::now() - start).count();
}

/// Adds the wall-clock seconds of its scope to an accumulator.
class ScopedTimer {
public:
  explicit ScopedTimer(double& sink) : sink_(sink), start_(WallClock::now()) {}
  ~ScopedTimer() { sink_ += seconds_since(start_); }
  ScopedTimer(const ScopedTimer&) = delete;
  ScopedTimer& operator=(const ScopedTimer&) = delete;

private:
  double& sink_;
  WallClock::time_point start_;
};

} // namespace trifem
