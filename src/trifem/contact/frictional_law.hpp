// SPDX-License-Identifier: MIT
// Coulomb friction of solids in the multiplier framework of the normal contact: the tangential
// traction at each slave node is a multiplier, sticking and slipping nodes are told apart by a
// primal-dual active set (semismooth Newton; docs/theory/contact.md §7).
#pragma once

#include "trifem/contact/contact_law.hpp"

namespace trifem::contact {

/// The slip of slave node k within the step and its derivative: the tangential part of the
/// motion of the slave node relative to the master's material point under it,
///   v = P w,   w = x^m_old(ξ) - x_s,old,   P = I - n n,
/// (x^m_old(ξ) = Σ_a N_a(ξ) x_a,old: where the master point the node now projects onto was at
/// the step start; since x_s - x^m(ξ) = g n, v = P [(x_s - x_s,old) - (x^m(ξ) - x^m_old(ξ))]).
/// Its variation goes through ξ and n only: Δv = P Σ_a x_a,old N_{a,α} Δξ^α - (n·w) Δn - n (w·Δn).
struct Slip {
  Vec3 normal = Vec3::Zero(); ///< n: the master normal at the projection
  Vec3 w = Vec3::Zero();
  Vec3 v = Vec3::Zero();
  StencilRows<3> dv; ///< ∂v/∂(stencil coordinates) (with derivatives only)
};

/// The slip of a node with a projection (`node.derivatives` set: with its derivative).
Slip slip_of(const SlaveNodeRows& node);

/// Coulomb friction between solids: multipliers (λ_n, t_x, t_y, t_z) per slave node, the
/// contact pressure of FrictionlessLaw (≤ 0 compressive) and the tangential traction t on the
/// slave body (its work along the axes over the current area; the master body takes -t). With
/// the augmented pressure p = max(0, -(λ_n + c g)) (= -λ_n once the gap is closed), c = c_N and
/// A = A_k, the rows of t are
///   separated:  (A/c) t = 0
///   sticking:   A (v + n (n·t)/c) = 0                 (no slip, t tangential)
///   slipping:   (A/c) (t - μ p q/|q|) = 0,  q = P t - c v   (|t| = μ p against the slip)
/// and the slip indicator of a node in contact is |P t - c v| - μ p (zero within kSlipBand of
/// the limit): a sticking node whose
/// trial traction exceeds the friction limit slips; a slipping node whose slip would reverse
/// sticks (Alart–Curnier's semismooth form, split by the active set). A component along an
/// axis in which neither the node nor the master facet can move (SlaveNodeRows::held, e.g. plane
/// strain) is held at zero instead: no slip and no work along it.
class FrictionalLaw final : public ContactLaw {
public:
  FrictionalLaw(dofs::FieldId displacement, Real friction_coefficient);
  std::string name() const override { return "Coulomb friction"; }
  int num_components() const override { return 4; }
  dofs::FieldId paired_field(int /*c*/) const override { return u_; }
  int work_axis(int c) const override { return c - 1; }
  bool frictional() const override { return true; }
  Real indicator(const SlaveNodeRows& node) const override;
  Real slip_indicator(const SlaveNodeRows& node) const override;
  void active_rows(const SlaveNodeRows& node, LocalSystem& out) const override;
  void inactive_rows(const SlaveNodeRows& node, LocalSystem& out) const override;
  Real friction_coefficient() const { return mu_; }
  /// The slip indicator is zero while |q| is within this fraction of μ p of the friction
  /// limit: a node keeps its state there (a sticking node at the limit, a slipping node at
  /// rest), so that states converged to a loose tolerance do not flip back and forth.
  static constexpr Real kSlipBand = 1e-3;

private:
  void sticking_rows(const SlaveNodeRows& node, const Slip& slip, LocalSystem& out) const;
  void slipping_rows(const SlaveNodeRows& node, const Slip& slip, LocalSystem& out) const;
  /// The rows of the held components (SlaveNodeRows::held): (A/c) t_i = 0.
  void hold_rows(const SlaveNodeRows& node, LocalSystem& out) const;

  dofs::FieldId u_;
  Real mu_;
};

} // namespace trifem::contact
