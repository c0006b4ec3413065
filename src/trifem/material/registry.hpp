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

/// All registered laws.
const std::vector<LawEntry>& registered_laws();

/// The entry for `type`; InputError naming `context` and listing the known types otherwise.
const LawEntry& find_law(const std::string& type, const std::string& context);

/// Validates `values` (unknown keys, required keys, ranges, the law's own check; messages name
/// `context.key`) and constructs the law.
std::unique_ptr<ElasticLaw> create_law(const std::string& type, const ParameterValues& values,
                                       const std::string& context);

} // namespace trifem::material
