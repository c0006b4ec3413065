// SPDX-License-Identifier: MIT
// Consistent mass matrices of cells of every family and of quad4 shells, shared by the inertia
// and the body forces.
#pragma once

#include "trifem/fe/hex8.hpp"
#include "trifem/fe/reference_element.hpp"
#include "trifem/mesh/mesh.hpp"
#include "trifem/physics/solid_cell.hpp"

#include <optional>
#include <vector>

namespace trifem::physics {

/// m_ab = ∫ ρ N_a N_b dV over the cell with reference nodes X (2x2x2 Gauss: exact for a
/// parallelepiped); its row sums are ∫ ρ N_a dV. None if det(dX/dξ) ≤ 0 at a Gauss point (an
/// inverted or degenerate cell).
std::optional<Eigen::Matrix<Real, 8, 8>> consistent_cell_mass(const fe::HexCoords& X, Real density);

/// m_ab = Σ_q ρ N_a N_b dV_q over the points of the rule of a cell of any family but hex8
/// (exact for an affine cell).
Eigen::MatrixXd consistent_cell_mass(const CellGeometry& geo, Real density);

/// The lumped (diagonal) mass of the consistent mass matrix m: its row sums ∫ ρ N_a dV where all
/// are positive (hex8, tet4, penta6 cells, shells), else its diagonal scaled to keep the total
/// mass, m_a = m_aa Σ_bc m_bc / Σ_b m_bb (Hinton, Rock and Zienkiewicz 1976: the row sums of a
/// tet10's or hex20's mass are negative at its corners).
Eigen::VectorXd lumped_mass(const Eigen::MatrixXd& m);

/// The most nodes of a mass element (a hex20 cell; a hex8 has 8, a quad4 shell 4).
inline constexpr int kMaxMassNodes = fe::kMaxCellNodes;
/// A vector per node of a mass element (rows: nodes, columns: x, y, z; no heap allocation).
using NodalVectors = Eigen::Matrix<Real, Eigen::Dynamic, 3, 0, kMaxMassNodes, 3>;

/// A piece of the model's mass: its nodes and its consistent mass matrix m_ab over them (sized
/// to its nodes).
struct MassElement {
  std::vector<Index> nodes;
  Eigen::MatrixXd mass;
};

/// The mass elements of `cells` (any family: a hex8 by 2x2x2 Gauss points, the others by their
/// family's rule, exact for an affine cell) of the given densities (> 0). Throws InputError
/// naming the first inverted or degenerate cell.
std::vector<MassElement> cell_mass_elements(const mesh::Mesh& mesh, const std::vector<Index>& cells,
                                            const std::vector<Real>& densities);

/// The quad4 facet with reference nodes X (a triangle: its last node repeats the third) as a
/// thin shell of mass per area `areal_density` = ρ t [t/mm²]: m_ab = ∫ ρ t N_a N_b dA over the
/// reference mid-surface (2x2 Gauss: exact for a flat parallelogram and a triangle). The
/// shell's rotary inertia through its thickness, of relative order (t/L)², is left out.
Eigen::Matrix<Real, 4, 4> consistent_shell_mass(const fe::QuadCoords& X, Real areal_density);

} // namespace trifem::physics
