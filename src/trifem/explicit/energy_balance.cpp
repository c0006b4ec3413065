// SPDX-License-Identifier: MIT
#include "trifem/explicit/energy_balance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace trifem::explicit_dynamics {

EnergyBalance::EnergyBalance(const ExplicitView& model) {
  Real stiffness_volume = 0.0; // Σ μ_e V_e [mJ]
  for (Index c = 0; c < model.num_cells(); ++c)
    if (model.deformable(c))
      stiffness_volume += model.law(c).shear_modulus() * model.volumes()[c];
  floor_ = 1e-10 * stiffness_volume;
}

bool EnergyBalance::record(const Energies& e) {
  scale_ = std::max({scale_, std::abs(e.external_work), e.kinetic, std::abs(e.strain),
                     e.damping_work, std::abs(e.initial)});
  last_ = scale_ > floor_ ? std::abs(e.balance()) / scale_ : 0.0;
  if (!std::isfinite(last_))
    last_ = std::numeric_limits<Real>::infinity();
  max_ = std::max(max_, last_);
  const bool first = !exceeded_ && last_ > kThreshold;
  exceeded_ = exceeded_ || first;
  return first;
}

} // namespace trifem::explicit_dynamics
