// SPDX-License-Identifier: MIT
#include "trifem/material/material_axes.hpp"

#include "trifem/core/error.hpp"

#include <cmath>

namespace trifem::material {
namespace {

/// Relative size below which a projected direction counts as degenerate.
constexpr Real kDegenerate = 1e-8;

std::string text(const Vec3& v) {
  return fmt::format("[{}, {}, {}]", v.x(), v.y(), v.z());
}

Mat3 from_columns(const Vec3& e1, const Vec3& e2) {
  Mat3 Q;
  Q.col(0) = e1;
  Q.col(1) = e2;
  Q.col(2) = e1.cross(e2);
  return Q;
}

} // namespace

Mat3 vector_basis(const Vec3& a, const Vec3& d, const std::string& context) {
  TRIFEM_CHECK(a.allFinite() && a.norm() > 0.0, "{}.a = {}: must be a nonzero vector", context,
               text(a));
  const Vec3 e1 = a.normalized();
  const Vec3 normal = d - d.dot(e1) * e1;
  TRIFEM_CHECK(d.allFinite() && normal.norm() > kDegenerate * d.norm(),
               "{}.d = {}: must not be parallel to {}.a = {} (d fixes the (e1, e2) plane)", context,
               text(d), context, text(a));
  return from_columns(e1, normal.normalized());
}

Mat3 cylindrical_basis(const Vec3& center, const Vec3& axis, const Vec3& point,
                       const std::string& context) {
  const Vec3 e3 = axis.normalized();
  const Vec3 p = point - center;
  const Vec3 radial = p - p.dot(e3) * e3;
  TRIFEM_CHECK(radial.norm() > kDegenerate * p.norm() && radial.norm() > 0.0,
               "{}: the cell centroid {} lies on the cylinder axis (center {}, axis {}), where "
               "the radial direction is undefined",
               context, text(point), text(center), text(axis));
  const Vec3 e1 = radial.normalized();
  return from_columns(e1, e3.cross(e1));
}

Mat3 spherical_basis(const Vec3& center, const Vec3& axis, const Vec3& point,
                     const std::string& context) {
  const Vec3 p = point - center;
  TRIFEM_CHECK(p.norm() > 0.0, "{}: the cell centroid {} is the centre of the spherical axes",
               context, text(point));
  const Vec3 e1 = p.normalized();
  const Vec3 azimuthal = axis.normalized().cross(e1);
  TRIFEM_CHECK(azimuthal.norm() > kDegenerate,
               "{}: the cell centroid {} lies on the pole axis {} through the centre {}, where "
               "the azimuthal direction is undefined",
               context, text(point), text(axis), text(center));
  return from_columns(e1, azimuthal.normalized());
}

Mat3 completed_basis(const Vec3& e1, const std::string& context) {
  TRIFEM_CHECK(e1.allFinite() && e1.norm() > 0.0, "{}: the direction {} must be a nonzero vector",
               context, text(e1));
  const Vec3 n = e1.normalized();
  int least = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(n[k]) < std::abs(n[least]))
      least = k;
  const Vec3 g = Vec3::Unit(least);
  return from_columns(n, (g - g.dot(n) * n).normalized());
}

Mat3 axes_basis(const AxesSpec& axes, const Vec3& point, const std::string& context) {
  switch (axes.kind) {
  case AxesKind::Vector:
    return vector_basis(axes.a, axes.d, context);
  case AxesKind::Cylindrical:
    return cylindrical_basis(axes.center, axes.axis, point, context);
  case AxesKind::Spherical:
    return spherical_basis(axes.center, axes.axis, point, context);
  case AxesKind::Mesh:
    break; // per cell from the mesh's cell data: model::orient_cells
  }
  throw LogicError("axes_basis: no basis at a point for this kind of axes");
}

} // namespace trifem::material
