// SPDX-License-Identifier: MIT
#include "trifem/physics/solid_cell.hpp"

#include "trifem/core/error.hpp"
#include "trifem/fe/hex8.hpp"
#include "trifem/tensor/kinematics.hpp"

namespace trifem::physics {
namespace {

/// Adds the material and geometric stiffness of one point to K.
void add_point_tangent(const fe::ShapeGrads& g, const Mat3& F, const material::StressTangent& st,
                       Real dV, CellMatrixX& K) {
  StrainMatrixX B;
  strain_displacement(F, g, B);
  const StrainMatrixX DB = (st.D * dV) * B;
  K.noalias() += B.transpose() * DB;
  add_geometric_stiffness(g, st.S, dV, K);
}

} // namespace

void strain_displacement(const Mat3& F, const fe::ShapeGrads& g, StrainMatrixX& B) {
  B.resize(6, 3 * g.rows());
  fill_strain_displacement(F, g, B);
}

void add_geometric_stiffness(const fe::ShapeGrads& g, const Mat3& S, Real dV, CellMatrixX& K) {
  for (Index a = 0; a < g.rows(); ++a)
    for (Index b = 0; b < g.rows(); ++b) {
      const Real geometric = g.row(a).dot(S * g.row(b).transpose()) * dV;
      for (int k = 0; k < 3; ++k)
        K(3 * a + k, 3 * b + k) += geometric;
    }
}

std::optional<CellGeometry> cell_geometry(const fe::ReferenceCell& reference,
                                          const fe::CellNodeCoords& X) {
  CellGeometry geo;
  geo.reference = &reference;
  for (const fe::CellQuadraturePoint& p : reference.rule().points) {
    const fe::ShapeGrads dN = reference.shape_grad(p.xi);
    const Mat3 J = X.transpose() * dN; // dX/dxi
    const Real det = J.determinant();
    if (!(det > 0.0))
      return std::nullopt;
    geo.dN_dX.push_back(dN * J.inverse());
    geo.dV.push_back(det * p.weight);
  }
  return geo;
}

AnyCellGeometry reference_geometry(const mesh::Mesh& mesh, Index c) {
  const mesh::CellType type = mesh.cell_type(c);
  if (type == mesh::CellType::Hex8) {
    const auto geo = fe::hex8_geometry(fe::cell_coordinates(mesh, c));
    TRIFEM_CHECK(geo.has_value(),
                 "{} is inverted or degenerate (det(dX/dxi) <= 0 at a Gauss point); "
                 "check its node order",
                 mesh.describe(c));
    return *geo;
  }
  const std::span<const Index> nodes = mesh.cell_nodes(c);
  fe::CellNodeCoords X(static_cast<Index>(nodes.size()), 3);
  for (std::size_t a = 0; a < nodes.size(); ++a)
    X.row(static_cast<Index>(a)) = mesh.node(nodes[a]).transpose();
  auto geo = cell_geometry(fe::reference_cell(type), X);
  TRIFEM_CHECK(geo.has_value(),
               "{}, a {}, is inverted or degenerate (det(dX/dxi) <= 0 at a quadrature "
               "point); check its node order and its mid-edge nodes",
               mesh.describe(c), mesh::name(type));
  return std::move(*geo);
}

bool solid_cell(const CellGeometry& geo, const fe::CellNodeCoords& u,
                const material::ElasticLaw& law, CellVectorX& f, CellMatrixX* K) {
  const Index n = geo.num_nodes();
  f.setZero(3 * n);
  if (K)
    K->setZero(3 * n, 3 * n);
  for (std::size_t q = 0; q < geo.dV.size(); ++q) {
    const fe::ShapeGrads& g = geo.dN_dX[q];
    const Mat3 F = Mat3::Identity() + u.transpose() * g;
    if (!(F.determinant() > 0.0))
      return false;
    const Mat3 C = F.transpose() * F;
    const Real dV = geo.dV[q];
    if (!K) {
      const Mat3 P = F * law.stress(C);
      for (Index a = 0; a < n; ++a)
        f.segment<3>(3 * a) += P * g.row(a).transpose() * dV;
      continue;
    }
    const material::StressTangent st = law.stress_tangent(C);
    const Mat3 P = F * st.S;
    for (Index a = 0; a < n; ++a)
      f.segment<3>(3 * a) += P * g.row(a).transpose() * dV;
    add_point_tangent(g, F, st, dV, *K);
  }
  return true;
}

CellStress solid_cell_stress(const CellGeometry& geo, const fe::CellNodeCoords& u,
                             const material::ElasticLaw& law) {
  CellStress out;
  Real volume = 0.0, current = 0.0;
  for (std::size_t q = 0; q < geo.dV.size(); ++q) {
    const Mat3 F = Mat3::Identity() + u.transpose() * geo.dN_dX[q];
    const Real J = F.determinant();
    out.cauchy += kinematics::cauchy_from_pk2(F, law.stress(F.transpose() * F)) * J * geo.dV[q];
    volume += geo.dV[q];
    current += J * geo.dV[q];
  }
  out.cauchy /= current;
  out.J = current / volume;
  return out;
}

} // namespace trifem::physics
