// SPDX-License-Identifier: MIT
#include "trifem/physics/body_force_term.hpp"

namespace trifem::physics {

BodyForceTerm::BodyForceTerm(const dofs::DofMap& dofs, dofs::FieldId displacement,
                             const std::vector<MassElement>& elements, Vec3 force,
                             dofs::LoadCurve curve)
    : dofs_(dofs), u_(displacement), force_(force), curve_(std::move(curve)) {
  nodes_.reserve(elements.size());
  nodal_mass_.reserve(elements.size());
  for (const MassElement& e : elements) {
    nodes_.push_back(e.nodes);
    nodal_mass_.push_back(e.mass.rowwise().sum()); // ∫ ρ N_a (Σ_b N_b = 1)
  }
}

BodyForceTerm::BodyForceTerm(const mesh::Mesh& mesh, const dofs::DofMap& dofs,
                             dofs::FieldId displacement, const std::vector<Index>& cells,
                             const std::vector<Real>& densities, Vec3 force, dofs::LoadCurve curve)
    : BodyForceTerm(dofs, displacement, cell_mass_elements(mesh, cells, densities), force,
                    std::move(curve)) {}

void BodyForceTerm::element_dofs(Index e, std::vector<Index>& dofs) const {
  const std::vector<Index>& nodes = nodes_[e];
  dofs.resize(3 * nodes.size());
  for (std::size_t a = 0; a < nodes.size(); ++a)
    for (int k = 0; k < 3; ++k)
      dofs[3 * a + k] = dofs_.dof(u_, nodes[a], k);
}

bool BodyForceTerm::evaluate(Index e, const EvalState& state, LocalVector& r,
                             LocalMatrix* K) const {
  const Vec3 b = force_ * curve_(state.time);
  const auto n = static_cast<Index>(nodes_[e].size());
  r.resize(3 * n);
  for (Index a = 0; a < n; ++a) // R = f_int − f_ext
    r.segment<3>(3 * a) = -nodal_mass_[e][a] * b;
  if (K)
    K->setZero(3 * n, 3 * n);
  return true;
}

} // namespace trifem::physics
