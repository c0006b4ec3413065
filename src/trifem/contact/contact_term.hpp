// SPDX-License-Identifier: MIT
// One-pass node-to-segment contact with Lagrange multipliers at the slave nodes, interface work
// integrated over both surfaces (Chen, Sunagawa & Hisada 2009, §3 and Appendix A;
// docs/theory/contact.md).
#pragma once

#include "trifem/contact/active_set.hpp"
#include "trifem/contact/contact_law.hpp"
#include "trifem/mesh/mesh.hpp"

#include <memory>
#include <optional>

namespace trifem::contact {

/// Multipliers of the nodes of a facet (row a, column = component; at most 4 components).
using FacetMultipliers =
    Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic, 0, fe::kMaxFacetNodes, 4>;

/// How the interface work of the multipliers is integrated (docs/theory/contact.md §4).
enum class Integration {
  /// The paper's scheme: slave facets with λ^s(ξ) = Σ_k M_k(ξ) λ_k, master facets with
  /// λ^m(ξ) = Σ_i N_i(ξ) λ^m_i, λ^m_i = Σ_k M_k(ζ_i) λ_k (ζ_i: projection of master node i
  /// onto the slave surface; 0 if it has none within the search distance or if it lies beyond
  /// the free boundary of the slave surface: exposed). Passes the contact patch test.
  BothSurfaces,
  /// Conventional one-pass NTS: lumped point force λ_k a_k at slave node k (a_k = ∫ M_k n da,
  /// current) and its reaction -λ_k N_a(ξ_k) a_k on the nodes of the master facet it projects
  /// onto. Fails the patch test (kept to show it).
  SlaveNodes,
};

/// Parameters of a contact pair. Lengths refer to h = the mean reference facet size of both
/// surfaces; non-positive values select the defaults given.
struct ContactSettings {
  Integration integration = Integration::BothSurfaces;
  Real scale = 0;              ///< c_N > 0 [stress/length], ≈ E/h (a scaling only; required)
  Real search_distance = 0;    ///< projections farther than this do not exist; ≤ 0: 0.5 h
  Real release_threshold = -1; ///< ε_t [stress]; < 0: 1e-8 c_N h (≈ 1e-8 E)
  Real gap_tolerance = -1; ///< initial set g ≤ tol, settled set |g| ≤ tol [length]; < 0: 1e-6 h
  int max_active_set_updates = 5;   ///< evaluations per step before the set is frozen
  int max_active_set_resolves = 10; ///< updates of a frozen set once it has settled
  bool update_active_set = true;    ///< false: the set stays as initialised or assigned
  Real xi_tolerance = 1e-6;         ///< interior projections accepted in [-1-tol, 1+tol]²
  /// The same for the projections of the master nodes onto the slave surface (BothSurfaces):
  /// a master node just beyond an edge of the slave surface keeps the multiplier extrapolated
  /// from the edge facet instead of being exposed (λ^m = 0). Such nodes are the rule where a
  /// symmetry plane cuts both surfaces: master nodes on the plane lie off the slave surface by
  /// |g| sin θ (g their gap, θ the tilt of the slave facet), far below 0.5 % of a facet.
  Real master_xi_tolerance = 1e-2;
  /// The same for a slave node just beyond a free edge of the master surface: it keeps the
  /// projection onto the extended edge facet (and its contact) instead of being released.
  /// Such nodes are the rule where the edges of equal surfaces meet (two blocks of the same
  /// section pressed together), where round-off alone puts the slave edge on either side.
  Real slave_free_edge_tolerance = 1e-2;
};

/// Interface state of one slave node k in a configuration x (ContactTerm::slave_states). A node
/// is `projected` if it has an admissible projection onto the master surface: one within the
/// search distance that does not lie beyond the master's free boundary. Nodes that are not have
/// gap = 0 and a zero master normal (no NaN: read `projected` first).
struct SlaveNodeState {
  Index node = -1;                 ///< mesh node
  Vec3 position = Vec3::Zero();    ///< current position x = X + u [length]
  Vec3 area_vector = Vec3::Zero(); ///< a_k = ∫ M_k n da over the current slave surface [length²]
  Vec3 normal = Vec3::Zero();      ///< a_k / |a_k|: outward unit normal of the slave surface
  bool projected = false;          ///< admissible projection onto the master surface
  bool active = false;             ///< in the active set (of the last prepare())
  bool frictional = false;         ///< of a frictional law: multipliers 1-3 are the friction
                                   ///< traction on the slave body [stress]
  bool slipping = false;           ///< active and slipping (frictional laws)
  Real accumulated_slip = 0;       ///< frictional laws: ContactTerm::accumulated_slip [length]
  Real gap = 0;                    ///< g = (x - x^m(ξ))·n^m(ξ) [length]: ≥ 0 separated
  Vec3 master_normal = Vec3::Zero(); ///< n^m(ξ) at the projection (outward from the master)
  Vector multiplier; ///< λ_k as stored (components and units: the ContactLaw); at a mid-edge
                     ///< node the components interpolated from the corners (corner_interpolated)
                     ///< hold the mean of the edge's corners
  /// Mesh nodes of the corners of the edge whose mid-edge node this is ({-1, -1} at a corner):
  /// a field interpolated from the corners takes there the mean of these.
  std::array<Index, 2> edge_corners{-1, -1};
};

/// Contact of a master and a slave surface (fixed for the run: one pass), frictionless or
/// through any ContactLaw. Unknowns: the multipliers λ_k of every slave node k (a field with
/// one entity per slave surface node, ordered as ContactSurface::nodes()).
///
/// Residual contributions (R = f_int - f_ext; the interface traction λ n is external):
///   slave facets:   R_{F_c,a} -= s_c ∫ N_a λ^s_c(ξ) n da      (BothSurfaces)
///   master facets:  R_{F_c,a} -= s_c ∫ N_a λ^m_c(ξ) n da      (BothSurfaces)
///   slave facets:   R_{F_c,a} -= λ_{a,c} a_a,  R_{F_c,q} += λ_{a,c} N_q(ξ_a) a_a   (SlaveNodes)
///   slave node k:   rows G_k of the law (active or inactive) on the λ_k DOFs
/// with s_c = ContactLaw::work_factor(c, Δt) (the row scaling of the field paired with c; the
/// SlaveNodes terms carry it as well) and n da = (t_1 × t_2) dξ in the current configuration, by
/// the facet type's rule (exact for flat facets: 2×2 Gauss on quad4). Facets may be tri3, tri6,
/// quad4 or quad8, on either side. The consistent tangent includes the area-vector derivatives, the
/// multiplier columns, the derivative of L_ik = M_k(ζ_i) through the projection of master node i,
/// and of N_q(ξ_k).
///
/// Elements: [slave facets | master facets (BothSurfaces only) | slave nodes]. Stencils are
/// sorted and unique and depend on the current projections (a node's projection facet is in
/// the stencil whenever the projection exists, so active-set flips never change the pattern);
/// prepare() recomputes them and reports a change (the assembler then rebuilds the pattern).
/// Active set: see ActiveSet (primal-dual, indicator of the law, frozen after a few updates
/// per step, re-checked once settled; pending() > 0 after a converged step means the step
/// must be cut back).
class ContactTerm final : public physics::Term {
public:
  /// `multiplier`: field with slave.nodes().size() entities and law->num_components()
  /// components. Throws InputError for empty or overlapping surfaces or a bad field/setting.
  ContactTerm(const mesh::Mesh& mesh, const dofs::DofMap& dofs, dofs::FieldId displacement,
              dofs::FieldId multiplier, const mesh::Surface& master, const mesh::Surface& slave,
              std::shared_ptr<const ContactLaw> law, ContactSettings settings);

  std::string name() const override { return "contact"; }
  bool joins_bodies() const override { return true; }
  Index num_elements() const override { return static_cast<Index>(stencils_.size()); }
  void element_dofs(Index e, std::vector<Index>& dofs) const override { dofs = stencils_[e]; }
  bool evaluate(Index e, const physics::EvalState& state, physics::LocalVector& r,
                physics::LocalMatrix* K) const override;
  /// Search and projections in the current configuration, then the active-set update.
  bool prepare(const physics::EvalState& state) override;
  void commit(const physics::EvalState& state) override;
  /// Restores the active set of the last commit (a retried step starts from it).
  void reject() override { active_ = committed_active_; }
  /// Rejects a converged step whose active set has not settled (ActiveSet::pending() > 0), or
  /// in which a slave node crossed the master surface (tunnelling: it was in front of the
  /// master surface, or within the search distance behind it, at the step start and ends
  /// behind it beyond the search distance, where no projection finds it): the step is cut back.
  std::string step_rejection(const physics::EvalState& state) const override;
  /// A slave node that carried a substantial pressure at the step start (more than
  /// kReleaseFraction of the peak) slid beyond the master surface: the step is cut back while
  /// it can be (a smaller step finds the equilibrium in which it leaves), and at the minimum
  /// step size accepted with a warning (the node left the edge of the master surface).
  std::string step_caution(const physics::EvalState& state) const override;
  /// The committed active set, admissible projections and contact pressures (3 numbers per
  /// slave node); of a frictional law then the accumulated slips and the dissipation.
  std::vector<double> history() const override;
  void restore_history(const std::vector<double>& values) override;
  /// Fraction of the peak contact pressure above which losing the projection rejects a step.
  static constexpr Real kReleaseFraction = 0.25;

  const ContactSurface& master() const { return master_; }
  const ContactSurface& slave() const { return slave_; }
  const ContactSettings& settings() const { return settings_; }
  const ActiveSet& active_set() const { return active_; }
  ActiveSet& active_set() { return active_; }
  /// Projection of slave node k onto the master surface (last prepare()).
  const std::optional<Projection>& slave_projection(Index k) const { return slave_proj_[k]; }
  /// Projection of master node i (index into master().nodes()) onto the slave surface.
  const std::optional<Projection>& master_projection(Index i) const { return master_proj_[i]; }
  /// A_k = ∫ M_k dA over the reference slave surface; on quadratic facets, whose corner
  /// functions integrate to zero (tri6) or less (quad8), the facet area shared in proportion
  /// to ∫ M_k² dA (HRZ lumping), so that every row weight is positive.
  Real tributary_area(Index k) const { return area_[k]; }
  /// DOF of component c of λ_k.
  Index multiplier_dof(Index k, int c) const { return dofs_.dof(lambda_, k, c); }
  /// Total interface force on the slave body in the state x: of the components paired with
  /// the displacement, f = ∫ λ^s n da = Σ_k λ_k a_k (normal) plus ∫ t^s da (friction)
  /// (both integration options give the same total); with `friction_only` the friction part.
  Vec3 slave_force(const Vector& x, bool friction_only = false) const;
  /// Whether the pair's law has friction tractions (FrictionalLaw).
  bool frictional() const { return law_->frictional(); }
  /// Of a frictional law: the slip of slave node k summed over the converged steps, Σ |Δg_T|,
  /// with Δg_T the tangential part (normal to the master) of its motion over a step relative to
  /// the master point it projects onto [length]; 0 for a frictionless law.
  Real accumulated_slip(Index k) const { return slip_.empty() ? 0.0 : slip_[k]; }
  /// Of a frictional law: the work dissipated by friction over the converged steps,
  /// Σ_steps Σ_k −t_k · Δg_T,k |a_k| over the active slave nodes (t_k the friction traction on
  /// the slave body, a_k its area vector at the step end) [force × length].
  Real friction_dissipation() const { return dissipation_; }
  /// Total interface force (as slave_force) on the master body in the state x (projections of
  /// the last prepare()): ∫ λ^m n da (BothSurfaces) or -Σ_k λ_k a_k over the slave nodes that
  /// transfer their force (SlaveNodes, = -slave_force). The both-surface scheme does not
  /// conserve momentum exactly: master + slave force is zero for a uniform pressure (patch
  /// test) and otherwise decreases as the master nodes resolve the pressure distribution.
  Vec3 master_force(const Vector& x) const;
  /// Interface state of every slave node (order of slave().nodes()) in the state x
  /// (contact_measures.cpp): projections onto the master surface recomputed in x with the
  /// search distance and tolerances of prepare(), area vectors in x, the active flags of the
  /// current active set and the multipliers read from x.
  std::vector<SlaveNodeState> slave_states(const Vector& x) const;
  /// Current area of the active part of the slave surface in the state x: Σ |a_k| over the
  /// active slave nodes k, a_k = ∫ M_k n da (current configuration) [length²].
  Real contact_area(const Vector& x) const;

private:
  enum class Kind { SlaveFacet, MasterFacet, SlaveNode };
  std::pair<Kind, Index> locate(Index e) const;
  Vec3 position(Index node, const Vector& x) const;
  /// Current coordinates of facet f of `surface` (master_ or slave_) in the state x.
  FacetCoords coords(const ContactSurface& surface, Index f, const Vector& x) const;
  Index u_dof(Index node, int i) const { return dofs_.dof(u_, node, i); }
  /// λ of the nodes of slave facet f (row a, column c).
  FacetMultipliers facet_multipliers(Index f, const Vector& x) const;

  void resolve_defaults();
  void project_all(const Vector& x);
  /// Per slave node: 1 if its projection of the last prepare() exists and is admissible.
  std::vector<char> admissible_projections() const;
  void update_active_set(const physics::EvalState& state);
  bool rebuild_stencils();
  void stencil_of(Kind kind, Index i, std::vector<Index>& dofs) const;
  void add_node_dofs(Index node, bool rows, std::vector<Index>& dofs) const;

  // tunnelling (crossing_check.cpp)
  /// Closest point of the master surface to p in the state x, without a distance limit.
  std::optional<Projection> nearest_on_master(const Vec3& p, const Vector& x) const;
  /// Whether slave node k must be checked for a crossing: it has no admissible projection now
  /// and had one at the last commit, or some node of the pair moved farther than the search
  /// distance within the step.
  bool crossing_candidate(Index k, bool large_motion) const;
  /// The reason to reject a step from state.x_old to state.x because a slave node crossed the
  /// master surface within it (empty: none did).
  std::string crossing_rejection(const physics::EvalState& state) const;

  // element kernels (interface_integrals.cpp)
  void slave_facet_work(Index f, const Vector& x, Real dt, LocalSystem& out) const;
  void master_facet_work(Index f, const Vector& x, Real dt, LocalSystem& out) const;
  void slave_point_forces(Index f, const Vector& x, Real dt, LocalSystem& out) const;
  void slave_node_rows(Index k, const physics::EvalState& state, LocalSystem& out) const;
  /// Adds the slips and the frictional work of the converged step from state.x_old to state.x.
  void accumulate_slip(const physics::EvalState& state);
  /// Slave node k as its law sees it in `state` (without local positions and derivatives).
  void describe_node(Index k, const physics::EvalState& state, SlaveNodeRows& node) const;

  const mesh::Mesh& mesh_;
  const dofs::DofMap& dofs_;
  dofs::FieldId u_, lambda_;
  ContactSurface master_, slave_;
  std::shared_ptr<const ContactLaw> law_;
  ContactSettings settings_;
  std::vector<dofs::FieldId> paired_; ///< unique fields paired with the components (rows)
  /// Slave-node index of each node of each slave facet (facet f's in facet_nodes(f) order).
  std::vector<std::array<Index, fe::kMaxFacetNodes>> slave_facet_k_;
  std::vector<Real> area_; ///< A_k
  Real h_ = 0;             ///< mean reference facet size
  ActiveSet active_;
  std::vector<std::optional<Projection>> slave_proj_, master_proj_;
  std::vector<std::vector<Index>> stencils_;
  std::vector<Real> committed_pressure_;  ///< |λ_k,0| of active nodes at the step start
  ActiveSet committed_active_;            ///< the active set at the last commit
  std::vector<char> committed_projected_; ///< admissible projection at the last commit
  std::vector<Real> slip_;                ///< accumulated slip per slave node (frictional laws)
  Real dissipation_ = 0;                  ///< accumulated frictional work
};

} // namespace trifem::contact
