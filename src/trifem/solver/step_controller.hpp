// SPDX-License-Identifier: MIT
// Adaptive time step: lands on must points, cuts back on failure, regrows after easy steps.
#pragma once

#include "trifem/core/types.hpp"

#include <vector>

namespace trifem::solver {

/// Step-size settings [s].
struct StepSettings {
  Real start_time = 0.0;
  Real end_time = 1.0;
  Real dt = 0.1;
  Real dt_min = 1e-7;
  Real dt_max = 0.1;
  Real growth = 1.5;             ///< factor after an easy step
  Real cutback = 0.5;            ///< factor after a failed step
  int target_iterations = 6;     ///< a step is easy if it converged in at most this many iterations
  std::vector<Real> must_points; ///< times every step sequence must hit exactly
  /// > 0: a steady-state step; the problem reaches each time by backward-Euler pseudo-steps of
  /// this size (long against the transport times), repeated from the last until one changes no
  /// unknown by more than the Newton increment tolerance (run_time_loop), not by dt.
  Real steady_dt = 0.0;
};

/// Proposes steps and reacts to their outcome.
class StepController {
public:
  explicit StepController(StepSettings settings);

  bool finished() const;
  Real time() const { return time_; }
  /// Size of the next step (shortened to land on the next must point or the end time).
  Real next_step() const;
  /// The step [time, time + dt] converged in `iterations` Newton iterations.
  void accept(Real dt, int iterations);
  /// The step failed; returns false if the step is already at dt_min (the run must stop).
  bool reject(Real dt);
  /// True if a step of size dt cannot be cut back (it is at dt_min).
  bool at_minimum(Real dt) const;
  Real dt() const { return dt_; }
  const StepSettings& settings() const { return settings_; }
  int cutbacks() const { return cutbacks_; }

private:
  /// Largest of |start|, |end| and the span: the scale of the time tolerances (never zero).
  Real time_scale() const;

  StepSettings settings_;
  Real time_;
  Real dt_;
  int cutbacks_ = 0;
};

} // namespace trifem::solver
