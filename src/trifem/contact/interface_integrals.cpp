// SPDX-License-Identifier: MIT
// Element kernels of ContactTerm: the interface work of the multipliers on the slave and master
// facets (docs/theory/contact.md §4) and its consistent tangent (§6 there, K_c1 and K_c2).
#include "trifem/contact/contact_term.hpp"
#include "trifem/physics/facet_area.hpp"

namespace trifem::contact {
namespace {

using MultiplierRows = Eigen::Matrix<Real, Eigen::Dynamic, kStencil>;

Mat3 skew(const Vec3& v) {
  Mat3 S;
  S << 0, -v[2], v[1], v[2], 0, -v[0], -v[1], v[0], 0;
  return S;
}

/// ∂r/∂x_b of the weighted area vector r = w t_1 × t_2 at a point of a facet:
/// w (N_{b,2} [t_1]_× - N_{b,1} [t_2]_×).
Mat3 area_derivative(const FacetPoint& fp, int b, Real w) {
  return w * (fp.dN(b, 1) * skew(fp.t[0]) - fp.dN(b, 0) * skew(fp.t[1]));
}

/// A master node i and the slave facet s_i it projects onto at ζ_i:
/// λ^m_i = Σ_b M_b(ζ_i) λ_{k_b} and its derivative through ζ_i with respect to the stencil
/// coordinates (x_i, slave facet nodes): Σ_b λ_{k_b} M_{b,β}(ζ_i) ∂ζ_i^β/∂x.
struct MasterLink {
  bool linked = false;
  fe::QuadShape M;                 ///< M_b(ζ_i) = L_{i k_b}
  Vector lambda;                   ///< λ^m_i (per component)
  MultiplierRows dlambda;          ///< ∂λ^m_i/∂(x_i, x_{s,0..3}) through ζ_i
  std::array<Index, 5> x_at{};     ///< local position of x of the stencil points
  Eigen::Matrix<Index, 4, 1> l_at; ///< local position of λ component 0 of the facet nodes
};

} // namespace

void ContactTerm::slave_facet_work(Index f, const Vector& x, Real dt, LocalSystem& out) const {
  const auto& nodes = slave_.facet(f).nodes;
  const fe::QuadCoords X = coords(nodes, x);
  const Eigen::Matrix<Real, 4, Eigen::Dynamic> lam = facet_multipliers(f, x);
  std::array<Index, 4> x_at{}, l_at{};
  for (int a = 0; a < 4; ++a) {
    x_at[a] = out.at(u_dof(nodes[a], 0));
    l_at[a] = out.at(multiplier_dof(slave_facet_k_[f][a], 0));
  }
  for (const auto& qp : fe::quad_gauss_2x2()) {
    const FacetPoint fp = evaluate_facet(X, qp.xi);
    for (int c = 0; c < lam.cols(); ++c) {
      const Real wc = law_->work_factor(c, dt) * qp.weight;
      const Vec3 r = wc * fp.t[0].cross(fp.t[1]);
      const Real lc = fp.N.dot(lam.col(c));
      for (int a = 0; a < 4; ++a) {
        const Index row = out.at(dofs_.dof(law_->paired_field(c), nodes[a], 0));
        out.r().segment<3>(row) -= fp.N[a] * lc * r;
        if (!out.with_jacobian())
          continue;
        for (int b = 0; b < 4; ++b) {
          out.K().block<3, 3>(row, x_at[b]) -= fp.N[a] * lc * area_derivative(fp, b, wc);
          out.K().block<3, 1>(row, l_at[b] + c) -= fp.N[a] * fp.N[b] * r;
        }
      }
    }
  }
}

void ContactTerm::master_facet_work(Index f, const Vector& x, Real dt, LocalSystem& out) const {
  const auto& nodes = master_.facet(f).nodes;
  const fe::QuadCoords X = coords(nodes, x);
  const int C = law_->num_components();
  std::array<MasterLink, 4> link;
  std::array<Index, 4> x_at{};
  for (int i = 0; i < 4; ++i) {
    x_at[i] = out.at(u_dof(nodes[i], 0));
    const auto& pr = master_proj_[master_.local_node(nodes[i])];
    if (!pr || pr->on_free_boundary)
      continue; // exposed master node: λ^m_i = 0
    MasterLink& l = link[i];
    l.linked = true;
    const auto lam = facet_multipliers(pr->facet, x);
    l.M = fe::quad4_shape(pr->xi);
    l.lambda = lam.transpose() * l.M;
    const auto stencil = stencil_nodes(nodes[i], slave_, pr->facet);
    for (int j = 0; j < 5; ++j)
      l.x_at[j] = out.at(u_dof(stencil[j], 0));
    for (int b = 0; b < 4; ++b)
      l.l_at[b] = out.at(multiplier_dof(slave_facet_k_[pr->facet][b], 0));
    if (out.with_jacobian()) {
      const ProjectionDerivatives d =
          projection_derivatives(*pr, coords(slave_.facet(pr->facet).nodes, x));
      l.dlambda = lam.transpose() * fe::quad4_shape_grad(pr->xi) * d.dxi;
    }
  }
  for (const auto& qp : fe::quad_gauss_2x2()) {
    const FacetPoint fp = evaluate_facet(X, qp.xi);
    Vector lm = Vector::Zero(C); // λ^m(ξ) = Σ_i N_i(ξ) λ^m_i
    for (int i = 0; i < 4; ++i)
      if (link[i].linked)
        lm += fp.N[i] * link[i].lambda;
    for (int c = 0; c < C; ++c) {
      const Real wc = law_->work_factor(c, dt) * qp.weight;
      const Vec3 r = wc * fp.t[0].cross(fp.t[1]);
      for (int a = 0; a < 4; ++a) {
        const Index row = out.at(dofs_.dof(law_->paired_field(c), nodes[a], 0));
        out.r().segment<3>(row) -= fp.N[a] * lm[c] * r;
        if (!out.with_jacobian())
          continue;
        for (int b = 0; b < 4; ++b)
          out.K().block<3, 3>(row, x_at[b]) -= fp.N[a] * lm[c] * area_derivative(fp, b, wc);
        for (int i = 0; i < 4; ++i) {
          if (!link[i].linked)
            continue;
          const Vec3 coef = -fp.N[a] * fp.N[i] * r; // ∂R_a/∂λ^m_i
          for (int b = 0; b < 4; ++b)
            out.K().block<3, 1>(row, link[i].l_at[b] + c) += coef * link[i].M[b];
          for (int j = 0; j < 5; ++j)
            out.K().block<3, 3>(row, link[i].x_at[j]) +=
                coef * link[i].dlambda.row(c).segment<3>(3 * j);
        }
      }
    }
  }
}

void ContactTerm::slave_point_forces(Index f, const Vector& x, Real dt, LocalSystem& out) const {
  const auto& nodes = slave_.facet(f).nodes;
  physics::FacetMatrix dA;
  const physics::FacetVector A =
      physics::facet_area_vectors(coords(nodes, x), out.with_jacobian() ? &dA : nullptr);
  const Eigen::Matrix<Real, 4, Eigen::Dynamic> lam = facet_multipliers(f, x);
  std::array<Index, 4> x_at{};
  for (int a = 0; a < 4; ++a)
    x_at[a] = out.at(u_dof(nodes[a], 0));
  for (int a = 0; a < 4; ++a) {
    const Index l_at = out.at(multiplier_dof(slave_facet_k_[f][a], 0));
    const auto& pr = slave_proj_[slave_facet_k_[f][a]];
    const bool transfer = pr && !pr->on_free_boundary;
    fe::QuadShape Nq;
    Eigen::Matrix<Real, 4, kStencil> dNq; // ∂N_q(ξ_a)/∂(x_a, master facet nodes)
    std::array<Index, 5> q_at{};
    if (transfer) {
      const auto& q = master_.facet(pr->facet).nodes;
      Nq = fe::quad4_shape(pr->xi);
      const auto stencil = stencil_nodes(nodes[a], master_, pr->facet);
      for (int j = 0; j < 5; ++j)
        q_at[j] = out.at(u_dof(stencil[j], 0));
      if (out.with_jacobian())
        dNq = fe::quad4_shape_grad(pr->xi) * projection_derivatives(*pr, coords(q, x)).dxi;
    }
    for (int c = 0; c < lam.cols(); ++c) {
      const dofs::FieldId F = law_->paired_field(c);
      const Real sc = law_->work_factor(c, dt);
      const Vec3 a_a = sc * A.segment<3>(3 * a);
      const Index row = out.at(dofs_.dof(F, nodes[a], 0));
      out.r().segment<3>(row) -= lam(a, c) * a_a;
      if (out.with_jacobian()) {
        out.K().block<3, 1>(row, l_at + c) -= a_a;
        for (int b = 0; b < 4; ++b)
          out.K().block<3, 3>(row, x_at[b]) -= sc * lam(a, c) * dA.block<3, 3>(3 * a, 3 * b);
      }
      if (!transfer)
        continue;
      for (int qn = 0; qn < 4; ++qn) {
        const Index qrow = out.at(dofs_.dof(F, master_.facet(pr->facet).nodes[qn], 0));
        out.r().segment<3>(qrow) += lam(a, c) * Nq[qn] * a_a;
        if (!out.with_jacobian())
          continue;
        out.K().block<3, 1>(qrow, l_at + c) += Nq[qn] * a_a;
        for (int b = 0; b < 4; ++b)
          out.K().block<3, 3>(qrow, x_at[b]) +=
              sc * lam(a, c) * Nq[qn] * dA.block<3, 3>(3 * a, 3 * b);
        for (int j = 0; j < 5; ++j)
          out.K().block<3, 3>(qrow, q_at[j]) += lam(a, c) * a_a * dNq.row(qn).segment<3>(3 * j);
      }
    }
  }
}

Vec3 ContactTerm::master_force(const Vector& x) const {
  Vec3 f = Vec3::Zero();
  if (settings_.integration == Integration::SlaveNodes) {
    for (Index s = 0; s < slave_.num_facets(); ++s) {
      const physics::FacetVector A = physics::facet_area_vectors(coords(slave_.facet(s).nodes, x));
      for (int a = 0; a < 4; ++a) {
        const Index k = slave_facet_k_[s][a];
        if (slave_proj_[k] && !slave_proj_[k]->on_free_boundary)
          f -= x[multiplier_dof(k, 0)] * A.segment<3>(3 * a);
      }
    }
    return f;
  }
  for (Index m = 0; m < master_.num_facets(); ++m) {
    const auto& nodes = master_.facet(m).nodes;
    fe::QuadShape lm = fe::QuadShape::Zero(); // λ^m_i of the facet nodes
    for (int i = 0; i < 4; ++i) {
      const auto& pr = master_proj_[master_.local_node(nodes[i])];
      if (pr && !pr->on_free_boundary)
        lm[i] = facet_multipliers(pr->facet, x).col(0).dot(fe::quad4_shape(pr->xi));
    }
    const fe::QuadCoords X = coords(nodes, x);
    for (const auto& qp : fe::quad_gauss_2x2()) {
      const FacetPoint fp = evaluate_facet(X, qp.xi);
      f += fp.N.dot(lm) * qp.weight * fp.t[0].cross(fp.t[1]);
    }
  }
  return f;
}

} // namespace trifem::contact
