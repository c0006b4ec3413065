// SPDX-License-Identifier: MIT
// Closed-form homogeneous uniaxial-stress state of the multiplier formulation, for the explicit
// verification tests.
#pragma once

#include "trifem/core/types.hpp"

#include <cmath>

namespace trifem::test {

/// Homogeneous uniaxial stress at axial stretch a: stretches (a, b, b), J = a b², multiplier
/// λ = α (J − 1) and nominal stress P.
struct Uniaxial {
  Real a, b, J, lambda, P;
};

/// W = μ/2 (I₁ − 3) − μ ln J with λ Ψ, Ψ = J − 1, penalty α: S = μ (I − C⁻¹) + λ J C⁻¹. The
/// lateral condition S₂₂ = μ (1 − 1/b²) + α a (a b² − 1) = 0 gives b (Newton from the
/// incompressible value 1/√a, converged to round-off); P = a S₁₁ = μ (a − 1/a) + λ J / a.
inline Uniaxial uniaxial_state(Real mu, Real alpha, Real a) {
  Real b = 1.0 / std::sqrt(a);
  for (int it = 0; it < 50; ++it) {
    const Real f = mu * (1.0 - 1.0 / (b * b)) + alpha * a * (a * b * b - 1.0);
    const Real df = 2.0 * mu / (b * b * b) + 2.0 * alpha * a * a * b;
    b -= f / df;
  }
  const Real J = a * b * b, lambda = alpha * (J - 1.0);
  return {a, b, J, lambda, mu * (a - 1.0 / a) + lambda * J / a};
}

} // namespace trifem::test
