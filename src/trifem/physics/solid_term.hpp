// SPDX-License-Identifier: MIT
// Hyperelastic solid over a set of cells of any family (total Lagrangian).
#pragma once

#include "trifem/dofs/dof_map.hpp"
#include "trifem/fe/hex8.hpp"
#include "trifem/material/elastic_law.hpp"
#include "trifem/mesh/mesh.hpp"
#include "trifem/physics/nodal_dilatation.hpp"
#include "trifem/physics/solid_cell.hpp"
#include "trifem/physics/solid_kernel.hpp"
#include "trifem/physics/term.hpp"

#include <memory>
#include <optional>
#include <variant>

namespace trifem::physics {

/// The formulation of a solid cell.
enum class SolidElement {
  Displacement,   ///< standard displacement element (locks when nearly incompressible)
  MeanDilatation, ///< mean dilatation, Q1/P0 on a hex8 (mean_dilatation_kernel.hpp)
  /// the dilatation averaged over the corners' patches: tet4 and penta6 (nodal_dilatation.hpp)
  NodalDilatation,
};

/// Internal virtual work of hyperelastic cells: hex8 cells by solid_kernel.hpp and
/// mean_dilatation_kernel.hpp, the other families by solid_cell.hpp and mean_dilatation_cell,
/// tet4 and penta6 cells also by nodal_dilatation.hpp (an element of those reaches the nodes
/// of the cells around it). Each cell has a law (shared, immutable).
class SolidTerm final : public Term {
public:
  /// `cells[i]` uses `laws[i]` and the formulation `elements[i]` (empty: all displacement);
  /// reference geometry is computed once here. Throws
  /// InputError naming the cell if a cell is inverted or degenerate in the reference
  /// configuration, or if a cell that is not a tet4 or a penta6 asks for NodalDilatation.
  SolidTerm(const mesh::Mesh& mesh, const dofs::DofMap& dofs, dofs::FieldId displacement,
            std::vector<Index> cells, std::vector<std::shared_ptr<const material::ElasticLaw>> laws,
            std::vector<SolidElement> elements = {});

  std::string name() const override { return "solid"; }
  Index num_elements() const override { return static_cast<Index>(cells_.size()); }
  void element_dofs(Index e, std::vector<Index>& dofs) const override;
  bool evaluate(Index e, const EvalState& state, LocalVector& r, LocalMatrix* K) const override;
  /// A state in which a cell turned inside out (physics/folded_cells.hpp).
  std::string step_rejection(const EvalState& state) const override;

  /// Mesh cell of element e.
  Index cell(Index e) const { return cells_[e]; }
  /// Averaged Cauchy stress and J of element e at state x.
  CellStress stress(Index e, const Vector& x) const;

private:
  fe::HexCoords displacements(Index e, const Vector& x) const;
  fe::CellNodeCoords cell_displacements(Index e, const Vector& x) const;
  Eigen::MatrixX3d patch_displacements(Index i, const Vector& x) const;
  /// P = ∂Π/∂v of the volume of element e of the nodal-dilatation cells (their i-th).
  Real nodal_pressure(Index i, const Vector& x) const;

  const mesh::Mesh& mesh_;
  const dofs::DofMap& dofs_;
  dofs::FieldId u_;
  std::vector<Index> cells_;
  std::vector<std::shared_ptr<const material::ElasticLaw>> laws_;
  std::vector<SolidElement> elements_;
  /// Per element: the hex8 kernels' geometry, or that of another family.
  std::vector<AnyCellGeometry> geometry_;
  /// The nodal-dilatation cells: their element indices and their i among them (−1: none).
  std::vector<Index> nodal_elements_, nodal_index_;
  std::optional<NodalDilatation> nodal_;
};

} // namespace trifem::physics
