// SPDX-License-Identifier: MIT
#include "trifem/physics/bath_term.hpp"

#include "trifem/core/error.hpp"
#include "trifem/physics/facet_area.hpp"

#include <cmath>

namespace trifem::physics {

BathTerm::BathTerm(const mesh::Mesh& mesh, const dofs::DofMap& dofs, MixtureFields fields,
                   std::vector<mesh::Facet> facets, const material::Electrochemistry& chem,
                   Real concentration, dofs::LoadCurve curve, Real pressure)
    : mesh_(mesh), dofs_(dofs), fields_(fields), facets_(std::move(facets)), chem_(chem),
      concentration_(concentration), curve_(std::move(curve)), pressure_(pressure) {
  TRIFEM_CHECK(concentration_ > 0.0, "bath concentration {} must be > 0", concentration_);
}

Real BathTerm::concentration(Real t) const {
  return chem_.c_ref + (concentration_ - chem_.c_ref) * curve_(t);
}

void BathTerm::element_dofs(Index e, std::vector<Index>& dofs) const {
  dofs.clear();
  for (dofs::FieldId f : {fields_.u, fields_.w, fields_.j_plus, fields_.j_minus}) {
    if (!f.valid())
      continue;
    for (Index n : facets_[e].nodes)
      for (int k = 0; k < 3; ++k)
        dofs.push_back(dofs_.dof(f, n, k));
  }
}

bool BathTerm::evaluate(Index e, const EvalState& state, LocalVector& r, LocalMatrix* K) const {
  const mesh::Facet& f = facets_[e];
  fe::QuadCoords x;
  for (int a = 0; a < 4; ++a)
    for (int k = 0; k < 3; ++k)
      x(a, k) = mesh_.node(f.nodes[a])[k] + state.x[dofs_.dof(fields_.u, f.nodes[a], k)];
  FacetMatrix da;
  const FacetVector area = facet_area_vectors(x, K ? &da : nullptr);
  const Real c = concentration(state.time), RT = chem_.RT(), dt = state.dt > 0 ? state.dt : 1.0;
  // natural rows -mu* a, scaled by -dt (water) and -dt c_ref (ions)
  std::array<Real, 3> factor = {
      (pressure(state.time) - 2.0 * RT * chem_.osmotic_bath * (c - chem_.c_ref)) * dt,
      RT * std::log(c / chem_.c_ref) * dt * chem_.c_ref, 0.0};
  factor[2] = factor[1];
  const int rows = ions() ? 3 : 1, n = 12 * (rows + 1);
  r.setZero(n);
  if (K)
    K->setZero(n, n);
  for (int q = 0; q < rows; ++q) {
    r.segment<12>(12 * (q + 1)) = factor[q] * area;
    if (K)
      K->block<12, 12>(12 * (q + 1), 0) = factor[q] * da;
  }
  return true;
}

} // namespace trifem::physics
