// SPDX-License-Identifier: MIT
// The distorted hex8 cell of the tangent tests, and the deformed mixture element on it: a
// non-equilibrium state with non-zero fluxes, a non-Donnan ion content, Phi = 0.93 and a
// prestress.
#pragma once

#include "trifem/material/registry.hpp"
#include "trifem/physics/mixture_kernel.hpp"

#include <cstdlib>
#include <string>

namespace trifem::test {

/// The unit cube's corners moved by up to ±0.075 each, from std::rand seeded with `seed`
/// (later std::rand draws continue that sequence).
inline fe::HexCoords distorted_unit_cube(unsigned seed) {
  std::srand(seed);
  fe::HexCoords X;
  const Real r[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                        {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (int a = 0; a < 8; ++a)
    for (int k = 0; k < 3; ++k)
      X(a, k) = r[a][k] + 0.15 * (std::rand() / Real(RAND_MAX) - 0.5);
  return X;
}

/// The inputs of mixture_hex8 (step.chem points to chem: set it again after a copy).
struct Setup {
  fe::HexGeometry geo;
  physics::MixtureUnknowns x;
  physics::MixtureHistory h;
  material::MixtureProperties mat;
  material::Electrochemistry chem;
  physics::MixtureStep step;
};

/// `laws` replaces or adds mixture values, e.g. a permeability law given as
/// material::transport_law_key entries.
inline Setup make_setup(bool ions, const std::string& solid,
                        const material::ParameterValues& laws = {}) {
  Setup s;
  s.geo = *fe::hex8_geometry(distorted_unit_cube(ions ? 3 : 4));
  s.x.u = 0.08 * fe::HexCoords::Random();
  s.x.w = 2e-5 * fe::HexCoords::Random();
  s.x.jp = 3e-9 * fe::HexCoords::Random();
  s.x.jm = 2e-9 * fe::HexCoords::Random();
  s.x.p = 0.12;
  s.x.eta = -1500.0;
  material::ParameterValues values =
      ions ? material::ParameterValues{{"phi_s0", 0.25},       {"permeability", 1.07e-3},
                                       {"fixed_charge", 2e-4}, {"d_plus", 5e-4},
                                       {"d_minus", 8e-4},      {"osmotic", 0.93}}
           : material::ParameterValues{{"phi_s0", 0.25}, {"permeability", 1.07e-3}};
  for (const auto& [key, value] : laws) {
    values.erase(key.substr(0, key.find('.'))); // a law replaces the constant
    values[key] = value;
  }
  s.mat = material::make_mixture(
      ions, material::create_law(solid, {{"E", 0.3}, {"nu", 0.2}}, "solid"), values, "m");
  Real V0 = 0.0;
  for (Real dV : s.geo.dV)
    V0 += dV;
  s.h.V0 = V0;
  s.h.V_old = 0.97 * V0;
  const Real Vw = V0 * 0.75;
  s.h.N_fixed = s.h.N_fixed_old = 2e-4 * Vw;
  s.h.N_plus = 2.9e-4 * Vw;
  s.h.N_minus = 0.85e-4 * Vw;
  s.step = {0.7, 0.05, &s.chem};
  return s;
}

// Strain-dependent transport laws (docs/theory/triphasic.md §2a).

/// Holmes-Mow permeability, FEBio's cartilage-like M and alpha.
inline const material::ParameterValues kHolmesMow = {{"permeability.holmes-mow.k0", 1.07e-3},
                                                     {"permeability.holmes-mow.M", 4.6},
                                                     {"permeability.holmes-mow.alpha", 2.0}};
/// Exponential (perm-exp-iso) permeability.
inline const material::ParameterValues kExponential = {{"permeability.exponential.k0", 1.07e-3},
                                                       {"permeability.exponential.M", 3.0}};
/// Mackie-Meares diffusivities of both ions (free-solution d0 of Na+ and Cl-).
inline const material::ParameterValues kMackieMeares = {{"d_plus.mackie-meares.d0", 1.33e-3},
                                                        {"d_minus.mackie-meares.d0", 2.03e-3}};

} // namespace trifem::test
