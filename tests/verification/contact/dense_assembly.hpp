// SPDX-License-Identifier: MIT
// Dense assembly of one contact term over all DOFs (for the finite-difference tests).
#pragma once

#include "trifem/contact/contact_term.hpp"

#include <gtest/gtest.h>

namespace trifem::test {

/// Two blocks meeting at y = 0 for the finite-difference tests of the contact term: the x (= z)
/// node coordinates of the master block (below) and of the slave block (above), and their cells.
struct FdLayout {
  const char* name;
  std::vector<Real> master; ///< x (= z) node coordinates of the master block
  std::vector<Real> slave;  ///< x (= z) node coordinates of the slave block
  mesh::CellType master_cells = mesh::CellType::Hex8, slave_cells = mesh::CellType::Hex8;
};

/// Projections near facet centres; near facet edges (|ξ| up to 0.97); curved tri6 slave facets
/// on quad8 master facets.
inline const FdLayout kFdInterior{"interior", {-0.25, 0.25, 0.75, 1.25}, {0.0, 0.5, 1.0}};
inline const FdLayout kFdNearEdges{
    "near-edges", {-0.25, 0.25, 0.75, 1.25}, {0.0, 0.24, 0.5, 0.77, 1.0}};
inline const FdLayout kFdTri6OnQuad8{"tri6/quad8",
                                     {-0.25, 0.25, 0.75, 1.25},
                                     {0.0, 0.5, 1.0},
                                     mesh::CellType::Hex20,
                                     mesh::CellType::Tet10};

/// Residual (and Jacobian) of the whole term over all DOFs at x with step dt from the state
/// x_old, after prepare(x). Returns whether prepare() changed the stencils.
inline bool assemble_dense(contact::ContactTerm& term, const Vector& x, const Vector& x_old,
                           Real dt, Vector& R, Eigen::MatrixXd* K) {
  const physics::EvalState state{x, x_old, 1.0, dt};
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

/// The same for a step that starts at x.
inline bool assemble_dense(contact::ContactTerm& term, const Vector& x, Real dt, Vector& R,
                           Eigen::MatrixXd* K) {
  return assemble_dense(term, x, x, dt, R, K);
}

/// Central differences (step h) of the whole term's residual over all DOFs at x, in a step of
/// size dt from x_old; the stencils must not change under the perturbations (checked). The
/// projections of x are restored on return.
inline Eigen::MatrixXd fd_jacobian(contact::ContactTerm& term, const Vector& x, const Vector& x_old,
                                   Real dt, Real h = 1e-6) {
  const Index n = static_cast<Index>(x.size());
  Eigen::MatrixXd fd = Eigen::MatrixXd::Zero(n, n);
  Vector Rp, Rm;
  for (Index j = 0; j < n; ++j) {
    Vector xp = x, xm = x;
    xp[j] += h;
    xm[j] -= h;
    EXPECT_FALSE(assemble_dense(term, xp, x_old, dt, Rp, nullptr)) << "stencil changed at " << j;
    EXPECT_FALSE(assemble_dense(term, xm, x_old, dt, Rm, nullptr)) << "stencil changed at " << j;
    fd.col(j) = (Rp - Rm) / (2 * h);
  }
  assemble_dense(term, x, x_old, dt, Rp, nullptr);
  return fd;
}

} // namespace trifem::test
