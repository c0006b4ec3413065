// SPDX-License-Identifier: MIT
#include "trifem/material/registry.hpp"

#include "trifem/core/error.hpp"
#include "trifem/material/ellipsoidal_fibre_distribution.hpp"
#include "trifem/material/fibre_distribution.hpp"
#include "trifem/material/fibre_exp_linear.hpp"
#include "trifem/material/fibre_exp_pow.hpp"
#include "trifem/material/holmes_mow.hpp"
#include "trifem/material/holmes_mow_uncoupled.hpp"
#include "trifem/material/mooney_rivlin.hpp"
#include "trifem/material/neo_hookean.hpp"
#include "trifem/material/ogden.hpp"
#include "trifem/material/ogden_unconstrained.hpp"
#include "trifem/material/orthotropic_elastic.hpp"
#include "trifem/material/porous_neo_hookean.hpp"
#include "trifem/material/saint_venant_kirchhoff.hpp"
#include "trifem/material/solid_mixture.hpp"
#include "trifem/material/veronda_westmann.hpp"
#include "trifem/material/yeoh.hpp"

namespace trifem::material {
namespace {

/// The registry entry of `Law`, with its static `check(values, context)` if it has one.
template <class Law>
LawEntry entry(std::string type, std::string doc, ParameterValues example) {
  LawEntry e;
  e.type = std::move(type);
  e.doc = std::move(doc);
  e.parameters = &Law::schema();
  e.make = [](const ParameterValues& p) { return std::make_unique<Law>(p); };
  if constexpr (requires(const ParameterValues& p, const std::string& c) { Law::check(p, c); })
    e.check = &Law::check;
  e.example = std::move(example);
  return e;
}

} // namespace

const std::vector<LawEntry>& registered_laws() {
  static const std::vector<LawEntry> laws = {
      entry<SaintVenantKirchhoff>("saint-venant-kirchhoff",
                                  "S = lambda tr(E) I + 2 mu E (the paper's solid)",
                                  {{"E", 1.0}, {"nu", 0.3}}),
      entry<NeoHookean>("neo-hookean",
                        "compressible neo-Hookean, W = mu/2(I1-3) - mu lnJ + lambda/2 (lnJ)^2",
                        {{"E", 1.0}, {"nu", 0.3}}),
      entry<HolmesMow>("holmes-mow",
                       "Holmes-Mow, W = (lambda+2mu)/(4 beta) (e^Q - 1) (strain-stiffening)",
                       {{"E", 1.0}, {"nu", 0.2}, {"beta", 0.5}}),
      entry<MooneyRivlin>("mooney-rivlin",
                          "uncoupled Mooney-Rivlin, W = c1 (I1~-3) + c2 (I2~-3) + k/2 (lnJ)^2",
                          {{"c1", 0.3}, {"c2", 0.05}, {"k", 10.0}}),
      entry<Ogden>("ogden", "uncoupled Ogden, W = sum c_i/m_i^2 (sum_a l~_a^m_i - 3) + k/2 (lnJ)^2",
                   {{"c1", 0.4}, {"m1", 4.0}, {"c2", 0.2}, {"m2", -2.0}, {"k", 10.0}}),
      entry<OgdenUnconstrained>(
          "ogden-unconstrained",
          "compressible Ogden, W = sum c_i/m_i^2 (sum_a l_a^m_i - 3 - m_i lnJ) + cp/2 (J-1)^2",
          {{"c1", 0.4}, {"m1", 4.0}, {"c2", 0.2}, {"m2", -2.0}, {"cp", 2.0}}),
      entry<VerondaWestmann>(
          "veronda-westmann",
          "uncoupled Veronda-Westmann, W = c1 (e^(c2 (I1~-3)) - 1) - c1 c2/2 (I2~-3) + k/2 (lnJ)^2",
          {{"c1", 0.2}, {"c2", 1.5}, {"k", 10.0}}),
      entry<Yeoh>("yeoh", "uncoupled Yeoh, W = sum_i c_i (I1~-3)^i + k/2 (lnJ)^2",
                  {{"c1", 0.3}, {"c2", -0.02}, {"c3", 0.005}, {"k", 10.0}}),
      entry<HolmesMowUncoupled>("holmes-mow-uncoupled",
                                "uncoupled Holmes-Mow (FEBio form), W = mu/(2 beta) "
                                "(e^(beta (I1~-3)) - 1) + k/2 (lnJ)^2",
                                {{"mu", 0.3}, {"beta", 0.5}, {"k", 10.0}}),
      entry<PorousNeoHookean>("porous-neo-hookean",
                              "neo-Hookean whose pores close at J = phi0, W = mu ((I1 (J~/J)^(2/3) "
                              "- 3)/2 - ln J~), J~ = (J - phi0)/(1 - phi0)",
                              {{"E", 1.0}, {"phi0", 0.2}}),
      entry<OrthotropicElastic>("orthotropic-elastic",
                                "linear orthotropic in E (engineering constants), S = D : E",
                                {{"E1", 1.0},
                                 {"E2", 2.0},
                                 {"E3", 3.0},
                                 {"G12", 0.5},
                                 {"G23", 0.8},
                                 {"G31", 0.4},
                                 {"v12", 0.3},
                                 {"v23", 0.2},
                                 {"v31", 0.1}}),
  };
  return laws;
}

namespace {

/// fibre-exp-linear of the whole fibre stretch (FEBio's coupled fiber-exp-linear).
LawEntry coupled_exp_linear(const ParameterValues& example) {
  LawEntry e = entry<FibreExpLinear>("fibre-exp-linear-coupled",
                                     "tension-only fibre of the whole stretch l = |F a0|, "
                                     "l dW/dl = c3 (exp(c4 (l-1)) - 1), then linear above lam_max",
                                     example);
  e.make = [](const ParameterValues& p) { return std::make_unique<FibreExpLinear>(p, true); };
  return e;
}

/// ellipsoidal-fibre-distribution of the deviatoric deformation (FEBio's EFD uncoupled).
LawEntry uncoupled_efd(const ParameterValues& example) {
  LawEntry e = entry<EllipsoidalFibreDistribution>(
      "ellipsoidal-fibre-distribution-uncoupled",
      "ellipsoidal-fibre-distribution of the deviatoric stretch I_n~ = J^(-2/3) I_n", example);
  e.make = [](const ParameterValues& p) {
    return std::make_unique<EllipsoidalFibreDistribution>(p, true);
  };
  return e;
}

} // namespace

const std::vector<LawEntry>& constituent_laws() {
  static const std::vector<LawEntry> laws = [] {
    ParameterValues fibre = {{"ksi", 5.0}, {"alpha", 1.0}, {"beta", 2.5}};
    set_vector(fibre, "fibre", Vec3(1.0, 0.0, 0.0));
    ParameterValues distribution = {{"ksi", 5.0}, {"alpha", 1.0}, {"beta", 2.5}};
    set_vector(distribution, "semi_axes", Vec3(1.0, 1.0, 1.0));
    ParameterValues efd = {};
    set_vector(efd, "ksi", Vec3(4.0, 2.0, 2.0));
    set_vector(efd, "beta", Vec3(2.5, 3.0, 3.0));
    ParameterValues exp_linear = {{"c3", 0.5}, {"c4", 20.0}, {"c5", 100.0}, {"lam_max", 1.05}};
    set_vector(exp_linear, "fibre", Vec3(1.0, 0.0, 0.0));
    return std::vector<LawEntry>{
        entry<FibreExpPow>("fibre-exp-pow",
                           "tension-only fibre, W = ksi/(alpha beta) (exp(alpha (I_n-1)^beta) - 1)",
                           fibre),
        entry<FibreDistribution>("fibre-distribution",
                                 "fibre-exp-pow fibres in all directions, mean weighted by a "
                                 "spherical or ellipsoidal density",
                                 distribution),
        entry<FibreExpLinear>("fibre-exp-linear",
                              "uncoupled tension-only fibre, l dW/dl = c3 (exp(c4 (l-1)) - 1), "
                              "then linear above lam_max",
                              exp_linear),
        coupled_exp_linear(exp_linear),
        entry<EllipsoidalFibreDistribution>(
            "ellipsoidal-fibre-distribution",
            "power-law fibres in all directions, W = int_S2 ksi(n) (I_n-1)^beta(n) dS, ksi and "
            "beta ellipsoidal",
            efd),
        uncoupled_efd(efd),
    };
  }();
  return laws;
}

const LawEntry& find_law(const std::string& type, const std::string& context) {
  std::string known;
  for (const auto* laws : {&registered_laws(), &constituent_laws()})
    for (const auto& law : *laws) {
      if (law.type == type)
        return law;
      known += (known.empty() ? "" : ", ") + law.type;
    }
  throw InputError(fmt::format("{}.type = '{}': unknown material type (expected one of: {})",
                               context, type, known));
}

std::unique_ptr<ElasticLaw> create_law(const std::string& type, const ParameterValues& values,
                                       const std::string& context) {
  const LawEntry& law = find_law(type, context);
  const ParameterValues checked = validate_parameters(*law.parameters, values, context);
  if (law.check)
    law.check(checked, context);
  return law.make(checked);
}

std::unique_ptr<ElasticLaw> create_law(const LawSpec& spec, const std::string& context) {
  if (spec.type != kSolidMixtureType) {
    TRIFEM_CHECK(spec.constituents.empty(),
                 "{}.constituent: only a {} has constituents ({}.type = '{}')", context,
                 kSolidMixtureType, context, spec.type);
    return create_law(spec.type, spec.parameters, context);
  }
  TRIFEM_CHECK(spec.parameters.empty(), "{}.{}: unknown key (a {} has only constituents)", context,
               spec.parameters.empty() ? "" : spec.parameters.begin()->first, kSolidMixtureType);
  std::vector<std::shared_ptr<const ElasticLaw>> parts;
  for (std::size_t i = 0; i < spec.constituents.size(); ++i) {
    const LawSpec& part = spec.constituents[i];
    const std::string where = fmt::format("{}.constituent[{}]", context, i + 1);
    TRIFEM_CHECK(part.type != kSolidMixtureType,
                 "{}.type = '{}': nested solid mixtures are not supported (list the inner "
                 "mixture's constituents in the outer one)",
                 where, part.type);
    parts.push_back(create_law(part, where));
  }
  return std::make_unique<SolidMixture>(std::move(parts), context);
}

} // namespace trifem::material
