// SPDX-License-Identifier: MIT
#include "trifem/linalg/block_split.hpp"

#include <algorithm>

namespace trifem::linalg {
namespace {

enum class Role { displacement, flux, potential };

Role role_of(const std::string& name) {
  if (name == "fluid_flux" || name == "cation_flux" || name == "anion_flux")
    return Role::flux;
  if (name == "pressure" || name == "electric_potential" ||
      name.rfind("contact_multipliers", 0) == 0)
    return Role::potential;
  return Role::displacement;
}

} // namespace

BlockSplit BlockSplit::from_fields(const std::vector<int>& equation_fields,
                                   const std::vector<std::string>& field_names) {
  std::vector<Role> roles;
  for (const std::string& name : field_names)
    roles.push_back(role_of(name));
  BlockSplit split;
  for (std::size_t eq = 0; eq < equation_fields.size(); ++eq) {
    const int field = equation_fields[eq];
    const Role role =
        field >= 0 && field < static_cast<int>(roles.size()) ? roles[field] : Role::displacement;
    std::vector<Index>& group = role == Role::flux        ? split.flux
                                : role == Role::potential ? split.potential
                                                          : split.displacement;
    group.push_back(static_cast<Index>(eq));
  }
  return split;
}

std::vector<Index> BlockSplit::primal() const {
  std::vector<Index> all(displacement);
  all.insert(all.end(), flux.begin(), flux.end());
  std::sort(all.begin(), all.end());
  return all;
}

} // namespace trifem::linalg
