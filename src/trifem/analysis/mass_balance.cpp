// SPDX-License-Identifier: MIT
#include "trifem/analysis/mass_balance.hpp"

#include "trifem/physics/surface_flux.hpp"

#include <cmath>

namespace trifem::analysis {
namespace {

/// The region of the mixture elements whose cells satisfy `inside`.
template <class Inside>
BalanceRegion make_region(const model::Model& model, std::string name, const Inside& inside,
                          const std::vector<mesh::Facet>& boundary) {
  BalanceRegion r{std::move(name), {}, {}, {}, {}};
  for (Index e = 0; e < model.mixture->num_elements(); ++e)
    if (inside(model.mixture->cell(e)))
      r.elements.push_back(e);
  for (const mesh::Facet& f : boundary)
    if (inside(f.cell))
      r.facets.push_back(f);
  return r;
}

} // namespace

MassBalance::MassBalance(const model::Model& model) : model_(model) {
  if (!model.mixture) {
    regions_.push_back({});
    return;
  }
  const std::vector<mesh::Facet> boundary = model.mesh.boundary_facets();
  regions_.push_back(make_region(
      model, "", [](Index) { return true; }, boundary));
  std::vector<BalanceRegion> bodies;
  for (const auto& [name, cells] : model.mesh.cell_blocks()) {
    std::vector<char> in(model.mesh.num_cells(), 0);
    for (Index c : cells)
      in[c] = 1;
    BalanceRegion r = make_region(
        model, name, [&](Index c) { return in[c] != 0; }, boundary);
    if (!r.elements.empty())
      bodies.push_back(std::move(r));
  }
  if (bodies.size() > 1)
    regions_.insert(regions_.end(), bodies.begin(), bodies.end());
  for (BalanceRegion& r : regions_)
    r.last = measure(r);
}

bool MassBalance::has_ions() const {
  return model_.fields.j_plus.valid();
}

Balance MassBalance::measure(const BalanceRegion& region) const {
  Balance b;
  if (!model_.mixture)
    return b;
  const Vector& x = model_.problem->state();
  const auto outflow = [&](dofs::FieldId f, Real scale) {
    return physics::surface_outflow(model_.mesh, model_.dofs, model_.fields.u, f, region.facets, x,
                                    scale);
  };
  const physics::MixtureTerm& m = *model_.mixture;
  for (Index e : region.elements) {
    b.total[0] += m.water_volume(e);
    if (has_ions()) {
      b.total[1] += m.history(e).N_plus;
      b.total[2] += m.history(e).N_minus;
    }
  }
  b.outflow[0] = outflow(model_.fields.w, 1.0);
  if (has_ions()) {
    b.outflow[1] = outflow(model_.fields.j_plus, model_.chem.c_ref);
    b.outflow[2] = outflow(model_.fields.j_minus, model_.chem.c_ref);
  }
  return b;
}

void MassBalance::record_step(Real dt) {
  for (BalanceRegion& r : regions_) {
    const Balance now = measure(r);
    for (int q = 0; q < 3; ++q) {
      if (now.total[q] == 0.0)
        continue;
      const Real error = std::abs(now.total[q] - r.last.total[q] + dt * now.outflow[q]);
      r.worst[q] = std::max(r.worst[q], error / std::abs(now.total[q]));
    }
    r.last = now;
  }
}

} // namespace trifem::analysis
