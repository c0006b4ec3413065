// SPDX-License-Identifier: MIT
// Uncoupled Veronda-Westmann solid (the FEBio "Veronda-Westmann" form).
#pragma once

#include "trifem/material/energy_function_law.hpp"
#include "trifem/material/schema.hpp"
#include "trifem/material/uncoupled.hpp"

#include <string>

namespace trifem::material {

/// Veronda & Westmann (1970) in FEBio's uncoupled form:
///   W = c1 [exp(c2 (I1~ - 3)) - 1] - c1 c2 / 2 (I2~ - 3) + k/2 (ln J)^2,
/// with the isochoric invariants of uncoupled::isochoric. Small strain: shear modulus
/// mu = c1 c2, bulk modulus k.
class VerondaWestmann final : public EnergyFunctionLaw {
public:
  /// Parameters: c1 (MPa, > 0), c2 (> 0), k (bulk modulus, MPa, > 0).
  explicit VerondaWestmann(const ParameterValues& params);
  static const std::vector<ParameterSchema>& schema();

  Real p_wave_modulus() const override { return k_ + 4.0 / 3.0 * shear_modulus(); }
  Real shear_modulus() const override { return c1_ * c2_; }
  std::string type() const override { return "veronda-westmann"; }

private:
  uncoupled::ScalarFunction strain_energy(const Mat3& C, bool with_hessian) const override;

  Real c1_, c2_, k_;
};

} // namespace trifem::material
