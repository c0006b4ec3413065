// SPDX-License-Identifier: MIT
// Reference elements of the cell families (hex8, tet4, tet10, penta6 = wedge, hex20) and of
// their facets (tri3, tri6, quad4, quad8): node coordinates, shape functions and their
// gradients, default quadrature rules, the facets of each cell and the VTK cell types.
//
// Reference domains and node orders (Gmsh's, so that a Gmsh element's node list is the cell's
// node list as it stands):
//   hex8   [-1,1]^3, corners 0-3 counter-clockwise at zeta = -1 from (-1,-1,-1), 4-7 above
//          them at zeta = +1 (the order of hex8.hpp and mesh/hex_faces.hpp).
//   hex20  the hex8 corners, then the 20-node serendipity mid-edge nodes 8-19 on the edges
//          (0,1) (0,3) (0,4) (1,2) (1,5) (2,3) (2,6) (3,7) (4,5) (4,7) (5,6) (6,7).
//   tet4   (0,0,0) (1,0,0) (0,1,0) (0,0,1).
//   tet10  the tet4 corners, then mid-edge nodes 4-9 on the edges (0,1) (1,2) (0,2) (0,3)
//          (2,3) (1,3).
//   penta6 (0,0,-1) (1,0,-1) (0,1,-1) (0,0,1) (1,0,1) (0,1,1): triangle x [-1,1].
//   tri3   (0,0) (1,0) (0,1); tri6 adds mid-edge nodes 3-5 on (0,1) (1,2) (2,0).
//   quad4  [-1,1]^2 counter-clockwise from (-1,-1) (as quad4_shape); quad8 adds mid-edge
//          nodes 4-7 on (0,1) (1,2) (2,3) (3,0).
//
// How the orders were verified: gmsh 4.8.4 meshed three small boxes, written as msh 2.2
// (gmsh -3 [-order 2] box.geo -format msh22): a box of second-order tetrahedra (1301 tet10 and
// 600 tri6 on its boundary), a sheared box with a trapezoidal base of transfinite hexahedra
// with Mesh.SecondOrderIncomplete = 1 (8 hex20, 24 quad8) and an extruded box of 24 prisms. A
// scratch script (not kept) read every element and checked that each node lies at the image,
// under the map from the element's corners, of the reference node given above (each mid-edge
// node at the midpoint of the two corners named here, within 2e-12 of the cell size; the same
// check fails for VTK's tet10 and hex20 orders), that det(dx/dxi) > 0 at the centroid of every
// tet, hex and prism, and that prism corners 3-5 are corners 0-2 moved by the extrusion step.
//
// VTK orders: hex8 and tet4 are VTK's. VTK's tet10 swaps the mid-edge nodes of (2,3) and
// (1,3); its hex20 numbers the mid-edge nodes bottom ring, top ring, then vertical edges; its
// wedge has the normal of the triangle (0,1,2) pointing out of the cell, Gmsh's into it (VTK's
// documentation of vtkWedge), so VTK's corners are 0 2 1 3 5 4 of the penta6. vtk_order()
// gives these permutations.
#pragma once

#include "trifem/fe/simplex_quadrature.hpp"
#include "trifem/mesh/cell_type.hpp"

#include <cstdint>
#include <vector>

namespace trifem::fe {

using mesh::CellType;
using mesh::FacetType;
using mesh::kMaxCellNodes;
using mesh::kMaxFacetNodes;

// Fixed-capacity matrices: no heap allocation per evaluation.
using ShapeValues = Eigen::Matrix<Real, Eigen::Dynamic, 1, 0, kMaxCellNodes, 1>;
/// Row a = dN_a/dxi.
using ShapeGrads = Eigen::Matrix<Real, Eigen::Dynamic, 3, 0, kMaxCellNodes, 3>;
/// Row a = coordinates of node a.
using CellNodeCoords = Eigen::Matrix<Real, Eigen::Dynamic, 3, 0, kMaxCellNodes, 3>;
using FacetShapeValues = Eigen::Matrix<Real, Eigen::Dynamic, 1, 0, kMaxFacetNodes, 1>;
/// Row a = dN_a/ds.
using FacetShapeGrads = Eigen::Matrix<Real, Eigen::Dynamic, 2, 0, kMaxFacetNodes, 2>;
/// Row a = (d²N_a/ds1², d²N_a/ds2², d²N_a/ds1 ds2).
using FacetShapeHessians = Eigen::Matrix<Real, Eigen::Dynamic, 3, 0, kMaxFacetNodes, 3>;
/// Row a = coordinates of node a.
using FacetNodeCoords = Eigen::Matrix<Real, Eigen::Dynamic, 2, 0, kMaxFacetNodes, 2>;

/// A facet of a reference cell: its type and the cell's local node numbers in the facet's node
/// order (mesh::cell_faces). The facet's shape functions map its reference facet onto the
/// cell's face with d x/d s1 x d x/d s2 pointing out of the cell.
using CellFacet = mesh::CellFace;

/// The reference element of a cell type (one immutable object per type: reference_cell()).
class ReferenceCell {
public:
  CellType type() const { return type_; }
  int num_nodes() const { return static_cast<int>(nodes_.rows()); }
  /// Polynomial order of the shape functions along an edge: 1 or 2.
  int order() const { return order_; }
  /// Row a = natural coordinates of node a.
  const CellNodeCoords& nodes() const { return nodes_; }
  /// N_a(xi); for hex8 the values of hex8_shape (and hex8_shape_grad below).
  ShapeValues shape(const Vec3& xi) const;
  /// Row a = dN_a/dxi.
  ShapeGrads shape_grad(const Vec3& xi) const;
  /// The default rule: exact for the consistent mass matrix of an affine cell (degree
  /// 2 x order): hex8 2x2x2 Gauss, hex20 3x3x3 Gauss, tet4 4 points of degree 2, tet10 14
  /// points of degree 5, penta6 3 triangle points times 2 Gauss points.
  const CellRule& rule() const { return rule_; }
  /// N_a at each point of rule(), in its order.
  const std::vector<ShapeValues>& rule_shapes() const { return rule_shapes_; }
  /// Volume of the reference domain.
  Real volume() const { return volume_; }
  /// The facets: hex zeta = -1, zeta = +1, eta = -1, xi = +1, eta = +1, xi = -1 (the faces of
  /// mesh::kHexFaces); tet opposite node 3, 2, 1, 0; penta6 the triangles z = -1 and z = +1,
  /// then the quadrilaterals y = 0, x + y = 1, x = 0.
  const std::vector<CellFacet>& facets() const { return mesh::cell_faces(type_); }
  /// VTK cell type number (hex8 12, tet4 10, tet10 24, penta6 13 = wedge, hex20 25).
  int vtk_type() const { return vtk_type_; }
  /// For each VTK node of the cell, the local node number.
  const std::vector<int>& vtk_order() const { return vtk_order_; }

private:
  explicit ReferenceCell(CellType type);
  friend const ReferenceCell& reference_cell(CellType type);

  CellType type_;
  int order_;
  CellNodeCoords nodes_;
  CellRule rule_;
  std::vector<ShapeValues> rule_shapes_;
  Real volume_;
  int vtk_type_;
  std::vector<int> vtk_order_;
};

/// The reference element of a facet type (one immutable object per type: reference_facet()).
class ReferenceFacet {
public:
  FacetType type() const { return type_; }
  int num_nodes() const { return static_cast<int>(nodes_.rows()); }
  /// Polynomial order of the shape functions along an edge: 1 or 2.
  int order() const { return order_; }
  /// Row a = natural coordinates of node a.
  const FacetNodeCoords& nodes() const { return nodes_; }
  /// N_a(s); for quad4 the values of quad4_shape (and quad4_shape_grad below).
  FacetShapeValues shape(const Vec2& s) const;
  /// Row a = dN_a/ds.
  FacetShapeGrads shape_grad(const Vec2& s) const;
  /// Row a = (N_a,11, N_a,22, N_a,12): zero for tri3, N_a,12 only for quad4 (what the
  /// curvature of a contact facet and its closest-point projection need).
  FacetShapeHessians shape_hessian(const Vec2& s) const;
  /// The default rule, exact to degree 2 x order: tri3 3 points, tri6 6 points of degree 4,
  /// quad4 2x2 Gauss, quad8 3x3 Gauss.
  const FacetRule& rule() const { return rule_; }
  /// Area of the reference domain.
  Real area() const { return area_; }

private:
  explicit ReferenceFacet(FacetType type);
  friend const ReferenceFacet& reference_facet(FacetType type);

  FacetType type_;
  int order_;
  FacetNodeCoords nodes_;
  FacetRule rule_;
  Real area_;
};

/// The reference element of `type`.
const ReferenceCell& reference_cell(CellType type);

/// The reference element of `type`.
const ReferenceFacet& reference_facet(FacetType type);

} // namespace trifem::fe
