// SPDX-License-Identifier: MIT
#include "trifem/physics/facet_area_any.hpp"

#include "trifem/tensor/rotation.hpp"

namespace trifem::physics {

FacetPositions facet_positions(const mesh::Mesh& mesh, const mesh::Facet& f,
                               const dofs::DofMap* dofs, dofs::FieldId u, const Vector* x) {
  FacetPositions p(f.num_nodes(), 3);
  for (int a = 0; a < f.num_nodes(); ++a)
    for (int k = 0; k < 3; ++k)
      p(a, k) = mesh.node(f.node(a))[k] + (x ? (*x)[dofs->dof(u, f.node(a), k)] : 0.0);
  return p;
}

FacetVectorX facet_area_vectors(const fe::ReferenceFacet& reference, const FacetPositions& x,
                                FacetMatrixX* derivative) {
  const Index n = reference.num_nodes();
  FacetVectorX a = FacetVectorX::Zero(3 * n);
  if (derivative)
    derivative->setZero(3 * n, 3 * n);
  for (const fe::FacetQuadraturePoint& p : reference.rule().points) {
    const fe::FacetShapeValues N = reference.shape(p.xi);
    const fe::FacetShapeGrads dN = reference.shape_grad(p.xi);
    const Vec3 t1 = x.transpose() * dN.col(0), t2 = x.transpose() * dN.col(1);
    const Vec3 r = t1.cross(t2) * p.weight;
    for (Index i = 0; i < n; ++i) {
      a.segment<3>(3 * i) += N[i] * r;
      if (!derivative)
        continue;
      for (Index b = 0; b < n; ++b)
        derivative->block<3, 3>(3 * i, 3 * b) +=
            N[i] * p.weight * (dN(b, 1) * rotation::skew(t1) - dN(b, 0) * rotation::skew(t2));
    }
  }
  return a;
}

Real reference_area(const mesh::Mesh& mesh, const std::vector<mesh::Facet>& facets) {
  Real area = 0.0;
  for (const mesh::Facet& f : facets) {
    const fe::ReferenceFacet& reference = fe::reference_facet(f.type);
    const FacetPositions X = facet_positions(mesh, f);
    for (const fe::FacetQuadraturePoint& p : reference.rule().points) {
      const fe::FacetShapeGrads dN = reference.shape_grad(p.xi);
      const Vec3 t1 = X.transpose() * dN.col(0), t2 = X.transpose() * dN.col(1);
      area += t1.cross(t2).norm() * p.weight;
    }
  }
  return area;
}

} // namespace trifem::physics
