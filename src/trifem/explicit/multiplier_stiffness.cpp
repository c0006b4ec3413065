// SPDX-License-Identifier: MIT
#include "trifem/explicit/multiplier_stiffness.hpp"

namespace trifem::explicit_dynamics {

bool multiplier_stiffness(const fe::HexGeometry& geo, const fe::HexCoords& u, Constraint constraint,
                          Real lambda, physics::HexMatrix& K) {
  physics::HexMatrix k = physics::HexMatrix::Zero();
  for (int q = 0; q < 8; ++q) {
    const fe::HexShapeGrad& g = geo.dN_dX[q];
    const Mat3 F = Mat3::Identity() + u.transpose() * g;
    const Real J = F.determinant();
    if (!(J > 0.0))
      return false;
    const fe::HexShapeGrad s = g * F.inverse(); // row a = (F⁻ᵀ ∇N_a)ᵀ
    const Real w = lambda * geo.dV[q];
    for (int a = 0; a < 8; ++a)
      for (int b = 0; b < 8; ++b) {
        const Mat3 ba = s.row(b).transpose() * s.row(a); // (ba)_ik = s_b,i s_a,k
        if (constraint == Constraint::JMinusOne)
          k.block<3, 3>(3 * a, 3 * b) += (w * J) * (ba.transpose() - ba);
        else
          k.block<3, 3>(3 * a, 3 * b) -= w * ba;
      }
  }
  K = k;
  return true;
}

} // namespace trifem::explicit_dynamics
