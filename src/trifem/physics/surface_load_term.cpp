// SPDX-License-Identifier: MIT
#include "trifem/physics/surface_load_term.hpp"

#include "trifem/fe/hex8.hpp"
#include "trifem/physics/facet_area.hpp"
#include "trifem/physics/facet_area_any.hpp"

namespace trifem::physics {
namespace {

void facet_dofs(const mesh::Facet& f, const dofs::DofMap& map, dofs::FieldId u,
                std::vector<Index>& dofs) {
  const int n = f.num_nodes();
  dofs.resize(static_cast<std::size_t>(3 * n));
  for (int a = 0; a < n; ++a)
    for (int k = 0; k < 3; ++k)
      dofs[static_cast<std::size_t>(3 * a + k)] = map.dof(u, f.node(a), k);
}

/// The residual r_a = -t int N_a |x_s1 x x_s2| ds of a traction t per current area on a facet
/// of `ref`'s family with nodal positions x and, if K is given, its derivative
/// K_ab = -t (x) int N_a [N_b,s1 (x_s2 x n) + N_b,s2 (n x x_s1)] ds.
void current_area_load(const fe::ReferenceFacet& ref, const FacetPositions& x, const Vec3& t,
                       LocalVector& r, LocalMatrix* K) {
  const int n = ref.num_nodes();
  Eigen::Matrix<Real, Eigen::Dynamic, 1, 0, fe::kMaxFacetNodes, 1> w =
      Eigen::Matrix<Real, Eigen::Dynamic, 1, 0, fe::kMaxFacetNodes, 1>::Zero(n);
  FacetMatrixX dw; // row a, columns 3 b + k: d(int N_a |x_s1 x x_s2| ds)/dx_bk
  if (K)
    dw.setZero(n, 3 * n);
  for (const fe::FacetQuadraturePoint& p : ref.rule().points) {
    const fe::FacetShapeGrads dN = ref.shape_grad(p.xi);
    const fe::FacetShapeValues N = ref.shape(p.xi);
    const Vec3 T1 = x.transpose() * dN.col(0), T2 = x.transpose() * dN.col(1);
    const Vec3 normal_area = T1.cross(T2);
    const Real da = normal_area.norm();
    for (int a = 0; a < n; ++a)
      w[a] += N[a] * da * p.weight;
    if (!K)
      continue;
    const Vec3 normal = normal_area / da;
    for (int b = 0; b < n; ++b) {
      const Vec3 g = dN(b, 0) * T2.cross(normal) + dN(b, 1) * normal.cross(T1);
      for (int a = 0; a < n; ++a)
        dw.block<1, 3>(a, 3 * b) += N[a] * p.weight * g.transpose();
    }
  }
  r.resize(3 * n);
  for (int a = 0; a < n; ++a)
    r.segment<3>(3 * a) = -w[a] * t;
  if (K) {
    K->setZero(3 * n, 3 * n);
    for (int a = 0; a < n; ++a)
      K->block(3 * a, 0, 3, 3 * n) = -t * dw.row(a);
  }
}

} // namespace

PressureTerm::PressureTerm(const mesh::Mesh& mesh, const dofs::DofMap& dofs,
                           dofs::FieldId displacement, std::vector<mesh::Facet> facets,
                           Real magnitude, dofs::LoadCurve curve, PressureNormal normal)
    : mesh_(mesh), dofs_(dofs), u_(displacement), facets_(std::move(facets)), magnitude_(magnitude),
      curve_(std::move(curve)) {
  if (normal == PressureNormal::Reference)
    for (const mesh::Facet& f : facets_)
      reference_areas_.push_back(
          facet_area_vectors(fe::reference_facet(f.type), facet_positions(mesh, f)));
}

void PressureTerm::element_dofs(Index e, std::vector<Index>& dofs) const {
  facet_dofs(facets_[e], dofs_, u_, dofs);
}

bool PressureTerm::evaluate(Index e, const EvalState& state, LocalVector& r, LocalMatrix* K) const {
  const mesh::Facet& f = facets_[e];
  if (!reference_areas_.empty()) { // a dead load: R = -f_ext = p int N_a N dA
    r = magnitude_ * curve_(state.time) * reference_areas_[e];
    if (K)
      K->setZero(r.size(), r.size());
    return true;
  }
  if (!f.is_quad4()) {
    const Real p = magnitude_ * curve_(state.time);
    FacetMatrixX da;
    r = p * facet_area_vectors(fe::reference_facet(f.type),
                               facet_positions(mesh_, f, &dofs_, u_, &state.x), K ? &da : nullptr);
    if (K)
      *K = p * da;
    return true;
  }
  fe::QuadCoords x;
  for (int a = 0; a < 4; ++a)
    for (int k = 0; k < 3; ++k)
      x(a, k) = mesh_.node(f.nodes[a])[k] + state.x[dofs_.dof(u_, f.nodes[a], k)];
  const Real p = magnitude_ * curve_(state.time);
  // R = f_int - f_ext with f_ext = -p n da
  FacetMatrix da;
  r = p * facet_area_vectors(x, K ? &da : nullptr);
  if (K)
    *K = p * da;
  return true;
}

TractionTerm::TractionTerm(const mesh::Mesh& mesh, const dofs::DofMap& dofs,
                           dofs::FieldId displacement, std::vector<mesh::Facet> facets,
                           Vec3 traction, dofs::LoadCurve curve, TractionArea area)
    : mesh_(mesh), dofs_(dofs), u_(displacement), facets_(std::move(facets)), traction_(traction),
      curve_(std::move(curve)), area_(area) {
  if (area_ == TractionArea::Current)
    return; // the areas change with the state: evaluated each time
  nodal_area_.reserve(facets_.size());
  for (const auto& f : facets_) {
    if (!f.is_quad4()) { // ∫ N_a dA by the facet type's rule
      const fe::ReferenceFacet& ref = fe::reference_facet(f.type);
      const FacetPositions X = facet_positions(mesh, f);
      std::vector<Real> w(static_cast<std::size_t>(ref.num_nodes()), 0.0);
      for (const fe::FacetQuadraturePoint& p : ref.rule().points) {
        const fe::FacetShapeGrads dN = ref.shape_grad(p.xi);
        const Vec3 T1 = X.transpose() * dN.col(0), T2 = X.transpose() * dN.col(1);
        const fe::FacetShapeValues N = ref.shape(p.xi);
        for (int a = 0; a < ref.num_nodes(); ++a)
          w[static_cast<std::size_t>(a)] += N[a] * T1.cross(T2).norm() * p.weight;
      }
      nodal_area_.push_back(std::move(w));
      continue;
    }
    fe::QuadCoords X;
    for (int a = 0; a < 4; ++a)
      X.row(a) = mesh.node(f.nodes[a]).transpose();
    Eigen::Matrix<Real, 4, 1> w = Eigen::Matrix<Real, 4, 1>::Zero();
    for (const auto& qp : fe::quad_gauss_2x2()) {
      const fe::QuadShapeGrad dN = fe::quad4_shape_grad(qp.xi);
      const Vec3 T1 = X.transpose() * dN.col(0), T2 = X.transpose() * dN.col(1);
      w += fe::quad4_shape(qp.xi) * T1.cross(T2).norm() * qp.weight;
    }
    nodal_area_.emplace_back(w.begin(), w.end());
  }
}

void TractionTerm::element_dofs(Index e, std::vector<Index>& dofs) const {
  facet_dofs(facets_[e], dofs_, u_, dofs);
}

bool TractionTerm::evaluate(Index e, const EvalState& state, LocalVector& r, LocalMatrix* K) const {
  const Vec3 t = traction_ * curve_(state.time);
  if (area_ == TractionArea::Current) {
    current_area_load(fe::reference_facet(facets_[e].type),
                      facet_positions(mesh_, facets_[e], &dofs_, u_, &state.x), t, r, K);
    return true;
  }
  const auto n = static_cast<Index>(nodal_area_[e].size());
  r.resize(3 * n);
  for (Index a = 0; a < n; ++a)
    r.segment<3>(3 * a) = -nodal_area_[e][static_cast<std::size_t>(a)] * t;
  if (K)
    K->setZero(3 * n, 3 * n);
  return true;
}

} // namespace trifem::physics
