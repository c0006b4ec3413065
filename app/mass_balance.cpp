// SPDX-License-Identifier: MIT
#include "mass_balance.hpp"

#include "trifem/physics/surface_flux.hpp"

#include <cmath>

namespace trifem::app {

MassBalance::MassBalance(const Model& model)
    : model_(model), boundary_(model.mesh.boundary_facets()) {
  last_ = measure();
}

bool MassBalance::has_ions() const {
  return model_.fields.j_plus.valid();
}

Balance MassBalance::measure() const {
  Balance b;
  if (!model_.mixture)
    return b;
  const Vector& x = model_.problem->state();
  const auto outflow = [&](dofs::FieldId f, Real scale) {
    return physics::surface_outflow(model_.mesh, model_.dofs, model_.fields.u, f, boundary_, x,
                                    scale);
  };
  b.total[0] = model_.mixture->total_water_volume();
  b.outflow[0] = outflow(model_.fields.w, 1.0);
  if (has_ions()) {
    b.total[1] = model_.mixture->total_moles(true);
    b.total[2] = model_.mixture->total_moles(false);
    b.outflow[1] = outflow(model_.fields.j_plus, model_.chem.c_ref);
    b.outflow[2] = outflow(model_.fields.j_minus, model_.chem.c_ref);
  }
  return b;
}

void MassBalance::record_step(Real dt) {
  const Balance now = measure();
  for (int q = 0; q < 3; ++q) {
    if (now.total[q] == 0.0)
      continue;
    const Real error = std::abs(now.total[q] - last_.total[q] + dt * now.outflow[q]);
    worst_[q] = std::max(worst_[q], error / std::abs(now.total[q]));
  }
  last_ = now;
}

} // namespace trifem::app
