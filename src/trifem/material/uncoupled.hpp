// SPDX-License-Identifier: MIT
// Building blocks of the uncoupled hyperelastic laws W = W~(C~) + k U(J): scalar functions of C
// with their derivatives, the isochoric scaling and the volumetric energy.
#pragma once

#include "trifem/tensor/tensor.hpp"

namespace trifem::material {

/// Building blocks of the uncoupled laws W = W~(C~) + k U(J), C~ = J^(-2/3) C (FEBio theory
/// manual, "uncoupled hyperelastic materials"); shared by MooneyRivlin and Ogden.
namespace uncoupled {

/// A scalar function f(C) and its derivatives df/dC and d2f/dC2; the second derivative in Voigt
/// form holds the components IJKL (stress-like rows, strain-like columns), zero if not asked for.
struct ScalarFunction {
  Real value = 0.0;
  Mat3 gradient = Mat3::Zero();
  Mat6 hessian = Mat6::Zero();
};

/// sum += weight f (value and both derivatives).
void accumulate(ScalarFunction& sum, Real weight, const ScalarFunction& f);

/// The isochoric scaling g = I3^q f(C) of f, e.g. I1~ = I3^(-1/3) I1, I2~ = I3^(-2/3) I2:
///   dg/dC   = I3^q (df/dC + q f C^-1),
///   d2g/dC2 = I3^q [d2f/dC2 + q (df/dC (x) C^-1 + C^-1 (x) df/dC) + q^2 f C^-1 (x) C^-1
///                   - q f C^-1 (.) C^-1],
/// with (A (.) A)_IJKL = (A_IK A_JL + A_IL A_JK)/2. The hessian only if `with_hessian`.
ScalarFunction isochoric(const ScalarFunction& f, Real q, const Mat3& C, bool with_hessian);

/// The first deviatoric invariant I1~ = I3^(-1/3) tr C with its derivatives.
ScalarFunction isochoric_first_invariant(const Mat3& C, bool with_hessian);

/// W(f) of a scalar function f given W = w, dW/df = dw and d2W/df2 = d2w at f: the value w,
/// dW/dC = dw df/dC and, if `with_hessian`, d2W/dC2 = d2w df/dC (x) df/dC + dw d2f/dC2.
ScalarFunction compose(const ScalarFunction& f, Real w, Real dw, Real d2w, bool with_hessian);

/// U(J) = (ln J)^2 / 2, dU/dC = ln J C^-1 / 2,
/// d2U/dC2 = C^-1 (x) C^-1 / 4 - ln J / 2 C^-1 (.) C^-1. The hessian only if `with_hessian`.
ScalarFunction log_volumetric(const Mat3& C, bool with_hessian);

/// The spectral function f(C) = tr C^a = sum_a c_a^a of C with eigenvalues c (> 0) and unit
/// eigenvectors n (columns), df/dC = a C^(a-1) and, if `with_hessian`, by the Daleckii-Krein
/// formula d2f/dC2 = a [sum_a G_aa M_a (x) M_a + 2 sum_(a<b) G_ab N_ab (x) N_ab], M_a = n_a (x)
/// n_a, N_ab = (n_a (x) n_b + n_b (x) n_a)/2, G_ab the divided difference of x^(a-1) at (c_a,
/// c_b) and G_aa = (a-1) c_a^(a-2) its limit, evaluated to round-off for equal, nearly equal and
/// distinct eigenvalues (no tolerance). Shared by the Ogden laws.
ScalarFunction power_trace(const Vec3& c, const Mat3& n, Real a, bool with_hessian);

} // namespace uncoupled

} // namespace trifem::material
