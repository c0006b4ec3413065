// SPDX-License-Identifier: MIT
#include "trifem/dofs/dirichlet.hpp"

namespace trifem::dofs {

void constrain_all(const std::vector<DirichletCondition>& conditions, DofMap& map) {
  for (const auto& c : conditions)
    for (Index d : c.dofs)
      map.constrain(d);
}

void prescribed_values(const std::vector<DirichletCondition>& conditions, Real t, Vector& target) {
  for (const auto& c : conditions) {
    const Real v = c.value(t);
    for (std::size_t i = 0; i < c.dofs.size(); ++i)
      target[c.dofs[i]] = c.offsets.empty() ? v : v + c.offsets[i];
  }
}

} // namespace trifem::dofs
