// SPDX-License-Identifier: MIT
// Total Lagrangian solid element of any cell family of fe::ReferenceCell (tet4, tet10,
// penta6, hex8, hex20): the reference geometry at the quadrature points of the family's rule,
// the internal force and the consistent tangent (the hex8 path of the models stays
// solid_kernel.hpp's solid_hex8).
#pragma once

#include "trifem/fe/reference_element.hpp"
#include "trifem/material/elastic_law.hpp"
#include "trifem/mesh/mesh.hpp"
#include "trifem/physics/solid_kernel.hpp"

#include <optional>
#include <variant>
#include <vector>

namespace trifem::physics {

/// The most DOFs of a cell: three per node.
inline constexpr int kMaxCellDofs = 3 * fe::kMaxCellNodes;

/// Nodal vectors and matrices of one cell, node-major (u_0x, u_0y, u_0z, u_1x, ...), on the
/// stack.
using CellVectorX = Eigen::Matrix<Real, Eigen::Dynamic, 1, 0, kMaxCellDofs, 1>;
using CellMatrixX =
    Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxCellDofs, kMaxCellDofs>;

/// A strain-displacement matrix of a cell (6 strain-like Voigt rows, node-major columns).
using StrainMatrixX = Eigen::Matrix<Real, 6, Eigen::Dynamic, 0, 6, kMaxCellDofs>;

/// {dE} = B {du} at a point with deformation gradient F and ∇N_a = row a of g (as
/// solid_kernel.hpp's hex8 version).
void strain_displacement(const Mat3& F, const fe::ShapeGrads& g, StrainMatrixX& B);

/// Adds the geometric stiffness of the stress S over dV: K_ab += (∇N_a · S ∇N_b) dV I.
void add_geometric_stiffness(const fe::ShapeGrads& g, const Mat3& S, Real dV, CellMatrixX& K);

/// Reference-configuration values of a cell at the points of its family's rule.
struct CellGeometry {
  const fe::ReferenceCell* reference = nullptr;
  std::vector<fe::ShapeGrads> dN_dX; ///< per point: row a = dN_a/dX
  std::vector<Real> dV;              ///< per point: det(dX/dxi) × weight
  int num_nodes() const { return reference->num_nodes(); }
};

/// The geometry of the cell of `reference`'s family with node coordinates X (one row per
/// node); empty if det(dX/dxi) <= 0 at a point of the rule (an inverted or degenerate cell).
std::optional<CellGeometry> cell_geometry(const fe::ReferenceCell& reference,
                                          const fe::CellNodeCoords& X);

/// The reference geometry of a mesh cell: a hex8's fixed-size one (fe::hex8_geometry), or that of
/// its family's element.
using AnyCellGeometry = std::variant<fe::HexGeometry, CellGeometry>;

/// The reference geometry of cell c of the mesh; InputError naming the cell if it is inverted or
/// degenerate (det(dX/dxi) <= 0 at a quadrature point).
AnyCellGeometry reference_geometry(const mesh::Mesh& mesh, Index c);

/// Internal force f_a = ∫ F S ∇N_a dV and, if K is given, the tangent
/// K_ab = ∫ [(∇N_a · S ∇N_b) I + B_aᵀ D B_b] dV (as solid_hex8), for the nodal displacements
/// u (one row per node). False if J <= 0 at a point of the rule.
bool solid_cell(const CellGeometry& geo, const fe::CellNodeCoords& u,
                const material::ElasticLaw& law, CellVectorX& f, CellMatrixX* K);

/// The volume-averaged Cauchy stress, (∫ σ dv) / (∫ dv), and J = v / V of the cell (as
/// solid_hex8_stress).
CellStress solid_cell_stress(const CellGeometry& geo, const fe::CellNodeCoords& u,
                             const material::ElasticLaw& law);

} // namespace trifem::physics
