// SPDX-License-Identifier: MIT
// The cell families of fe::ReferenceCell for tests: their list, deterministic noise and
// distorted instances of each reference cell.
#pragma once

#include "trifem/fe/reference_element.hpp"

#include <random>

namespace trifem::test {

inline constexpr fe::CellType kCellFamilies[] = {fe::CellType::Tet4, fe::CellType::Tet10,
                                                 fe::CellType::Penta6, fe::CellType::Hex8,
                                                 fe::CellType::Hex20};

/// Uniform numbers in [-1, 1] from a fixed seed (the same sequence on every platform: the raw
/// output of std::mt19937, which the standard fixes).
class Noise {
public:
  explicit Noise(unsigned seed) : engine_(seed) {}
  Real next() { return 2.0 * static_cast<Real>(engine_()) / engine_.max() - 1.0; }

private:
  std::mt19937 engine_;
};

/// The reference nodes of `type`, every node (mid-edge nodes too: curved edges) moved by up to
/// `amplitude` of the reference cell's size in each coordinate.
inline fe::CellNodeCoords distorted_cell(fe::CellType type, unsigned seed, Real amplitude) {
  Noise noise(seed);
  fe::CellNodeCoords X = fe::reference_cell(type).nodes();
  for (Index a = 0; a < X.rows(); ++a)
    for (int k = 0; k < 3; ++k)
      X(a, k) += amplitude * noise.next();
  return X;
}

/// The nodal vectors of a cell (3 per node, node-major) as rows of node coordinates.
inline fe::CellNodeCoords as_rows(const Eigen::VectorXd& v) {
  fe::CellNodeCoords u(v.size() / 3, 3);
  for (Index a = 0; a < u.rows(); ++a)
    u.row(a) = v.segment<3>(3 * a).transpose();
  return u;
}

} // namespace trifem::test
