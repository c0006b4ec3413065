// SPDX-License-Identifier: MIT
#include "trifem/fe/reference_element.hpp"

#include "trifem/core/error.hpp"
#include "trifem/fe/hex8.hpp"
#include "trifem/mesh/hex_faces.hpp"

#include <array>
#include <numeric>
#include <span>
#include <type_traits>

namespace trifem::fe {
namespace {

using mesh::Edge;

// VTK's mid-edge node orders of VTK_QUADRATIC_TETRA and VTK_QUADRATIC_HEXAHEDRON.
constexpr Edge kVtkTet10Edges[] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
constexpr Edge kVtkHex20Edges[] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                   {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};

constexpr std::array<std::array<Real, 3>, 4> kTetCorners = {
    {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
constexpr std::array<std::array<Real, 3>, 6> kWedgeCorners = {
    {{0, 0, -1}, {1, 0, -1}, {0, 1, -1}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}}};
constexpr std::array<std::array<Real, 2>, 3> kTriangleCorners = {{{0, 0}, {1, 0}, {0, 1}}};
constexpr std::array<std::array<Real, 2>, 4> kSquareCorners = {
    {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}};

template <int D>
using Point = Eigen::Matrix<Real, D, 1>;
template <int D>
using Values = std::conditional_t<D == 3, ShapeValues, FacetShapeValues>;
template <int D>
using Grads = std::conditional_t<D == 3, ShapeGrads, FacetShapeGrads>;
template <int D>
using Coords = std::conditional_t<D == 3, CellNodeCoords, FacetNodeCoords>;

[[noreturn]] void unknown_type(int type) {
  detail::throw_logic_error(fmt::format("unknown element type {}", type), __FILE__, __LINE__);
}

// ---- shape functions ---------------------------------------------------------------------

/// Barycentric coordinates of the simplex: L_0 = 1 - sum_i xi_i, L_i = xi_(i-1).
template <int D>
Eigen::Matrix<Real, D + 1, 1> barycentric(const Point<D>& xi) {
  Eigen::Matrix<Real, D + 1, 1> L;
  L[0] = 1.0 - xi.sum();
  L.template tail<D>() = xi;
  return L;
}

/// Row i = dL_i/dxi.
template <int D>
Eigen::Matrix<Real, D + 1, D> barycentric_grad() {
  Eigen::Matrix<Real, D + 1, D> dL;
  dL.row(0).setConstant(-1.0);
  dL.template bottomRows<D>().setIdentity();
  return dL;
}

/// Quadratic simplex: L_i (2 L_i - 1) at the corners, 4 L_i L_j at the midpoint of edge (i, j).
template <int D>
Values<D> quadratic_simplex_shape(const Point<D>& xi, std::span<const Edge> edges) {
  const auto L = barycentric<D>(xi);
  Values<D> N(D + 1 + static_cast<Index>(edges.size()));
  for (int i = 0; i <= D; ++i)
    N[i] = L[i] * (2.0 * L[i] - 1.0);
  for (std::size_t e = 0; e < edges.size(); ++e)
    N[D + 1 + static_cast<Index>(e)] = 4.0 * L[edges[e][0]] * L[edges[e][1]];
  return N;
}

template <int D>
Grads<D> quadratic_simplex_grad(const Point<D>& xi, std::span<const Edge> edges) {
  const auto L = barycentric<D>(xi);
  const auto dL = barycentric_grad<D>();
  Grads<D> G(D + 1 + static_cast<Index>(edges.size()), D);
  for (int i = 0; i <= D; ++i)
    G.row(i) = (4.0 * L[i] - 1.0) * dL.row(i);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const int i = edges[e][0], j = edges[e][1];
    G.row(D + 1 + static_cast<Index>(e)) = 4.0 * (L[j] * dL.row(i) + L[i] * dL.row(j));
  }
  return G;
}

/// prod_j f_j over j other than `skip1` and `skip2`.
template <int D>
Real product_except(const Point<D>& f, int skip1, int skip2 = -1) {
  Real p = 1.0;
  for (int j = 0; j < D; ++j)
    if (j != skip1 && j != skip2)
      p *= f[j];
  return p;
}

/// The coordinate in which the mid-edge node r of [-1,1]^D is 0.
template <int D>
int zero_coordinate(const Point<D>& r) {
  int k = 0;
  while (k < D - 1 && r[k] != 0.0)
    ++k;
  return k;
}

/// Serendipity functions on [-1,1]^D with the 2^D corners first: at corner r,
/// prod_j (1 + xi_j r_j) (xi . r - (D - 1)) / 2^D; at mid-edge node r with r_k = 0,
/// (1 - xi_k^2) prod_(j != k) (1 + xi_j r_j) / 2^(D - 1).
template <int D>
Values<D> serendipity_shape(const Point<D>& xi, const Coords<D>& nodes) {
  Values<D> N(nodes.rows());
  for (Index a = 0; a < nodes.rows(); ++a) {
    const Point<D> r = nodes.row(a).transpose();
    const Point<D> f = Point<D>::Ones() + xi.cwiseProduct(r);
    if (a < (1 << D)) {
      N[a] = f.prod() * (xi.dot(r) - (D - 1)) / (1 << D);
    } else {
      const int k = zero_coordinate<D>(r);
      N[a] = (1.0 - xi[k] * xi[k]) * product_except<D>(f, k) / (1 << (D - 1));
    }
  }
  return N;
}

template <int D>
Grads<D> serendipity_grad(const Point<D>& xi, const Coords<D>& nodes) {
  Grads<D> G(nodes.rows(), D);
  for (Index a = 0; a < nodes.rows(); ++a) {
    const Point<D> r = nodes.row(a).transpose();
    const Point<D> f = Point<D>::Ones() + xi.cwiseProduct(r);
    if (a < (1 << D)) {
      const Real s = xi.dot(r) - (D - 1);
      for (int m = 0; m < D; ++m)
        G(a, m) = r[m] * (product_except<D>(f, m) * s + f.prod()) / (1 << D);
      continue;
    }
    const int k = zero_coordinate<D>(r);
    for (int m = 0; m < D; ++m)
      G(a, m) = (m == k ? -2.0 * xi[k] * product_except<D>(f, k)
                        : (1.0 - xi[k] * xi[k]) * r[m] * product_except<D>(f, k, m)) /
                (1 << (D - 1));
  }
  return G;
}

/// Triangle x [-1, 1]: L_i(x, y) (1 -+ z)/2, bottom triangle first.
ShapeValues wedge6_shape(const Vec3& xi) {
  const auto L = barycentric<2>(xi.head<2>());
  const Real h[2] = {0.5 * (1.0 - xi[2]), 0.5 * (1.0 + xi[2])};
  ShapeValues N(6);
  for (int k = 0; k < 2; ++k)
    for (int i = 0; i < 3; ++i)
      N[3 * k + i] = L[i] * h[k];
  return N;
}

ShapeGrads wedge6_grad(const Vec3& xi) {
  const auto L = barycentric<2>(xi.head<2>());
  const auto dL = barycentric_grad<2>();
  const Real h[2] = {0.5 * (1.0 - xi[2]), 0.5 * (1.0 + xi[2])};
  const Real dh[2] = {-0.5, 0.5};
  ShapeGrads G(6, 3);
  for (int k = 0; k < 2; ++k)
    for (int i = 0; i < 3; ++i)
      G.row(3 * k + i) << dL(i, 0) * h[k], dL(i, 1) * h[k], L[i] * dh[k];
  return G;
}

// ---- node coordinates, facets and VTK orders ---------------------------------------------

template <class Matrix, std::size_t N, std::size_t D>
Matrix corner_coords(const std::array<std::array<Real, D>, N>& corners) {
  Matrix X(static_cast<Index>(N), static_cast<Index>(D));
  for (std::size_t a = 0; a < N; ++a)
    for (std::size_t d = 0; d < D; ++d)
      X(static_cast<Index>(a), static_cast<Index>(d)) = corners[a][d];
  return X;
}

/// The corners followed by the midpoints of the edges.
template <class Matrix>
Matrix with_mid_edge_nodes(const Matrix& corners, std::span<const Edge> edges) {
  const Index n = corners.rows();
  Matrix X(n + static_cast<Index>(edges.size()), corners.cols());
  X.topRows(n) = corners;
  for (std::size_t e = 0; e < edges.size(); ++e)
    X.row(n + static_cast<Index>(e)) = 0.5 * (corners.row(edges[e][0]) + corners.row(edges[e][1]));
  return X;
}

/// The local number of the mid-edge node between corners a and b.
int mid_edge_node(std::span<const Edge> edges, int num_corners, int a, int b) {
  for (std::size_t e = 0; e < edges.size(); ++e)
    if ((edges[e][0] == a && edges[e][1] == b) || (edges[e][0] == b && edges[e][1] == a))
      return num_corners + static_cast<int>(e);
  detail::throw_logic_error(fmt::format("no edge ({}, {})", a, b), __FILE__, __LINE__);
}

std::vector<int> identity_order(int n) {
  std::vector<int> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  return order;
}

/// The local node of each VTK node: corners in the same order, mid-edge nodes by their edges.
std::vector<int> vtk_order_by_edges(int num_corners, std::span<const Edge> edges,
                                    std::span<const Edge> vtk_edges) {
  std::vector<int> order = identity_order(num_corners);
  for (const Edge& edge : vtk_edges)
    order.push_back(mid_edge_node(edges, num_corners, edge[0], edge[1]));
  return order;
}

struct CellDefinition {
  int order;
  CellNodeCoords nodes;
  CellRule rule;
  Real volume;
  int vtk_type;
  std::vector<int> vtk_order;
};

CellDefinition hex8_definition() {
  return {.order = 1,
          .nodes = corner_coords<CellNodeCoords>(mesh::kHexNodeCoords),
          .rule = hex_gauss_rule(2),
          .volume = 8.0,
          .vtk_type = 12,
          .vtk_order = identity_order(8)};
}

CellDefinition hex20_definition() {
  CellDefinition d = hex8_definition();
  return {.order = 2,
          .nodes = with_mid_edge_nodes(d.nodes, mesh::mid_edges(CellType::Hex20)),
          .rule = hex_gauss_rule(3),
          .volume = 8.0,
          .vtk_type = 25,
          .vtk_order = vtk_order_by_edges(8, mesh::mid_edges(CellType::Hex20), kVtkHex20Edges)};
}

CellDefinition tet4_definition() {
  return {.order = 1,
          .nodes = corner_coords<CellNodeCoords>(kTetCorners),
          .rule = tet_rule_degree2(),
          .volume = 1.0 / 6.0,
          .vtk_type = 10,
          .vtk_order = identity_order(4)};
}

CellDefinition tet10_definition() {
  CellDefinition d = tet4_definition();
  return {.order = 2,
          .nodes = with_mid_edge_nodes(d.nodes, mesh::mid_edges(CellType::Tet10)),
          .rule = tet_rule_degree5(),
          .volume = 1.0 / 6.0,
          .vtk_type = 24,
          .vtk_order = vtk_order_by_edges(4, mesh::mid_edges(CellType::Tet10), kVtkTet10Edges)};
}

CellDefinition penta6_definition() {
  return {.order = 1,
          .nodes = corner_coords<CellNodeCoords>(kWedgeCorners),
          .rule = wedge_rule_degree2(),
          .volume = 1.0,
          .vtk_type = 13,
          .vtk_order = {0, 2, 1, 3, 5, 4}}; // VTK's triangle (0,1,2) faces out of the cell
}

CellDefinition cell_definition(CellType type) {
  switch (type) {
  case CellType::Hex8:
    return hex8_definition();
  case CellType::Tet4:
    return tet4_definition();
  case CellType::Tet10:
    return tet10_definition();
  case CellType::Penta6:
    return penta6_definition();
  case CellType::Hex20:
    return hex20_definition();
  }
  unknown_type(static_cast<int>(type));
}

struct FacetDefinition {
  int order;
  FacetNodeCoords nodes;
  FacetRule rule;
  Real area;
};

FacetDefinition facet_definition(FacetType type) {
  const auto triangle = corner_coords<FacetNodeCoords>(kTriangleCorners);
  const auto square = corner_coords<FacetNodeCoords>(kSquareCorners);
  switch (type) {
  case FacetType::Tri3:
    return {1, triangle, triangle_rule_degree2(), 0.5};
  case FacetType::Tri6:
    return {2, with_mid_edge_nodes(triangle, mesh::mid_edges(FacetType::Tri6)),
            triangle_rule_degree4(), 0.5};
  case FacetType::Quad4:
    return {1, square, quad_gauss_rule(2), 4.0};
  case FacetType::Quad8:
    return {2, with_mid_edge_nodes(square, mesh::mid_edges(FacetType::Quad8)), quad_gauss_rule(3),
            4.0};
  }
  unknown_type(static_cast<int>(type));
}

} // namespace

ReferenceCell::ReferenceCell(CellType type) : type_(type) {
  CellDefinition d = cell_definition(type);
  order_ = d.order;
  nodes_ = d.nodes;
  rule_ = std::move(d.rule);
  volume_ = d.volume;
  vtk_type_ = d.vtk_type;
  vtk_order_ = std::move(d.vtk_order);
  for (const CellQuadraturePoint& p : rule_.points)
    rule_shapes_.push_back(shape(p.xi));
}

ShapeValues ReferenceCell::shape(const Vec3& xi) const {
  switch (type_) {
  case CellType::Hex8:
    return hex8_shape(xi);
  case CellType::Tet4:
    return barycentric<3>(xi);
  case CellType::Tet10:
    return quadratic_simplex_shape<3>(xi, mesh::mid_edges(CellType::Tet10));
  case CellType::Penta6:
    return wedge6_shape(xi);
  case CellType::Hex20:
    return serendipity_shape<3>(xi, nodes_);
  }
  unknown_type(static_cast<int>(type_));
}

ShapeGrads ReferenceCell::shape_grad(const Vec3& xi) const {
  switch (type_) {
  case CellType::Hex8:
    return hex8_shape_grad(xi);
  case CellType::Tet4:
    return barycentric_grad<3>();
  case CellType::Tet10:
    return quadratic_simplex_grad<3>(xi, mesh::mid_edges(CellType::Tet10));
  case CellType::Penta6:
    return wedge6_grad(xi);
  case CellType::Hex20:
    return serendipity_grad<3>(xi, nodes_);
  }
  unknown_type(static_cast<int>(type_));
}

ReferenceFacet::ReferenceFacet(FacetType type) : type_(type) {
  FacetDefinition d = facet_definition(type);
  order_ = d.order;
  nodes_ = d.nodes;
  rule_ = std::move(d.rule);
  area_ = d.area;
}

FacetShapeValues ReferenceFacet::shape(const Vec2& s) const {
  switch (type_) {
  case FacetType::Tri3:
    return barycentric<2>(s);
  case FacetType::Tri6:
    return quadratic_simplex_shape<2>(s, mesh::mid_edges(FacetType::Tri6));
  case FacetType::Quad4:
    return quad4_shape(s);
  case FacetType::Quad8:
    return serendipity_shape<2>(s, nodes_);
  }
  unknown_type(static_cast<int>(type_));
}

FacetShapeGrads ReferenceFacet::shape_grad(const Vec2& s) const {
  switch (type_) {
  case FacetType::Tri3:
    return barycentric_grad<2>();
  case FacetType::Tri6:
    return quadratic_simplex_grad<2>(s, mesh::mid_edges(FacetType::Tri6));
  case FacetType::Quad4:
    return quad4_shape_grad(s);
  case FacetType::Quad8:
    return serendipity_grad<2>(s, nodes_);
  }
  unknown_type(static_cast<int>(type_));
}

namespace {

/// Second derivatives of the quadratic triangle: 4 dL_i (x) dL_i at the corners and
/// 4 (dL_i (x) dL_j + dL_j (x) dL_i) at the midpoint of edge (i, j).
FacetShapeHessians tri6_hessian() {
  const auto dL = barycentric_grad<2>();
  const auto row = [&](int i, int j) {
    return Eigen::RowVector3d(2 * dL(i, 0) * dL(j, 0), 2 * dL(i, 1) * dL(j, 1),
                              dL(i, 0) * dL(j, 1) + dL(j, 0) * dL(i, 1));
  };
  FacetShapeHessians H(6, 3);
  for (int i = 0; i < 3; ++i)
    H.row(i) = 2.0 * row(i, i);
  const auto edges = mesh::mid_edges(FacetType::Tri6);
  for (std::size_t e = 0; e < edges.size(); ++e)
    H.row(3 + static_cast<Index>(e)) = 4.0 * row(edges[e][0], edges[e][1]);
  return H;
}

/// Second derivatives of the serendipity square (corners first), f_m = 1 + s_m r_m: at corner
/// r, (f_2/2, f_1/2, r_1 r_2 (s.r - 1 + f_1 + f_2)/4); at the mid-edge node with r_k = 0,
/// N = (1 - s_k^2) f_o/2: N_,kk = -f_o, N_,oo = 0, N_,ko = -s_k r_o.
FacetShapeHessians quad8_hessian(const Vec2& s, const FacetNodeCoords& nodes) {
  FacetShapeHessians H(8, 3);
  for (Index a = 0; a < 8; ++a) {
    const Vec2 r = nodes.row(a).transpose();
    const Vec2 f = Vec2::Ones() + s.cwiseProduct(r);
    if (a < 4) {
      H.row(a) << 0.5 * f[1], 0.5 * f[0], 0.25 * r[0] * r[1] * (s.dot(r) - 1 + f[0] + f[1]);
      continue;
    }
    const int k = r[0] == 0.0 ? 0 : 1, o = 1 - k;
    H.row(a).setZero();
    H(a, k) = -f[o];
    H(a, 2) = -s[k] * r[o];
  }
  return H;
}

} // namespace

FacetShapeHessians ReferenceFacet::shape_hessian(const Vec2& s) const {
  switch (type_) {
  case FacetType::Tri3:
    return FacetShapeHessians::Zero(3, 3);
  case FacetType::Tri6:
    return tri6_hessian();
  case FacetType::Quad4: {
    FacetShapeHessians H = FacetShapeHessians::Zero(4, 3);
    for (Index a = 0; a < 4; ++a)
      H(a, 2) = 0.25 * nodes_(a, 0) * nodes_(a, 1);
    return H;
  }
  case FacetType::Quad8:
    return quad8_hessian(s, nodes_);
  }
  unknown_type(static_cast<int>(type_));
}

const ReferenceCell& reference_cell(CellType type) {
  // in the order of the enumerators
  static const std::array<ReferenceCell, 5> cells = {
      ReferenceCell(CellType::Hex8), ReferenceCell(CellType::Tet4), ReferenceCell(CellType::Tet10),
      ReferenceCell(CellType::Penta6), ReferenceCell(CellType::Hex20)};
  const auto i = static_cast<std::size_t>(type);
  TRIFEM_VERIFY(i < cells.size(), "unknown cell type {}", i);
  return cells[i];
}

const ReferenceFacet& reference_facet(FacetType type) {
  static const std::array<ReferenceFacet, 4> facets = {
      ReferenceFacet(FacetType::Tri3), ReferenceFacet(FacetType::Tri6),
      ReferenceFacet(FacetType::Quad4), ReferenceFacet(FacetType::Quad8)};
  const auto i = static_cast<std::size_t>(type);
  TRIFEM_VERIFY(i < facets.size(), "unknown facet type {}", i);
  return facets[i];
}

} // namespace trifem::fe
