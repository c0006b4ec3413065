// SPDX-License-Identifier: MIT
#include "trifem/solver/step_controller.hpp"

#include "trifem/core/error.hpp"

#include <algorithm>

namespace trifem::solver {
namespace {
/// Tolerance for "time equals a must point", relative to the time scale.
constexpr Real kTimeTol = 1e-10;
} // namespace

StepController::StepController(StepSettings settings)
    : settings_(std::move(settings)), time_(settings_.start_time), dt_(settings_.dt) {
  TRIFEM_VERIFY(settings_.dt > 0 && settings_.dt_min > 0 && settings_.dt_max >= settings_.dt_min &&
                    settings_.end_time > settings_.start_time,
                "bad step settings");
  std::sort(settings_.must_points.begin(), settings_.must_points.end());
}

Real StepController::time_scale() const {
  // the accumulated round-off of the time grows with |t|; the span cannot vanish
  return std::max({std::abs(settings_.start_time), std::abs(settings_.end_time),
                   settings_.end_time - settings_.start_time});
}

bool StepController::finished() const {
  return time_ >= settings_.end_time - kTimeTol * time_scale();
}

Real StepController::next_step() const {
  Real target = settings_.end_time;
  for (Real t : settings_.must_points) {
    if (t > time_ + kTimeTol * time_scale()) {
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
  for (Real t : settings_.must_points)
    if (std::abs(time_ - t) <= kTimeTol * time_scale())
      time_ = t;
  if (std::abs(time_ - settings_.end_time) <= kTimeTol * time_scale())
    time_ = settings_.end_time;
  if (iterations <= settings_.target_iterations)
    dt_ = std::min(settings_.dt_max, std::max(dt_, dt) * settings_.growth);
}

bool StepController::at_minimum(Real dt) const {
  return dt <= settings_.dt_min * (1.0 + 1e-12);
}

bool StepController::reject(Real dt) {
  if (at_minimum(dt))
    return false;
  ++cutbacks_;
  dt_ = std::max(settings_.dt_min, dt * settings_.cutback);
  return true;
}

} // namespace trifem::solver
