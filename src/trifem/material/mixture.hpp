// SPDX-License-Identifier: MIT
// Mixture properties of a biphasic (solid + water) or triphasic (+ Na+, Cl-) tissue
// (Lai, Hou & Mow 1991; Chen, Sunagawa & Hisada 2009, section 2). Composition: a solid law
// plus the constant transport and electrochemical coefficients.
#pragma once

#include "trifem/material/elastic_law.hpp"
#include "trifem/material/schema.hpp"

#include <memory>

namespace trifem::material {

/// Basis of the fixed-charge density input.
enum class FixedChargeBasis {
  Water, ///< per unit interstitial water volume (the paper's symbol definition)
  Tissue ///< per unit reference tissue volume (converted: cF0_water = cF0_tissue / phi_w0)
};

/// Validated mixture coefficients (mm-N-s-mmol units).
struct MixtureProperties {
  std::shared_ptr<const ElasticLaw> solid;
  bool charged = false;     ///< triphasic (true) or biphasic (false)
  Real phi_s0 = 0.25;       ///< solid volume fraction in the reference state, (0, 1)
  Real permeability = 1e-3; ///< kappa [mm^4/(N s)], > 0
  Real fixed_charge = 0.0;  ///< cF0 per reference water volume [mEq/mm^3 = mmol/mm^3], >= 0
  Real d_plus = 5e-4;       ///< cation diffusivity [mm^2/s], > 0
  Real d_minus = 8e-4;      ///< anion diffusivity [mm^2/s], > 0
  Real gamma_plus = 1.0;    ///< cation activity coefficient, > 0
  Real gamma_minus = 1.0;   ///< anion activity coefficient, > 0
  Real osmotic = 1.0;       ///< osmotic coefficient Phi, > 0

  Real phi_w0() const { return 1.0 - phi_s0; }
};

/// Parameter schema of the mixture types ("biphasic": phi_s0, permeability; "triphasic": also
/// fixed_charge, d_plus, d_minus, gamma_plus, gamma_minus, osmotic, fixed_charge_basis
/// (0 = water, 1 = tissue)).
const std::vector<ParameterSchema>& mixture_schema(bool charged);

/// Builds validated properties from case values (messages name `context.key`).
MixtureProperties make_mixture(bool charged, std::shared_ptr<const ElasticLaw> solid,
                               const ParameterValues& values, const std::string& context);

/// Physical constants and the reference bath.
struct Electrochemistry {
  Real R = 8.314;        ///< gas constant [mJ/(mmol K)]
  Real T = 298.0;        ///< absolute temperature [K]
  Real faraday = 96.485; ///< Faraday constant [C/mmol]; psi [mV] = eta [mJ/mmol] / faraday
  Real c_ref = 1.5e-4;   ///< reference bath NaCl concentration [mmol/mm^3] (0.15 M)
  Real gamma_bath = 1.0; ///< bath activity coefficient (both ions)
  Real osmotic_bath = 1.0;
  Real RT() const { return R * T; }
};

} // namespace trifem::material
