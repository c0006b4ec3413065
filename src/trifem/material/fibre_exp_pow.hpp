// SPDX-License-Identifier: MIT
// Tension-only fibre family with an exponential-power energy (FEBio's "fiber-exp-pow").
#pragma once

#include "trifem/material/elastic_law.hpp"
#include "trifem/material/schema.hpp"

#include <string>

namespace trifem::material {

/// One fibre family of reference direction a0 (|a0| = 1), stretched when I_n = a0 . C a0 > 1:
///   W(I_n) = xi/(alpha beta) [exp(alpha (I_n - 1)^beta) - 1]   (I_n > 1; alpha = 0: the limit
///            W = xi/beta (I_n - 1)^beta),   W = 0 for I_n <= 1 (no load in compression),
///   S = 2 W'(I_n) a0 (x) a0,   D = 4 W''(I_n) a0 (x) a0 (x) a0 (x) a0,
/// with x = I_n - 1, W' = xi x^(beta-1) e^(alpha x^beta),
/// W'' = xi x^(beta-2) [beta (alpha x^beta + 1) - 1] e^(alpha x^beta) (FEBio user's manual,
/// "Fiber with Exponential-Power Law"; FEBio's FEFiberExpPow with mu = 0, lam0 = 1). beta >= 2
/// keeps W' continuous at I_n = 1 (D jumps there by 4 xi a0^4 when beta = 2). At C = I the
/// fibre is inert (S = 0, D = 0), so both small-strain moduli are 0: the law is valid only as a
/// constituent of a SolidMixture with a ground matrix (registry: constituent_laws()).
class FibreExpPow final : public ElasticLaw {
public:
  /// Parameters: ksi (MPa, >= 0), alpha (>= 0), beta (>= 2), fibre (Vector, nonzero;
  /// normalised here).
  explicit FibreExpPow(const ParameterValues& params);
  static const std::vector<ParameterSchema>& schema();
  /// The check the schema's ranges cannot express, fibre != 0: InputError naming
  /// `context.fibre` otherwise.
  static void check(const ParameterValues& params, const std::string& context);

  Real energy(const Mat3& C) const override;
  Mat3 stress(const Mat3& C) const override;
  StressTangent stress_tangent(const Mat3& C) const override;
  /// 0: the fibre carries no load at C = I (and none across its direction).
  Real p_wave_modulus() const override { return 0.0; }
  /// 0, as p_wave_modulus().
  Real shear_modulus() const override { return 0.0; }
  std::string type() const override { return "fibre-exp-pow"; }

  /// The unit fibre direction a0 in the reference configuration.
  const Vec3& direction() const { return a0_; }

private:
  /// W'(I_n) and W''(I_n) at x = I_n - 1 > 0.
  std::pair<Real, Real> derivatives(Real x) const;

  Real ksi_;
  Real alpha_;
  Real beta_;
  Vec3 a0_;
};

} // namespace trifem::material
