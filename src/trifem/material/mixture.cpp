// SPDX-License-Identifier: MIT
#include "trifem/material/mixture.hpp"

#include "trifem/core/error.hpp"

#include <map>
#include <tuple>

namespace trifem::material {
namespace {

/// The mixture keys that take a law instead of a number.
constexpr std::string_view kLawKeys[] = {"permeability", "d_plus", "d_minus"};

/// One law given for a mixture key: its type and parameters.
struct LawValues {
  std::string type;
  ParameterValues values;
};

/// Mixture values split into the plain keys and the laws (by mixture key).
struct SplitValues {
  ParameterValues plain;
  std::map<std::string, LawValues> laws;
};

SplitValues split_laws(const ParameterValues& values, const std::string& context) {
  SplitValues s;
  for (const auto& [name, value] : values) {
    const auto dot = name.find('.');
    if (dot == std::string::npos) {
      s.plain[name] = value;
      continue;
    }
    const auto dot2 = name.find('.', dot + 1);
    TRIFEM_CHECK(dot2 != std::string::npos, "{}.{}: expected a law parameter <key>.<type>.<name>",
                 context, name);
    const std::string key = name.substr(0, dot), type = name.substr(dot + 1, dot2 - dot - 1);
    TRIFEM_CHECK(!transport_laws(key).empty(),
                 "{}.{}: only permeability, d_plus and d_minus take a law (a table with a type)",
                 context, key);
    LawValues& law = s.laws[key];
    TRIFEM_CHECK(law.type.empty() || law.type == type, "{}.{}: two laws given ('{}' and '{}')",
                 context, key, law.type, type);
    law.type = type;
    law.values[name.substr(dot2 + 1)] = value;
  }
  for (const auto& [key, law] : s.laws)
    TRIFEM_CHECK(s.plain.count(key) == 0, "{}.{}: given both as a number and as a law", context,
                 key);
  return s;
}

const TransportLawInfo& find_transport_law(const std::string& key, const std::string& type,
                                           const std::string& context) {
  std::string known;
  for (const TransportLawInfo* law : transport_laws(key)) {
    if (law->type == type)
      return *law;
    known += (known.empty() ? "" : ", ") + law->type;
  }
  throw InputError(fmt::format("{}.{}.type = '{}': unknown {} law (expected one of: {})", context,
                               key, type, key == "permeability" ? "permeability" : "diffusivity",
                               known));
}

std::shared_ptr<const PermeabilityLaw> permeability_law(const SplitValues& s, Real phi_s0,
                                                        const std::string& context) {
  const auto it = s.laws.find("permeability");
  if (it == s.laws.end())
    return constant_permeability(s.plain.at("permeability"));
  return create_permeability(it->second.type, it->second.values, phi_s0, context + ".permeability");
}

std::shared_ptr<const DiffusivityLaw> diffusivity_law(const SplitValues& s, const std::string& key,
                                                      const std::string& context) {
  const auto it = s.laws.find(key);
  if (it == s.laws.end())
    return constant_diffusivity(s.plain.at(key));
  return create_diffusivity(it->second.type, it->second.values, context + "." + key);
}

} // namespace

const std::vector<ParameterSchema>& mixture_schema(bool charged) {
  static const std::vector<ParameterSchema> biphasic = {
      {"phi_s0", "", "solid volume fraction in the reference state", Range::half_open(0.0, 1.0),
       std::nullopt},
      {"permeability", "mm^4/(N s)", "hydraulic permeability kappa", Range::positive(),
       std::nullopt},
  };
  static const std::vector<ParameterSchema> triphasic = [] {
    std::vector<ParameterSchema> s = biphasic;
    // bounded far above any tissue (2e-4 in cartilage) and below the concentration of water
    // itself (0.055 mmol/mm^3): beyond it the Donnan state overflows
    s.push_back({"fixed_charge", "mEq/mm^3", "fixed charge density magnitude cF0 (negative charge)",
                 Range::closed(0.0, 1.0), std::nullopt});
    s.push_back({"fixed_charge_basis", "", "0: per water volume, 1: per reference tissue volume",
                 Range::closed(0.0, 1.0), 0.0});
    s.push_back({"d_plus", "mm^2/s", "cation (Na+) diffusivity", Range::positive(), std::nullopt});
    s.push_back({"d_minus", "mm^2/s", "anion (Cl-) diffusivity", Range::positive(), std::nullopt});
    s.push_back({"free_d_plus", "mm^2/s",
                 "cation diffusivity in free solution, of its friction with the water (0: d_plus, "
                 "no friction with the solid)",
                 Range::non_negative(), 0.0});
    s.push_back({"free_d_minus", "mm^2/s",
                 "anion diffusivity in free solution, of its friction with the water (0: "
                 "d_minus, no friction with the solid)",
                 Range::non_negative(), 0.0});
    s.push_back({"gamma_plus", "", "cation activity coefficient", Range::positive(), 1.0});
    s.push_back({"gamma_minus", "", "anion activity coefficient", Range::positive(), 1.0});
    s.push_back({"osmotic", "", "osmotic coefficient Phi", Range::positive(), 1.0});
    return s;
  }();
  return charged ? triphasic : biphasic;
}

std::vector<const TransportLawInfo*> transport_laws(std::string_view key) {
  std::vector<const TransportLawInfo*> out;
  if (key == kLawKeys[0])
    for (const auto& law : permeability_laws())
      out.push_back(&law);
  if (key == kLawKeys[1] || key == kLawKeys[2])
    for (const auto& law : diffusivity_laws())
      out.push_back(&law);
  return out;
}

std::string transport_law_key(std::string_view key, std::string_view type,
                              std::string_view parameter) {
  return fmt::format("{}.{}.{}", key, type, parameter);
}

ParameterValues validate_mixture_parameters(bool charged, const ParameterValues& values,
                                            const std::string& context) {
  const SplitValues s = split_laws(values, context);
  ParameterValues plain = s.plain;
  for (const auto& [key, law] : s.laws)
    plain[key] = 1.0; // stands for the law while the keys of the mixture type are checked
  ParameterValues out = validate_parameters(mixture_schema(charged), plain, context);
  for (const auto& [key, law] : s.laws) {
    out.erase(key);
    const TransportLawInfo& info = find_transport_law(key, law.type, context);
    for (const auto& [name, value] :
         validate_parameters(*info.parameters, law.values, context + "." + key))
      out[transport_law_key(key, law.type, name)] = value;
  }
  return out;
}

MixtureProperties make_mixture(bool charged, std::shared_ptr<const ElasticLaw> solid,
                               const ParameterValues& values, const std::string& context) {
  const ParameterValues v = validate_mixture_parameters(charged, values, context);
  const SplitValues s = split_laws(v, context);
  MixtureProperties m;
  m.solid = std::move(solid);
  m.charged = charged;
  m.phi_s0 = v.at("phi_s0");
  m.permeability_law = permeability_law(s, m.phi_s0, context);
  m.permeability = m.permeability_law->value(1.0);
  if (!charged)
    return m;
  const Real basis = v.at("fixed_charge_basis");
  TRIFEM_CHECK(basis == 0.0 || basis == 1.0, "{}.fixed_charge_basis = {}: expected 0 or 1", context,
               basis);
  m.fixed_charge = basis == 0.0 ? v.at("fixed_charge") : v.at("fixed_charge") / m.phi_w0();
  m.d_plus_law = diffusivity_law(s, "d_plus", context);
  m.d_minus_law = diffusivity_law(s, "d_minus", context);
  m.d_plus = m.d_plus_law->value(m.phi_w0());
  m.d_minus = m.d_minus_law->value(m.phi_w0());
  m.free_d_plus = v.at("free_d_plus");
  m.free_d_minus = v.at("free_d_minus");
  for (const auto& [key, free, d] : {std::tuple{"free_d_plus", m.free_d_plus, m.d_plus},
                                     std::tuple{"free_d_minus", m.free_d_minus, m.d_minus}})
    TRIFEM_CHECK(free == 0.0 || free >= d,
                 "{}.{} = {} is below the diffusivity in the tissue ({} mm^2/s in the reference "
                 "state): the ion's friction with the solid would be negative",
                 context, key, free, d);
  m.gamma_plus = v.at("gamma_plus");
  m.gamma_minus = v.at("gamma_minus");
  m.osmotic = v.at("osmotic");
  return m;
}

} // namespace trifem::material
