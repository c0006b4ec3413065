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
  const Real b12 = normal.dot(x12);
  Mat2 b;
  b << 0, b12, b12, 0;
  return b;
}

Vec2 facet_corner(int a) {
  static constexpr Real kCorners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  return {kCorners[a][0], kCorners[a][1]};
}

FacetPoint evaluate_facet(const fe::QuadCoords& X, const Vec2& xi) {
  FacetPoint p;
  p.N = fe::quad4_shape(xi);
  p.dN = fe::quad4_shape_grad(xi);
  p.x = X.transpose() * p.N;
  p.t[0] = X.transpose() * p.dN.col(0);
  p.t[1] = X.transpose() * p.dN.col(1);
  // d²N_a/dξdη = ξ_a η_a / 4 with (ξ_a η_a) = (+1, -1, +1, -1).
  p.x12 = 0.25 * (X.row(0) - X.row(1) + X.row(2) - X.row(3)).transpose();
  const Vec3 r = p.t[0].cross(p.t[1]);
  p.jacobian = r.norm();
  p.normal = p.jacobian > 0 ? Vec3(r / p.jacobian) : Vec3::Zero();
  return p;
}

Real facet_size(const fe::QuadCoords& X) {
  Real h = 0;
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b)
      h = std::max(h, (X.row(a) - X.row(b)).norm());
  return h;
}

} // namespace trifem::contact
