// SPDX-License-Identifier: MIT
// Frictionless contact of biphasic/triphasic mixtures (docs/theory/contact.md §13): the contact
// pressure plus continuity of the water and ion potentials and of the normal fluxes.
#pragma once

#include "trifem/contact/contact_law.hpp"

namespace trifem::contact {

/// The mixture fields a MixtureContactLaw acts on. Ion fields are invalid for a biphasic
/// interface. Stored unknowns follow physics::MixtureTerm: w [mm/s], ion fluxes j±/c_ref [mm/s].
struct MixtureContactFields {
  dofs::FieldId u, w, j_plus, j_minus;
};

/// Multiplier components per slave node k (2 biphasic, 4 triphasic):
///   0: t_k [MPa]            contact pressure (normal total traction), paired with u
///   1: mū_w,k [MPa]         bath-normalised water potential, paired with w
///   2: c_ref mū_+,k [MPa]   scaled cation potential (like the stored c_ref η), paired with j+
///   3: c_ref mū_-,k [MPa]   scaled anion potential, paired with j-
/// Interface work (ContactTerm): the mixture's w and ion rows are scaled by -Δt and -Δt c_ref,
/// so the natural term -∫ N_a mū n da becomes +Δt ∫ N_a mū_w n da (w rows) and
/// +Δt ∫ N_a (c_ref mū_±) n da (ion rows): work_factor = -Δt for components 1..3.
/// Active rows (slave node k projecting at ξ_k onto the master surface, normal n = n^m(ξ_k)):
///   G_u = A_k g_k                                   (as FrictionlessLaw)
///   G_w = Δt A_k (w^m(ξ_k) - w_s)·n,   G_± = Δt A_k (ĵ±^m(ξ_k) - ĵ±_s)·n   (ĵ = j/c_ref, stored)
///   ΔG_w = Δt A_k [ (Σ_a N_a Δw_a - Δw_s)·n + (w^m - w_s)·Δn + (Σ_a N_{a,α} w_a)·n Δξ^α ]
/// Inactive rows (separated or not projecting): (A_k / c_N) λ_k,c = 0 for every component, i.e.
/// t = 0 and the bath potentials mū = 0 (free-draining; docs/theory/contact.md §13.3).
/// Wetted rows (in contact, interface wetted by the bath; NodeContact::Wetted): G_u = A_k g_k
/// and (A_k / c_N) λ_k,c = 0 for c ≥ 1 (free-draining while the surfaces touch).
/// Indicator of the active set: t_k + c_N g_k (mechanical complementarity only).
class MixtureContactLaw final : public ContactLaw {
public:
  /// Biphasic if the ion fields of `fields` are invalid, triphasic if both are valid.
  explicit MixtureContactLaw(MixtureContactFields fields);
  std::string name() const override { return triphasic() ? "triphasic" : "biphasic"; }
  int num_components() const override { return triphasic() ? 4 : 2; }
  dofs::FieldId paired_field(int c) const override;
  Real work_factor(int c, Real dt) const override { return c == 0 ? 1.0 : -dt; }
  /// The potentials' multipliers and the fluxes (c ≥ 1): linear from the corners.
  bool corner_interpolated(int c) const override { return c >= 1; }
  std::vector<dofs::FieldId> constraint_fields() const override;
  Real indicator(const SlaveNodeRows& node) const override;
  bool wettable() const override { return true; }
  void active_rows(const SlaveNodeRows& node, LocalSystem& out) const override;
  void inactive_rows(const SlaveNodeRows& node, LocalSystem& out) const override;

  bool triphasic() const { return f_.j_plus.valid(); }

private:
  /// G_c = Δt A_k (f^m(ξ_k) - f_s)·n of the flux field F on the λ component c, f^m
  /// interpolated linearly from the master facet's corners.
  void flux_row(const SlaveNodeRows& node, int c, dofs::FieldId F, LocalSystem& out) const;
  /// (A_k / c_N) λ_k,c = 0 for the components c ≥ first.
  void bath_rows(const SlaveNodeRows& node, int first, LocalSystem& out) const;

  MixtureContactFields f_;
  FrictionlessLaw normal_;
};

} // namespace trifem::contact
