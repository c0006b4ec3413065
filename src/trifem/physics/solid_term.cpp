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
  for (Index c : cells_) {
    const fe::HexCoords X = fe::cell_coordinates(mesh, c);
    auto geo = fe::hex8_geometry(X);
    TRIFEM_CHECK(geo.has_value(),
                 "cell {} is inverted or degenerate (det(dX/dxi) <= 0 at a Gauss point); "
                 "check its node order",
                 c);
    geometry_.push_back(*geo);
  }
}

void SolidTerm::element_dofs(Index e, std::vector<Index>& dofs) const {
  dofs.resize(24);
  const auto& nodes = mesh_.cell(cells_[e]);
  for (int a = 0; a < 8; ++a)
    for (int k = 0; k < 3; ++k)
      dofs[3 * a + k] = dofs_.dof(u_, nodes[a], k);
}

fe::HexCoords SolidTerm::displacements(Index e, const Vector& x) const {
  fe::HexCoords u;
  const auto& nodes = mesh_.cell(cells_[e]);
  for (int a = 0; a < 8; ++a)
    for (int k = 0; k < 3; ++k)
      u(a, k) = x[dofs_.dof(u_, nodes[a], k)];
  return u;
}

bool SolidTerm::evaluate(Index e, const EvalState& state, LocalVector& r, LocalMatrix* K) const {
  HexVector f;
  HexMatrix Ke;
  const auto kernel =
      elements_[e] == SolidElement::MeanDilatation ? mean_dilatation_hex8 : solid_hex8;
  const bool ok = kernel(geometry_[e], displacements(e, state.x), *laws_[e], f, K ? &Ke : nullptr);
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
  const auto stress = elements_[e] == SolidElement::MeanDilatation ? mean_dilatation_hex8_stress
                                                                   : solid_hex8_stress;
  return stress(geometry_[e], displacements(e, x), *laws_[e]);
}

} // namespace trifem::physics
