// SPDX-License-Identifier: MIT
#include "trifem/physics/facet_area.hpp"

namespace trifem::physics {
namespace {

Mat3 skew(const Vec3& v) {
  Mat3 S;
  S << 0, -v[2], v[1], v[2], 0, -v[0], -v[1], v[0], 0;
  return S;
}

} // namespace

FacetVector facet_area_vectors(const fe::QuadCoords& x, FacetMatrix* derivative) {
  FacetVector a = FacetVector::Zero();
  if (derivative)
    derivative->setZero();
  for (const auto& qp : fe::quad_gauss_2x2()) {
    const fe::QuadShape N = fe::quad4_shape(qp.xi);
    const fe::QuadShapeGrad dN = fe::quad4_shape_grad(qp.xi);
    const Vec3 t1 = x.transpose() * dN.col(0), t2 = x.transpose() * dN.col(1);
    const Vec3 r = t1.cross(t2) * qp.weight;
    for (int a_ = 0; a_ < 4; ++a_) {
      a.segment<3>(3 * a_) += N[a_] * r;
      if (!derivative)
        continue;
      for (int b = 0; b < 4; ++b)
        derivative->block<3, 3>(3 * a_, 3 * b) +=
            N[a_] * qp.weight * (dN(b, 1) * skew(t1) - dN(b, 0) * skew(t2));
    }
  }
  return a;
}

} // namespace trifem::physics
