// SPDX-License-Identifier: MIT
#include "trifem/mesh/cell_type.hpp"

#include "trifem/core/error.hpp"
#include "trifem/mesh/hex_faces.hpp"

namespace trifem::mesh {
namespace {

constexpr Edge kHexEdges[] = {{0, 1}, {0, 3}, {0, 4}, {1, 2}, {1, 5}, {2, 3},
                              {2, 6}, {3, 7}, {4, 5}, {4, 7}, {5, 6}, {6, 7}};
constexpr Edge kTetEdges[] = {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {2, 3}, {1, 3}};
constexpr Edge kWedgeEdges[] = {{0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5},
                                {5, 3}, {0, 3}, {1, 4}, {2, 5}};
constexpr Edge kTriangleEdges[] = {{0, 1}, {1, 2}, {2, 0}};
constexpr Edge kQuadEdges[] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};

// Faces of the linear cells, corners counter-clockwise seen from outside (hex: kHexFaces).
constexpr std::array<std::array<int, 3>, 4> kTetFaces = {
    {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}};
constexpr std::array<std::array<int, 3>, 2> kWedgeTriangles = {{{0, 2, 1}, {3, 4, 5}}};
constexpr std::array<std::array<int, 4>, 3> kWedgeQuads = {
    {{0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}}};

[[noreturn]] void unknown_type(int type) {
  detail::throw_logic_error(fmt::format("unknown element type {}", type), __FILE__, __LINE__);
}

template <std::size_t N, std::size_t M>
void add_faces(std::vector<CellFace>& faces, const std::array<std::array<int, N>, M>& corners) {
  static_assert(N == 3 || N == 4);
  for (const auto& face : corners)
    faces.push_back({N == 3 ? FacetType::Tri3 : FacetType::Quad4, {face.begin(), face.end()}});
}

/// The local number of the mid-edge node between corners a and b.
int mid_edge_node(std::span<const Edge> edges, int num_corners, int a, int b) {
  for (std::size_t e = 0; e < edges.size(); ++e)
    if ((edges[e][0] == a && edges[e][1] == b) || (edges[e][0] == b && edges[e][1] == a))
      return num_corners + static_cast<int>(e);
  detail::throw_logic_error(fmt::format("no edge ({}, {})", a, b), __FILE__, __LINE__);
}

/// The faces of a quadratic cell from those of its corners: the mid-edge nodes of each face
/// follow its corners, edge (0,1) first.
std::vector<CellFace> quadratic_faces(std::vector<CellFace> faces, std::span<const Edge> edges,
                                      int num_corners) {
  for (CellFace& face : faces) {
    face.type = face.type == FacetType::Tri3 ? FacetType::Tri6 : FacetType::Quad8;
    const std::vector<int> corners = face.nodes;
    for (std::size_t i = 0; i < corners.size(); ++i)
      face.nodes.push_back(
          mid_edge_node(edges, num_corners, corners[i], corners[(i + 1) % corners.size()]));
  }
  return faces;
}

std::vector<CellFace> linear_faces(CellType type) {
  std::vector<CellFace> faces;
  switch (type) {
  case CellType::Hex8:
  case CellType::Hex20:
    add_faces(faces, kHexFaces);
    break;
  case CellType::Tet4:
  case CellType::Tet10:
    add_faces(faces, kTetFaces);
    break;
  case CellType::Penta6:
    add_faces(faces, kWedgeTriangles);
    add_faces(faces, kWedgeQuads);
    break;
  }
  return faces;
}

std::vector<CellFace> faces_of(CellType type) {
  std::vector<CellFace> faces = linear_faces(type);
  const auto edges = mid_edges(type);
  return edges.empty() ? faces : quadratic_faces(std::move(faces), edges, num_corners(type));
}

} // namespace

int num_nodes(CellType type) {
  switch (type) {
  case CellType::Hex8:
    return 8;
  case CellType::Tet4:
    return 4;
  case CellType::Tet10:
    return 10;
  case CellType::Penta6:
    return 6;
  case CellType::Hex20:
    return 20;
  }
  unknown_type(static_cast<int>(type));
}

int num_nodes(FacetType type) {
  switch (type) {
  case FacetType::Tri3:
    return 3;
  case FacetType::Tri6:
    return 6;
  case FacetType::Quad4:
    return 4;
  case FacetType::Quad8:
    return 8;
  }
  unknown_type(static_cast<int>(type));
}

CellType linear_type(CellType type) {
  switch (type) {
  case CellType::Tet10:
    return CellType::Tet4;
  case CellType::Hex20:
    return CellType::Hex8;
  default:
    return type;
  }
}

int num_corners(CellType type) {
  switch (type) {
  case CellType::Hex8:
  case CellType::Hex20:
    return 8;
  case CellType::Tet4:
  case CellType::Tet10:
    return 4;
  case CellType::Penta6:
    return 6;
  }
  unknown_type(static_cast<int>(type));
}

int num_corners(FacetType type) {
  return type == FacetType::Tri3 || type == FacetType::Tri6 ? 3 : 4;
}

std::string_view name(CellType type) {
  switch (type) {
  case CellType::Hex8:
    return "hex8";
  case CellType::Tet4:
    return "tet4";
  case CellType::Tet10:
    return "tet10";
  case CellType::Penta6:
    return "penta6";
  case CellType::Hex20:
    return "hex20";
  }
  unknown_type(static_cast<int>(type));
}

std::string_view name(FacetType type) {
  switch (type) {
  case FacetType::Tri3:
    return "tri3";
  case FacetType::Tri6:
    return "tri6";
  case FacetType::Quad4:
    return "quad4";
  case FacetType::Quad8:
    return "quad8";
  }
  unknown_type(static_cast<int>(type));
}

std::span<const Edge> corner_edges(CellType type) {
  switch (type) {
  case CellType::Hex8:
  case CellType::Hex20:
    return kHexEdges;
  case CellType::Tet4:
  case CellType::Tet10:
    return kTetEdges;
  case CellType::Penta6:
    return kWedgeEdges;
  }
  unknown_type(static_cast<int>(type));
}

std::span<const Edge> mid_edges(CellType type) {
  switch (type) {
  case CellType::Tet10:
    return kTetEdges; // Gmsh's tet10 mid-edge order is the order of the tet edges
  case CellType::Hex20:
    return kHexEdges; // likewise for hex20
  default:
    return {};
  }
}

std::span<const Edge> mid_edges(FacetType type) {
  switch (type) {
  case FacetType::Tri6:
    return kTriangleEdges;
  case FacetType::Quad8:
    return kQuadEdges;
  default:
    return {};
  }
}

const std::vector<CellFace>& cell_faces(CellType type) {
  // in the order of the enumerators
  static const std::array<std::vector<CellFace>, 5> faces = {
      faces_of(CellType::Hex8), faces_of(CellType::Tet4), faces_of(CellType::Tet10),
      faces_of(CellType::Penta6), faces_of(CellType::Hex20)};
  const auto i = static_cast<std::size_t>(type);
  TRIFEM_VERIFY(i < faces.size(), "unknown cell type {}", i);
  return faces[i];
}

} // namespace trifem::mesh
