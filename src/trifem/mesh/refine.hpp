// SPDX-License-Identifier: MIT
// Uniform refinement of a hex8 mesh (each cell into eight), for mesh-convergence studies.
#pragma once

#include "trifem/mesh/mesh.hpp"

#include <functional>

namespace trifem::mesh {

/// The mesh with every hex8 split into eight by its edge midpoints, face centres and centre,
/// placed by the cell's trilinear map: the refined mesh covers exactly the same region, and a
/// node shared by neighbouring cells stays shared. The nodes of `mesh` keep their indices; cell
/// c becomes cells 8c, ..., 8c + 7. Named sets are carried over:
/// - cell blocks and cell data: a child inherits its parent's membership and values;
/// - surfaces: each facet becomes the four facets of the children on its face;
/// - other node sets: a new node belongs to a set when every corner it is built from (the two
///   of its edge, the four of its face, the eight of its cell) belongs to it, so a set of the
///   nodes of a face, an edge or a block gains the new nodes on it.
/// Throws InputError if the refined mesh would have more nodes or cells than an Index holds.
Mesh refine_uniformly(const Mesh& mesh);

/// `mesh` refined `levels` times (levels >= 0; each level multiplies the cells by eight).
Mesh refine_uniformly(const Mesh& mesh, int levels);

// Building blocks shared with the refinement of the other families (fe::refine_uniformly),
// where coarse cell c has the children 8c, ..., 8c + 7 as here.

/// Adds the cell blocks and cell data of `coarse` to `fine`, each cell's going to its children.
void add_refined_cell_sets(const Mesh& coarse, Mesh& fine);

/// The node set `set` of the coarse mesh in the fine one: its own nodes, and each new node n
/// (coarse_nodes <= n < fine_nodes) all of whose `parents(n)` (the coarse nodes it is built
/// from) belong to it.
std::vector<Index> refined_node_set(const std::vector<Index>& set, Index coarse_nodes,
                                    Index fine_nodes,
                                    const std::function<std::vector<Index>(Index)>& parents);

/// InputError unless every facet of the surface `name` bounds a cell (a surface mesh cannot be
/// refined with the cells).
void check_refinable_surface(const std::string& name, const Surface& surface);

} // namespace trifem::mesh
