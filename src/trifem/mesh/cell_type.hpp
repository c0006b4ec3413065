// SPDX-License-Identifier: MIT
// The cell families of a mesh (hex8, tet4, tet10, penta6 = wedge, hex20) and their boundary
// facets (tri3, tri6, quad4, quad8): node counts, names, edges and faces. Topology only; the
// shape functions and quadrature rules are fe::ReferenceCell's.
//
// Node orders are Gmsh's (so that a Gmsh element's node list is the cell's as it stands):
//   hex8   corners 0-3 counter-clockwise at zeta = -1, 4-7 above them (hex_faces.hpp).
//   hex20  the hex8 corners, then mid-edge nodes 8-19 on the edges of mid_edges(Hex20).
//   tet4   (0,0,0) (1,0,0) (0,1,0) (0,0,1); tet10 adds mid-edge nodes 4-9 (mid_edges(Tet10)).
//   penta6 the triangle (0,1,2) at z = -1, then (3,4,5) above it at z = +1.
//   tri3   counter-clockwise; tri6 adds mid-edge nodes 3-5 on (0,1) (1,2) (2,0).
//   quad4  counter-clockwise; quad8 adds mid-edge nodes 4-7 on (0,1) (1,2) (2,3) (3,0).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace trifem::mesh {

enum class CellType : std::uint8_t { Hex8, Tet4, Tet10, Penta6, Hex20 };
enum class FacetType : std::uint8_t { Tri3, Tri6, Quad4, Quad8 };

inline constexpr int kMaxCellNodes = 20;
inline constexpr int kMaxFacetNodes = 8;

/// Two local node numbers.
using Edge = std::array<int, 2>;

int num_nodes(CellType type);
int num_nodes(FacetType type);
/// The number of corner (vertex) nodes; they come first.
int num_corners(CellType type);
/// The type of a cell's corners: tet4 for tet10, hex8 for hex20, else the type itself.
CellType linear_type(CellType type);
int num_corners(FacetType type);
/// Lower-case name as in input files: "hex8", "tet4", "tet10", "penta6", "hex20".
std::string_view name(CellType type);
/// "tri3", "tri6", "quad4", "quad8".
std::string_view name(FacetType type);

/// The edges between corners (12 of a hex, 6 of a tet, 9 of a wedge).
std::span<const Edge> corner_edges(CellType type);
/// Of a quadratic cell or facet: mid-edge node num_corners + e lies on edge e (empty for
/// linear ones).
std::span<const Edge> mid_edges(CellType type);
std::span<const Edge> mid_edges(FacetType type);

/// A face of a cell: its facet type and the cell's local node numbers in the facet's node
/// order, corners counter-clockwise seen from outside the cell, then the mid-edge nodes.
struct CellFace {
  FacetType type;
  std::vector<int> nodes;
};

/// The faces of a cell: hex zeta = -1, zeta = +1, eta = -1, xi = +1, eta = +1, xi = -1 (the
/// faces of kHexFaces); tet opposite node 3, 2, 1, 0; penta6 the triangles z = -1 and z = +1,
/// then the quadrilaterals y = 0, x + y = 1, x = 0.
const std::vector<CellFace>& cell_faces(CellType type);

} // namespace trifem::mesh
