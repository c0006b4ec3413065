// SPDX-License-Identifier: MIT
// Uncoupled Holmes-Mow law (FEBio's "uncoupled Holmes-Mow"): an exponential of the deviatoric
// first invariant plus the volumetric energy of the uncoupled laws.
#pragma once

#include "trifem/material/energy_function_law.hpp"
#include "trifem/material/schema.hpp"
#include "trifem/material/uncoupled.hpp"

#include <string>

namespace trifem::material {

/// W = mu/(2 beta) (exp(beta (I1~ - 3)) - 1) + k/2 (ln J)^2 (FEBio's FEHolmesMowUC), so that
/// dW/dI1~ = mu/2 exp(beta (I1~ - 3)): the shear modulus is mu at small strain; beta = 0 is the
/// limit mu/2 (I1~ - 3), an uncoupled neo-Hookean.
class HolmesMowUncoupled final : public EnergyFunctionLaw {
public:
  /// Parameters: mu (MPa, > 0), beta (>= 0), k (bulk modulus, MPa, > 0).
  explicit HolmesMowUncoupled(const ParameterValues& params);
  static const std::vector<ParameterSchema>& schema();

  Real p_wave_modulus() const override { return k_ + 4.0 / 3.0 * mu_; }
  Real shear_modulus() const override { return mu_; }
  std::string type() const override { return "holmes-mow-uncoupled"; }

private:
  /// W(C) with dW/dC and, if `with_hessian`, d2W/dC2.
  uncoupled::ScalarFunction strain_energy(const Mat3& C, bool with_hessian) const override;

  Real mu_, beta_, k_;
};

} // namespace trifem::material
