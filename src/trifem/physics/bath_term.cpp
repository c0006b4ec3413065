// SPDX-License-Identifier: MIT
#include "trifem/physics/bath_term.hpp"

#include "trifem/core/error.hpp"
#include "trifem/physics/facet_area.hpp"
#include "trifem/physics/facet_area_any.hpp"

#include <cmath>

namespace trifem::physics {
namespace {

/// The bath's rows on a facet of any family: the fluxes' area vectors P a (P of
/// mixture_flux_map) times the natural values `factor` of the fields (water, cations, anions).
void bath_rows(const mesh::Facet& f, const FacetVectorX& area, const FacetMatrixX* d_area,
               const std::array<Real, 3>& factor, int fields, LocalVector& r, LocalMatrix* K) {
  const MixtureFluxMap& P = mixture_flux_map(f.type);
  const int n = f.num_nodes(), corners = f.num_corners(), size = 3 * n + 3 * corners * fields;
  r.setZero(size);
  if (K)
    K->setZero(size, size);
  for (int field = 0; field < fields; ++field)
    for (int a = 0; a < corners; ++a)
      for (int m = 0; m < n; ++m) {
        if (P(a, m) == 0.0)
          continue;
        const int row = 3 * n + 3 * corners * field + 3 * a;
        r.segment<3>(row) += factor[field] * P(a, m) * area.segment<3>(3 * m);
        if (K)
          K->block(row, 0, 3, 3 * n) += factor[field] * P(a, m) * d_area->middleRows(3 * m, 3);
      }
}

} // namespace

BathTerm::BathTerm(const mesh::Mesh& mesh, const dofs::DofMap& dofs, MixtureFields fields,
                   std::vector<mesh::Facet> facets, const material::Electrochemistry& chem,
                   Real concentration, dofs::LoadCurve curve, Real pressure)
    : mesh_(mesh), dofs_(dofs), fields_(fields), facets_(std::move(facets)), chem_(chem),
      concentration_(concentration), curve_(std::move(curve)), pressure_(pressure) {
  TRIFEM_CHECK(concentration_ > 0.0, "bath concentration {} must be > 0", concentration_);
}

std::array<Real, 3> BathTerm::natural_factors(const EvalState& state) const {
  const Real c = concentration(state.time), RT = chem_.RT(), dt = state.dt > 0 ? state.dt : 1.0;
  // natural rows -mu* a, scaled by -dt (water) and -dt c_ref (ions)
  const Real water =
      (pressure(state.time) - 2.0 * RT * chem_.osmotic_bath * (c - chem_.c_ref)) * dt;
  const Real ion = RT * std::log(c / chem_.c_ref) * dt * chem_.c_ref;
  return {water, ion, ion};
}

Real BathTerm::concentration(Real t) const {
  return chem_.c_ref + (concentration_ - chem_.c_ref) * curve_(t);
}

void BathTerm::element_dofs(Index e, std::vector<Index>& dofs) const {
  const mesh::Facet& facet = facets_[e];
  dofs.clear();
  for (dofs::FieldId f : {fields_.u, fields_.w, fields_.j_plus, fields_.j_minus}) {
    if (!f.valid())
      continue;
    // the fluxes at the corners (physics::mixture_flux_map), the displacement at every node
    const int nodes = f == fields_.u ? facet.num_nodes() : facet.num_corners();
    for (int a = 0; a < nodes; ++a)
      for (int k = 0; k < 3; ++k)
        dofs.push_back(dofs_.dof(f, facet.node(a), k));
  }
}

bool BathTerm::evaluate(Index e, const EvalState& state, LocalVector& r, LocalMatrix* K) const {
  const mesh::Facet& f = facets_[e];
  if (!f.is_quad4()) {
    FacetMatrixX da;
    const FacetVectorX area = facet_area_vectors(
        fe::reference_facet(f.type), facet_positions(mesh_, f, &dofs_, fields_.u, &state.x),
        K ? &da : nullptr);
    bath_rows(f, area, K ? &da : nullptr, natural_factors(state), ions() ? 3 : 1, r, K);
    return true;
  }
  fe::QuadCoords x;
  for (int a = 0; a < 4; ++a)
    for (int k = 0; k < 3; ++k)
      x(a, k) = mesh_.node(f.nodes[a])[k] + state.x[dofs_.dof(fields_.u, f.nodes[a], k)];
  FacetMatrix da;
  const FacetVector area = facet_area_vectors(x, K ? &da : nullptr);
  const std::array<Real, 3> factor = natural_factors(state);
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
