// SPDX-License-Identifier: MIT
#include "trifem/fe/quadrature.hpp"

#include <cmath>

namespace trifem::fe {
namespace {
const Real kG = 1.0 / std::sqrt(3.0);
} // namespace

const std::array<HexQuadraturePoint, 8>& hex_gauss_2x2x2() {
  static const std::array<HexQuadraturePoint, 8> rule = [] {
    std::array<HexQuadraturePoint, 8> r{};
    int q = 0;
    for (int k = 0; k < 2; ++k)
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i)
          r[q++] = {Vec3((2 * i - 1) * kG, (2 * j - 1) * kG, (2 * k - 1) * kG), 1.0};
    return r;
  }();
  return rule;
}

const std::array<QuadQuadraturePoint, 4>& quad_gauss_2x2() {
  static const std::array<QuadQuadraturePoint, 4> rule = [] {
    std::array<QuadQuadraturePoint, 4> r{};
    int q = 0;
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i)
        r[q++] = {Vec2((2 * i - 1) * kG, (2 * j - 1) * kG), 1.0};
    return r;
  }();
  return rule;
}

} // namespace trifem::fe
