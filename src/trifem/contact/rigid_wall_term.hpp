// SPDX-License-Identifier: MIT
// Frictionless contact of the nodes of a surface with a moving rigid plane, nodal Lagrange
// multipliers and the primal-dual active set of ContactTerm (docs/theory/constraints.md §2).
#pragma once

#include "trifem/contact/active_set.hpp"
#include "trifem/dofs/dof_map.hpp"
#include "trifem/dofs/load_curve.hpp"
#include "trifem/mesh/mesh.hpp"
#include "trifem/physics/term.hpp"

namespace trifem::contact {

/// The plane n·(x − p) = offset · curve(t) and the scales of the active set.
struct RigidWallSettings {
  Vec3 point = Vec3::Zero();   ///< p: a point of the plane at t = 0 [length]
  Vec3 normal = Vec3::UnitZ(); ///< n: unit normal, towards the side the nodes keep to
  Real offset = 0.0;           ///< the plane moves by offset · curve(t) along n [length]
  dofs::LoadCurve curve = dofs::LoadCurve::constant(1.0);
  Real scale = 0.0;             ///< c > 0 [force/length]: complementarity scaling (≈ E h)
  Real gap_tolerance = 0.0;     ///< > 0 [length]: initial set g ≤ tol, settled set |g| ≤ tol
  Real release_threshold = 0.0; ///< ≥ 0 [force]: hysteresis of the release
  int max_active_set_updates = 5;
  int max_active_set_resolves = 10;
};

/// Unknowns: the normal contact force λ_k ≤ 0 (compressive) of each node k of the surface (a
/// field with one entity per node, one component). With the gap g_k = n·(x_k − p) − s(t):
///   R_{u_k} += λ_k n,   R_{λ_k} = g_k (active) or λ_k / c (inactive),
/// indicator λ_k + c g_k (active where negative). The force of the wall on node k is −λ_k n.
/// One element per node: DOFs (u_k, λ_k).
class RigidWallTerm final : public physics::Term {
public:
  /// `nodes`: the mesh nodes of the surface; `multiplier`: a field with nodes.size() entities
  /// and one component. Throws InputError for no nodes, a zero normal or scale, a bad field.
  RigidWallTerm(const mesh::Mesh& mesh, const dofs::DofMap& dofs, dofs::FieldId displacement,
                dofs::FieldId multiplier, std::vector<Index> nodes, RigidWallSettings settings);

  std::string name() const override { return "rigid wall"; }
  Index num_elements() const override { return static_cast<Index>(nodes_.size()); }
  void element_dofs(Index e, std::vector<Index>& dofs) const override;
  bool evaluate(Index e, const physics::EvalState& state, physics::LocalVector& r,
                physics::LocalMatrix* K) const override;
  /// The active-set update at the state (ContactTerm's rules).
  bool prepare(const physics::EvalState& state) override;
  void commit(const physics::EvalState& state) override;
  void reject() override { active_ = committed_; }
  /// A converged step whose active set has not settled is cut back.
  std::string step_rejection(const physics::EvalState& state) const override;
  /// The committed contact flags (one per node).
  std::vector<double> history() const override;
  void restore_history(const std::vector<double>& values) override;

  /// g_k in the state x at time t [length].
  Real gap(Index k, const Vector& x, Real t) const;
  /// The force of the wall on the body in the state x, −Σ_k λ_k n [force].
  Vec3 force(const Vector& x) const;
  /// Nodes in the active set.
  Index num_active() const { return active_.num_active(); }
  const ActiveSet& active_set() const { return active_; }
  const std::vector<Index>& nodes() const { return nodes_; }
  Index multiplier_dof(Index k) const { return dofs_.dof(lambda_, k, 0); }

private:
  Index u_dof(Index k, int i) const { return dofs_.dof(u_, nodes_[k], i); }

  const mesh::Mesh& mesh_;
  const dofs::DofMap& dofs_;
  dofs::FieldId u_, lambda_;
  std::vector<Index> nodes_;
  RigidWallSettings settings_;
  ActiveSet active_, committed_;
};

} // namespace trifem::contact
