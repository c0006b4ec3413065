// SPDX-License-Identifier: MIT
#include "trifem/solver/step_controller.hpp"

#include "trifem/core/error.hpp"

#include <algorithm>

namespace trifem::solver {
namespace {
/// Relative tolerance for "time equals a must point".
constexpr Real kTimeTol = 1e-10;
} // namespace

StepController::StepController(StepSettings settings)
    : settings_(std::move(settings)), time_(settings_.start_time), dt_(settings_.dt) {
  TRIFEM_VERIFY(settings_.dt > 0 && settings_.dt_min > 0 && settings_.dt_max >= settings_.dt_min,
                "bad step settings");
  std::sort(settings_.must_points.begin(), settings_.must_points.end());
}

bool StepController::finished() const {
  return time_ >= settings_.end_time - kTimeTol * std::max(1.0, std::abs(settings_.end_time));
}

Real StepController::next_step() const {
  const Real scale = std::max(1.0, std::abs(settings_.end_time));
  Real target = settings_.end_time;
  for (Real t : settings_.must_points) {
    if (t > time_ + kTimeTol * scale) {
      target = std::min(target, t);
      break;
    }
  }
  Real dt = std::min(dt_, target - time_);
  // Avoid a sliver step just before the target: stretch this step instead.
  if (target - time_ - dt < 0.25 * dt)
    dt = target - time_;
  return dt;
}

void StepController::accept(Real dt, int iterations) {
  time_ += dt;
  const Real scale = std::max(1.0, std::abs(settings_.end_time));
  for (Real t : settings_.must_points)
    if (std::abs(time_ - t) <= kTimeTol * scale)
      time_ = t;
  if (iterations <= settings_.target_iterations)
    dt_ = std::min(settings_.dt_max, std::max(dt_, dt) * settings_.growth);
}

bool StepController::reject(Real dt) {
  if (dt <= settings_.dt_min * (1.0 + 1e-12))
    return false;
  ++cutbacks_;
  dt_ = std::max(settings_.dt_min, dt * settings_.cutback);
  return true;
}

} // namespace trifem::solver
