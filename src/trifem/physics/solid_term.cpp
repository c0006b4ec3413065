// SPDX-License-Identifier: MIT
#include "trifem/physics/solid_term.hpp"

#include "trifem/core/error.hpp"
#include "trifem/physics/folded_cells.hpp"
#include "trifem/physics/mean_dilatation_kernel.hpp"

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
}

void SolidTerm::element_dofs(Index e, std::vector<Index>& dofs) const {
  const std::span<const Index> nodes = mesh_.cell_nodes(cells_[e]);
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

bool SolidTerm::evaluate(Index e, const EvalState& state, LocalVector& r, LocalMatrix* K) const {
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

CellStress SolidTerm::stress(Index e, const Vector& x) const {
  if (const auto* geo = std::get_if<CellGeometry>(&geometry_[e]))
    return (elements_[e] == SolidElement::MeanDilatation
                ? mean_dilatation_cell_stress
                : solid_cell_stress)(*geo, cell_displacements(e, x), *laws_[e]);
  const auto stress = elements_[e] == SolidElement::MeanDilatation ? mean_dilatation_hex8_stress
                                                                   : solid_hex8_stress;
  return stress(std::get<fe::HexGeometry>(geometry_[e]), displacements(e, x), *laws_[e]);
}

} // namespace trifem::physics
