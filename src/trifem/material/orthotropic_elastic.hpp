// SPDX-License-Identifier: MIT
// Linear orthotropic law in the Green-Lagrange strain (FEBio's "orthotropic elastic").
#pragma once

#include "trifem/material/elastic_law.hpp"
#include "trifem/material/schema.hpp"

#include <string>

namespace trifem::material {

/// S = D : E with E = (C - I)/2 and W = E : D : E / 2, D the orthotropic stiffness of the
/// engineering constants in the law's own basis (the material axes: [<name>.axes] turns it):
/// the normal block is the inverse of the compliance
///   [ 1/E1     -v12/E1  -v31/E3 ]
///   [ -v12/E1  1/E2     -v23/E2 ]
///   [ -v31/E3  -v23/E2  1/E3    ]   (FEBio's convention for v12, v23, v31),
/// and S_12 = G12 (2 E_12), S_23 = G23 (2 E_23), S_31 = G31 (2 E_31). This is FEBio's
/// FEOrthoElastic: W = sum_a mu_a A_a : E^2 + 1/2 sum_ab lambda_ab (A_a : E)(A_b : E) with
/// A_a = e_a (x) e_a is the same quadratic form. D is constant; the stress grows with C as in the
/// Saint Venant-Kirchhoff law (stable only in moderate compression).
class OrthotropicElastic final : public ElasticLaw {
public:
  /// Parameters: E1, E2, E3 (MPa, > 0), G12, G23, G31 (MPa, > 0), v12, v23, v31 (the compliance
  /// positive definite).
  explicit OrthotropicElastic(const ParameterValues& params);
  static const std::vector<ParameterSchema>& schema();
  /// The check the schema's ranges cannot express, a positive definite compliance (a stable
  /// material): InputError naming `context.v12`, `context.v23` and `context.v31` otherwise.
  static void check(const ParameterValues& params, const std::string& context);

  Real energy(const Mat3& C) const override;
  Mat3 stress(const Mat3& C) const override;
  StressTangent stress_tangent(const Mat3& C) const override;
  /// The largest normal stiffness D_11, D_22, D_33 (the fastest longitudinal wave).
  Real p_wave_modulus() const override { return p_wave_modulus_; }
  /// The largest shear modulus.
  Real shear_modulus() const override { return shear_modulus_; }
  std::string type() const override { return "orthotropic-elastic"; }

  /// The constant tangent D (Voigt: stress-like rows, strain-like columns).
  const Mat6& stiffness() const { return D_; }

private:
  Mat6 D_ = Mat6::Zero();
  Real p_wave_modulus_ = 0.0;
  Real shear_modulus_ = 0.0;
};

} // namespace trifem::material
