// SPDX-License-Identifier: MIT
// Compressible neo-Hookean solid (the FEBio "neo-Hookean" form).
#pragma once

#include "trifem/material/elastic_law.hpp"
#include "trifem/material/schema.hpp"

namespace trifem::material {

/// W = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2   (Bonet & Wood, eq. 6.27),
/// S = mu (I - C^-1) + lambda ln J C^-1,
/// D = lambda C^-1 (x) C^-1 + 2 (mu - lambda ln J) C^-1 (.) C^-1,
/// with (A (.) A)_IJKL = (A_IK A_JL + A_IL A_JK)/2.
class NeoHookean final : public ElasticLaw {
public:
  /// Parameters: E (Young's modulus, MPa, > 0), nu (Poisson's ratio, (-1, 0.5)).
  explicit NeoHookean(const ParameterValues& params);
  static const std::vector<ParameterSchema>& schema();

  Real energy(const Mat3& C) const override;
  Mat3 stress(const Mat3& C) const override;
  StressTangent stress_tangent(const Mat3& C) const override;
  Real p_wave_modulus() const override { return lame_.lambda + 2.0 * lame_.mu; }
  Real shear_modulus() const override { return lame_.mu; }
  std::string type() const override { return "neo-hookean"; }

private:
  Lame lame_;
};

} // namespace trifem::material
