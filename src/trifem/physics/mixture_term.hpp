// SPDX-License-Identifier: MIT
// The biphasic/triphasic mixture over a set of cells of any family: unknown scaling, history
// (element volumes and ion moles), initial Donnan states, and per-cell output.
#pragma once

#include "trifem/dofs/dof_map.hpp"
#include "trifem/dofs/load_curve.hpp"
#include "trifem/mesh/mesh.hpp"
#include "trifem/physics/mixture_kernel.hpp"

#include <memory>
#include <optional>
#include <utility>

namespace trifem::physics {

/// The fields of a mixture model. Ion fields are invalid in biphasic-only models.
/// Stored unknowns are scaled for conditioning (docs/theory/triphasic.md §5): the ion flux DOFs
/// hold j / c_ref [mm/s] and the potential DOF holds c_ref eta [MPa].
/// `p_corner`, `eta_corner` (nodal, one component; valid in models with mixture tets): the
/// potentials of tet cells, continuous and linear from their corners (docs/theory/elements.md);
/// the cell fields `p`, `eta` hold those of the other cells.
struct MixtureFields {
  dofs::FieldId u, w, j_plus, j_minus, p, eta;
  dofs::FieldId p_corner, eta_corner;
};

/// Whether mixture cells of `type` take potentials linear from their corners in a model with
/// `fields` (tets, when the model has the corner fields).
bool has_corner_potentials(const MixtureFields& fields, mesh::CellType type);

/// The stored pressure p [MPa] and potential c_ref η [MPa] of mixture cell c in state x: its
/// cell unknowns, or the means of its corners' (has_corner_potentials); η is 0 without ions.
std::pair<Real, Real> cell_potentials(const mesh::Mesh& mesh, const dofs::DofMap& dofs,
                                      const MixtureFields& fields, const Vector& x, Index c);

/// How the initial state is set (docs/theory/triphasic.md §6).
enum class InitialState {
  Donnan,            ///< IC-1: Donnan equilibrium with the bath at the reference configuration
  DonnanPrestressed, ///< IC-3a: as IC-1 plus a constant Cauchy prestress Pi0 (zero net stress)
};

/// Mixture term. Rows are scaled to be energy-conjugate to the stored unknowns
/// (w, p rows by -dt; ion rows by -dt c_ref; eta row by -dt / c_ref).
class MixtureTerm final : public Term {
public:
  /// `props[i]` is the mixture of `cells[i]`; `fixed_charge_curve` scales every cell's fixed
  /// charge in time (free-swelling ramp); empty = constant.
  MixtureTerm(const mesh::Mesh& mesh, const dofs::DofMap& dofs, MixtureFields fields,
              std::vector<Index> cells,
              std::vector<std::shared_ptr<const material::MixtureProperties>> props,
              const material::Electrochemistry& chem,
              std::optional<dofs::LoadCurve> fixed_charge_curve = std::nullopt);

  std::string name() const override { return "mixture"; }
  Index num_elements() const override { return static_cast<Index>(cells_.size()); }
  void element_dofs(Index e, std::vector<Index>& dofs) const override;
  bool evaluate(Index e, const EvalState& state, LocalVector& r, LocalMatrix* K) const override;
  void commit(const EvalState& state) override;
  /// A state in which a cell turned inside out (physics/folded_cells.hpp).
  std::string step_rejection(const EvalState& state) const override;
  /// The committed MixtureHistory of every element (6 numbers each).
  std::vector<double> history() const override;
  void restore_history(const std::vector<double>& values) override;
  /// Every cell's flux block in the scaled rows and unknowns (docs/theory/solvers.md §4).
  void transport_cells(const EvalState& state, std::vector<CellTransport>& out) const override;

  /// Sets p, eta (and the ion moles) of every element to the Donnan equilibrium with the
  /// reference bath at the configuration in x, at time `time` (fixed charge from the curve).
  void initialize(InitialState kind, Real time, Vector& x);

  /// Element chemistry, fluxes and stresses at a committed state x (physical units).
  MixtureCellOutput output(Index e, const Vector& x) const;
  /// Total ion moles [mmol] of the committed state.
  Real total_moles(bool cation) const;
  /// Water volume [mm^3] of element e in the committed state, V - phi_s0 V0.
  Real water_volume(Index e) const;

  Index cell(Index e) const { return cells_[e]; }
  bool has_ions() const { return fields_.j_plus.valid(); }
  const MixtureFields& fields() const { return fields_; }
  const MixtureHistory& history(Index e) const { return history_[e]; }
  /// Overrides the committed history of an element (non-equilibrium initial states).
  void set_history(Index e, const MixtureHistory& h) { history_[e] = h; }
  /// Friction terms with the lumped mass ([analysis] flux_mass = "lumped").
  void set_lumped_flux_mass(bool lumped) { lumped_flux_mass_ = lumped; }

private:
  /// The unknowns of element e in state x, in physical units (rows of `v`'s nodal fields:
  /// the cell's nodes).
  template <class Coords>
  void gather(Index e, const Vector& x, MixtureUnknownsOf<Coords>& v) const;
  /// The reference volume of element e at the displacements of state x.
  Real current_volume(Index e, const Vector& x) const;
  /// Element e's chemistry, fluxes and stresses in state x with history h.
  MixtureCellOutput cell_output(Index e, const Vector& x, const MixtureHistory& h,
                                const MixtureStep& s) const;
  MixtureHistory history_at(Index e, Real time) const;
  MixtureStep step(Index e, Real dt) const;
  bool ions(Index e) const { return has_ions() && props_[e]->charged; }
  MixtureLayout layout(Index e) const;
  /// Whether cell e's potentials are linear from its corners (a tet with p_corner valid).
  bool corner_potentials(Index e) const;
  /// The corner potentials of cell e in state x (physical units) with its committed volumes.
  CornerPotentials corners(Index e, const Vector& x) const;
  /// The corner volumes of cell e at the displacement of state x.
  std::array<Real, 4> corner_volumes_at(Index e, const Vector& x) const;
  void scale(Index e, Real dt, LocalVector& r, LocalMatrix* K) const;
  /// The CellTransport of element e from its scaled flux block.
  CellTransport cell_transport(Index e, const MixtureFluxBlock& scaled_block) const;

  const mesh::Mesh& mesh_;
  const dofs::DofMap& dofs_;
  MixtureFields fields_;
  std::vector<Index> cells_;
  std::vector<std::shared_ptr<const material::MixtureProperties>> props_;
  material::Electrochemistry chem_;
  std::optional<dofs::LoadCurve> fixed_charge_curve_;
  bool lumped_flux_mass_ = false;
  std::vector<AnyCellGeometry> geometry_;
  std::vector<MixtureHistory> history_;
  std::vector<Real> prestress_;
  /// Per element: V_b of the corners at the last converged step (cells with corner potentials).
  std::vector<std::array<Real, 4>> corner_volume_old_;
};

} // namespace trifem::physics
