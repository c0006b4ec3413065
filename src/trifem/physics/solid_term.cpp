// SPDX-License-Identifier: MIT
#include "trifem/physics/solid_term.hpp"

#include "trifem/core/error.hpp"
#include "trifem/physics/folded_cells.hpp"
#include "trifem/physics/mean_dilatation_kernel.hpp"

#include <algorithm>

namespace trifem::physics {

SolidTerm::SolidTerm(const mesh::Mesh& mesh, const dofs::DofMap& dofs, dofs::FieldId displacement,
                     std::vector<Index> cells,
                     std::vector<std::shared_ptr<const material::ElasticLaw>> laws,
                     std::vector<SolidElement> elements)
    : mesh_(mesh), dofs_(dofs), u_(displacement), cells_(std::move(cells)), laws_(std::move(laws)),
      elements_(std::move(elements)) {
  TRIFEM_VERIFY(cells_.size() == laws_.size(), "one law per cell expected");
  if (elements_.empty())
    elements_.assign(cells_.size(), SolidElement::Displacement);
  TRIFEM_VERIFY(elements_.size() == cells_.size(), "one formulation per cell expected");
  geometry_.reserve(cells_.size());
  for (const Index c : cells_)
    geometry_.push_back(reference_geometry(mesh, c));
  nodal_index_.assign(cells_.size(), -1);
  std::vector<Index> nodal_cells;
  std::vector<const CellGeometry*> nodal_geometry;
  for (std::size_t e = 0; e < cells_.size(); ++e) {
    if (elements_[e] != SolidElement::NodalDilatation)
      continue;
    const mesh::CellType type = mesh.cell_type(cells_[e]);
    TRIFEM_CHECK(type == mesh::CellType::Tet4 || type == mesh::CellType::Penta6,
                 "cell {}: the nodal-dilatation element takes tet4 and penta6 cells, not {}",
                 cells_[e], mesh::name(type));
    nodal_index_[e] = static_cast<Index>(nodal_cells.size());
    nodal_elements_.push_back(static_cast<Index>(e));
    nodal_cells.push_back(cells_[e]);
    nodal_geometry.push_back(&std::get<CellGeometry>(geometry_[e]));
  }
  if (!nodal_cells.empty())
    nodal_.emplace(mesh, nodal_cells, std::move(nodal_geometry));
}

void SolidTerm::element_dofs(Index e, std::vector<Index>& dofs) const {
  const std::span<const Index> nodes =
      nodal_index_[e] < 0 ? mesh_.cell_nodes(cells_[e]) : nodal_->patch(nodal_index_[e]);
  dofs.resize(3 * nodes.size());
  for (std::size_t a = 0; a < nodes.size(); ++a)
    for (int k = 0; k < 3; ++k)
      dofs[3 * a + static_cast<std::size_t>(k)] = dofs_.dof(u_, nodes[a], k);
}

fe::HexCoords SolidTerm::displacements(Index e, const Vector& x) const {
  fe::HexCoords u;
  const auto& nodes = mesh_.cell(cells_[e]);
  for (int a = 0; a < 8; ++a)
    for (int k = 0; k < 3; ++k)
      u(a, k) = x[dofs_.dof(u_, nodes[a], k)];
  return u;
}

fe::CellNodeCoords SolidTerm::cell_displacements(Index e, const Vector& x) const {
  const std::span<const Index> nodes = mesh_.cell_nodes(cells_[e]);
  fe::CellNodeCoords u(static_cast<Index>(nodes.size()), 3);
  for (std::size_t a = 0; a < nodes.size(); ++a)
    for (int k = 0; k < 3; ++k)
      u(static_cast<Index>(a), k) = x[dofs_.dof(u_, nodes[a], k)];
  return u;
}

Eigen::MatrixX3d SolidTerm::patch_displacements(Index i, const Vector& x) const {
  const std::span<const Index> nodes = nodal_->patch(i);
  Eigen::MatrixX3d u(static_cast<Index>(nodes.size()), 3);
  for (std::size_t a = 0; a < nodes.size(); ++a)
    for (int k = 0; k < 3; ++k)
      u(static_cast<Index>(a), k) = x[dofs_.dof(u_, nodes[a], k)];
  return u;
}

bool SolidTerm::evaluate(Index e, const EvalState& state, LocalVector& r, LocalMatrix* K) const {
  if (const Index i = nodal_index_[e]; i >= 0)
    return nodal_->evaluate(i, patch_displacements(i, state.x), *laws_[e], r, K);
  if (const auto* geo = std::get_if<CellGeometry>(&geometry_[e])) {
    CellVectorX f;
    CellMatrixX Ke;
    const auto kernel =
        elements_[e] == SolidElement::MeanDilatation ? mean_dilatation_cell : solid_cell;
    if (!kernel(*geo, cell_displacements(e, state.x), *laws_[e], f, K ? &Ke : nullptr))
      return false;
    r = f;
    if (K)
      *K = Ke;
    return true;
  }
  HexVector f;
  HexMatrix Ke;
  const auto kernel =
      elements_[e] == SolidElement::MeanDilatation ? mean_dilatation_hex8 : solid_hex8;
  const bool ok = kernel(std::get<fe::HexGeometry>(geometry_[e]), displacements(e, state.x),
                         *laws_[e], f, K ? &Ke : nullptr);
  if (!ok)
    return false;
  r = f;
  if (K)
    *K = Ke;
  return true;
}

std::string SolidTerm::step_rejection(const EvalState& state) const {
  return folded_cell_rejection(mesh_, dofs_, u_, cells_, state.x);
}

Real SolidTerm::nodal_pressure(Index i, const Vector& x) const {
  // P_i = ∂Π/∂v_i = Σ_k π_k ω_ki over the elements k sharing a node with i
  Real P = 0.0;
  for (const NodalDilatation::Neighbour& k : nodal_->neighbours(i)) {
    const auto& weights = nodal_->neighbours(k.element);
    const auto it = std::find_if(weights.begin(), weights.end(),
                                 [i](const auto& nb) { return nb.element == i; });
    const Index e = nodal_elements_[static_cast<std::size_t>(k.element)];
    const Eigen::MatrixX3d u = patch_displacements(k.element, x);
    const auto& geo = std::get<CellGeometry>(geometry_[e]);
    DilatationSplit split;
    const Real Jbar = nodal_->dilatation(k.element, u);
    if (!(Jbar > 0.0) ||
        !dilatation_split(geo, u.topRows(geo.num_nodes()), *laws_[e], Jbar, false, split))
      return 0.0;
    P += split.pi * it->weight;
  }
  return P;
}

CellStress SolidTerm::stress(Index e, const Vector& x) const {
  if (const Index i = nodal_index_[e]; i >= 0) {
    const Eigen::MatrixX3d u = patch_displacements(i, x);
    const auto& geo = std::get<CellGeometry>(geometry_[e]);
    return dilatation_split_stress(geo, u.topRows(geo.num_nodes()), *laws_[e],
                                   nodal_->dilatation(i, u), nodal_pressure(i, x));
  }
  if (const auto* geo = std::get_if<CellGeometry>(&geometry_[e]))
    return (elements_[e] == SolidElement::MeanDilatation
                ? mean_dilatation_cell_stress
                : solid_cell_stress)(*geo, cell_displacements(e, x), *laws_[e]);
  const auto stress = elements_[e] == SolidElement::MeanDilatation ? mean_dilatation_hex8_stress
                                                                   : solid_hex8_stress;
  return stress(std::get<fe::HexGeometry>(geometry_[e]), displacements(e, x), *laws_[e]);
}

} // namespace trifem::physics
