// SPDX-License-Identifier: MIT
// Compressible Ogden solid with up to six terms (the FEBio "Ogden unconstrained" form).
#pragma once

#include "trifem/material/elastic_law.hpp"
#include "trifem/material/schema.hpp"

#include <string>
#include <vector>

namespace trifem::material {

/// Ogden's law without the isochoric split (FEBio's "Ogden unconstrained"), with l_a the
/// principal stretches and c_a = l_a^2 the eigenvalues of C:
///   W = sum_i c_i/m_i^2 (l_1^m_i + l_2^m_i + l_3^m_i - 3 - m_i ln J) + cp/2 (J - 1)^2
///     = sum_i c_i/m_i^2 (tr C^(m_i/2) - 3 - m_i/2 ln I3) + cp/2 (I3^(1/2) - 1)^2,
/// whose principal Cauchy stresses are sigma_a = sum_i c_i/m_i (l_a^m_i - 1)/J + cp (J - 1).
/// tr C^a and its derivatives are uncoupled::power_trace (smooth through equal stretches);
///   d(ln I3)/dC = C^-1,  d2(ln I3)/dC2 = -C^-1 (.) C^-1,
///   dJ/dC = J/2 C^-1,    d2J/dC2 = J/4 C^-1 (x) C^-1 - J/2 C^-1 (.) C^-1.
/// Small strain: shear modulus mu = (c_1 + ... + c_6)/2, Lame's lambda = cp. A term with
/// c_i = 0 is absent.
class OgdenUnconstrained final : public ElasticLaw {
public:
  /// Parameters: c1..c6 (MPa, default 0), m1..m6 (default 1, nonzero where c_i != 0), cp (MPa,
  /// >= 0); c1 + ... + c6 > 0.
  explicit OgdenUnconstrained(const ParameterValues& params);
  static const std::vector<ParameterSchema>& schema();
  /// The checks the schema's ranges cannot express, m_i != 0 for a present term and
  /// c1 + ... + c6 > 0: InputError naming `context.key` otherwise.
  static void check(const ParameterValues& params, const std::string& context);

  Real energy(const Mat3& C) const override;
  Mat3 stress(const Mat3& C) const override;
  StressTangent stress_tangent(const Mat3& C) const override;
  Real p_wave_modulus() const override { return cp_ + 2.0 * shear_modulus(); }
  Real shear_modulus() const override;
  std::string type() const override { return "ogden-unconstrained"; }

private:
  struct Term {
    Real c;
    Real m;
  };
  /// W(C), dW/dC and, if `with_hessian`, d2W/dC2 (value, gradient, hessian).
  void evaluate(const Mat3& C, bool with_hessian, Real& W, Mat3& dW, Mat6* d2W) const;

  std::vector<Term> terms_;
  Real cp_;
};

} // namespace trifem::material
