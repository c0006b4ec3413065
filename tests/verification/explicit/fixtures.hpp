// SPDX-License-Identifier: MIT
// Shared set-up of the explicit verification tests: laws and models in μ = ρ = 1 units.
#pragma once

#include "trifem/explicit/explicit_model.hpp"
#include "trifem/explicit/explicit_solver.hpp"
#include "trifem/material/registry.hpp"

#include <memory>

namespace trifem::test {

/// The explicit part of the multiplier formulation: W = μ/2 (I1 − 3) − μ ln J, i.e. the
/// registry's neo-Hookean with ν = 0 (E = 2μ); the bulk response comes from λ Ψ(C).
inline std::shared_ptr<const material::ElasticLaw> deviatoric_neo_hookean(Real mu) {
  return material::create_law("neo-hookean", {{"E", 2.0 * mu}, {"nu", 0.0}}, "test");
}

/// Compressible neo-Hookean with shear modulus μ and small-strain bulk modulus κ
/// (ν = (3κ − 2μ) / (2(3κ + μ))): the pure-displacement Q1 comparison.
inline std::shared_ptr<const material::ElasticLaw> compressible_neo_hookean(Real mu, Real kappa) {
  const Real nu = (3.0 * kappa - 2.0 * mu) / (2.0 * (3.0 * kappa + mu));
  return material::create_law("neo-hookean", {{"E", 2.0 * mu * (1.0 + nu)}, {"nu", nu}}, "test");
}

} // namespace trifem::test
