// SPDX-License-Identifier: MIT
// Interface of hyperelastic solid laws in total Lagrangian form.
#pragma once

#include "trifem/tensor/tensor.hpp"

#include <string>

namespace trifem::material {

/// Second Piola-Kirchhoff stress S and material tangent D = dS/dE (Voigt, 6x6) at one point.
struct StressTangent {
  Mat3 S;
  Mat6 D;
};

/// A hyperelastic law W(C). Holds only validated, immutable parameters (no state).
class ElasticLaw {
public:
  virtual ~ElasticLaw() = default;
  /// Strain energy per reference volume W(C) [MPa].
  virtual Real energy(const Mat3& C) const = 0;
  /// S = 2 dW/dC [MPa].
  virtual Mat3 stress(const Mat3& C) const = 0;
  /// S and D = dS/dE = 4 d2W/dC2 in Voigt form (stress-like rows, strain-like columns) [MPa].
  virtual StressTangent stress_tangent(const Mat3& C) const = 0;
  /// Small-strain P-wave modulus lambda + 2 mu [MPa]: the scale used for convergence norms and
  /// stable time steps.
  virtual Real p_wave_modulus() const = 0;
  /// Small-strain shear modulus mu [MPa].
  virtual Real shear_modulus() const = 0;
  /// Registered type name, e.g. "neo-hookean".
  virtual std::string type() const = 0;
};

/// Lame constants from Young's modulus E and Poisson's ratio nu.
struct Lame {
  Real lambda;
  Real mu;
};
inline Lame lame_from_young(Real E, Real nu) {
  return {E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)), E / (2.0 * (1.0 + nu))};
}

} // namespace trifem::material
