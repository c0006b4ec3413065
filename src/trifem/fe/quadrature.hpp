// SPDX-License-Identifier: MIT
// Gauss-Legendre rules on the reference hexahedron [-1,1]^3 and square [-1,1]^2.
#pragma once

#include "trifem/tensor/tensor.hpp"

#include <array>

namespace trifem::fe {

/// A quadrature point on the reference hexahedron.
struct HexQuadraturePoint {
  Vec3 xi;
  Real weight;
};

/// A quadrature point on the reference square.
struct QuadQuadraturePoint {
  Vec2 xi;
  Real weight;
};

/// 2x2x2 Gauss rule (exact for polynomials of degree <= 3 per direction).
const std::array<HexQuadraturePoint, 8>& hex_gauss_2x2x2();

/// 2x2 Gauss rule on the square.
const std::array<QuadQuadraturePoint, 4>& quad_gauss_2x2();

} // namespace trifem::fe
