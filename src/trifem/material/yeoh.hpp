// SPDX-License-Identifier: MIT
// Uncoupled Yeoh solid (the FEBio "Yeoh" form).
#pragma once

#include "trifem/material/energy_function_law.hpp"
#include "trifem/material/schema.hpp"
#include "trifem/material/uncoupled.hpp"

#include <array>
#include <string>

namespace trifem::material {

/// Yeoh (1993) in FEBio's uncoupled form: with x = I1~ - 3, I1~ = I3^(-1/3) I1,
///   W = c1 x + c2 x^2 + ... + c6 x^6 + k/2 (ln J)^2,
///   dW/dC = W'(x) dI1~/dC + k dU/dC,  d2W/dC2 = W''(x) dI1~/dC (x) dI1~/dC + W'(x) d2I1~/dC2
///           + k d2U/dC2,
/// the isochoric I1~ and U = (ln J)^2/2 those of uncoupled::isochoric and log_volumetric.
/// Small strain: shear modulus mu = 2 c1, bulk modulus k.
class Yeoh final : public EnergyFunctionLaw {
public:
  /// Parameters: c1 (MPa, > 0), c2..c6 (MPa, default 0), k (bulk modulus, MPa, > 0).
  explicit Yeoh(const ParameterValues& params);
  static const std::vector<ParameterSchema>& schema();

  Real p_wave_modulus() const override { return k_ + 4.0 / 3.0 * shear_modulus(); }
  Real shear_modulus() const override { return 2.0 * c_[0]; }
  std::string type() const override { return "yeoh"; }

private:
  /// W(C) with dW/dC and, if `with_hessian`, d2W/dC2.
  uncoupled::ScalarFunction strain_energy(const Mat3& C, bool with_hessian) const override;

  std::array<Real, 6> c_{};
  Real k_;
};

} // namespace trifem::material
