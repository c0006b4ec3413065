// SPDX-License-Identifier: MIT
// The consistent mass matrix of a hex8 cell, shared by its inertia and its body forces.
#pragma once

#include "trifem/fe/hex8.hpp"

#include <optional>

namespace trifem::physics {

/// m_ab = ∫ ρ N_a N_b dV over the cell with reference nodes X (2x2x2 Gauss: exact for a
/// parallelepiped); its row sums are ∫ ρ N_a dV. None if det(dX/dξ) ≤ 0 at a Gauss point (an
/// inverted or degenerate cell).
std::optional<Eigen::Matrix<Real, 8, 8>> consistent_cell_mass(const fe::HexCoords& X, Real density);

} // namespace trifem::physics
