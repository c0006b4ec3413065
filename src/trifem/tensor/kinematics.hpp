// SPDX-License-Identifier: MIT
// Large-deformation kinematics at a point (Holzapfel, Nonlinear Solid Mechanics, ch. 2).
#pragma once

#include "trifem/tensor/tensor.hpp"

namespace trifem::kinematics {

/// Green-Lagrange strain E = (F^T F - I)/2  (Holzapfel eq. 2.67).
inline Mat3 green_lagrange(const Mat3& F) {
  return 0.5 * (F.transpose() * F - Mat3::Identity());
}

/// Right Cauchy-Green tensor C = F^T F.
inline Mat3 right_cauchy_green(const Mat3& F) {
  return F.transpose() * F;
}

/// Cofactor J F^{-T}, the Nanson map n da = Cof(F) N dA (Holzapfel eq. 2.55).
Mat3 cofactor(const Mat3& F);

/// Cauchy stress sigma = F S F^T / J from the second Piola-Kirchhoff stress.
inline Mat3 cauchy_from_pk2(const Mat3& F, const Mat3& S) {
  return F * S * F.transpose() / F.determinant();
}

/// First Piola-Kirchhoff stress P = F S.
inline Mat3 pk1_from_pk2(const Mat3& F, const Mat3& S) {
  return F * S;
}

} // namespace trifem::kinematics
