// SPDX-License-Identifier: MIT
// A mesh with its nodes moved (graded or curved test geometries built from a box).
#pragma once

#include "trifem/mesh/mesh.hpp"

namespace trifem::test {

/// A copy of `mesh` with every node moved to map(X) (topology and names kept).
template <class Map>
mesh::Mesh map_nodes(const mesh::Mesh& mesh, Map&& map) {
  mesh::Mesh out;
  for (Index n = 0; n < mesh.num_nodes(); ++n)
    out.add_node(map(mesh.node(n)));
  for (Index c = 0; c < mesh.num_cells(); ++c)
    out.add_cell(mesh.cell_type(c), mesh.cell_nodes(c));
  for (const auto& [name, surface] : mesh.surfaces())
    out.add_surface(name, surface);
  for (const auto& [name, nodes] : mesh.node_sets())
    if (!out.has_node_set(name))
      out.add_node_set(name, nodes);
  for (const auto& [name, cells] : mesh.cell_blocks())
    out.add_cell_block(name, cells);
  return out;
}

} // namespace trifem::test
