// SPDX-License-Identifier: MIT
// Quadrature rules of the reference elements: symmetric positive-weight rules on the triangle
// {x, y >= 0, x + y <= 1} and the tetrahedron {x, y, z >= 0, x + y + z <= 1}, the product of
// a triangle rule and a Gauss-Legendre rule on the wedge (triangle x [-1, 1]), and
// Gauss-Legendre products on the square [-1, 1]^2 and the hexahedron [-1, 1]^3.
#pragma once

#include "trifem/tensor/tensor.hpp"

#include <vector>

namespace trifem::fe {

/// A quadrature point of a reference cell: natural coordinates and weight.
struct CellQuadraturePoint {
  Vec3 xi;
  Real weight;
};

/// A quadrature point of a reference facet: natural coordinates and weight.
struct FacetQuadraturePoint {
  Vec2 xi;
  Real weight;
};

/// Quadrature points and the polynomial degree they integrate exactly: every polynomial of
/// total degree <= `degree`. The Gauss-Legendre products are exact, too, for every polynomial
/// of degree <= `degree` in each coordinate separately; the wedge rule for every polynomial of
/// total degree <= `degree` in (x, y) times degree <= 3 in z.
template <class Point>
struct QuadratureRule {
  std::vector<Point> points;
  int degree = 0;
};

using CellRule = QuadratureRule<CellQuadraturePoint>;
using FacetRule = QuadratureRule<FacetQuadraturePoint>;

/// n x n x n Gauss-Legendre rule on [-1, 1]^3, n = 1, 2 or 3 (degree 2n - 1), x running
/// fastest. For n = 2 the points and weights equal hex_gauss_2x2x2() bit for bit.
CellRule hex_gauss_rule(int points_per_direction);

/// n x n Gauss-Legendre rule on [-1, 1]^2, n = 1, 2 or 3 (degree 2n - 1), x running fastest.
FacetRule quad_gauss_rule(int points_per_direction);

/// 3-point rule of degree 2 on the triangle (points halfway between the centroid and the
/// corners).
FacetRule triangle_rule_degree2();

/// 6-point rule of degree 4 on the triangle (two orbits of three points).
FacetRule triangle_rule_degree4();

/// 4-point rule of degree 2 on the tetrahedron.
CellRule tet_rule_degree2();

/// 14-point rule of degree 5 on the tetrahedron (two orbits of four points, one of six).
CellRule tet_rule_degree5();

/// The 3-point degree-2 triangle rule times the 2-point Gauss rule in z on the wedge: degree 2
/// in (x, y), 3 in z; the z layers run slowest.
CellRule wedge_rule_degree2();

} // namespace trifem::fe
