// SPDX-License-Identifier: MIT
// Uncoupled Mooney-Rivlin solid (the FEBio "Mooney-Rivlin" form).
#pragma once

#include "trifem/material/energy_function_law.hpp"
#include "trifem/material/schema.hpp"
#include "trifem/material/uncoupled.hpp"

#include <string>

namespace trifem::material {

/// W = c1 (I1~ - 3) + c2 (I2~ - 3) + k/2 (ln J)^2 with I1~ = I3^(-1/3) I1, I2~ = I3^(-2/3) I2
/// the invariants of C~ = J^(-2/3) C (FEBio theory manual, uncoupled Mooney-Rivlin),
///   S = 2 dW/dC = 2 c1 dI1~/dC + 2 c2 dI2~/dC + k ln J C^-1,
///   D = 4 d2W/dC2 = 4 c1 d2I1~/dC2 + 4 c2 d2I2~/dC2 + k (C^-1 (x) C^-1 - 2 ln J C^-1 (.) C^-1),
/// with dI1/dC = I, dI2/dC = I1 I - C, d2I2/dC2 = I (x) I - I (.) I and the isochoric scaling of
/// uncoupled::isochoric. Small strain: shear modulus mu = 2 (c1 + c2), bulk modulus k.
class MooneyRivlin final : public EnergyFunctionLaw {
public:
  /// Parameters: c1, c2 (MPa, c1 + c2 > 0), k (bulk modulus, MPa, > 0).
  explicit MooneyRivlin(const ParameterValues& params);
  static const std::vector<ParameterSchema>& schema();
  /// The check the schema's ranges cannot express, c1 + c2 > 0: InputError naming
  /// `context.c1` and `context.c2` otherwise.
  static void check(const ParameterValues& params, const std::string& context);

  Real p_wave_modulus() const override { return k_ + 4.0 / 3.0 * shear_modulus(); }
  Real shear_modulus() const override { return 2.0 * (c1_ + c2_); }
  std::string type() const override { return "mooney-rivlin"; }

private:
  /// W(C) with dW/dC and, if `with_hessian`, d2W/dC2.
  uncoupled::ScalarFunction strain_energy(const Mat3& C, bool with_hessian) const override;

  Real c1_;
  Real c2_;
  Real k_;
};

} // namespace trifem::material
