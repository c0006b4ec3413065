// SPDX-License-Identifier: MIT
#include "trifem/physics/surface_flux.hpp"

#include "trifem/fe/hex8.hpp"

namespace trifem::physics {

Real surface_outflow(const mesh::Mesh& mesh, const dofs::DofMap& dofs, dofs::FieldId u,
                     dofs::FieldId flux, const std::vector<mesh::Facet>& facets, const Vector& x,
                     Real scale) {
  Real total = 0.0;
  for (const mesh::Facet& f : facets) {
    fe::QuadCoords xc, j;
    for (int a = 0; a < 4; ++a)
      for (int k = 0; k < 3; ++k) {
        xc(a, k) = mesh.node(f.nodes[a])[k] + x[dofs.dof(u, f.nodes[a], k)];
        j(a, k) = x[dofs.dof(flux, f.nodes[a], k)];
      }
    for (const auto& qp : fe::quad_gauss_2x2()) {
      const fe::QuadShapeGrad dN = fe::quad4_shape_grad(qp.xi);
      const Vec3 area = (xc.transpose() * dN.col(0)).cross(xc.transpose() * dN.col(1));
      const Vec3 jq = j.transpose() * fe::quad4_shape(qp.xi);
      total += jq.dot(area) * qp.weight;
    }
  }
  return scale * total;
}

} // namespace trifem::physics
