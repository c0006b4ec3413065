// SPDX-License-Identifier: MIT
// Meshes of several boxes of any cell family put side by side, their coincident nodes merged
// (one body whose cells conform or, on purpose, do not) or kept apart (bodies that touch).
#pragma once

#include "trifem/mesh/box.hpp"
#include "trifem/mesh/mesh.hpp"

#include <array>
#include <cmath>
#include <map>
#include <tuple>
#include <vector>

namespace trifem::test {

/// Meshes assembled from boxes, nodes at the same place merged unless asked not to.
class BoxAssembly {
public:
  /// Adds the cells of a box of `type` cells at `origin` with `size` and `divisions`.
  void add_box(mesh::CellType type, const Vec3& origin, const Vec3& size,
               std::array<int, 3> divisions, bool merge = true) {
    mesh::BoxSpec spec;
    spec.origin = origin;
    spec.size = size;
    spec.divisions = divisions;
    spec.cell = type;
    const mesh::Mesh box = mesh::make_box(spec);
    std::vector<Index> node(static_cast<std::size_t>(box.num_nodes()));
    for (Index n = 0; n < box.num_nodes(); ++n)
      node[static_cast<std::size_t>(n)] =
          merge ? node_at(box.node(n)) : mesh_.add_node(box.node(n));
    for (Index c = 0; c < box.num_cells(); ++c) {
      std::vector<Index> cell;
      for (Index n : box.cell_nodes(c))
        cell.push_back(node[static_cast<std::size_t>(n)]);
      mesh_.add_cell(box.cell_type(c), cell);
    }
  }
  const mesh::Mesh& mesh() const { return mesh_; }

private:
  Index node_at(const Vec3& x) {
    const auto key = std::make_tuple(std::lround(x.x() * 1e6), std::lround(x.y() * 1e6),
                                     std::lround(x.z() * 1e6));
    if (const auto it = nodes_.find(key); it != nodes_.end())
      return it->second;
    return nodes_[key] = mesh_.add_node(x);
  }
  mesh::Mesh mesh_;
  std::map<std::tuple<long, long, long>, Index> nodes_;
};

} // namespace trifem::test
