// SPDX-License-Identifier: MIT
// The discrete model of an explicit run: mesh, laws, densities, fixities and surface loads, with
// everything that does not change during the run precomputed (cell geometry, lumped mass,
// node-to-cell incidence).
#pragma once

#include "trifem/dofs/load_curve.hpp"
#include "trifem/fe/hex8.hpp"
#include "trifem/material/elastic_law.hpp"
#include "trifem/mesh/mesh.hpp"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace trifem::model {
struct Model;
} // namespace trifem::model

namespace trifem::explicit_dynamics {

/// u_k = 0 on the nodes of a named node set (k = 0, 1, 2).
struct Fixity {
  std::string node_set;
  int component = 0;
};

/// What a surface load applies.
enum class LoadKind {
  FollowerPressure, ///< p(t) on the current surface, f_a = −p ∫ N_a n da (p > 0 pushes in)
  DeadTraction      ///< t(t) per reference area, f_a = t ∫ N_a dA
};

/// A load on a named surface, scaled by a load curve.
struct SurfaceLoad {
  LoadKind kind = LoadKind::FollowerPressure;
  std::string surface;
  Real pressure = 0.0;          ///< [MPa], FollowerPressure
  Vec3 traction = Vec3::Zero(); ///< [MPa], DeadTraction
  dofs::LoadCurve curve = dofs::LoadCurve::constant();
};

/// One material of the model: a law W(C) and a mass density.
struct ExplicitMaterial {
  std::shared_ptr<const material::ElasticLaw> law; ///< W(C) (shared, immutable)
  Real density = 0.0;                              ///< ρ [t/mm³] (> 0)
};

/// Everything the user specifies besides the mesh. One material for every cell: set `law` and
/// `density`. Several materials: leave `law` empty and give `materials` with `cell_material`.
struct ModelSpec {
  std::shared_ptr<const material::ElasticLaw> law; ///< single-material shorthand: W(C) of all cells
  Real density = 0.0;                              ///< single-material shorthand: ρ [t/mm³]
  std::vector<ExplicitMaterial> materials;         ///< several materials (used if `law` is empty)
  std::vector<int> cell_material; ///< index into `materials` of every cell (size num_cells)
  std::vector<Fixity> fixities;
  std::vector<SurfaceLoad> loads;
};

/// CSR list of the (cell, local node) pairs incident to every node.
struct NodeIncidence {
  std::vector<Index> offsets;                 ///< size num_nodes + 1
  std::vector<std::pair<Index, int>> entries; ///< (cell, local node 0..7), sorted by cell
};

/// A surface load with its facets resolved.
struct ResolvedLoad {
  SurfaceLoad load;
  std::vector<mesh::Facet> facets;
  std::vector<Eigen::Matrix<Real, 4, 1>> nodal_area; ///< ∫ N_a dA per facet (dead traction)
};

/// The immutable discrete model. DOF numbering: 3 a + k for node a, component k.
class ExplicitModel {
public:
  /// Validates the spec (named sets exist, ρ > 0, every cell has a material and
  /// det(∂X/∂ξ) > 0) and precomputes the geometry, the lumped mass and the incidence. The
  /// single-material shorthand is stored as `materials` = {law, density}. Throws InputError.
  ExplicitModel(mesh::Mesh mesh, ModelSpec spec);
  /// The model of the shared `model` (its solid cells, laws and densities) in its current
  /// step: the DOFs it constrains are fixed (they keep the displacement they start from), and
  /// `loads` act on the surfaces. The mesh is copied. InputError if a cell has no solid law or
  /// no density, or a DOF is tied to another (rigid bodies).
  ExplicitModel(const model::Model& model, std::vector<SurfaceLoad> loads);

  const mesh::Mesh& mesh() const { return mesh_; }
  /// W(C) of cell c.
  const material::ElasticLaw& law(Index c) const {
    return *spec_.materials[spec_.cell_material[c]].law;
  }
  /// ρ of cell c [t/mm³].
  Real density(Index c) const { return spec_.materials[spec_.cell_material[c]].density; }
  /// The materials, indexed by material_of().
  const std::vector<ExplicitMaterial>& materials() const { return spec_.materials; }
  /// Index into materials() of cell c.
  int material_of(Index c) const { return spec_.cell_material[c]; }
  Index num_cells() const { return mesh_.num_cells(); }
  Index num_dofs() const { return 3 * mesh_.num_nodes(); }

  /// Reference gradients and dV at the 2x2x2 Gauss points of every cell.
  const std::vector<fe::HexGeometry>& geometry() const { return geometry_; }
  /// Reference cell volumes V_e = Γ_ee [mm³].
  const Vector& volumes() const { return volumes_; }
  /// Characteristic lengths h_e = V_e / (largest face area) [mm].
  const Vector& lengths() const { return lengths_; }
  /// Row-sum lumped mass per DOF, m_a = ∫ ρ N_a dV [t].
  const Vector& mass() const { return mass_; }
  /// 1/m per DOF, 0 on fixed DOFs (their acceleration is zero) [1/t].
  const Vector& inverse_mass() const { return inverse_mass_; }
  /// true for DOFs with u = 0 prescribed.
  const std::vector<char>& fixed() const { return fixed_; }
  const NodeIncidence& incidence() const { return incidence_; }
  const std::vector<ResolvedLoad>& loads() const { return loads_; }

  /// The 8 x 3 nodal displacements of cell c taken from the global vector U.
  fe::HexCoords cell_values(Index c, const Vector& U) const;

private:
  void check_materials();
  void build_geometry();
  void build_mass();
  void fix(const std::vector<char>& fixed);
  void build_incidence();
  void resolve_loads();

  mesh::Mesh mesh_;
  ModelSpec spec_;
  std::vector<fe::HexGeometry> geometry_;
  Vector volumes_, lengths_, mass_, inverse_mass_;
  std::vector<char> fixed_;
  NodeIncidence incidence_;
  std::vector<ResolvedLoad> loads_;
};

} // namespace trifem::explicit_dynamics
