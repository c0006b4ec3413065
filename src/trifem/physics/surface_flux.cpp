// SPDX-License-Identifier: MIT
#include "trifem/physics/surface_flux.hpp"

#include "trifem/fe/hex8.hpp"
#include "trifem/physics/facet_area_any.hpp"
#include "trifem/physics/mixture_kernel.hpp"

namespace trifem::physics {
namespace {

/// The outflow through a facet of any family: the flux at its corners (mixture_flux_map) times
/// the corners' area vectors P a.
Real facet_outflow(const mesh::Mesh& mesh, const dofs::DofMap& dofs, dofs::FieldId u,
                   dofs::FieldId flux, const mesh::Facet& f, const Vector& x) {
  const FacetVectorX area =
      facet_area_vectors(fe::reference_facet(f.type), facet_positions(mesh, f, &dofs, u, &x));
  const MixtureFluxMap& P = mixture_flux_map(f.type);
  Real total = 0.0;
  for (int a = 0; a < f.num_corners(); ++a)
    for (int m = 0; m < f.num_nodes(); ++m)
      for (int k = 0; k < 3; ++k)
        total += P(a, m) * area[3 * m + k] * x[dofs.dof(flux, f.node(a), k)];
  return total;
}

} // namespace

Real surface_outflow(const mesh::Mesh& mesh, const dofs::DofMap& dofs, dofs::FieldId u,
                     dofs::FieldId flux, const std::vector<mesh::Facet>& facets, const Vector& x,
                     Real scale) {
  Real total = 0.0;
  for (const mesh::Facet& f : facets) {
    if (!f.is_quad4()) {
      total += facet_outflow(mesh, dofs, u, flux, f, x);
      continue;
    }
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
