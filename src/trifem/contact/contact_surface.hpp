// SPDX-License-Identifier: MIT
// A contact surface: the facets of a named mesh surface, its unique nodes and the node -> facet
// and facet -> facet (across edges) adjacency, evaluated in a current configuration.
#pragma once

#include "trifem/contact/facet_geometry.hpp"
#include "trifem/mesh/mesh.hpp"

#include <functional>
#include <span>
#include <vector>

namespace trifem::contact {

/// Current nodal positions x_i (length unit of the mesh), indexed by *mesh* node: either a view
/// of an array (not owned; it must outlive this object) or a callable `Vec3(Index)`.
class NodePositions {
public:
  /// View of x[i] for mesh node i.
  NodePositions(const std::vector<Vec3>& x) : array_(&x) {}
  /// Positions from a callable, e.g. X_i + u_i read from a solution vector.
  NodePositions(std::function<Vec3(Index)> fn) : fn_(std::move(fn)) {}

  /// Current position of mesh node i.
  Vec3 operator()(Index i) const { return array_ ? (*array_)[i] : fn_(i); }

private:
  const std::vector<Vec3>* array_ = nullptr;
  std::function<Vec3(Index)> fn_;
};

/// Facets (tri3, tri6, quad4, quad8; mixed if need be) of one contact surface with topology.
/// Built once (topology is fixed); geometry is always evaluated from a NodePositions, so one
/// object serves every Newton iteration. Facet edge e joins corners e and (e+1) mod corners
/// (quad: e = 0 is η = -1, 1 is ξ = +1, 2 is η = +1 and 3 is ξ = -1) and holds mid-edge node e.
class ContactSurface {
public:
  /// Takes the facets of `surface` (copied). Facet node indices are mesh node indices.
  explicit ContactSurface(const mesh::Surface& surface);
  /// The surface `name` of `mesh`; throws InputError if it does not exist.
  ContactSurface(const mesh::Mesh& mesh, const std::string& name);

  Index num_facets() const { return static_cast<Index>(facets_.size()); }
  const mesh::Facet& facet(Index f) const { return facets_[f]; }
  const std::vector<mesh::Facet>& facets() const { return facets_; }

  /// Type of facet f.
  mesh::FacetType facet_type(Index f) const { return facets_[f].type; }
  /// Mesh nodes of facet f in the order of its type: corners, then mid-edge nodes.
  std::span<const Index> facet_nodes(Index f) const {
    return {facet_node_list_.data() + facet_offsets_[f],
            static_cast<std::size_t>(facet_offsets_[f + 1] - facet_offsets_[f])};
  }

  /// Sorted unique mesh node indices of the surface (corners and mid-edge nodes).
  const std::vector<Index>& nodes() const { return nodes_; }
  Index num_nodes() const { return static_cast<Index>(nodes_.size()); }
  /// The two corners (indices into nodes()) of the facet edge whose mid-edge node is surface
  /// node k, or {-1, -1} if k is a corner (of every facet it belongs to).
  std::array<Index, 2> edge_corners(Index k) const { return edge_corners_[k]; }
  bool is_mid_edge_node(Index k) const { return edge_corners_[k][0] >= 0; }
  /// True if a facet of the surface is quadratic (tri6, quad8).
  bool has_quadratic_facets() const { return has_quadratic_facets_; }

  /// Position of mesh node `mesh_node` in nodes(), or -1 if it is not on this surface.
  Index local_node(Index mesh_node) const;
  /// Facets incident to surface node k (k indexes nodes()), ascending.
  std::span<const Index> node_facets(Index k) const;

  /// The facet sharing edge e of facet f, or -1 on the free boundary of the surface (or if more
  /// than two facets share the edge).
  Index edge_neighbour(Index f, int e) const { return edge_neighbours_[4 * f + e]; }
  /// True if a boundary point of facet f lies on a free boundary edge, one with no neighbour:
  /// `edge` if `corner` < 0, else either edge at `corner` (Projection::edge, ::corner).
  bool on_free_boundary(Index f, int edge, int corner) const;

  /// Current nodal coordinates of facet f (row a = x of facet node a).
  FacetCoords coords(Index f, const NodePositions& x) const;
  /// Geometry of facet f at ξ in the configuration x.
  FacetPoint evaluate(Index f, const Vec2& xi, const NodePositions& x) const {
    return evaluate_facet(coords(f, x), xi);
  }

private:
  void build_adjacency();
  void build_node_facets();
  void build_edge_neighbours();
  void build_edge_corners();

  std::vector<mesh::Facet> facets_;
  std::vector<Index> facet_offsets_ = {0}; ///< facet f's nodes: facet_node_list_[offsets f..f+1)
  std::vector<Index> facet_node_list_;
  std::vector<Index> nodes_;
  std::vector<Index> node_facet_offsets_; ///< CSR offsets into node_facet_list_
  std::vector<Index> node_facet_list_;
  std::vector<Index> edge_neighbours_;             ///< 4 per facet
  std::vector<std::array<Index, 2>> edge_corners_; ///< per surface node
  bool has_quadratic_facets_ = false;
};

} // namespace trifem::contact
