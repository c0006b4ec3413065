// SPDX-License-Identifier: MIT
#include "trifem/material/uncoupled.hpp"

#include <cmath>

namespace trifem::material {
namespace uncoupled {

using voigt::outer;
using voigt::symmetric_product;

void accumulate(ScalarFunction& sum, Real weight, const ScalarFunction& f) {
  sum.value += weight * f.value;
  sum.gradient += weight * f.gradient;
  sum.hessian += weight * f.hessian;
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

} // namespace uncoupled

} // namespace trifem::material
