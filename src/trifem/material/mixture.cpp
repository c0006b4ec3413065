// SPDX-License-Identifier: MIT
#include "trifem/material/mixture.hpp"

#include "trifem/core/error.hpp"

namespace trifem::material {

const std::vector<ParameterSchema>& mixture_schema(bool charged) {
  static const std::vector<ParameterSchema> biphasic = {
      {"phi_s0", "", "solid volume fraction in the reference state", Range::open(0.0, 1.0),
       std::nullopt},
      {"permeability", "mm^4/(N s)", "hydraulic permeability kappa", Range::positive(),
       std::nullopt},
  };
  static const std::vector<ParameterSchema> triphasic = [] {
    std::vector<ParameterSchema> s = biphasic;
    s.push_back({"fixed_charge", "mEq/mm^3", "fixed charge density magnitude cF0 (negative charge)",
                 Range::non_negative(), std::nullopt});
    s.push_back({"fixed_charge_basis", "", "0: per water volume, 1: per reference tissue volume",
                 Range::closed(0.0, 1.0), 0.0});
    s.push_back({"d_plus", "mm^2/s", "cation (Na+) diffusivity", Range::positive(), std::nullopt});
    s.push_back({"d_minus", "mm^2/s", "anion (Cl-) diffusivity", Range::positive(), std::nullopt});
    s.push_back({"gamma_plus", "", "cation activity coefficient", Range::positive(), 1.0});
    s.push_back({"gamma_minus", "", "anion activity coefficient", Range::positive(), 1.0});
    s.push_back({"osmotic", "", "osmotic coefficient Phi", Range::positive(), 1.0});
    return s;
  }();
  return charged ? triphasic : biphasic;
}

MixtureProperties make_mixture(bool charged, std::shared_ptr<const ElasticLaw> solid,
                               const ParameterValues& values, const std::string& context) {
  const ParameterValues v = validate_parameters(mixture_schema(charged), values, context);
  MixtureProperties m;
  m.solid = std::move(solid);
  m.charged = charged;
  m.phi_s0 = v.at("phi_s0");
  m.permeability = v.at("permeability");
  if (!charged)
    return m;
  const Real basis = v.at("fixed_charge_basis");
  TRIFEM_CHECK(basis == 0.0 || basis == 1.0, "{}.fixed_charge_basis = {}: expected 0 or 1", context,
               basis);
  m.fixed_charge = basis == 0.0 ? v.at("fixed_charge") : v.at("fixed_charge") / m.phi_w0();
  m.d_plus = v.at("d_plus");
  m.d_minus = v.at("d_minus");
  m.gamma_plus = v.at("gamma_plus");
  m.gamma_minus = v.at("gamma_minus");
  m.osmotic = v.at("osmotic");
  return m;
}

} // namespace trifem::material
