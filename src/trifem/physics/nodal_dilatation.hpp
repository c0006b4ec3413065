// SPDX-License-Identifier: MIT
// Locking-free tet4 and penta6 cells: the dilatation of a cell averaged over the patches of its
// corners (nodal averaging), for any hyperelastic law.
#pragma once

#include "trifem/mesh/mesh.hpp"
#include "trifem/physics/mean_dilatation_kernel.hpp"
#include "trifem/physics/term.hpp"

#include <span>
#include <vector>

namespace trifem::physics {

/// The nodally averaged dilatation element (in the spirit of Bonet & Burton 1998's average
/// nodal pressure tetrahedron, written as an energy for any law). Every node a has the volume
/// ratio θ_a = v_a / V_a of its share of the cells around it, v_a = Σ_{e∋a} v_e / n_e (n_e the
/// cell's nodes; V_a likewise in the reference), and a cell sees the mean of its corners',
///
///     J̄_e = (1/n_e) Σ_{a∈e} θ_a = Σ_j ω_ej v_j,
///
/// in the modified deformation C̄ = (J̄_e/J)^(2/3) C of the mean-dilatation element. The energy
/// Π = Σ_e Σ_q W(C̄_q) w_q is that of the whole patch, so the force and the tangent of a cell
/// reach every node of the cells that share a node with it; the tangent is symmetric. One
/// volume constraint per node instead of one per cell: tet4 and penta6 meshes (a triangle in
/// the wedge's plane) do not lock (docs/theory/elements.md).
class NodalDilatation {
public:
  /// `cells` (mesh cells, tet4 or penta6) and their reference geometries in the same order:
  /// the volumes are averaged over these cells only (another body or material beside them does
  /// not enter). The geometries must outlive this object.
  NodalDilatation(const mesh::Mesh& mesh, std::span<const Index> cells,
                  std::vector<const CellGeometry*> geometry);

  /// The nodes whose displacements element i depends on: its own (in its order), then those of
  /// the cells sharing a node with it.
  std::span<const Index> patch(Index i) const;

  /// Force (3 per patch node, node-major) and, with K, tangent of element i with law `law` at
  /// the patch displacements u (rows: patch(i)). False if a cell of the patch is inverted.
  bool evaluate(Index i, const Eigen::MatrixX3d& u, const material::ElasticLaw& law, LocalVector& r,
                LocalMatrix* K) const;

  /// J̄ of element i at the patch displacements u (0 if a cell of the patch is inverted).
  Real dilatation(Index i, const Eigen::MatrixX3d& u) const;

  /// The elements sharing a node with element i (itself included) and the weights ω_ij of
  /// their volumes in J̄_i.
  struct Neighbour {
    Index element;
    Real weight;
  };
  std::span<const Neighbour> neighbours(Index i) const;

private:
  std::vector<const CellGeometry*> geometry_;
  std::vector<Index> patch_offsets_, patch_nodes_;
  std::vector<Index> neighbour_offsets_;
  std::vector<Neighbour> neighbours_;
  /// Per (element, neighbour) entry: where the neighbour's nodes stand in the element's patch.
  std::vector<Index> local_offsets_, local_;
};

} // namespace trifem::physics
