// SPDX-License-Identifier: MIT
// Uncoupled Ogden solid with up to three terms (the FEBio "Ogden" form).
#pragma once

#include "trifem/material/energy_function_law.hpp"
#include "trifem/material/schema.hpp"
#include "trifem/material/uncoupled.hpp"

#include <string>
#include <vector>

namespace trifem::material {

/// Ogden (1972, Proc R Soc Lond A 326:565) in FEBio's uncoupled form, with the deviatoric
/// principal stretches l~_a = J^(-1/3) l_a and c_a the eigenvalues of C:
///   W = sum_i c_i/m_i^2 (l~_1^m_i + l~_2^m_i + l~_3^m_i - 3) + k/2 (ln J)^2
///     = sum_i c_i/m_i^2 (I3^(-m_i/6) tr C^(m_i/2) - 3) + k/2 (ln J)^2.
/// Each term is the isochoric scaling (uncoupled::isochoric, q = -m/6) of the spectral function
/// f(C) = tr C^a, a = m/2, with df/dC = a C^(a-1) and, by the Daleckii-Krein formula,
///   d2f/dC2 = a [ sum_a G_aa M_a (x) M_a + 2 sum_(a<b) G_ab N_ab (x) N_ab ],
/// M_a = n_a (x) n_a, N_ab = (n_a (x) n_b + n_b (x) n_a)/2, G_ab the divided difference of
/// x^(a-1) at (c_a, c_b) and G_aa = (a-1) c_a^(a-2) its limit. G is evaluated in a form exact to
/// round-off for equal, nearly equal and distinct eigenvalues (no tolerance, no branch on
/// coincidence), so the tangent is smooth through C = I and uniaxial states.
/// Small strain: shear modulus mu = (c_1 + c_2 + c_3)/2, bulk modulus k. A term with c_i = 0 is
/// absent.
class Ogden final : public EnergyFunctionLaw {
public:
  /// Parameters: c1..c3 (MPa), m1..m3 (nonzero where c_i != 0), k (bulk modulus, MPa, > 0);
  /// c1 + c2 + c3 > 0.
  explicit Ogden(const ParameterValues& params);
  static const std::vector<ParameterSchema>& schema();
  /// The checks the schema's ranges cannot express, m_i != 0 for a present term and
  /// c1 + c2 + c3 > 0: InputError naming `context.key` otherwise.
  static void check(const ParameterValues& params, const std::string& context);

  Real p_wave_modulus() const override { return k_ + 4.0 / 3.0 * shear_modulus(); }
  Real shear_modulus() const override;
  std::string type() const override { return "ogden"; }

private:
  /// One term c/m^2 (sum_a l~_a^m - 3).
  struct Term {
    Real c;
    Real m;
  };
  /// W(C) with dW/dC and, if `with_hessian`, d2W/dC2.
  uncoupled::ScalarFunction strain_energy(const Mat3& C, bool with_hessian) const override;

  std::vector<Term> terms_;
  Real k_;
};

} // namespace trifem::material
