// SPDX-License-Identifier: MIT
// A solid law evaluated in a local material basis (the material axes of a cell).
#pragma once

#include "trifem/material/elastic_law.hpp"

#include <memory>

namespace trifem::material {

/// The 6x6 matrix T with voigt::stress(Q A Q^T) = T voigt::stress(A) for every symmetric A
/// (stress-like Voigt components). Its strain-like counterpart for Q^T is T^T (S : E is
/// invariant), so a tangent D_loc of local components rotates to the global D = T D_loc T^T.
Mat6 voigt_rotation(const Mat3& Q);

/// The law `law` whose directions (fibre vectors, ellipsoid semi-axes) are read in the local
/// orthonormal basis Q = [e1 e2 e3] (columns: the local axes in global components):
///   W(C) = W_loc(Q^T C Q),   S = Q S_loc Q^T,   D = T D_loc T^T  (T = voigt_rotation(Q)),
/// with S_loc, D_loc the stress and tangent of `law` at C_loc = Q^T C Q. The small-strain
/// moduli and the type are those of `law` (a rotation changes neither).
class RotatedLaw final : public ElasticLaw {
public:
  /// Q must be a rotation (orthonormal, det +1; LogicError otherwise, to 1e-12): the case
  /// reader builds it from validated axes.
  RotatedLaw(std::shared_ptr<const ElasticLaw> law, const Mat3& Q);

  Real energy(const Mat3& C) const override;
  Mat3 stress(const Mat3& C) const override;
  StressTangent stress_tangent(const Mat3& C) const override;
  Real p_wave_modulus() const override { return law_->p_wave_modulus(); }
  Real shear_modulus() const override { return law_->shear_modulus(); }
  std::string type() const override { return law_->type(); }

  /// The local basis (columns e1, e2, e3 in global components).
  const Mat3& basis() const { return Q_; }

private:
  Mat3 local(const Mat3& C) const { return Q_.transpose() * C * Q_; }

  std::shared_ptr<const ElasticLaw> law_;
  Mat3 Q_;
  Mat6 T_;
};

} // namespace trifem::material
