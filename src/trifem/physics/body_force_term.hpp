// SPDX-License-Identifier: MIT
// A dead body force per unit mass on hex8 cells (gravity).
#pragma once

#include "trifem/dofs/dof_map.hpp"
#include "trifem/dofs/load_curve.hpp"
#include "trifem/mesh/mesh.hpp"
#include "trifem/physics/term.hpp"

namespace trifem::physics {

/// The body force b(t) = force * curve(t) per unit mass [mm/s² = N/t] on cells of reference
/// density ρ: f_ext,a = ∫ ρ b N_a dV over the reference volume, a dead load (its direction and
/// the mass it acts on do not change with the deformation: its Jacobian is zero). The nodes of
/// rigid cells follow their body, which receives the force and its moment by condensation.
class BodyForceTerm final : public Term {
public:
  /// `densities[i]` > 0 is the mass per reference volume of `cells[i]` [t/mm³]. Throws
  /// InputError naming the cell if a cell is inverted or degenerate.
  BodyForceTerm(const mesh::Mesh& mesh, const dofs::DofMap& dofs, dofs::FieldId displacement,
                std::vector<Index> cells, const std::vector<Real>& densities, Vec3 force,
                dofs::LoadCurve curve);
  std::string name() const override { return "body force"; }
  Index num_elements() const override { return static_cast<Index>(cells_.size()); }
  void element_dofs(Index e, std::vector<Index>& dofs) const override;
  /// r_a = −(∫ ρ N_a dV) b(t), K = 0.
  bool evaluate(Index e, const EvalState& state, LocalVector& r, LocalMatrix* K) const override;

  /// ∫ ρ N_a dV of element e (the mass its nodes receive) [t].
  const Eigen::Matrix<Real, 8, 1>& nodal_mass(Index e) const { return nodal_mass_[e]; }

private:
  const mesh::Mesh& mesh_;
  const dofs::DofMap& dofs_;
  dofs::FieldId u_;
  std::vector<Index> cells_;
  std::vector<Eigen::Matrix<Real, 8, 1>> nodal_mass_; ///< ∫ ρ N_a dV per cell
  Vec3 force_;
  dofs::LoadCurve curve_;
};

} // namespace trifem::physics
