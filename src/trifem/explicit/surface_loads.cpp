// SPDX-License-Identifier: MIT
#include "trifem/explicit/surface_loads.hpp"

#include "trifem/fe/quadrature.hpp"

namespace trifem::explicit_dynamics {
namespace {

void add_pressure(const ExplicitModel& model, const ResolvedLoad& r, const Vector& U, Real p,
                  Vector& f) {
  const auto& rule = fe::quad_gauss_2x2();
  for (const mesh::Facet& facet : r.facets) {
    fe::QuadCoords x;
    for (int a = 0; a < 4; ++a) {
      const Index n = facet.nodes[a];
      x.row(a) = (model.mesh().node(n) + U.segment<3>(3 * n)).transpose();
    }
    for (const auto& qp : rule) {
      const fe::QuadShape N = fe::quad4_shape(qp.xi);
      const fe::QuadShapeGrad dN = fe::quad4_shape_grad(qp.xi);
      const Vec3 t1 = x.transpose() * dN.col(0), t2 = x.transpose() * dN.col(1);
      const Vec3 nda = t1.cross(t2) * qp.weight; // n da, outward from the body
      for (int a = 0; a < 4; ++a)
        f.segment<3>(3 * facet.nodes[a]) -= p * N[a] * nda;
    }
  }
}

void add_traction(const ResolvedLoad& r, const Vec3& t, Vector& f) {
  for (std::size_t i = 0; i < r.facets.size(); ++i)
    for (int a = 0; a < 4; ++a)
      f.segment<3>(3 * r.facets[i].nodes[a]) += r.nodal_area[i][a] * t;
}

} // namespace

void external_force(const ExplicitModel& model, const Vector& U, Real time, Vector& f) {
  f.setZero(model.num_dofs());
  for (const ResolvedLoad& r : model.loads()) {
    const Real scale = r.load.curve(time);
    if (r.load.kind == LoadKind::FollowerPressure)
      add_pressure(model, r, U, r.load.pressure * scale, f);
    else
      add_traction(r, r.load.traction * scale, f);
  }
}

bool has_follower_loads(const ExplicitModel& model) {
  for (const ResolvedLoad& r : model.loads())
    if (r.load.kind == LoadKind::FollowerPressure)
      return true;
  return false;
}

} // namespace trifem::explicit_dynamics
