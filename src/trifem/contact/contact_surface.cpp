// SPDX-License-Identifier: MIT
#include "trifem/contact/contact_surface.hpp"

#include <algorithm>
#include <tuple>

namespace trifem::contact {

ContactSurface::ContactSurface(const mesh::Surface& surface)
    : facets_(surface.facets), nodes_(mesh::surface_nodes(surface)) {
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
}

void ContactSurface::build_node_facets() {
  // CSR; facets are ascending because they are visited in order. A degenerate facet may repeat
  // a node: only its first occurrence counts.
  const auto first = [](const mesh::Facet& facet, int a) {
    return std::find(facet.nodes.begin(), facet.nodes.begin() + a, facet.nodes[a]) ==
           facet.nodes.begin() + a;
  };
  node_facet_offsets_.assign(nodes_.size() + 1, 0);
  for (const mesh::Facet& facet : facets_)
    for (int a = 0; a < 4; ++a)
      node_facet_offsets_[local_node(facet.nodes[a]) + 1] += first(facet, a) ? 1 : 0;
  for (std::size_t k = 0; k < nodes_.size(); ++k)
    node_facet_offsets_[k + 1] += node_facet_offsets_[k];
  node_facet_list_.resize(node_facet_offsets_.back());
  std::vector<Index> fill(node_facet_offsets_.begin(), node_facet_offsets_.end() - 1);
  for (Index f = 0; f < num_facets(); ++f)
    for (int a = 0; a < 4; ++a)
      if (first(facets_[f], a))
        node_facet_list_[fill[local_node(facets_[f].nodes[a])]++] = f;
}

void ContactSurface::build_edge_neighbours() {
  // Sort (min node, max node, 4 facet + edge) and pair equal node pairs.
  std::vector<std::tuple<Index, Index, Index>> edges;
  edges.reserve(4 * facets_.size());
  for (Index f = 0; f < num_facets(); ++f)
    for (int e = 0; e < 4; ++e) {
      const Index a = facets_[f].nodes[e], b = facets_[f].nodes[(e + 1) % 4];
      edges.emplace_back(std::min(a, b), std::max(a, b), 4 * f + e);
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

bool ContactSurface::on_free_boundary(Index f, const Vec2& xi_c,
                                      const std::array<bool, 2>& fixed) const {
  bool free = false;
  if (fixed[1])
    free = free || edge_neighbour(f, xi_c[1] < 0 ? 0 : 2) < 0;
  if (fixed[0])
    free = free || edge_neighbour(f, xi_c[0] > 0 ? 1 : 3) < 0;
  return free;
}

fe::QuadCoords ContactSurface::coords(Index f, const NodePositions& x) const {
  fe::QuadCoords X;
  for (int a = 0; a < 4; ++a)
    X.row(a) = x(facets_[f].nodes[a]).transpose();
  return X;
}

} // namespace trifem::contact
