// SPDX-License-Identifier: MIT
#include "trifem/contact/contact_surface.hpp"

#include <algorithm>
#include <tuple>

namespace trifem::contact {

ContactSurface::ContactSurface(const mesh::Surface& surface)
    : facets_(surface.facets), nodes_(mesh::surface_nodes(surface)) {
  for (const mesh::Facet& facet : facets_) {
    for (int a = 0; a < facet.num_nodes(); ++a)
      facet_node_list_.push_back(facet.node(a));
    facet_offsets_.push_back(static_cast<Index>(facet_node_list_.size()));
  }
  build_adjacency();
}

ContactSurface::ContactSurface(const mesh::Mesh& mesh, const std::string& name)
    : ContactSurface(mesh.surface(name)) {}

Index ContactSurface::local_node(Index mesh_node) const {
  const auto it = std::lower_bound(nodes_.begin(), nodes_.end(), mesh_node);
  return (it != nodes_.end() && *it == mesh_node) ? static_cast<Index>(it - nodes_.begin()) : -1;
}

std::span<const Index> ContactSurface::node_facets(Index k) const {
  const auto begin = node_facet_list_.begin() + node_facet_offsets_[k];
  const auto end = node_facet_list_.begin() + node_facet_offsets_[k + 1];
  return {begin, end};
}

void ContactSurface::build_adjacency() {
  build_node_facets();
  build_edge_neighbours();
  build_edge_corners();
}

void ContactSurface::build_edge_corners() {
  edge_corners_.assign(nodes_.size(), {-1, -1});
  for (Index f = 0; f < num_facets(); ++f) {
    const mesh::Facet& facet = facets_[f];
    const int corners = facet.num_corners();
    has_quadratic_facets_ = has_quadratic_facets_ || facet.num_nodes() > corners;
    for (int e = 0; e < facet.num_nodes() - corners; ++e)
      edge_corners_[local_node(facet.node(corners + e))] = {
          local_node(facet.nodes[e]), local_node(facet.nodes[(e + 1) % corners])};
  }
}

void ContactSurface::build_node_facets() {
  // CSR; facets are ascending because they are visited in order. A degenerate facet may repeat
  // a node: only its first occurrence counts.
  const auto first = [](std::span<const Index> nodes, std::size_t a) {
    return std::find(nodes.begin(), nodes.begin() + a, nodes[a]) == nodes.begin() + a;
  };
  node_facet_offsets_.assign(nodes_.size() + 1, 0);
  for (Index f = 0; f < num_facets(); ++f) {
    const auto nodes = facet_nodes(f);
    for (std::size_t a = 0; a < nodes.size(); ++a)
      node_facet_offsets_[local_node(nodes[a]) + 1] += first(nodes, a) ? 1 : 0;
  }
  for (std::size_t k = 0; k < nodes_.size(); ++k)
    node_facet_offsets_[k + 1] += node_facet_offsets_[k];
  node_facet_list_.resize(node_facet_offsets_.back());
  std::vector<Index> fill(node_facet_offsets_.begin(), node_facet_offsets_.end() - 1);
  for (Index f = 0; f < num_facets(); ++f) {
    const auto nodes = facet_nodes(f);
    for (std::size_t a = 0; a < nodes.size(); ++a)
      if (first(nodes, a))
        node_facet_list_[fill[local_node(nodes[a])]++] = f;
  }
}

void ContactSurface::build_edge_neighbours() {
  // Sort (min node, max node, 4 facet + edge) and pair equal node pairs.
  std::vector<std::tuple<Index, Index, Index>> edges;
  edges.reserve(4 * facets_.size());
  for (Index f = 0; f < num_facets(); ++f) {
    const int corners = facets_[f].num_corners();
    for (int e = 0; e < corners; ++e) {
      const Index a = facets_[f].nodes[e], b = facets_[f].nodes[(e + 1) % corners];
      edges.emplace_back(std::min(a, b), std::max(a, b), 4 * f + e);
    }
  }
  std::sort(edges.begin(), edges.end());
  edge_neighbours_.assign(4 * facets_.size(), -1);
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i + 1;
    while (j < edges.size() && std::get<0>(edges[j]) == std::get<0>(edges[i]) &&
           std::get<1>(edges[j]) == std::get<1>(edges[i]))
      ++j;
    if (j == i + 2) { // manifold edge shared by exactly two facets
      const Index p = std::get<2>(edges[i]), q = std::get<2>(edges[i + 1]);
      edge_neighbours_[p] = q / 4;
      edge_neighbours_[q] = p / 4;
    }
    i = j;
  }
}

bool ContactSurface::on_free_boundary(Index f, int edge, int corner) const {
  if (corner < 0)
    return edge_neighbour(f, edge) < 0;
  const int corners = facets_[f].num_corners();
  return edge_neighbour(f, corner) < 0 || edge_neighbour(f, (corner + corners - 1) % corners) < 0;
}

FacetCoords ContactSurface::coords(Index f, const NodePositions& x) const {
  const auto nodes = facet_nodes(f);
  FacetNodePositions X(static_cast<Index>(nodes.size()), 3);
  for (std::size_t a = 0; a < nodes.size(); ++a)
    X.row(static_cast<Index>(a)) = x(nodes[a]).transpose();
  return {facets_[f].type, X};
}

} // namespace trifem::contact
