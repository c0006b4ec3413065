// SPDX-License-Identifier: MIT
// Element residual and Jacobian of a contact element addressed by *global* DOF numbers, so that
// kernels with data-dependent stencils (projections) need no hand-made local ordering.
#pragma once

#include "trifem/core/error.hpp"
#include "trifem/physics/term.hpp"

#include <algorithm>
#include <span>

namespace trifem::contact {

/// View of an element's (r, K) whose rows and columns are the sorted, unique global DOFs
/// `dofs` (the element's stencil). The constructor zeroes r (and K, if given).
class LocalSystem {
public:
  LocalSystem(std::span<const Index> dofs, physics::LocalVector& r, physics::LocalMatrix* K)
      : dofs_(dofs), r_(r), K_(K) {
    const Index n = static_cast<Index>(dofs.size());
    r_.setZero(n);
    if (K_)
      K_->setZero(n, n);
  }

  bool with_jacobian() const { return K_ != nullptr; }
  physics::LocalVector& r() { return r_; }
  physics::LocalMatrix& K() { return *K_; }

  /// Local position of a global DOF of the stencil (a logic error if it is not in it).
  Index at(Index dof) const {
    const auto it = std::lower_bound(dofs_.begin(), dofs_.end(), dof);
    TRIFEM_VERIFY(it != dofs_.end() && *it == dof, "DOF {} is not in the contact stencil", dof);
    return static_cast<Index>(it - dofs_.begin());
  }

private:
  std::span<const Index> dofs_;
  physics::LocalVector& r_;
  physics::LocalMatrix* K_;
};

} // namespace trifem::contact
