// SPDX-License-Identifier: MIT
// Reader for Gmsh MSH files (ASCII 4.1 and 2.2) producing a Mesh.
#pragma once

#include "trifem/mesh/mesh.hpp"

#include <filesystem>

namespace trifem::mesh {

/// Reads a Gmsh MSH file (format 4.1 ASCII; also 2.2 ASCII).
///
/// - Volume elements become cells: hexahedron8 (type 5), tetra4 (4), tetra10 (11), prism6 (6,
///   a penta6 cell) and hexahedron20 (17), in Gmsh's node order (mesh/cell_type.hpp). Physical
///   volume groups become named cell blocks. If the file defines no physical groups at all, every
///   hex goes into block "volume"; otherwise hexes in no physical volume go into block "unassigned"
///   (created only if needed).
/// - Quad4 (type 3) elements in physical surface groups become named surfaces, oriented outward
///   against the hex that owns the face (each also registers a node set of the same name). A
///   quad on a face between two hexes is oriented out of the hex whose face has the quad's node
///   order (right-hand rule), else out of the hex with the lower index. Quads in no physical
///   group are ignored. Triangles (triangle3, type 2; triangle6, 9) and quads (quad4, 3; quad8,
///   16) on the faces of tets, wedges and hex20 cells likewise become their facets (of the
///   cell face's type: a tet10's face is a tri6 facet with its mid-edge nodes).
/// - Elements of dimension 0 or 1 in physical point/curve groups become node sets; otherwise
///   they are ignored.
/// - Names come from $PhysicalNames; an unnamed physical group of dimension 0/1/2/3 is called
///   "point_<tag>", "curve_<tag>", "surface_<tag>" or "volume_<tag>".
/// - Nodes are renumbered densely 0..n-1 in file order.
/// - Each $ElementData view becomes cell data named by the view (its first string tag), with
///   the view's number of components; cells the view does not list get NaN. Values on elements
///   that are not cells (e.g. the quads of a physical surface) are ignored. Sections with the
///   same view name (e.g. partitions) are joined; the time value and step are ignored.
///   $NodeData and $ElementNodeData are ignored.
///
/// Throws InputError, with a message starting with "<file>:<line>: ", for a missing, empty,
/// binary or truncated file, an unsupported version, an undefined node tag, any other volume or
/// surface element type (pyramids, hexahedron27, ...), a cell with negative volume,
/// a quad of a physical surface that is not a face of any hex, or, in $ElementData, a malformed
/// header, a wrong number of values on a line, a non-finite value, an element tag not in
/// $Elements, or a second value for one element.
Mesh read_gmsh(const std::filesystem::path& file);

} // namespace trifem::mesh
