// SPDX-License-Identifier: MIT
// Scalar measures of the relative motion of two rigid bodies, with their exact first and
// second derivatives by the bodies' unknowns (docs/theory/rigid.md §5). The unknowns of a pair
// are q = (u_a, Θ_a, u_b, Θ_b): the displacement of each body's center and its total rotation
// vector. Points and directions fixed in a body (or in space) are the attachments
//
//     point:      y = X_c + u_c + R(Θ) S,   S = X − X_c       ∂y/∂q = [I, −[s]× T(Θ)],  s = R S
//     direction:  y = R(Θ) V                                  ∂y/∂q = [0, −[y]× T(Θ)]
//
// and a measure is built from dot products of attachments: a weighted sum Q = Σ w y_i·y_j,
// its square root (a distance) or the angle atan2(Q1, Q2). The second derivative of m·y by Θ
// at fixed m is H(Θ, s × m) + Tᵀ[m]×[s]×T (H: rotation::tangent_derivative).
#pragma once

#include "trifem/core/types.hpp"
#include "trifem/tensor/tensor.hpp"

#include <array>
#include <span>
#include <vector>

namespace trifem::physics::rigid {

/// Number of unknowns of a pair of bodies.
inline constexpr int kPairDofs = 12;
using PairVector = Eigen::Matrix<Real, kPairDofs, 1>;
using PairMatrix = Eigen::Matrix<Real, kPairDofs, kPairDofs>;

/// The motion of the two bodies of a pair: body k moves with (u[k], theta[k]) about its
/// reference center X_c = centre[k]; a body that does not move (space) has moving[k] = false.
struct PairState {
  std::array<bool, 2> moving{false, false};
  std::array<Vec3, 2> centre{Vec3::Zero(), Vec3::Zero()};
  std::array<Vec3, 2> u{Vec3::Zero(), Vec3::Zero()};
  std::array<Vec3, 2> theta{Vec3::Zero(), Vec3::Zero()};
};

/// A point or a direction fixed in body 0 (a) or 1 (b) of the pair, or in space (−1).
struct Attachment {
  int body = -1;
  Vec3 reference = Vec3::Zero(); ///< X (a point) or V (a direction), reference configuration
  bool point = true;
};

/// y_i · y_j with a weight.
struct Dot {
  int i = 0, j = 0; ///< attachment indices
  Real weight = 1.0;
};

/// What a measure computes from its dot products.
enum class MeasureKind {
  Sum,    ///< Q1 = Σ w y_i·y_j
  Length, ///< √Q1
  Angle   ///< atan2(Q1, Q2) ∈ (−π, π]
};

/// A scalar function of the attachments.
struct Measure {
  MeasureKind kind = MeasureKind::Sum;
  std::vector<Dot> first;
  std::vector<Dot> second; ///< Q2 of an angle
};

/// A measure's value with its gradient and Hessian by q.
struct MeasureValue {
  Real value = 0.0;
  PairVector gradient = PairVector::Zero();
  PairMatrix hessian = PairMatrix::Zero();
};

/// An attachment evaluated at a state: y, ∂y/∂q and what its second derivatives need.
struct AttachmentValue {
  Vec3 y = Vec3::Zero();
  Eigen::Matrix<Real, 3, kPairDofs> jacobian = Eigen::Matrix<Real, 3, kPairDofs>::Zero();
  int body = -1;             ///< −1: fixed in space (no derivatives)
  Vec3 arm = Vec3::Zero();   ///< s = R S (a point) or y (a direction)
  Vec3 theta = Vec3::Zero(); ///< Θ of its body
};

/// The attachments at `state`.
std::vector<AttachmentValue> evaluate(std::span<const Attachment> attachments,
                                      const PairState& state);

/// The value of `measure` (and, if `derivatives`, its gradient and Hessian). False for a
/// Length at zero or an Angle of two zero sums, where the derivatives do not exist.
bool evaluate(const Measure& measure, std::span<const AttachmentValue> y, bool derivatives,
              MeasureValue& out);

} // namespace trifem::physics::rigid
