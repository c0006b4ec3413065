// SPDX-License-Identifier: MIT
// Central differences of a solid law: S = 2 dW/dC from the energy and D = dS/dE from the stress,
// the independent answers the law tests compare the analytic stress and tangent with.
#pragma once

#include "trifem/material/elastic_law.hpp"
#include "trifem/tensor/tensor.hpp"

namespace trifem::test {

/// S = 2 dW/dC by central differences of the energy (step h on C_ij and C_ji together).
inline Mat3 stress_by_differences(const material::ElasticLaw& m, const Mat3& C, Real h) {
  Mat3 S;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      Mat3 dC = Mat3::Zero();
      dC(i, j) += 0.5 * h;
      dC(j, i) += 0.5 * h;
      S(i, j) = 2.0 * (m.energy(C + dC) - m.energy(C - dC)) / (2.0 * h);
    }
  return S;
}

/// D = dS/dE by central differences of the stress: column c perturbs the strain-like Voigt
/// component c of E by h (so a shear column moves E_IJ = E_JI by h/2, and C = I + 2E by h).
inline Mat6 tangent_by_differences(const material::ElasticLaw& m, const Mat3& C, Real h) {
  Mat6 D;
  for (int c = 0; c < 6; ++c) {
    Vec6 dE = Vec6::Zero();
    dE[c] = h;
    const Mat3 dC = 2.0 * voigt::from_strain(dE);
    D.col(c) = voigt::stress(m.stress(C + dC) - m.stress(C - dC)) / (2.0 * h);
  }
  return D;
}

} // namespace trifem::test
