// SPDX-License-Identifier: MIT
#include "trifem/material/registry.hpp"

#include "trifem/core/error.hpp"
#include "trifem/material/neo_hookean.hpp"
#include "trifem/material/saint_venant_kirchhoff.hpp"

namespace trifem::material {
namespace {

template <class Law>
LawEntry entry(std::string type, std::string doc) {
  return {std::move(type), std::move(doc), &Law::schema(),
          [](const ParameterValues& p) { return std::make_unique<Law>(p); }};
}

} // namespace

const std::vector<LawEntry>& registered_laws() {
  static const std::vector<LawEntry> laws = {
      entry<SaintVenantKirchhoff>("saint-venant-kirchhoff",
                                  "S = lambda tr(E) I + 2 mu E (the paper's solid)"),
      entry<NeoHookean>("neo-hookean", "compressible neo-Hookean, W = mu/2(I1-3) - mu lnJ + "
                                       "lambda/2 (lnJ)^2"),
  };
  return laws;
}

const LawEntry& find_law(const std::string& type, const std::string& context) {
  std::string known;
  for (const auto& law : registered_laws()) {
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
  return law.make(validate_parameters(*law.parameters, values, context));
}

} // namespace trifem::material
