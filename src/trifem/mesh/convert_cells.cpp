// SPDX-License-Identifier: MIT
#include "trifem/mesh/convert_cells.hpp"

#include "trifem/core/error.hpp"

#include <algorithm>
#include <map>
#include <utility>

namespace trifem::mesh {
namespace {

// Kuhn's split: the tets 0 -> 0 + e_i -> 0 + e_i + e_j -> 6 for the six orders (i, j, k) of the
// axes, as local nodes of a hex8 (node 1 = 0 + e_x, 3 = 0 + e_y, 4 = 0 + e_z; 2, 5, 7 the face
// diagonals); those of odd orders have their nodes 1 and 2 swapped to keep a positive volume.
const std::vector<std::vector<int>> kHexTets = {
    {0, 1, 2, 6}, // x y z
    {0, 5, 1, 6}, // x z y (odd)
    {0, 2, 3, 6}, // y x z (odd)
    {0, 3, 7, 6}, // y z x
    {0, 4, 5, 6}, // z x y
    {0, 7, 4, 6}, // z y x (odd)
};
const std::vector<std::vector<int>> kHexWedges = {{0, 1, 2, 4, 5, 6}, {0, 2, 3, 4, 6, 7}};
const std::vector<std::vector<int>> kHexItself = {{0, 1, 2, 3, 4, 5, 6, 7}};

/// The linear cells each hex becomes, as lists of its local nodes.
const std::vector<std::vector<int>>& pieces(CellType linear) {
  switch (linear) {
  case CellType::Tet4:
    return kHexTets;
  case CellType::Penta6:
    return kHexWedges;
  default:
    return kHexItself;
  }
}

/// Mid-edge nodes, one per edge (a pair of corner nodes, the smaller first).
class MidEdgeNodes {
public:
  explicit MidEdgeNodes(Mesh& mesh) : mesh_(mesh) {}

  Index node(Index a, Index b) {
    const std::pair<Index, Index> key = std::minmax(a, b);
    const auto [it, added] = nodes_.try_emplace(key, -1);
    if (added)
      it->second = mesh_.add_node(0.5 * (mesh_.node(a) + mesh_.node(b)));
    return it->second;
  }
  const std::map<std::pair<Index, Index>, Index>& edges() const { return nodes_; }

private:
  Mesh& mesh_;
  std::map<std::pair<Index, Index>, Index> nodes_;
};

/// The node sets of `hexes` (its surfaces' among them), each with the mid-edge nodes of the
/// edges whose both ends it holds.
std::map<std::string, std::vector<Index>> node_sets(const Mesh& hexes, const MidEdgeNodes& mid) {
  std::map<std::string, std::vector<Index>> sets = hexes.node_sets();
  for (auto& [name, nodes] : sets) {
    const std::size_t corners = nodes.size();
    for (const auto& [edge, node] : mid.edges())
      if (std::binary_search(nodes.begin(), nodes.begin() + static_cast<std::ptrdiff_t>(corners),
                             edge.first) &&
          std::binary_search(nodes.begin(), nodes.begin() + static_cast<std::ptrdiff_t>(corners),
                             edge.second))
        nodes.push_back(node);
  }
  return sets;
}

/// The faces of the cells `children` of a hex that lie on its facet f (their corners among
/// f's), as quads (a triangle's fourth corner repeating its third).
void add_child_faces(const Mesh& out, const std::vector<Index>& children, const Facet& f,
                     std::vector<std::array<Index, 4>>& faces) {
  for (Index child : children) {
    const std::span<const Index> nodes = out.cell_nodes(child);
    for (const CellFace& face : cell_faces(out.cell_type(child))) {
      const int corners = face.type == FacetType::Tri3 || face.type == FacetType::Tri6 ? 3 : 4;
      std::array<Index, 4> quad{};
      bool on_f = true;
      for (int i = 0; i < corners; ++i) {
        quad[static_cast<std::size_t>(i)] = nodes[static_cast<std::size_t>(face.nodes[i])];
        on_f =
            on_f && std::ranges::find(f.nodes, quad[static_cast<std::size_t>(i)]) != f.nodes.end();
      }
      if (corners == 3)
        quad[3] = quad[2];
      if (on_f)
        faces.push_back(quad);
    }
  }
}

} // namespace

Mesh convert_cells(const Mesh& hexes, CellType type) {
  TRIFEM_CHECK(hexes.all_hex8(), "converting cells: the mesh has {} cells, expected hex8 only",
               name(hexes.cell_type(hexes.first_non_hex8())));
  if (type == CellType::Hex8)
    return hexes;
  const CellType linear = linear_type(type);
  const std::span<const Edge> edges = mid_edges(type);
  Mesh out;
  for (const Vec3& x : hexes.nodes())
    out.add_node(x);
  MidEdgeNodes mid(out);
  std::vector<std::vector<Index>> children(static_cast<std::size_t>(hexes.num_cells()));
  std::vector<Index> nodes;
  for (Index c = 0; c < hexes.num_cells(); ++c) {
    const Hex8 hex = hexes.cell(c);
    for (const std::vector<int>& piece : pieces(linear)) {
      nodes.clear();
      for (int a : piece)
        nodes.push_back(hex[static_cast<std::size_t>(a)]);
      for (const Edge& e : edges)
        nodes.push_back(
            mid.node(nodes[static_cast<std::size_t>(e[0])], nodes[static_cast<std::size_t>(e[1])]));
      children[static_cast<std::size_t>(c)].push_back(out.add_cell(type, nodes));
    }
  }
  for (auto& [name, set] : node_sets(hexes, mid))
    if (!hexes.has_surface(name)) // (re-created with the surface below)
      out.add_node_set(name, std::move(set));
  for (const auto& [name, surface] : hexes.surfaces()) {
    std::vector<std::array<Index, 4>> faces;
    for (const Facet& f : surface.facets)
      if (f.bounds_cell())
        add_child_faces(out, children[static_cast<std::size_t>(f.cell)], f, faces);
    out.add_surface(name, Surface{out.orient_quads(faces)});
  }
  for (const auto& [name, cells] : hexes.cell_blocks()) {
    std::vector<Index> block;
    for (Index c : cells)
      for (Index child : children[static_cast<std::size_t>(c)])
        block.push_back(child);
    out.add_cell_block(name, std::move(block));
  }
  for (const auto& [name, data] : hexes.cell_data()) {
    CellData split{.components = data.components, .values = {}};
    for (Index c = 0; c < hexes.num_cells(); ++c)
      for (std::size_t i = 0; i < children[static_cast<std::size_t>(c)].size(); ++i)
        for (int k = 0; k < data.components; ++k)
          split.values.push_back(data.value(c, k));
    out.add_cell_data(name, std::move(split));
  }
  return out;
}

} // namespace trifem::mesh
