// SPDX-License-Identifier: MIT
#include "trifem/physics/linear_constraint_term.hpp"

#include "trifem/core/error.hpp"

#include <algorithm>
#include <cmath>

namespace trifem::physics {

LinearConstraintTerm::LinearConstraintTerm(std::vector<LinearConstraint> constraints)
    : constraints_(std::move(constraints)) {
  for (std::size_t i = 0; i < constraints_.size(); ++i) {
    const LinearConstraint& c = constraints_[i];
    TRIFEM_CHECK(!c.coefficients.empty() && c.multiplier >= 0,
                 "linear constraint {}: no coefficient or no multiplier", i + 1);
    std::vector<Index> dofs;
    for (const auto& [dof, coefficient] : c.coefficients) {
      TRIFEM_CHECK(dof >= 0 && coefficient != 0.0 && std::isfinite(coefficient),
                   "linear constraint {}: invalid DOF {} or coefficient {}", i + 1, dof,
                   coefficient);
      dofs.push_back(dof);
    }
    std::sort(dofs.begin(), dofs.end());
    TRIFEM_CHECK(std::adjacent_find(dofs.begin(), dofs.end()) == dofs.end(),
                 "linear constraint {}: a DOF appears twice", i + 1);
  }
}

void LinearConstraintTerm::element_dofs(Index e, std::vector<Index>& dofs) const {
  const LinearConstraint& c = constraints_[e];
  dofs.clear();
  for (const auto& entry : c.coefficients)
    dofs.push_back(entry.first);
  dofs.push_back(c.multiplier);
}

bool LinearConstraintTerm::evaluate(Index e, const EvalState& state, LocalVector& r,
                                    LocalMatrix* K) const {
  const LinearConstraint& c = constraints_[e];
  const auto n = static_cast<Index>(c.coefficients.size());
  const Real lambda = state.x[c.multiplier];
  r.setZero(n + 1);
  Real g = -c.rhs(state.time);
  for (Index j = 0; j < n; ++j) {
    const auto [dof, coefficient] = c.coefficients[j];
    r[j] = lambda * coefficient;
    g += coefficient * state.x[dof];
  }
  r[n] = g;
  if (K) {
    K->setZero(n + 1, n + 1);
    for (Index j = 0; j < n; ++j)
      (*K)(j, n) = (*K)(n, j) = c.coefficients[j].second;
  }
  return true;
}

} // namespace trifem::physics
