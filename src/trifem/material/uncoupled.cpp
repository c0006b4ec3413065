// SPDX-License-Identifier: MIT
#include "trifem/material/uncoupled.hpp"

#include <cmath>

namespace trifem::material {
namespace uncoupled {
namespace {

/// (x^p - y^p)/(x - y) for x, y > 0, and its limit p x^(p-1) at y = x. Written as
/// x^(p-1) expm1(p ln(y/x))/d with d = (y - x)/x, it is accurate to round-off for any pair,
/// including nearly equal ones (ln(y/x) = log1p(d) there), with no tolerance.
Real power_divided_difference(Real x, Real y, Real p) {
  const Real d = (y - x) / x;
  if (d == 0.0)
    return p * std::pow(x, p - 1.0);
  const Real log_ratio = std::abs(d) < 0.5 ? std::log1p(d) : std::log(y / x);
  return std::pow(x, p - 1.0) * std::expm1(p * log_ratio) / d;
}

/// d(C^b)/dC (Voigt, components IJKL) by the Daleckii-Krein formula from the eigenvalues c and
/// eigenvectors n of C: sum_a G_aa M_a (x) M_a + 2 sum_(a<b) G_ab N_ab (x) N_ab.
Mat6 power_derivative(const Vec3& c, const Mat3& n, Real b) {
  Mat6 D = Mat6::Zero();
  for (int a = 0; a < 3; ++a)
    for (int e = a; e < 3; ++e) {
      const Mat3 na_ne = n.col(a) * n.col(e).transpose();
      const Vec6 N = voigt::stress(0.5 * (na_ne + na_ne.transpose()));
      const Real weight = (a == e ? 1.0 : 2.0) * power_divided_difference(c[a], c[e], b);
      D += weight * N * N.transpose();
    }
  return D;
}

} // namespace

using voigt::outer;
using voigt::symmetric_product;

void accumulate(ScalarFunction& sum, Real weight, const ScalarFunction& f) {
  sum.value += weight * f.value;
  sum.gradient += weight * f.gradient;
  sum.hessian += weight * f.hessian;
}

ScalarFunction isochoric_first_invariant(const Mat3& C, bool with_hessian) {
  return isochoric({C.trace(), Mat3::Identity(), Mat6::Zero()}, -1.0 / 3.0, C, with_hessian);
}

ScalarFunction compose(const ScalarFunction& f, Real w, Real dw, Real d2w, bool with_hessian) {
  ScalarFunction W{w, dw * f.gradient, Mat6::Zero()};
  if (with_hessian)
    W.hessian = d2w * voigt::outer(f.gradient, f.gradient) + dw * f.hessian;
  return W;
}

ScalarFunction isochoric(const ScalarFunction& f, Real q, const Mat3& C, bool with_hessian) {
  const Mat3 Ci = C.inverse();
  const Real scale = std::pow(C.determinant(), q);
  ScalarFunction g{scale * f.value, scale * (f.gradient + q * f.value * Ci), Mat6::Zero()};
  if (with_hessian)
    g.hessian = scale * (f.hessian + q * (outer(f.gradient, Ci) + outer(Ci, f.gradient)) +
                         q * q * f.value * outer(Ci, Ci) - q * f.value * symmetric_product(Ci));
  return g;
}

ScalarFunction log_volumetric(const Mat3& C, bool with_hessian) {
  const Mat3 Ci = C.inverse();
  const Real lnJ = 0.5 * std::log(C.determinant());
  ScalarFunction U{0.5 * lnJ * lnJ, 0.5 * lnJ * Ci, Mat6::Zero()};
  if (with_hessian)
    U.hessian = 0.25 * outer(Ci, Ci) - 0.5 * lnJ * symmetric_product(Ci);
  return U;
}

ScalarFunction power_trace(const Vec3& c, const Mat3& n, Real a, bool with_hessian) {
  const Vec3 c_a = c.array().pow(a);
  ScalarFunction f{c_a.sum(), Mat3::Zero(), Mat6::Zero()};
  f.gradient = n * (a * c_a.cwiseQuotient(c)).asDiagonal() * n.transpose();
  if (with_hessian)
    f.hessian = a * power_derivative(c, n, a - 1.0);
  return f;
}

} // namespace uncoupled

} // namespace trifem::material
