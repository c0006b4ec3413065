// SPDX-License-Identifier: MIT
#include "trifem/contact/facet_geometry.hpp"

#include <algorithm>

namespace trifem::contact {

Mat2 FacetPoint::metric() const {
  Mat2 a;
  a << t[0].dot(t[0]), t[0].dot(t[1]), t[1].dot(t[0]), t[1].dot(t[1]);
  return a;
}

Mat2 FacetPoint::curvature() const {
  const Real b12 = normal.dot(x2[2]);
  Mat2 b;
  b << normal.dot(x2[0]), b12, b12, normal.dot(x2[1]);
  return b;
}

FacetPoint evaluate_facet(const FacetCoords& X, const Vec2& xi) {
  FacetPoint p;
  p.N = X.reference->shape(xi);
  p.dN = X.reference->shape_grad(xi);
  p.d2N = X.reference->shape_hessian(xi);
  p.x = X.x.transpose() * p.N;
  for (int alpha = 0; alpha < 2; ++alpha)
    p.t[alpha] = X.x.transpose() * p.dN.col(alpha);
  for (int k = 0; k < 3; ++k)
    p.x2[k] = X.x.transpose() * p.d2N.col(k);
  const Vec3 r = p.t[0].cross(p.t[1]);
  p.jacobian = r.norm();
  p.normal = p.jacobian > 0 ? Vec3(r / p.jacobian) : Vec3::Zero();
  return p;
}

Vec2 facet_centre(mesh::FacetType type) {
  return is_triangle(type) ? Vec2(1.0 / 3, 1.0 / 3) : Vec2::Zero();
}

Vec2 facet_corner(mesh::FacetType type, int a) {
  return fe::reference_facet(type).nodes().row(a).transpose();
}

bool inside_facet(mesh::FacetType type, const Vec2& xi, Real tolerance) {
  if (is_triangle(type))
    return xi[0] >= -tolerance && xi[1] >= -tolerance && xi.sum() <= 1 + tolerance;
  return xi.lpNorm<Eigen::Infinity>() <= 1 + tolerance;
}

Real outside_distance(mesh::FacetType type, const Vec2& xi) {
  if (is_triangle(type))
    return std::max({0.0, -xi[0], -xi[1], xi.sum() - 1});
  return std::max(0.0, xi.lpNorm<Eigen::Infinity>() - 1);
}

Vec2 edge_direction(mesh::FacetType type, int e) {
  const int corners = mesh::num_corners(type);
  return facet_corner(type, (e + 1) % corners) - facet_corner(type, e);
}

mesh::FacetType corner_facet_type(mesh::FacetType type) {
  switch (type) {
  case mesh::FacetType::Tri6:
    return mesh::FacetType::Tri3;
  case mesh::FacetType::Quad8:
    return mesh::FacetType::Quad4;
  default:
    return type;
  }
}

fe::FacetShapeValues corner_shape(mesh::FacetType type, const Vec2& xi) {
  fe::FacetShapeValues N = fe::FacetShapeValues::Zero(mesh::num_nodes(type));
  N.head(mesh::num_corners(type)) = fe::reference_facet(corner_facet_type(type)).shape(xi);
  return N;
}

fe::FacetShapeGrads corner_shape_grad(mesh::FacetType type, const Vec2& xi) {
  fe::FacetShapeGrads G = fe::FacetShapeGrads::Zero(mesh::num_nodes(type), 2);
  G.topRows(mesh::num_corners(type)) = fe::reference_facet(corner_facet_type(type)).shape_grad(xi);
  return G;
}

Real facet_size(const FacetCoords& X) {
  Real h = 0;
  const int corners = X.num_corners();
  for (int a = 0; a < corners; ++a)
    for (int b = a + 1; b < corners; ++b)
      h = std::max(h, (X.x.row(a) - X.x.row(b)).norm());
  return h;
}

Real facet_bulge(const FacetCoords& X) {
  const int corners = X.num_corners();
  Real bulge = 0;
  for (int e = corners; e < X.num_nodes(); ++e) {
    const int a = e - corners, b = (a + 1) % corners;
    bulge = std::max(bulge, (X.x.row(e) - 0.5 * (X.x.row(a) + X.x.row(b))).norm());
  }
  return bulge;
}

} // namespace trifem::contact
