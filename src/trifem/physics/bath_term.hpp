// SPDX-License-Identifier: MIT
// A bath of NaCl concentration c*(t) different from the reference bath, on a surface of a
// mixture (facets of any family; the fluxes at their corners): the natural boundary terms -int N_a
// mu*_bar n da of the water and ion rows (docs/theory/triphasic.md §2 and §8 item 4). Surfaces
// without any condition are in the reference bath (no term).
#pragma once

#include "trifem/dofs/load_curve.hpp"
#include "trifem/material/mixture.hpp"
#include "trifem/mesh/mesh.hpp"
#include "trifem/physics/mixture_term.hpp"

namespace trifem::physics {

/// Bath boundary: c*(t) = c_ref + (concentration - c_ref) curve(t), gauge pressure
/// p*(t) = pressure curve(t), potential 0. Bath-normalised potentials
/// mu_w* = p* - 2 RT Phi* (c* - c_ref), mu_+-* = RT ln(c* / c_ref). Rows scaled like the mixture
/// term's. The bath's pressure acts on the water only: it does not push on the surface (a
/// [[loads.pressure]] does).
class BathTerm final : public Term {
public:
  BathTerm(const mesh::Mesh& mesh, const dofs::DofMap& dofs, MixtureFields fields,
           std::vector<mesh::Facet> facets, const material::Electrochemistry& chem,
           Real concentration, dofs::LoadCurve curve, Real pressure = 0.0);

  std::string name() const override { return "bath"; }
  Index num_elements() const override { return static_cast<Index>(facets_.size()); }
  void element_dofs(Index e, std::vector<Index>& dofs) const override;
  bool evaluate(Index e, const EvalState& state, LocalVector& r, LocalMatrix* K) const override;

  /// Bath concentration at time t [mmol/mm^3].
  Real concentration(Real t) const;
  /// Bath gauge pressure at time t [MPa].
  Real pressure(Real t) const { return pressure_ * curve_(t); }

private:
  bool ions() const { return fields_.j_plus.valid(); }
  /// The scaled natural values -mu* of the water and ion rows at the state's time.
  std::array<Real, 3> natural_factors(const EvalState& state) const;

  const mesh::Mesh& mesh_;
  const dofs::DofMap& dofs_;
  MixtureFields fields_;
  std::vector<mesh::Facet> facets_;
  material::Electrochemistry chem_;
  Real concentration_;
  dofs::LoadCurve curve_;
  Real pressure_;
};

} // namespace trifem::physics
