// SPDX-License-Identifier: MIT
#include "trifem/material/rotated_law.hpp"

#include "trifem/core/error.hpp"

#include <cmath>

namespace trifem::material {

Mat6 voigt_rotation(const Mat3& Q) {
  // Column c is the image of the c-th stress-like unit tensor: exact by construction, and the
  // identity (to the bit) for Q = I.
  Mat6 T;
  for (int c = 0; c < 6; ++c) {
    Vec6 unit = Vec6::Zero();
    unit[c] = 1.0;
    T.col(c) = voigt::stress(Q * voigt::from_stress(unit) * Q.transpose());
  }
  return T;
}

RotatedLaw::RotatedLaw(std::shared_ptr<const ElasticLaw> law, const Mat3& Q)
    : law_(std::move(law)), Q_(Q), T_(voigt_rotation(Q)) {
  if (!law_)
    throw LogicError("RotatedLaw: no law");
  const Real off = (Q.transpose() * Q - Mat3::Identity()).cwiseAbs().maxCoeff();
  if (!(off <= 1e-12) || !(std::abs(Q.determinant() - 1.0) <= 1e-12))
    throw LogicError("RotatedLaw: the basis is not a rotation");
}

Real RotatedLaw::energy(const Mat3& C) const {
  return law_->energy(local(C));
}

Mat3 RotatedLaw::stress(const Mat3& C) const {
  return Q_ * law_->stress(local(C)) * Q_.transpose();
}

StressTangent RotatedLaw::stress_tangent(const Mat3& C) const {
  const StressTangent loc = law_->stress_tangent(local(C));
  return {Q_ * loc.S * Q_.transpose(), T_ * loc.D * T_.transpose()};
}

} // namespace trifem::material
