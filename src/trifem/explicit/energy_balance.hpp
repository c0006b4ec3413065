// SPDX-License-Identifier: MIT
// Energy balance check of an explicit run: kinetic + strain − external work + damping work stays
// at its initial value (0 from rest, the strain energy of a pre-strained start) up to the
// time-discretisation error; a large deviation means an unstable step.
#pragma once

#include "trifem/explicit/explicit_solver.hpp"
#include "trifem/explicit/explicit_view.hpp"

#include <array>

namespace trifem::explicit_dynamics {

/// Records the energies of a run and measures the balance error |total − initial| against the
/// largest energy met so far (external work, kinetic, strain, damping work or initial energy).
/// Energies below a round-off floor (10⁻¹⁰ Σ_e μ_e V_e: the rounding of W(C) near C = I) are not
/// judged.
class EnergyBalance {
public:
  /// Errors above this fraction of the largest energy are reported.
  static constexpr Real kThreshold = 0.05;

  explicit EnergyBalance(const ExplicitView& model);

  /// Adds the energies at one time; true the first time the error exceeds kThreshold.
  bool record(const Energies& e);
  /// |total − initial| / scale of the last record (0 while the scale is below the floor).
  Real last_error() const { return last_; }
  /// Largest error recorded so far.
  Real max_error() const { return max_; }
  bool exceeded() const { return exceeded_; }
  /// The scale, the largest error and whether it was exceeded (restart files).
  std::array<Real, 3> state() const { return {scale_, max_, exceeded_ ? 1.0 : 0.0}; }
  void restore(const std::array<Real, 3>& s) {
    scale_ = s[0];
    max_ = s[1];
    exceeded_ = s[2] != 0.0;
  }

private:
  Real floor_ = 0.0;
  Real scale_ = 0.0;
  Real last_ = 0.0;
  Real max_ = 0.0;
  bool exceeded_ = false;
};

} // namespace trifem::explicit_dynamics
