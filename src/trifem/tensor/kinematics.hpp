// SPDX-License-Identifier: MIT
// Large-deformation kinematics at a point (Holzapfel, Nonlinear Solid Mechanics, ch. 2).
#pragma once

#include "trifem/tensor/tensor.hpp"

namespace trifem::kinematics {

/// Cauchy stress sigma = F S F^T / J from the second Piola-Kirchhoff stress.
inline Mat3 cauchy_from_pk2(const Mat3& F, const Mat3& S) {
  return F * S * F.transpose() / F.determinant();
}

} // namespace trifem::kinematics
