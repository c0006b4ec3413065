// SPDX-License-Identifier: MIT
// Element kernels of ContactTerm: the interface work of the multipliers on the slave and master
// facets (docs/theory/contact.md §4) and its consistent tangent (§6 there, K_c1 and K_c2).
#include "trifem/contact/contact_term.hpp"
#include "trifem/physics/facet_area_any.hpp"

namespace trifem::contact {
namespace {

using MultiplierRows = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic, 0, 4, kMaxStencil>;

Mat3 skew(const Vec3& v) {
  Mat3 S;
  S << 0, -v[2], v[1], v[2], 0, -v[0], -v[1], v[0], 0;
  return S;
}

/// ∂r/∂x_b of the weighted area vector r = w t_1 × t_2 at a point of a facet:
/// w (N_{b,2} [t_1]_× - N_{b,1} [t_2]_×).
Mat3 area_derivative(const FacetPoint& fp, Index b, Real w) {
  return w * (fp.dN(b, 1) * skew(fp.t[0]) - fp.dN(b, 0) * skew(fp.t[1]));
}

/// The vector along which the interface work of a component acts at a facet point: the
/// weighted area vector r = w t_1 × t_2 (work_axis < 0: a normal component), or
/// sign e_i (n·r) for a traction component along axis i (sign -1 on the master facets, whose
/// body takes the opposite traction).
Vec3 work_vector(int axis, Real sign, const FacetPoint& fp, Real w) {
  const Vec3 r = w * fp.t[0].cross(fp.t[1]);
  if (axis < 0)
    return r;
  Vec3 out = Vec3::Zero();
  out[axis] = sign * fp.t[0].cross(fp.t[1]).normalized().dot(r);
  return out;
}

/// ∂(work_vector)/∂x_b.
Mat3 work_derivative(int axis, Real sign, const FacetPoint& fp, Index b, Real w) {
  const Mat3 dr = area_derivative(fp, b, w);
  if (axis < 0)
    return dr;
  Mat3 out = Mat3::Zero();
  out.row(axis) = sign * fp.t[0].cross(fp.t[1]).normalized().transpose() * dr;
  return out;
}

/// The same for a lumped area vector a (slave-node integration) and its derivative rows dA.
Vec3 point_work_vector(int axis, const Vec3& a) {
  if (axis < 0)
    return a;
  Vec3 out = Vec3::Zero();
  out[axis] = a.norm();
  return out;
}

Mat3 point_work_derivative(int axis, const Vec3& a, const Mat3& da) {
  if (axis < 0)
    return da;
  Mat3 out = Mat3::Zero();
  out.row(axis) = a.normalized().transpose() * da;
  return out;
}

/// A master node i and the slave facet s_i it projects onto at ζ_i:
/// λ^m_i = Σ_b M_b(ζ_i) λ_{k_b} and its derivative through ζ_i with respect to the stencil
/// coordinates (x_i, slave facet nodes): Σ_b λ_{k_b} M_{b,β}(ζ_i) ∂ζ_i^β/∂x.
struct MasterLink {
  bool linked = false;
  fe::FacetShapeValues M;  ///< M_b(ζ_i) = L_{i k_b}
  fe::FacetShapeValues Mc; ///< the same of the corner-interpolated components (corner_shape)
  Vector lambda;           ///< λ^m_i (per component)
  MultiplierRows dlambda;  ///< ∂λ^m_i/∂(x_i, x_{s,b}) through ζ_i
  std::array<Index, kMaxStencilPoints> x_at{};  ///< local position of x of the stencil points
  std::array<Index, fe::kMaxFacetNodes> l_at{}; ///< local position of λ component 0, node b
  int points = 0;                               ///< stencil points (1 + slave facet nodes)

  /// M_b of component c.
  const fe::FacetShapeValues& of(const ContactLaw& law, int c) const {
    return law.corner_interpolated(c) ? Mc : M;
  }
};

} // namespace

void ContactTerm::slave_facet_work(Index f, const Vector& x, Real dt, LocalSystem& out) const {
  const auto nodes = slave_.facet_nodes(f);
  const FacetCoords X = coords(slave_, f, x);
  const FacetMultipliers lam = facet_multipliers(f, x);
  const Index n = X.num_nodes();
  const bool quadratic = n > X.num_corners();
  std::array<Index, fe::kMaxFacetNodes> x_at{}, l_at{};
  for (Index a = 0; a < n; ++a) {
    x_at[a] = out.at(u_dof(nodes[a], 0));
    l_at[a] = out.at(multiplier_dof(slave_facet_k_[f][a], 0));
  }
  for (const auto& qp : X.reference->rule().points) {
    const FacetPoint fp = evaluate_facet(X, qp.xi);
    // the corners' linear functions, where they differ from N (quadratic facets)
    const fe::FacetShapeValues L = quadratic ? corner_shape(X.type(), qp.xi) : fp.N;
    for (int c = 0; c < lam.cols(); ++c) {
      const fe::FacetShapeValues& S = law_->corner_interpolated(c) ? L : fp.N;
      const Real wc = law_->work_factor(c, dt) * qp.weight;
      const int axis = law_->work_axis(c);
      const Vec3 r = work_vector(axis, 1.0, fp, wc);
      const Real lc = S.dot(lam.col(c));
      for (Index a = 0; a < n; ++a) {
        if (S[a] == 0.0)
          continue; // a mid-edge node of a corner-interpolated field
        const Index row = out.at(dofs_.dof(law_->paired_field(c), nodes[a], 0));
        out.r().segment<3>(row) -= S[a] * lc * r;
        if (!out.with_jacobian())
          continue;
        for (Index b = 0; b < n; ++b) {
          out.K().block<3, 3>(row, x_at[b]) -= S[a] * lc * work_derivative(axis, 1.0, fp, b, wc);
          out.K().block<3, 1>(row, l_at[b] + c) -= S[a] * S[b] * r;
        }
      }
    }
  }
}

void ContactTerm::master_facet_work(Index f, const Vector& x, Real dt, LocalSystem& out) const {
  const auto nodes = master_.facet_nodes(f);
  const FacetCoords X = coords(master_, f, x);
  const Index n = X.num_nodes();
  const bool quadratic = n > X.num_corners();
  const int C = law_->num_components();
  std::array<MasterLink, fe::kMaxFacetNodes> link;
  std::array<Index, fe::kMaxFacetNodes> x_at{};
  for (Index i = 0; i < n; ++i) {
    x_at[i] = out.at(u_dof(nodes[i], 0));
    const auto& pr = master_proj_[master_.local_node(nodes[i])];
    if (!pr || pr->on_free_boundary)
      continue; // exposed master node: λ^m_i = 0
    MasterLink& l = link[i];
    l.linked = true;
    const FacetMultipliers lam = facet_multipliers(pr->facet, x);
    const mesh::FacetType zeta_type = slave_.facet_type(pr->facet);
    const fe::ReferenceFacet& zeta_facet = fe::reference_facet(zeta_type);
    l.M = zeta_facet.shape(pr->xi);
    l.Mc = corner_shape(zeta_type, pr->xi);
    l.lambda.resize(C);
    for (int c = 0; c < C; ++c)
      l.lambda[c] = lam.col(c).dot(l.of(*law_, c));
    const StencilNodes stencil = stencil_nodes(nodes[i], slave_, pr->facet);
    l.points = stencil.size;
    for (int j = 0; j < stencil.size; ++j)
      l.x_at[j] = out.at(u_dof(stencil[j], 0));
    for (Index b = 0; b < lam.rows(); ++b)
      l.l_at[b] = out.at(multiplier_dof(slave_facet_k_[pr->facet][b], 0));
    if (out.with_jacobian()) {
      const ProjectionDerivatives d = projection_derivatives(*pr, coords(slave_, pr->facet, x));
      const fe::FacetShapeGrads G = zeta_facet.shape_grad(pr->xi);
      const fe::FacetShapeGrads Gc = corner_shape_grad(zeta_type, pr->xi);
      l.dlambda.resize(C, d.dxi.cols());
      for (int c = 0; c < C; ++c)
        l.dlambda.row(c) = lam.col(c).transpose() * (law_->corner_interpolated(c) ? Gc : G) * d.dxi;
    }
  }
  for (const auto& qp : X.reference->rule().points) {
    const FacetPoint fp = evaluate_facet(X, qp.xi);
    // the corners' linear functions, where they differ from N (quadratic facets)
    const fe::FacetShapeValues L = quadratic ? corner_shape(X.type(), qp.xi) : fp.N;
    for (int c = 0; c < C; ++c) {
      const fe::FacetShapeValues& S = law_->corner_interpolated(c) ? L : fp.N;
      Real lm = 0; // λ^m(ξ) = Σ_i S_i(ξ) λ^m_i
      for (Index i = 0; i < n; ++i)
        if (link[i].linked)
          lm += S[i] * link[i].lambda[c];
      const Real wc = law_->work_factor(c, dt) * qp.weight;
      const int axis = law_->work_axis(c);
      const Vec3 r = work_vector(axis, -1.0, fp, wc);
      for (Index a = 0; a < n; ++a) {
        if (S[a] == 0.0)
          continue; // a mid-edge node of a corner-interpolated field
        const Index row = out.at(dofs_.dof(law_->paired_field(c), nodes[a], 0));
        out.r().segment<3>(row) -= S[a] * lm * r;
        if (!out.with_jacobian())
          continue;
        for (Index b = 0; b < n; ++b)
          out.K().block<3, 3>(row, x_at[b]) -= S[a] * lm * work_derivative(axis, -1.0, fp, b, wc);
        for (Index i = 0; i < n; ++i) {
          const MasterLink& l = link[i];
          if (!l.linked)
            continue;
          const Vec3 coef = -S[a] * S[i] * r; // ∂R_a/∂λ^m_i
          const fe::FacetShapeValues& M = l.of(*law_, c);
          for (Index b = 0; b < M.size(); ++b)
            out.K().block<3, 1>(row, l.l_at[b] + c) += coef * M[b];
          for (int j = 0; j < l.points; ++j)
            out.K().block<3, 3>(row, l.x_at[j]) += coef * l.dlambda.row(c).segment<3>(3 * j);
        }
      }
    }
  }
}

void ContactTerm::slave_point_forces(Index f, const Vector& x, Real dt, LocalSystem& out) const {
  const auto nodes = slave_.facet_nodes(f);
  const FacetCoords X = coords(slave_, f, x);
  const Index n = X.num_nodes();
  physics::FacetMatrixX dA;
  const physics::FacetVectorX A =
      physics::facet_area_vectors(*X.reference, X.x, out.with_jacobian() ? &dA : nullptr);
  const FacetMultipliers lam = facet_multipliers(f, x);
  std::array<Index, fe::kMaxFacetNodes> x_at{};
  for (Index a = 0; a < n; ++a)
    x_at[a] = out.at(u_dof(nodes[a], 0));
  for (Index a = 0; a < n; ++a) {
    const Index l_at = out.at(multiplier_dof(slave_facet_k_[f][a], 0));
    const auto& pr = slave_proj_[slave_facet_k_[f][a]];
    const bool transfer = pr && !pr->on_free_boundary;
    fe::FacetShapeValues Nq;
    // ∂N_q(ξ_a)/∂(x_a, master facet nodes)
    Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic, 0, fe::kMaxFacetNodes, kMaxStencil> dNq;
    std::array<Index, kMaxStencilPoints> q_at{};
    StencilNodes stencil;
    if (transfer) {
      const fe::ReferenceFacet& master_facet = fe::reference_facet(master_.facet_type(pr->facet));
      Nq = master_facet.shape(pr->xi);
      stencil = stencil_nodes(nodes[a], master_, pr->facet);
      for (int j = 0; j < stencil.size; ++j)
        q_at[j] = out.at(u_dof(stencil[j], 0));
      if (out.with_jacobian())
        dNq = master_facet.shape_grad(pr->xi) *
              projection_derivatives(*pr, coords(master_, pr->facet, x)).dxi;
    }
    for (int c = 0; c < lam.cols(); ++c) {
      const dofs::FieldId F = law_->paired_field(c);
      const Real sc = law_->work_factor(c, dt);
      const int axis = law_->work_axis(c);
      const Vec3 a_a = sc * point_work_vector(axis, A.segment<3>(3 * a));
      const auto da = [&](Index b) {
        return Mat3(sc *
                    point_work_derivative(axis, A.segment<3>(3 * a), dA.block<3, 3>(3 * a, 3 * b)));
      };
      const Index row = out.at(dofs_.dof(F, nodes[a], 0));
      out.r().segment<3>(row) -= lam(a, c) * a_a;
      if (out.with_jacobian()) {
        out.K().block<3, 1>(row, l_at + c) -= a_a;
        for (Index b = 0; b < n; ++b)
          out.K().block<3, 3>(row, x_at[b]) -= lam(a, c) * da(b);
      }
      if (!transfer)
        continue;
      for (Index qn = 0; qn < Nq.size(); ++qn) {
        const Index qrow = out.at(dofs_.dof(F, stencil[static_cast<int>(qn) + 1], 0));
        out.r().segment<3>(qrow) += lam(a, c) * Nq[qn] * a_a;
        if (!out.with_jacobian())
          continue;
        out.K().block<3, 1>(qrow, l_at + c) += Nq[qn] * a_a;
        for (Index b = 0; b < n; ++b)
          out.K().block<3, 3>(qrow, x_at[b]) += lam(a, c) * Nq[qn] * da(b);
        for (int j = 0; j < stencil.size; ++j)
          out.K().block<3, 3>(qrow, q_at[j]) += lam(a, c) * a_a * dNq.row(qn).segment<3>(3 * j);
      }
    }
  }
}

Vec3 ContactTerm::slave_force(const Vector& x, bool friction_only) const {
  Vec3 f = Vec3::Zero();
  for (Index s = 0; s < slave_.num_facets(); ++s) {
    const FacetCoords X = coords(slave_, s, x);
    const FacetMultipliers lam = facet_multipliers(s, x);
    for (const auto& qp : X.reference->rule().points) {
      const FacetPoint fp = evaluate_facet(X, qp.xi);
      for (int c = 0; c < lam.cols(); ++c) // = Σ_a λ_a a_a as well (lumped forces: same sum)
        if (law_->paired_field(c) == u_ && (!friction_only || law_->work_axis(c) >= 0))
          f += fp.N.dot(lam.col(c)) * work_vector(law_->work_axis(c), 1.0, fp, qp.weight);
    }
  }
  return f;
}

Vec3 ContactTerm::master_force(const Vector& x) const {
  Vec3 f = Vec3::Zero();
  const int C = law_->num_components();
  if (settings_.integration == Integration::SlaveNodes) {
    for (Index s = 0; s < slave_.num_facets(); ++s) {
      const FacetCoords X = coords(slave_, s, x);
      const physics::FacetVectorX A = physics::facet_area_vectors(*X.reference, X.x);
      for (Index a = 0; a < X.num_nodes(); ++a) {
        const Index k = slave_facet_k_[s][a];
        if (!slave_proj_[k] || slave_proj_[k]->on_free_boundary)
          continue;
        for (int c = 0; c < C; ++c)
          if (law_->paired_field(c) == u_)
            f -= x[multiplier_dof(k, c)] *
                 point_work_vector(law_->work_axis(c), A.segment<3>(3 * a));
      }
    }
    return f;
  }
  for (Index m = 0; m < master_.num_facets(); ++m) {
    const auto nodes = master_.facet_nodes(m);
    const FacetCoords X = coords(master_, m, x);
    // λ^m_i of the nodes (rows) per component (columns)
    FacetMultipliers lm = FacetMultipliers::Zero(X.num_nodes(), C);
    for (Index i = 0; i < X.num_nodes(); ++i) {
      const auto& pr = master_proj_[master_.local_node(nodes[i])];
      if (pr && !pr->on_free_boundary)
        lm.row(i) = fe::reference_facet(slave_.facet_type(pr->facet)).shape(pr->xi).transpose() *
                    facet_multipliers(pr->facet, x);
    }
    for (const auto& qp : X.reference->rule().points) {
      const FacetPoint fp = evaluate_facet(X, qp.xi);
      for (int c = 0; c < C; ++c)
        if (law_->paired_field(c) == u_)
          f += fp.N.dot(lm.col(c)) * work_vector(law_->work_axis(c), -1.0, fp, qp.weight);
    }
  }
  return f;
}

} // namespace trifem::contact
