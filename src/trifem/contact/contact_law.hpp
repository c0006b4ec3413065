// SPDX-License-Identifier: MIT
// The contact-law seam (docs/theory/contact.md §3–§5): what the slave-node multipliers
// mean, which rows their interface work acts on, and which constraint each one imposes.
// Geometry, search, projections, the interface integrals and the DOF bookkeeping stay in
// ContactTerm; a law only sees one slave node at a time.
#pragma once

#include "trifem/contact/local_system.hpp"
#include "trifem/contact/projection_derivatives.hpp"
#include "trifem/dofs/dof_map.hpp"

#include <string>
#include <vector>

namespace trifem::contact {

/// One slave node k as seen by a law: its projection onto the master surface and the local
/// positions of its DOFs in the element (a LocalSystem over the element's stencil). A law that
/// needs other nodal fields (e.g. fluid fluxes w at the stencil nodes) lists them in
/// ContactLaw::constraint_fields(); their DOFs at `nodes` are then part of the stencil and can
/// be read from `state` and located with LocalSystem::at(dofs->dof(field, node, i)).
struct SlaveNodeRows {
  Index slave = -1;                                    ///< k: index into the slave surface's nodes
  StencilNodes nodes;                                  ///< mesh nodes (x_s, master facet nodes)
  const physics::EvalState* state = nullptr;           ///< the evaluated state (all DOFs)
  const dofs::DofMap* dofs = nullptr;                  ///< DOF numbering of `state`
  const Projection* projection = nullptr;              ///< onto the master surface (null: none)
  mesh::FacetType facet_type = mesh::FacetType::Quad4; ///< of the master facet projected onto
  /// A mid-edge node of a quadratic slave surface: the components interpolated from the
  /// corners (ContactLaw::corner_interpolated) have no constraint there (their rows hold λ = 0).
  bool mid_edge = false;
  const ProjectionDerivatives* derivatives = nullptr; ///< of *projection (null: none)
  Real weight = 0;       ///< A_k = ∫_slave M_k dA (reference tributary area; a fixed row weight)
  Real scale = 1;        ///< c_N > 0 [stress/length]: the complementarity scaling
  Real dt = 0;           ///< step size (for rate-type constraints such as flux continuity)
  Vector multiplier;     ///< λ_k (num_components() values)
  bool wetted = false;   ///< in contact with a wetted interface (NodeContact::Wetted)
  bool slipping = false; ///< in contact and slipping (NodeContact::Slipping; frictional laws)
  Index lambda_at = -1;  ///< local position of λ_k component 0 (components are contiguous)
  /// Local position of coordinate component 0 of stencil point j (j = 0: the slave node,
  /// 1 + a: master facet node a; -1 when there is no projection), j < nodes.size.
  std::array<Index, kMaxStencilPoints> x_at = no_positions();
  /// Position of each stencil point at the start of the step (set for frictional laws, with a
  /// projection only).
  std::array<Vec3, kMaxStencilPoints> x_old{};
  /// Per axis i: the displacement component i is prescribed at the slave node and at every
  /// node of the master facet it projects onto (e.g. plane strain), so no slip along e_i can
  /// occur and a traction along e_i does no work: frictional laws hold that component at zero
  /// (set for frictional laws only).
  std::array<bool, 3> held{};

  static std::array<Index, kMaxStencilPoints> no_positions() {
    std::array<Index, kMaxStencilPoints> a;
    a.fill(-1);
    return a;
  }
};

/// A contact law: the meaning of the multiplier components and their constraint rows.
/// Interface work (ContactTerm): component c adds R_{F_c,a} -= s_c ∫ N_a λ_c n da on the rows of
/// the vector field F_c = paired_field(c) at the facet nodes of both surfaces (s_c =
/// work_factor(c, Δt)); a component with a work axis i (a traction component e_i·t) adds
/// R_{F_c,a} -= s_c ∫ N_a λ_c e_i |n da| on the slave facets and the opposite on the master
/// facets.
class ContactLaw {
public:
  virtual ~ContactLaw() = default;
  virtual std::string name() const = 0;
  /// Multiplier components per slave node (= components of the multiplier field).
  virtual int num_components() const = 0;
  /// The nodal vector field (3 components per mesh node) that component c's interface work
  /// acts on (the displacement field for the contact pressure).
  virtual dofs::FieldId paired_field(int c) const = 0;
  /// Factor on component c's interface work in the rows of paired_field(c): the row scaling
  /// of the term that owns those rows (1 for momentum rows; -Δt for the -Δt-scaled mixture flux
  /// rows, so that R_{F_c,a} += Δt ∫ N_a λ_c n da there). `dt` is the step size.
  virtual Real work_factor(int /*c*/, Real /*dt*/) const { return 1; }
  /// The Cartesian axis i of a traction component (its work acts along e_i over the area),
  /// or -1 for a component whose work acts along the surface normal (n da).
  virtual int work_axis(int /*c*/) const { return -1; }
  /// Whether component c and its paired field are interpolated linearly from the corners on
  /// quadratic facets (the fluxes of tet10 and hex20 cells): its multiplier then lives on the
  /// corner slave nodes only, and its interface work acts through the corners' linear functions.
  virtual bool corner_interpolated(int /*c*/) const { return false; }
  /// Further nodal vector fields the constraint rows depend on at the slave node and the
  /// master facet nodes (positions are always available).
  virtual std::vector<dofs::FieldId> constraint_fields() const { return {}; }
  /// Complementarity function of the normal contact, e.g. λ_t + c_N g: the primal-dual active
  /// set activates a node where it is negative (docs/theory/contact.md §5.2).
  virtual Real indicator(const SlaveNodeRows& node) const = 0;
  /// Whether the law distinguishes a wetted from a sealed contact (NodeContact::Wetted).
  virtual bool wettable() const { return false; }
  /// Whether the law distinguishes sticking (NodeContact::Sealed) from slipping contact.
  virtual bool frictional() const { return false; }
  /// Of a frictional law at a node in contact: the slip function, > 0 where the node slips
  /// (e.g. |trial tangential traction| - μ p) [stress].
  virtual Real slip_indicator(const SlaveNodeRows& /*node*/) const { return 0; }
  /// Constraint rows (on the λ_k DOFs) of an active node, added to `out` (node.wetted tells
  /// a wetted from a sealed contact).
  virtual void active_rows(const SlaveNodeRows& node, LocalSystem& out) const = 0;
  /// Rows of an inactive node (separated, or not projecting onto the master surface).
  virtual void inactive_rows(const SlaveNodeRows& node, LocalSystem& out) const = 0;
};

/// Frictionless normal contact of solids, multiplier = contact pressure t (≤ 0 compressive,
/// the normal component of the total traction; docs/theory/contact.md §5.1):
///   active:   G_k = A_k g_k,          ΔG_k = A_k n·(Δx_s - Σ_a N_a(ξ) Δx_a)
///   inactive: G_k = (A_k / c_N) t_k   (t_k = 0; the weight only makes rows conjugate)
///   indicator: t_k + c_N g_k.
/// MixtureContactLaw (mixture_contact_law.hpp) appends (mū_w, c_ref mū_±) paired with w, j±.
class FrictionlessLaw final : public ContactLaw {
public:
  explicit FrictionlessLaw(dofs::FieldId displacement) : u_(displacement) {}
  std::string name() const override { return "frictionless"; }
  int num_components() const override { return 1; }
  dofs::FieldId paired_field(int /*c*/) const override { return u_; }
  Real indicator(const SlaveNodeRows& node) const override;
  void active_rows(const SlaveNodeRows& node, LocalSystem& out) const override;
  void inactive_rows(const SlaveNodeRows& node, LocalSystem& out) const override;

private:
  dofs::FieldId u_;
};

} // namespace trifem::contact
