// SPDX-License-Identifier: MIT
// Coupled Holmes-Mow solid, the strain-stiffening cartilage matrix (the FEBio "Holmes-Mow" form).
#pragma once

#include "trifem/material/elastic_law.hpp"
#include "trifem/material/schema.hpp"

namespace trifem::material {

/// Holmes & Mow (1990, J Biomech 23:1145, eq. 11) in FEBio's coupled form, with the Lame
/// constants lambda, mu of E, nu, Ha = lambda + 2 mu and the invariants I1, I2, I3 of C:
///   P = (2 mu - lambda)(I1 - 3) + lambda (I2 - 3) - Ha ln I3,   Q = beta P / Ha,
///   W = Ha/(4 beta) (e^Q - 1)   (W = P/4 at beta = 0, the limit),
///   S = 2 dW/dC = e^Q/2 dP/dC,  dP/dC = (2 mu - lambda + lambda I1) I - lambda C - Ha C^-1,
///   D = e^Q [ beta/Ha dP/dC (x) dP/dC + lambda (I (x) I - I (.) I) + Ha C^-1 (.) C^-1 ],
/// with (A (.) A)_IJKL = (A_IK A_JL + A_IL A_JK)/2. At C = I: S = 0, D = lambda I (x) I + 2 mu
/// I_sym. beta stiffens the solid in tension and compression alike.
class HolmesMow final : public ElasticLaw {
public:
  /// Parameters: E (Young's modulus, MPa, > 0), nu (Poisson's ratio, [0, 0.5)), beta
  /// (exponential stiffening, [0, inf)).
  explicit HolmesMow(const ParameterValues& params);
  static const std::vector<ParameterSchema>& schema();

  Real energy(const Mat3& C) const override;
  Mat3 stress(const Mat3& C) const override;
  StressTangent stress_tangent(const Mat3& C) const override;
  Real p_wave_modulus() const override { return lame_.lambda + 2.0 * lame_.mu; }
  Real shear_modulus() const override { return lame_.mu; }
  std::string type() const override { return "holmes-mow"; }

private:
  /// P(C), the exponent without the factor beta/Ha [MPa].
  Real exponent_base(const Mat3& C) const;
  /// dP/dC [MPa].
  Mat3 exponent_base_gradient(const Mat3& C) const;

  Lame lame_;
  Real beta_;
};

} // namespace trifem::material
