// SPDX-License-Identifier: MIT
// Meshes of any cell family from a structured hex8 mesh: each hex split into tets or wedges,
// and mid-edge nodes added for the quadratic families.
#pragma once

#include "trifem/mesh/mesh.hpp"

namespace trifem::mesh {

/// A mesh of `type` cells covering the cells of `hexes` (hex8 cells whose local axes point the
/// same way in every cell, as those of a structured box, so that the splits conform):
///   tet4, tet10  each hex into the six tets of Kuhn's split around its diagonal 0-6;
///   penta6       each hex into two wedges, the diagonal 0-2 of its bottom face extruded;
///   hex8, hex20  the hex itself;
/// tet10 and hex20 with a node at the midpoint of every edge. The cells of a hex follow one
/// another and take its cell blocks and cell data; node sets are kept, and a mid-edge node joins
/// every node set holding both ends of its edge (which, on a box, puts the nodes of a face's
/// edges on the face). A surface's facets on hex faces become the faces of the cells on them
/// (tri3 or tri6 facets of tets, those of wedges on its bottom and top faces, quad8 facets of
/// hex20), oriented as they were. InputError if `hexes` has cells other than hex8.
Mesh convert_cells(const Mesh& hexes, CellType type);

} // namespace trifem::mesh
