// SPDX-License-Identifier: MIT
// Neo-Hookean solid whose volume is bounded by its solid content (FEBio's "porous neo-Hookean"):
// the pores close as J falls to the solid volume fraction, where the energy becomes infinite.
#pragma once

#include "trifem/material/elastic_law.hpp"
#include "trifem/material/schema.hpp"

#include <string>
#include <vector>

namespace trifem::material {

/// With the solid volume fraction phi_s (referential), phi_w = 1 - phi_s and the volume ratio of
/// the pores J~ = (J - phi_s)/phi_w (FEBio's FEPorousNeoHookean, its lambda = 0):
///   W = mu [ (I1 (J~/J)^(2/3) - 3)/2 - ln J~ ],   mu = E/3 (1 + phi_w^2/2),
/// so that E is the small-strain Young's modulus (bulk modulus K = 2 mu / (3 phi_w^2)).
/// S = mu g I + q C^-1 with g = (J~/J)^(2/3), q = mu I1 g phi_s / (3 (J - phi_s)) - mu J/(J -
/// phi_s); D = 4 d2W/dC2 (derived in porous_neo_hookean.cpp). Defined for J > phi_s.
class PorousNeoHookean final : public ElasticLaw {
public:
  /// Parameters: E (MPa, > 0), phi0 (the solid volume fraction, [0, 1)).
  explicit PorousNeoHookean(const ParameterValues& params);
  static const std::vector<ParameterSchema>& schema();

  Real energy(const Mat3& C) const override;
  Mat3 stress(const Mat3& C) const override;
  StressTangent stress_tangent(const Mat3& C) const override;
  Real p_wave_modulus() const override { return bulk_ + 4.0 / 3.0 * mu_; }
  Real shear_modulus() const override { return mu_; }
  std::string type() const override { return "porous-neo-hookean"; }

private:
  Real phi_s_, phi_w_, mu_, bulk_;
};

} // namespace trifem::material
