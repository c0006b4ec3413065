// SPDX-License-Identifier: MIT
#include "trifem/explicit/multiplier_stiffness.hpp"

namespace trifem::explicit_dynamics {
namespace {

/// The stiffness of multiplier_stiffness for a cell geometry of any family (Grads: the type of
/// one point's reference gradients, Matrix: the cell matrix).
template <class Grads, class Matrix, class Geometry, class Coords>
bool multiplier_stiffness_of(const Geometry& geo, const Coords& u, Constraint constraint,
                             Real lambda, Matrix& K) {
  const auto n = u.rows();
  Matrix k = Matrix::Zero(3 * n, 3 * n);
  for (std::size_t q = 0; q < geo.dV.size(); ++q) {
    const auto& g = geo.dN_dX[q];
    const Mat3 F = Mat3::Identity() + u.transpose() * g;
    const Real J = F.determinant();
    if (!(J > 0.0))
      return false;
    const Grads s = g * F.inverse(); // row a = (F⁻ᵀ ∇N_a)ᵀ
    const Real w = lambda * geo.dV[q];
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) {
        const Mat3 ba = s.row(b).transpose() * s.row(a); // (ba)_ik = s_b,i s_a,k
        if (constraint == Constraint::JMinusOne)
          k.template block<3, 3>(3 * a, 3 * b) += (w * J) * (ba.transpose() - ba);
        else
          k.template block<3, 3>(3 * a, 3 * b) -= w * ba;
      }
  }
  K = k;
  return true;
}

} // namespace

bool multiplier_stiffness(const fe::HexGeometry& geo, const fe::HexCoords& u, Constraint constraint,
                          Real lambda, physics::HexMatrix& K) {
  return multiplier_stiffness_of<fe::HexShapeGrad>(geo, u, constraint, lambda, K);
}

bool multiplier_stiffness(const physics::CellGeometry& geo, const fe::CellNodeCoords& u,
                          Constraint constraint, Real lambda, physics::CellMatrixX& K) {
  return multiplier_stiffness_of<fe::ShapeGrads>(geo, u, constraint, lambda, K);
}

} // namespace trifem::explicit_dynamics
