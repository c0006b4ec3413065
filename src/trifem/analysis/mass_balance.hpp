// SPDX-License-Identifier: MIT
// Water and ion balances of mixture models, for the whole model and for every body (cell
// block): the change of the totals over a step against the outflow through the body's
// boundary (contact interfaces included), both computed independently.
#pragma once

#include "trifem/model/model.hpp"

#include <array>

namespace trifem::analysis {

/// Totals and outflow of water [mm^3, mm^3/s], cations and anions [mmol, mmol/s].
struct Balance {
  std::array<Real, 3> total{};
  std::array<Real, 3> outflow{};
};

/// The balance of one region: its mixture elements and its boundary facets.
struct BalanceRegion {
  std::string name;                ///< "" for the whole model, else the cell block
  std::vector<Index> elements;     ///< mixture-term elements
  std::vector<mesh::Facet> facets; ///< boundary facets of the region's cells
  Balance last;                    ///< at the last recorded step
  std::array<Real, 3> worst{};     ///< largest relative error so far
};

/// Tracks the balance errors of a run.
class MassBalance {
public:
  explicit MassBalance(const model::Model& model);
  /// Current totals (committed state) and boundary outflow (state x) of the whole model.
  Balance measure() const { return measure(regions_.front()); }
  /// Records a converged step of size dt: error = |delta total + dt outflow| / total, for the
  /// model and for every body.
  void record_step(Real dt);
  /// Largest relative error so far per quantity (water, cation, anion) of the whole model.
  const std::array<Real, 3>& worst() const { return regions_.front().worst; }
  /// The whole model first, then one region per cell block with mixture cells (if more than
  /// one block).
  const std::vector<BalanceRegion>& regions() const { return regions_; }
  bool has_ions() const;

private:
  Balance measure(const BalanceRegion& region) const;

  const model::Model& model_;
  std::vector<BalanceRegion> regions_;
};

} // namespace trifem::analysis
