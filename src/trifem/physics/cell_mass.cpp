// SPDX-License-Identifier: MIT
#include "trifem/physics/cell_mass.hpp"

namespace trifem::physics {

std::optional<Eigen::Matrix<Real, 8, 8>> consistent_cell_mass(const fe::HexCoords& X,
                                                              Real density) {
  Eigen::Matrix<Real, 8, 8> m = Eigen::Matrix<Real, 8, 8>::Zero();
  for (const fe::HexQuadraturePoint& q : fe::hex_gauss_2x2x2()) {
    const fe::HexShape N = fe::hex8_shape(q.xi);
    const Real detJ = (fe::hex8_shape_grad(q.xi).transpose() * X).determinant();
    if (!(detJ > 0.0))
      return std::nullopt;
    m.noalias() += (density * detJ * q.weight) * (N * N.transpose());
  }
  return m;
}

} // namespace trifem::physics
