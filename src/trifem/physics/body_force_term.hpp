// SPDX-License-Identifier: MIT
// A dead body force per unit mass on mass elements: hex8 cells and quad4 shells (gravity).
#pragma once

#include "trifem/dofs/dof_map.hpp"
#include "trifem/dofs/load_curve.hpp"
#include "trifem/mesh/mesh.hpp"
#include "trifem/physics/cell_mass.hpp"
#include "trifem/physics/term.hpp"

namespace trifem::physics {

/// The body force b(t) = force * curve(t) per unit mass [mm/s² = N/t] on mass elements: on a
/// cell of reference density ρ, f_ext,a = ∫ ρ b N_a dV over the reference volume (on a shell,
/// ∫ ρ t b N_a dA), a dead load (its direction and the mass it acts on do not change with the
/// deformation: its Jacobian is zero). The nodes of rigid cells and shells follow their body,
/// which receives the force and its moment by condensation.
class BodyForceTerm final : public Term {
public:
  /// The nodal masses ∫ ρ N_a are the row sums of the elements' consistent mass matrices.
  BodyForceTerm(const dofs::DofMap& dofs, dofs::FieldId displacement,
                const std::vector<MassElement>& elements, Vec3 force, dofs::LoadCurve curve);
  /// Of hex8 cells: `densities[i]` > 0 is the mass per reference volume of `cells[i]`
  /// [t/mm³]. Throws InputError naming the cell if a cell is inverted or degenerate.
  BodyForceTerm(const mesh::Mesh& mesh, const dofs::DofMap& dofs, dofs::FieldId displacement,
                const std::vector<Index>& cells, const std::vector<Real>& densities, Vec3 force,
                dofs::LoadCurve curve);
  std::string name() const override { return "body force"; }
  Index num_elements() const override { return static_cast<Index>(nodes_.size()); }
  void element_dofs(Index e, std::vector<Index>& dofs) const override;
  /// r_a = −(∫ ρ N_a) b(t), K = 0.
  bool evaluate(Index e, const EvalState& state, LocalVector& r, LocalMatrix* K) const override;

  /// ∫ ρ N_a of element e (the mass its nodes receive) [t].
  const Eigen::VectorXd& nodal_mass(Index e) const { return nodal_mass_[e]; }

private:
  const dofs::DofMap& dofs_;
  dofs::FieldId u_;
  std::vector<std::vector<Index>> nodes_;   ///< of every element
  std::vector<Eigen::VectorXd> nodal_mass_; ///< ∫ ρ N_a per element
  Vec3 force_;
  dofs::LoadCurve curve_;
};

} // namespace trifem::physics
