// SPDX-License-Identifier: MIT
#include "trifem/physics/body_force_term.hpp"

#include "trifem/core/error.hpp"
#include "trifem/fe/hex8.hpp"
#include "trifem/physics/cell_mass.hpp"

#include <cmath>

namespace trifem::physics {

BodyForceTerm::BodyForceTerm(const mesh::Mesh& mesh, const dofs::DofMap& dofs,
                             dofs::FieldId displacement, std::vector<Index> cells,
                             const std::vector<Real>& densities, Vec3 force, dofs::LoadCurve curve)
    : mesh_(mesh), dofs_(dofs), u_(displacement), cells_(std::move(cells)), force_(force),
      curve_(std::move(curve)) {
  TRIFEM_VERIFY(cells_.size() == densities.size(), "one density per cell expected");
  nodal_mass_.reserve(cells_.size());
  for (std::size_t i = 0; i < cells_.size(); ++i) {
    TRIFEM_VERIFY(densities[i] > 0.0 && std::isfinite(densities[i]), "density must be positive");
    const auto m = consistent_cell_mass(fe::cell_coordinates(mesh, cells_[i]), densities[i]);
    TRIFEM_CHECK(m.has_value(),
                 "cell {} is inverted or degenerate (det(dX/dxi) <= 0 at a Gauss point); "
                 "check its node order",
                 cells_[i]);
    nodal_mass_.push_back(m->rowwise().sum()); // ∫ ρ N_a dV (Σ_b N_b = 1)
  }
}

void BodyForceTerm::element_dofs(Index e, std::vector<Index>& dofs) const {
  dofs.resize(24);
  const auto& nodes = mesh_.cell(cells_[e]);
  for (int a = 0; a < 8; ++a)
    for (int k = 0; k < 3; ++k)
      dofs[3 * a + k] = dofs_.dof(u_, nodes[a], k);
}

bool BodyForceTerm::evaluate(Index e, const EvalState& state, LocalVector& r,
                             LocalMatrix* K) const {
  const Vec3 b = force_ * curve_(state.time);
  r.resize(24);
  for (int a = 0; a < 8; ++a) // R = f_int − f_ext
    r.segment<3>(3 * a) = -nodal_mass_[e][a] * b;
  if (K)
    K->setZero(24, 24);
  return true;
}

} // namespace trifem::physics
