// SPDX-License-Identifier: MIT
// A law given by its strain energy with both derivatives in C (the uncoupled laws): energy,
// stress and tangent written once.
#pragma once

#include "trifem/material/elastic_law.hpp"
#include "trifem/material/uncoupled.hpp"

namespace trifem::material {

/// W = strain_energy(C).value, S = 2 dW/dC, D = 4 d2W/dC2 of the law's strain_energy.
class EnergyFunctionLaw : public ElasticLaw {
public:
  Real energy(const Mat3& C) const final { return strain_energy(C, false).value; }
  Mat3 stress(const Mat3& C) const final { return 2.0 * strain_energy(C, false).gradient; }
  StressTangent stress_tangent(const Mat3& C) const final {
    const uncoupled::ScalarFunction W = strain_energy(C, true);
    return {2.0 * W.gradient, 4.0 * W.hessian};
  }

protected:
  /// W(C) with dW/dC and, if `with_hessian`, d2W/dC2.
  virtual uncoupled::ScalarFunction strain_energy(const Mat3& C, bool with_hessian) const = 0;
};

} // namespace trifem::material
