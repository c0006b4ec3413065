// SPDX-License-Identifier: MIT
// Registry entries of the transport laws of a mixture (permeability, ion diffusivity): type name,
// parameter schema and factory, shared by permeability.hpp and diffusivity.hpp.
#pragma once

#include "trifem/core/error.hpp"
#include "trifem/material/schema.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace trifem::material {

/// Name, description and parameter schema of a registered transport law.
struct TransportLawInfo {
  std::string type;                               ///< name used in case files
  std::string doc;                                ///< one-line description with the formula
  const std::vector<ParameterSchema>* parameters; ///< parameter schema
};

/// One registered transport law of kind `Law` (PermeabilityLaw or DiffusivityLaw).
template <class Law>
struct TransportLawEntry : TransportLawInfo {
  /// Builds the law from validated values; phi_s0 is the mixture's solid volume fraction in the
  /// reference state (laws that close the pores at J = phi_s0 need it).
  std::function<std::unique_ptr<Law>(const ParameterValues&, Real phi_s0)> make;
};

/// Validates `values` against the schema of the law `type` of `laws` (unknown keys, missing
/// required keys and ranges are InputErrors naming `context.key`; an unknown type names
/// `context.type` and lists the known types) and constructs the law.
template <class Law>
std::unique_ptr<Law> create_transport_law(const std::vector<TransportLawEntry<Law>>& laws,
                                          const std::string& type, const ParameterValues& values,
                                          Real phi_s0, const std::string& context,
                                          std::string_view noun) {
  std::string known;
  for (const auto& law : laws) {
    if (law.type == type)
      return law.make(validate_parameters(*law.parameters, values, context), phi_s0);
    known += (known.empty() ? "" : ", ") + law.type;
  }
  throw InputError(
      fmt::format("{}.type = '{}': unknown {} (expected one of: {})", context, type, noun, known));
}

} // namespace trifem::material
