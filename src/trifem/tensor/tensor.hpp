// SPDX-License-Identifier: MIT
// Fixed-size tensor aliases and Voigt notation.
//
// Voigt order for symmetric second-order tensors: (11, 22, 33, 12, 23, 13).
// Stress-like Voigt vectors hold the tensor components; strain-like vectors hold
// engineering shear (2 E_12), so that S : dE = S_voigt . dE_voigt.
#pragma once

#include "trifem/core/types.hpp"

#include <Eigen/Dense>

namespace trifem {

using Vec2 = Eigen::Matrix<Real, 2, 1>;
using Vec3 = Eigen::Matrix<Real, 3, 1>;
using Mat2 = Eigen::Matrix<Real, 2, 2>;
using Mat3 = Eigen::Matrix<Real, 3, 3>;
using Vec6 = Eigen::Matrix<Real, 6, 1>;
using Mat6 = Eigen::Matrix<Real, 6, 6>;

namespace voigt {

/// Row/column index pairs of the Voigt components.
inline constexpr int kI[6] = {0, 1, 2, 0, 1, 0};
inline constexpr int kJ[6] = {0, 1, 2, 1, 2, 2};

/// Symmetric tensor -> stress-like Voigt vector.
inline Vec6 stress(const Mat3& A) {
  Vec6 v;
  for (int k = 0; k < 6; ++k)
    v[k] = A(kI[k], kJ[k]);
  return v;
}

/// Symmetric tensor -> strain-like Voigt vector (shear components doubled).
inline Vec6 strain(const Mat3& A) {
  Vec6 v = stress(A);
  v.tail<3>() *= 2.0;
  return v;
}

/// Stress-like Voigt vector -> symmetric tensor.
inline Mat3 from_stress(const Vec6& v) {
  Mat3 A;
  for (int k = 0; k < 6; ++k)
    A(kI[k], kJ[k]) = A(kJ[k], kI[k]) = v[k];
  return A;
}

/// Strain-like Voigt vector -> symmetric tensor.
inline Mat3 from_strain(const Vec6& v) {
  Vec6 w = v;
  w.tail<3>() *= 0.5;
  return from_stress(w);
}

/// (A (x) B)_IJKL = A_IJ B_KL in Voigt form (stress-like rows, strain-like columns).
inline Mat6 outer(const Mat3& A, const Mat3& B) {
  return stress(A) * stress(B).transpose();
}

/// (A (.) A)_IJKL = (A_IK A_JL + A_IL A_JK)/2 in Voigt form.
inline Mat6 symmetric_product(const Mat3& A) {
  Mat6 D;
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 6; ++c) {
      const int I = kI[r], J = kJ[r], K = kI[c], L = kJ[c];
      D(r, c) = 0.5 * (A(I, K) * A(J, L) + A(I, L) * A(J, K));
    }
  return D;
}

} // namespace voigt
} // namespace trifem
