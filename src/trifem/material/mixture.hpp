// SPDX-License-Identifier: MIT
// Mixture properties of a biphasic (solid + water) or triphasic (+ Na+, Cl-) tissue
// (Lai, Hou & Mow 1991; Chen, Sunagawa & Hisada 2009, section 2). Composition: a solid law,
// a permeability law, two diffusivity laws and the constant electrochemical coefficients.
#pragma once

#include "trifem/material/diffusivity.hpp"
#include "trifem/material/elastic_law.hpp"
#include "trifem/material/permeability.hpp"
#include "trifem/material/schema.hpp"

#include <memory>
#include <string_view>

namespace trifem::material {

/// Validated mixture coefficients (mm-N-s-mmol units). The element evaluates the transport laws
/// at its current state; the plain numbers `permeability`, `d_plus` and `d_minus` are their values
/// in the reference state (characteristic scales and messages), set by make_mixture.
struct MixtureProperties {
  std::shared_ptr<const ElasticLaw> solid;
  bool charged = false; ///< triphasic (true) or biphasic (false)
  Real phi_s0 = 0.25;   ///< solid volume fraction in the reference state, (0, 1)
  /// kappa(J) [mm^4/(N s)] of the volume ratio J = V/V0.
  std::shared_ptr<const PermeabilityLaw> permeability_law = constant_permeability(1e-3);
  /// d+(phi_w), d-(phi_w) [mm^2/s] of the porosity (triphasic only).
  std::shared_ptr<const DiffusivityLaw> d_plus_law = constant_diffusivity(5e-4);
  std::shared_ptr<const DiffusivityLaw> d_minus_law = constant_diffusivity(8e-4);
  Real permeability = 1e-3; ///< kappa(J = 1) [mm^4/(N s)], > 0
  Real fixed_charge = 0.0;  ///< cF0 per reference water volume [mEq/mm^3 = mmol/mm^3], >= 0
  Real d_plus = 5e-4;       ///< cation diffusivity d+(phi_w0) [mm^2/s], > 0
  Real d_minus = 8e-4;      ///< anion diffusivity d-(phi_w0) [mm^2/s], > 0
  /// Free-solution diffusivities d0+- [mm^2/s] of the water-ion friction RT/(phi_w d0): 0 for
  /// d0 = d (the ions drag on the water only, the paper's model); d0 > d adds the friction of
  /// the ion with the solid, RT/(phi_w c) (1/d - 1/d0) (FEBio's free_diff).
  Real free_d_plus = 0.0, free_d_minus = 0.0;
  Real gamma_plus = 1.0;  ///< cation activity coefficient, > 0
  Real gamma_minus = 1.0; ///< anion activity coefficient, > 0
  Real osmotic = 1.0;     ///< osmotic coefficient Phi, > 0

  Real phi_w0() const { return 1.0 - phi_s0; }
};

/// Parameter schema of the mixture types ("biphasic": phi_s0, permeability; "triphasic": also
/// fixed_charge, d_plus, d_minus, free_d_plus, free_d_minus, gamma_plus, gamma_minus, osmotic,
/// fixed_charge_basis (0 = water, 1 = tissue)). A number for permeability, d_plus or d_minus is the
/// constant law; see transport_law_key() for a law of the state.
const std::vector<ParameterSchema>& mixture_schema(bool charged);

/// The laws that the mixture key `key` takes: the permeability laws for "permeability", the
/// diffusivity laws for "d_plus" and "d_minus", none for other keys.
std::vector<const TransportLawInfo*> transport_laws(std::string_view key);

/// The key under which parameter `parameter` of the law `type` given for the mixture key `key`
/// is stored in ParameterValues: "<key>.<type>.<parameter>", e.g. "permeability.holmes-mow.k0".
/// The values of one key hold either the number "<key>" (constant law) or one law's parameters
/// (every law has at least one parameter, so a law is never given by its type alone).
std::string transport_law_key(std::string_view key, std::string_view type,
                              std::string_view parameter);

/// Validates mixture case values: the plain keys against mixture_schema(charged) and each law
/// (transport_law_key) against its own schema. Unknown keys, types and parameters, missing and
/// out-of-range values are InputErrors naming `context.key`. Returns the values with the
/// defaults of the schema and of the laws filled in.
ParameterValues validate_mixture_parameters(bool charged, const ParameterValues& values,
                                            const std::string& context);

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
