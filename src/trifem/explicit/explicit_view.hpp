// SPDX-License-Identifier: MIT
// What the explicit integrator reads of the shared model, with everything that does not change
// during a step precomputed: cell geometry, lumped mass, node-to-cell incidence.
#pragma once

#include "trifem/explicit/rigid_motion.hpp"
#include "trifem/fe/hex8.hpp"
#include "trifem/material/elastic_law.hpp"
#include "trifem/mesh/mesh.hpp"
#include "trifem/physics/cell_mass.hpp"
#include "trifem/physics/solid_cell.hpp"

#include <utility>
#include <vector>

namespace trifem::model {
struct Model;
struct RigidBody;
} // namespace trifem::model

namespace trifem::explicit_dynamics {

/// CSR list of the (cell, local node) pairs incident to every node.
struct NodeIncidence {
  std::vector<Index> offsets;                 ///< size num_nodes + 1
  std::vector<std::pair<Index, int>> entries; ///< (cell, local node), sorted by cell
};

/// The explicit view of a model::Model in its current step. Its cells are hex8, tet10 or hex20
/// (tet4 and penta6 cells lock under the volume constraint: the model refuses them). Vectors are
/// indexed 3 a + k for node a, component k (mapped to the model's DOFs where loads are evaluated).
/// The model must outlive the view.
class ExplicitView {
public:
  /// The solid cells (laws, densities) of `model`; the DOFs it constrains in its current step
  /// follow their prescribed values (prescribe()); its load terms give F_S. The nodes of a rigid
  /// body whose six unknowns are all prescribed are constrained DOFs; those of another body
  /// move with it (bodies()). `shells`: the mass elements of the bodies' shells. Throws
  /// InputError if a solid cell has no density, a cell is a mixture's, a free node belongs to
  /// no cell, a cell is inverted, the model has rigid connectors, or a body's drive is not one
  /// the explicit integrator takes (docs/theory/explicit.md §9).
  explicit ExplicitView(const model::Model& model,
                        const std::vector<physics::MassElement>& shells = {});

  /// InputError naming the first cell that is not rigid and is a tet4 or a penta6: they lock
  /// under the one volume multiplier per cell of the explicit scheme (tet10 and hex20 cells take
  /// it as hex8 cells do). A run with a dynamic-explicit step checks it before its first step.
  static void check_cells(const model::Model& model);

  const mesh::Mesh& mesh() const { return mesh_; }
  /// W(C) of cell c.
  const material::ElasticLaw& law(Index c) const;
  /// ρ of cell c [t/mm³].
  Real density(Index c) const;
  /// false for the cells of a rigid body and those whose nodes all move with one body: they
  /// have no law or keep their strain, and the cell loops leave them out (0 forces, Ψ, W).
  bool deformable(Index c) const { return deformable_[c] != 0; }
  Index num_cells() const { return mesh_.num_cells(); }
  Index num_dofs() const { return 3 * mesh_.num_nodes(); }

  /// Reference gradients and dV of every cell: a hex8's at its 2x2x2 Gauss points, a cell of
  /// another family (tet10, hex20) at the points of its family's rule.
  const std::vector<physics::AnyCellGeometry>& geometry() const { return geometry_; }
  /// Where the nodal values of cell c lie in a vector of cell vectors (3 per node, node-major,
  /// the cells one after another): from cell_offsets()[c] to cell_offsets()[c + 1].
  const std::vector<Index>& cell_offsets() const { return cell_offsets_; }
  /// Reference cell volumes V_e = Γ_ee [mm³].
  const Vector& volumes() const { return volumes_; }
  /// Characteristic lengths h_e = V_e / (largest face area) [mm].
  const Vector& lengths() const { return lengths_; }
  /// Row-sum lumped mass per DOF, m_a = ∫ ρ N_a dV [t].
  const Vector& mass() const { return mass_; }
  /// The lumped mass of the free DOFs, 0 on fixed ones (they move as prescribed) [t].
  const Vector& free_mass() const { return free_mass_; }
  /// 1/m per DOF, 0 on fixed DOFs (the forces do not move them) [1/t].
  const Vector& inverse_mass() const { return inverse_mass_; }
  /// 1/m per DOF of every node with a mass that is not constrained, those of the rigid bodies
  /// included as if they were free: the frequencies of the mesh without the bodies' rigidity
  /// bound those with it from above, so the stable step estimated with it is safe [1/t].
  const Vector& frequency_inverse_mass() const { return frequency_inverse_mass_; }
  /// true for DOFs the model constrains (fixed or prescribed).
  const std::vector<char>& fixed() const { return fixed_; }
  /// The lumped mass of the DOFs whose motion the kinetic energy counts: the free DOFs and those
  /// of the bodies (0 on constrained DOFs) [t].
  const Vector& kinetic_mass() const { return kinetic_mass_; }
  /// true if a constrained DOF moves (a non-zero prescribed value).
  bool has_prescribed_motion() const { return prescribed_motion_; }
  /// Writes the prescribed values at time t into the constrained entries of U (3 a + k).
  void prescribe(Real time, Vector& U) const;

  /// The rigid bodies whose nodes move with them (their inverse mass is 0: the integrator moves
  /// them with the body).
  const std::vector<ExplicitBody>& bodies() const { return bodies_; }
  /// The number of bodies() of `model` in its current step: its rigid bodies but those whose
  /// motion is wholly prescribed.
  static std::size_t count_bodies(const model::Model& model);
  /// What the drive of body b prescribes at `time`. InputError if a rotation a body turns
  /// about one axis with is prescribed other than 0.
  BodyTarget target(std::size_t b, Real time) const;
  /// The motion of body b at the model's state x and velocity v (DOF vectors of the model; v
  /// empty: at rest), its velocities taken as those of t_{n−½}.
  BodyMotion motion(std::size_t b, const Vector& x, const Vector& v) const;
  /// Writes the unknowns of body b at `motion` into the model's DOF vector x (the translation
  /// of its center and its rotation vector; those of a body that only translates are nodal).
  void scatter_body(std::size_t b, const BodyMotion& motion, Vector& x) const;
  /// Writes the state at `time` into the model's DOF vector x: the displacements U (3 a + k),
  /// the unknowns of the bodies at `motions` and those of the bodies whose motion is prescribed.
  void scatter_state(const Vector& U, const std::vector<BodyMotion>& motions, Real time,
                     Vector& x) const;
  /// Writes the velocity of the unknowns of body b into the model's DOF vector v from the
  /// pivot's velocity and the angular velocity at `motion`.
  void scatter_body_velocity(std::size_t b, const BodyMotion& motion, const Vec3& pivot_velocity,
                             const Vec3& omega, Vector& v) const;
  const NodeIncidence& incidence() const { return incidence_; }

  /// On several processes (parallel::active()) the nodes are partitioned (METIS, the cells'
  /// couplings); a process gathers the forces of the nodes it owns, evaluates the cells that
  /// have one of them (all those the forces of its nodes need) and reports the cell values of
  /// the cells it owns (those whose first node it owns). Every vector over nodes or cells is
  /// whole on every process, the same bits everywhere. On one process all are its own.
  bool distributed() const { return !node_owner_.empty(); }
  bool owns_node(Index a) const { return node_owner_.empty() || node_owner_[a] == rank_; }
  bool owns_cell(Index c) const { return cell_owner_.empty() || cell_owner_[c] == rank_; }
  bool evaluates(Index c) const { return evaluated_.empty() || evaluated_[c] != 0; }
  /// The owning process of every cell (empty on one process).
  const std::vector<int>& cell_owners() const { return cell_owner_; }

  /// f = F_S(t, U) = −Σ over the model's load terms of their residual at U and time t [N]
  /// (follower pressures on the current surface, dead tractions per reference area), size
  /// num_dofs, overwritten; fixed DOFs included. With bodies, `motions` is their state and
  /// `loads` receives the forces and moments applied to them (about their pivots).
  void external_force(const Vector& U, Real time, Vector& f,
                      const std::vector<BodyMotion>& motions = {},
                      std::vector<BodyLoad>* loads = nullptr) const;

  /// Writes v (3 a + k) into the displacement entries of the model's DOF vector x.
  void scatter(const Vector& v, Vector& x) const;
  /// The displacement entries of the model's DOF vector x, 3 a + k.
  Vector gather(const Vector& x) const;

  /// The 8 x 3 nodal displacements of hex8 cell c taken from the global vector U.
  fe::HexCoords hex8_values(Index c, const Vector& U) const;
  /// The nodal displacements of cell c of any family (one row per node) taken from U.
  fe::CellNodeCoords node_values(Index c, const Vector& U) const;

private:
  void build_geometry();
  void build_mass();
  void build_incidence();
  void build_partition();
  void build_bodies();
  void add_rotating_body(const model::RigidBody& rigid);
  void add_translating_body(const model::RigidBody& rigid);
  void set_mass_properties(ExplicitBody& body, bool center_is_pivot) const;
  void set_deformable();
  /// The force and the moment about its pivot of the loads `generalized` on the unknowns of
  /// body b (of a body that only translates: none, its loads act on its nodes).
  BodyLoad applied_load(std::size_t b, const BodyMotion& motion, const Vector& generalized,
                        const Vector& x) const;

  const model::Model& model_;
  const mesh::Mesh& mesh_;
  std::vector<Index> dofs_;  ///< the model's DOF of 3 a + k
  std::vector<Index> local_; ///< 3 a + k of the model's displacement DOFs (−1: other fields)
  std::vector<physics::AnyCellGeometry> geometry_;
  std::vector<Index> cell_offsets_;
  Vector volumes_, lengths_, mass_, free_mass_, inverse_mass_, kinetic_mass_;
  Vector frequency_inverse_mass_;
  std::vector<char> fixed_, deformable_;
  std::vector<ExplicitBody> bodies_;
  std::vector<int> rotating_; ///< per body: its index among the model's rotating bodies (−1)
  std::vector<std::array<Index, 3>> leaders_; ///< per body that only translates: its DOFs
  std::vector<Index> carrier_; ///< per node: the model's rigid body carrying it wholly (−1)
  bool prescribed_motion_ = false;
  NodeIncidence incidence_;
  std::vector<int> node_owner_, cell_owner_; ///< empty on one process
  std::vector<char> evaluated_;              ///< empty on one process
  int rank_ = 0;
};

} // namespace trifem::explicit_dynamics
