// SPDX-License-Identifier: MIT
// Finite rotations parametrised by the total rotation vector Θ (docs/theory/rigid.md):
//
//     R(Θ) = exp[Θ]× = I + (sin θ/θ)[Θ]× + a[Θ]×²,   θ = |Θ|,   a = (1 − cos θ)/θ²
//     δR Rᵀ = [T δΘ]×,   T(Θ) = I + a[Θ]× + b[Θ]×²,   b = (θ − sin θ)/θ³
//
// T is the tangent map between a variation of Θ and the spatial angular variation; H is the
// derivative of Tᵀm by Θ at fixed m, the part of the geometric stiffness of a rotating body
// that comes from T itself. Every coefficient has a series below θ = 0.3, so that all of them
// keep full precision down to θ = 0.
#pragma once

#include "trifem/tensor/tensor.hpp"

namespace trifem::rotation {

/// [v]×: the matrix with [v]× w = v × w.
inline Mat3 skew(const Vec3& v) {
  Mat3 S;
  S << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return S;
}

/// The rotation matrix exp[Θ]×.
Mat3 matrix(const Vec3& theta);

/// The rotation vector of a rotation matrix (the inverse of matrix() for θ ≤ π; at θ = π
/// either of the two opposite vectors).
Vec3 vector(const Mat3& R);

/// T(Θ): δR Rᵀ = [T δΘ]×.
Mat3 tangent(const Vec3& theta);

/// H(Θ, m) = ∂(T(Θ)ᵀ m)/∂Θ at fixed m.
Mat3 tangent_derivative(const Vec3& theta, const Vec3& m);

} // namespace trifem::rotation
