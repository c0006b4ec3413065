// SPDX-License-Identifier: MIT
// Whether the cells of a mesh meet face to face. The elements assume a conforming mesh: two
// cells that touch share a whole face, with the same nodes. A node of one cell on the face or
// edge of another that does not have it (a hanging node) leaves the displacement and fluxes
// discontinuous there, the bodies gap or overlap, and no error would say so.
#pragma once

#include "trifem/mesh/mesh.hpp"

#include <optional>
#include <string>

namespace trifem::mesh {

/// Two cells that meet with hanging nodes, and how (the end of a sentence naming both).
struct HangingNodes {
  Index cell = -1;
  Index other = -1;
  std::string how;
};

/// The first pair of cells (in cell order) that share nodes and meet other than face to face:
///  - a quadratic face and a linear face on the same corners (a hex20 beside a hex8, a tet10
///    beside a tet4): the mid-edge nodes of one hang;
///  - two faces on the boundary of the cells, with a node in common, whose outward normals are
///    opposite and which overlap (the centroid of one lies on the other): a quadrilateral face
///    against the triangles of tets, or a face against the smaller faces of a finer mesh.
/// Faces of bodies that share no node (surfaces in contact) are not compared. nullopt if the
/// mesh conforms.
std::optional<HangingNodes> find_hanging_nodes(const Mesh& mesh);

} // namespace trifem::mesh
