// SPDX-License-Identifier: MIT
// Saint Venant-Kirchhoff solid (the paper's solid matrix, Chen et al. 2009, section 4.1).
#pragma once

#include "trifem/material/elastic_law.hpp"
#include "trifem/material/schema.hpp"

namespace trifem::material {

/// W = lambda/2 (tr E)^2 + mu E:E,  S = lambda tr(E) I + 2 mu E,
/// D = lambda I (x) I + 2 mu I_sym (constant). Unstable in strong compression: the uniaxial
/// Cauchy stress has a minimum at stretch 1/sqrt(3).
class SaintVenantKirchhoff final : public ElasticLaw {
public:
  /// Parameters: E (Young's modulus, MPa, > 0), nu (Poisson's ratio, (-1, 0.5)).
  explicit SaintVenantKirchhoff(const ParameterValues& params);
  static const std::vector<ParameterSchema>& schema();

  Real energy(const Mat3& C) const override;
  Mat3 stress(const Mat3& C) const override;
  StressTangent stress_tangent(const Mat3& C) const override;
  Real p_wave_modulus() const override { return lame_.lambda + 2.0 * lame_.mu; }
  Real shear_modulus() const override { return lame_.mu; }
  std::string type() const override { return "saint-venant-kirchhoff"; }

private:
  Lame lame_;
};

} // namespace trifem::material
