// SPDX-License-Identifier: MIT
// Dense assembly of one contact term over all DOFs (for the finite-difference tests).
#pragma once

#include "trifem/contact/contact_term.hpp"

#include <gtest/gtest.h>

namespace trifem::test {

/// Residual (and Jacobian) of the whole term over all DOFs at x with step dt, after
/// prepare(x). Returns whether prepare() changed the stencils.
inline bool assemble_dense(contact::ContactTerm& term, const Vector& x, Real dt, Vector& R,
                           Eigen::MatrixXd* K) {
  const physics::EvalState state{x, x, 1.0, dt};
  const bool changed = term.prepare(state);
  const Index n = static_cast<Index>(x.size());
  R.setZero(n);
  if (K)
    K->setZero(n, n);
  std::vector<Index> dofs;
  physics::LocalVector r;
  physics::LocalMatrix k;
  for (Index e = 0; e < term.num_elements(); ++e) {
    term.element_dofs(e, dofs);
    EXPECT_TRUE(term.evaluate(e, state, r, K ? &k : nullptr));
    for (std::size_t i = 0; i < dofs.size(); ++i) {
      R[dofs[i]] += r[i];
      if (K)
        for (std::size_t j = 0; j < dofs.size(); ++j)
          (*K)(dofs[i], dofs[j]) += k(i, j);
    }
  }
  return changed;
}

} // namespace trifem::test
