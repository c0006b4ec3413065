// SPDX-License-Identifier: MIT
// Registry of solid laws: type name -> schema + factory. Adding a law is one line in registry.cpp.
#pragma once

#include "trifem/material/elastic_law.hpp"
#include "trifem/material/schema.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace trifem::material {

/// One registered law.
struct LawEntry {
  std::string type;                               ///< name used in case files
  std::string doc;                                ///< one-line description
  const std::vector<ParameterSchema>* parameters; ///< parameter schema
  std::function<std::unique_ptr<ElasticLaw>(const ParameterValues&)> make;
  /// Checks between parameters that the schema's ranges cannot express (e.g. c1 + c2 > 0) on
  /// validated values: InputError naming `context.key`. Empty if the law has none.
  std::function<void(const ParameterValues&, const std::string& context)> check;
  /// Typical values (articular cartilage) that pass every check: the parameters of the
  /// registry-wide tests and benchmarks.
  ParameterValues example;
};

/// All registered laws that can be a material or a mixture's solid on their own (each has
/// positive small-strain moduli).
const std::vector<LawEntry>& registered_laws();

/// The laws that are valid only as constituents of a solid mixture (type "solid-mixture"):
/// fibre families, which carry no load at zero strain (small-strain moduli 0) and none across
/// their direction. Kept out of registered_laws(), whose registry-wide checks are relative to
/// the small-strain moduli.
const std::vector<LawEntry>& constituent_laws();

/// The entry for `type` among registered_laws() and constituent_laws(); InputError naming
/// `context` and listing the known types otherwise.
const LawEntry& find_law(const std::string& type, const std::string& context);

/// Validates `values` (unknown keys, required keys, ranges, the law's own check; messages name
/// `context.key`) and constructs the law (registered or constituent-only).
std::unique_ptr<ElasticLaw> create_law(const std::string& type, const ParameterValues& values,
                                       const std::string& context);

/// A solid law as a case gives it: a law's type and parameters, or a solid mixture (type
/// kSolidMixtureType, no parameters) and its constituents, each a law of registered_laws() or
/// constituent_laws() (no nested mixtures).
struct LawSpec {
  std::string type;
  ParameterValues parameters;
  std::vector<LawSpec> constituents; ///< set exactly for a solid mixture
};

/// The law of `spec`: create_law(type, parameters, context) or, for a solid mixture, the
/// SolidMixture of its constituents (each created with context `context.constituent[i]`,
/// counted from 1). InputError naming the key path for a mixture without constituents, a
/// nested mixture, parameters given to a mixture or constituents given to a law.
std::unique_ptr<ElasticLaw> create_law(const LawSpec& spec, const std::string& context);

} // namespace trifem::material
