// SPDX-License-Identifier: MIT
// Global water and ion balances of mixture models: the change of the totals over a step
// against the boundary outflow, both computed independently.
#pragma once

#include "model.hpp"

#include <array>

namespace trifem::app {

/// Totals and outflow of water [mm^3, mm^3/s], cations and anions [mmol, mmol/s].
struct Balance {
  std::array<Real, 3> total{};
  std::array<Real, 3> outflow{};
};

/// Tracks the balance errors of a run.
class MassBalance {
public:
  explicit MassBalance(const Model& model);
  /// Current totals (committed state) and boundary outflow (state x).
  Balance measure() const;
  /// Records a converged step of size dt: error = |delta total + dt outflow| / total.
  void record_step(Real dt);
  /// Largest relative error so far per quantity (water, cation, anion).
  const std::array<Real, 3>& worst() const { return worst_; }
  bool has_ions() const;

private:
  const Model& model_;
  std::vector<mesh::Facet> boundary_;
  Balance last_;
  std::array<Real, 3> worst_{};
};

} // namespace trifem::app
