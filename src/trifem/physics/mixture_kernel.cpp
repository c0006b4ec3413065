// SPDX-License-Identifier: MIT
#include "trifem/physics/mixture_kernel.hpp"

#include "trifem/physics/solid_kernel.hpp"

#include <cmath>

namespace trifem::physics {
namespace {

using Grad = Eigen::Matrix<Real, 98, 1>; ///< derivative of a scalar w.r.t. the local unknowns
using Node3 = Eigen::Matrix<Real, 8, 3>;

/// Current-configuration values at one Gauss point.
struct PointData {
  fe::HexShape N;
  Node3 b;         ///< spatial gradients b_a = F^-T Grad N_a
  Real dv;         ///< J dV
  Vec3 w, jp, jm;  ///< interpolated fluxes
  Mat3 Gw, Gp, Gm; ///< flux gradients sum_a x_a (x) b_a
};

/// Element integrals in the current configuration (docs/theory/triphasic.md §3, §4).
struct Integrals {
  std::array<PointData, 8> qp;
  Real V = 0.0;
  Node3 g = Node3::Zero();                                         ///< g_a = int b_a dv
  Eigen::Matrix<Real, 8, 8> m = Eigen::Matrix<Real, 8, 8>::Zero(); ///< int N_a N_b dv
};

const std::array<fe::HexShape, 8>& shape_at_gauss_points() {
  static const std::array<fe::HexShape, 8> N = [] {
    std::array<fe::HexShape, 8> out;
    for (int q = 0; q < 8; ++q)
      out[q] = fe::hex8_shape(fe::hex_gauss_2x2x2()[q].xi);
    return out;
  }();
  return N;
}

bool integrate(const fe::HexGeometry& geo, const MixtureUnknowns& x, bool ions, bool lumped,
               Integrals& I) {
  for (int q = 0; q < 8; ++q) {
    PointData& d = I.qp[q];
    const Mat3 F = deformation_gradient(geo.dN_dX[q], x.u);
    const Real J = F.determinant();
    if (!(J > 0.0))
      return false;
    d.N = shape_at_gauss_points()[q];
    d.b = geo.dN_dX[q] * F.inverse();
    d.dv = J * geo.dV[q];
    d.w = x.w.transpose() * d.N;
    d.Gw = x.w.transpose() * d.b;
    if (ions) {
      d.jp = x.jp.transpose() * d.N;
      d.jm = x.jm.transpose() * d.N;
      d.Gp = x.jp.transpose() * d.b;
      d.Gm = x.jm.transpose() * d.b;
    }
    I.V += d.dv;
    I.g += d.b * d.dv;
    I.m += d.N * d.N.transpose() * d.dv;
  }
  if (lumped) {
    const Eigen::Matrix<Real, 8, 1> row_sums = I.m.rowwise().sum();
    I.m = row_sums.asDiagonal();
  }
  return true;
}

/// Flux of a nodal field out of the element: sum_a g_a . j_a.
Real outflow(const Node3& g, const fe::HexCoords& j) {
  return (g.array() * j.array()).sum();
}

MixtureChemistry chemistry(const Integrals& I, const MixtureUnknowns& x, const MixtureHistory& h,
                           const material::MixtureProperties& mat, const MixtureStep& step,
                           bool ions) {
  MixtureChemistry c;
  c.V = I.V;
  c.Vw = I.V - mat.phi_s0 * h.V0;
  c.phi_w = c.Vw / c.V;
  c.mu_w = x.p;
  c.admissible = c.Vw > 0.0; // the transport laws are defined for J > phi_s0 only
  if (!c.admissible)
    return c;
  c.kappa = mat.permeability_law->value(c.V / h.V0);
  c.admissible = c.kappa > 0.0;
  c.A_ww = 1.0 / c.kappa;
  if (!ions || !c.admissible)
    return c;
  const material::Electrochemistry& ch = *step.chem;
  const Real RT = ch.RT();
  const Real N_plus = h.N_plus - step.dt * outflow(I.g, x.jp);
  const Real N_minus = h.N_minus - step.dt * outflow(I.g, x.jm);
  c.admissible = N_plus > 0.0 && N_minus > 0.0;
  if (!c.admissible)
    return c;
  c.c_plus = N_plus / c.Vw;
  c.c_minus = N_minus / c.Vw;
  c.c_fixed = h.N_fixed / c.Vw;
  c.mu_w = x.p - RT * (mat.osmotic * (c.c_plus + c.c_minus) - 2.0 * ch.osmotic_bath * ch.c_ref);
  c.mu_plus = RT * std::log(mat.gamma_plus * c.c_plus / (ch.gamma_bath * ch.c_ref)) + x.eta;
  c.mu_minus = RT * std::log(mat.gamma_minus * c.c_minus / (ch.gamma_bath * ch.c_ref)) - x.eta;
  c.d_plus = mat.d_plus_law->value(c.phi_w);
  c.d_minus = mat.d_minus_law->value(c.phi_w);
  c.A_wp = RT / (c.phi_w * c.d_plus);
  c.A_wm = RT / (c.phi_w * c.d_minus);
  c.A_ww += c.A_wp * c.c_plus + c.A_wm * c.c_minus;
  c.A_pp = c.A_wp / c.c_plus;
  c.A_mm = c.A_wm / c.c_minus;
  return c;
}

/// Mass-matrix products W_a = sum_b m_ab x_b (rows = nodes).
Node3 mass_product(const Integrals& I, const fe::HexCoords& x) {
  return I.m * x;
}

void residual(const Integrals& I, const MixtureChemistry& c, const MixtureUnknowns& x,
              const MixtureHistory& h, const MixtureStep& step, const MixtureLayout& L,
              const HexVector& f_int, LocalVector& r) {
  r.setZero(L.size());
  const Node3 W = mass_product(I, x.w);
  Node3 Rw = c.mu_w * I.g - c.A_ww * W;
  for (int a = 0; a < 8; ++a)
    r.segment<3>(L.u(a, 0)) =
        f_int.segment<3>(3 * a) - (x.p - step.prestress) * I.g.row(a).transpose();
  r[L.p()] = (I.V - h.V_old) / step.dt + outflow(I.g, x.w);
  if (L.ions) {
    const Node3 P = mass_product(I, x.jp), M = mass_product(I, x.jm);
    Rw += c.A_wp * P + c.A_wm * M;
    const Node3 Rp = c.mu_plus * I.g + c.A_wp * W - c.A_pp * P;
    const Node3 Rm = c.mu_minus * I.g + c.A_wm * W - c.A_mm * M;
    for (int a = 0; a < 8; ++a) {
      r.segment<3>(L.jp(a, 0)) = Rp.row(a).transpose();
      r.segment<3>(L.jm(a, 0)) = Rm.row(a).transpose();
    }
    r[L.eta()] =
        outflow(I.g, x.jp) - outflow(I.g, x.jm) - (h.N_plus - h.N_minus - h.N_fixed) / step.dt;
  }
  for (int a = 0; a < 8; ++a)
    r.segment<3>(L.w(a, 0)) = Rw.row(a).transpose();
}

/// d(outflow)/du_c = int [(div j) b_c - (grad j)^T b_c] dv  (docs/theory/triphasic.md §4, q_b).
Node3 outflow_shape_derivative(const Integrals& I, Mat3 PointData::*grad) {
  Node3 q = Node3::Zero();
  for (const PointData& d : I.qp) {
    const Mat3& G = d.*grad;
    q += (G.trace() * d.b - d.b * G) * d.dv;
  }
  return q;
}

/// Derivatives of the element-constant chemistry w.r.t. the local unknowns.
struct ChemistryGradients {
  Grad V, mu_w, mu_plus, mu_minus, A_ww, A_wp, A_wm, A_pp, A_mm, Qp, Qm;
};

ChemistryGradients chemistry_gradients(const Integrals& I, const MixtureChemistry& c,
                                       const MixtureHistory& h,
                                       const material::MixtureProperties& mat,
                                       const MixtureStep& step, const MixtureLayout& L) {
  ChemistryGradients d;
  for (Grad* v : {&d.V, &d.mu_w, &d.mu_plus, &d.mu_minus, &d.A_ww, &d.A_wp, &d.A_wm, &d.A_pp,
                  &d.A_mm, &d.Qp, &d.Qm})
    v->setZero();
  for (int a = 0; a < 8; ++a)
    d.V.segment<3>(L.u(a, 0)) = I.g.row(a).transpose();
  d.mu_w[L.p()] = 1.0;
  // 1/kappa(J), J = V/V0 (skipped for a constant permeability: the same arithmetic as before)
  const bool kappa_varies = !mat.permeability_law->is_constant();
  if (kappa_varies)
    d.A_ww = (-mat.permeability_law->derivative(c.V / h.V0) / (c.kappa * c.kappa * h.V0)) * d.V;
  if (!L.ions)
    return d;
  const Real RT = step.chem->RT();
  const Node3 qp = outflow_shape_derivative(I, &PointData::Gp);
  const Node3 qm = outflow_shape_derivative(I, &PointData::Gm);
  for (int a = 0; a < 8; ++a) {
    d.Qp.segment<3>(L.u(a, 0)) = qp.row(a).transpose();
    d.Qm.segment<3>(L.u(a, 0)) = qm.row(a).transpose();
    d.Qp.segment<3>(L.jp(a, 0)) = I.g.row(a).transpose();
    d.Qm.segment<3>(L.jm(a, 0)) = I.g.row(a).transpose();
  }
  const Grad dcp = (-step.dt * d.Qp - c.c_plus * d.V) / c.Vw;
  const Grad dcm = (-step.dt * d.Qm - c.c_minus * d.V) / c.Vw;
  const Grad dphi = (mat.phi_s0 * h.V0 / (c.V * c.V)) * d.V;
  d.mu_w -= RT * mat.osmotic * (dcp + dcm);
  d.mu_plus = (RT / c.c_plus) * dcp;
  d.mu_plus[L.eta()] += 1.0;
  d.mu_minus = (RT / c.c_minus) * dcm;
  d.mu_minus[L.eta()] -= 1.0;
  d.A_wp = (-c.A_wp / c.phi_w) * dphi;
  d.A_wm = (-c.A_wm / c.phi_w) * dphi;
  d.A_pp = -c.A_pp * (dcp / c.c_plus + dphi / c.phi_w);
  d.A_mm = -c.A_mm * (dcm / c.c_minus + dphi / c.phi_w);
  // d±(phi_w): dA_w± and dA_±± gain -A (dd±/dphi_w / d±) dphi_w (skipped if d± is constant)
  if (!mat.d_plus_law->is_constant()) {
    const Real dlnd = mat.d_plus_law->derivative(c.phi_w) / c.d_plus;
    d.A_wp -= (c.A_wp * dlnd) * dphi;
    d.A_pp -= (c.A_pp * dlnd) * dphi;
  }
  if (!mat.d_minus_law->is_constant()) {
    const Real dlnd = mat.d_minus_law->derivative(c.phi_w) / c.d_minus;
    d.A_wm -= (c.A_wm * dlnd) * dphi;
    d.A_mm -= (c.A_mm * dlnd) * dphi;
  }
  const Grad dA_ions = c.A_wp * dcp + c.c_plus * d.A_wp + c.A_wm * dcm + c.c_minus * d.A_wm;
  if (kappa_varies)
    d.A_ww += dA_ions;
  else
    d.A_ww = dA_ions;
  return d;
}

/// Adds s * H_ab (dg_a/du_b) to the u-columns of the 3 rows starting at `row`, for all a, b.
void add_area_derivative(const Integrals& I, const std::array<Real, 4>& s,
                         const std::array<int, 4>& row_offset, int rows, LocalMatrix& K) {
  for (const PointData& d : I.qp)
    for (int a = 0; a < 8; ++a)
      for (int b = 0; b < 8; ++b) {
        if (a == b)
          continue;
        const Mat3 H =
            (d.b.row(a).transpose() * d.b.row(b) - d.b.row(b).transpose() * d.b.row(a)) * d.dv;
        for (int f = 0; f < rows; ++f)
          K.block<3, 3>(row_offset[f] + 3 * a, MixtureLayout::u(b, 0)) += s[f] * H;
      }
}

void tangent(const Integrals& I, const MixtureChemistry& c, const MixtureUnknowns& x,
             const MixtureHistory& h, const material::MixtureProperties& mat,
             const MixtureStep& step, const MixtureLayout& L, const HexMatrix& K_solid,
             LocalMatrix& K) {
  const int n = L.size();
  K.setZero(n, n);
  K.topLeftCorner<24, 24>() = K_solid;
  const ChemistryGradients d = chemistry_gradients(I, c, h, mat, step, L);
  const Node3 W = mass_product(I, x.w);
  const Node3 P = L.ions ? mass_product(I, x.jp) : Node3::Zero();
  const Node3 M = L.ions ? mass_product(I, x.jm) : Node3::Zero();
  const Node3 qw = outflow_shape_derivative(I, &PointData::Gw);
  for (int a = 0; a < 8; ++a) {
    const Vec3 ga = I.g.row(a).transpose();
    K.block<3, 1>(L.u(a, 0), L.p()) = -ga;
    K.block<1, 3>(L.p(), L.w(a, 0)) = ga.transpose();
    K.block<1, 3>(L.p(), L.u(a, 0)) = ga.transpose() / step.dt + qw.row(a);
    // rank-one terms of the element-constant chemistry
    K.block(L.w(a, 0), 0, 3, n) +=
        (ga * d.mu_w.head(n).transpose()) - (W.row(a).transpose() * d.A_ww.head(n).transpose());
    if (L.ions) {
      K.block(L.w(a, 0), 0, 3, n) += P.row(a).transpose() * d.A_wp.head(n).transpose() +
                                     M.row(a).transpose() * d.A_wm.head(n).transpose();
      K.block(L.jp(a, 0), 0, 3, n) += ga * d.mu_plus.head(n).transpose() +
                                      W.row(a).transpose() * d.A_wp.head(n).transpose() -
                                      P.row(a).transpose() * d.A_pp.head(n).transpose();
      K.block(L.jm(a, 0), 0, 3, n) += ga * d.mu_minus.head(n).transpose() +
                                      W.row(a).transpose() * d.A_wm.head(n).transpose() -
                                      M.row(a).transpose() * d.A_mm.head(n).transpose();
    }
    // friction blocks (element-constant coefficients times the current mass matrix)
    for (int b = 0; b < 8; ++b) {
      const Real mab = I.m(a, b);
      for (int k = 0; k < 3; ++k) {
        K(L.w(a, k), L.w(b, k)) -= c.A_ww * mab;
        if (!L.ions)
          continue;
        K(L.w(a, k), L.jp(b, k)) += c.A_wp * mab;
        K(L.w(a, k), L.jm(b, k)) += c.A_wm * mab;
        K(L.jp(a, k), L.w(b, k)) += c.A_wp * mab;
        K(L.jm(a, k), L.w(b, k)) += c.A_wm * mab;
        K(L.jp(a, k), L.jp(b, k)) -= c.A_pp * mab;
        K(L.jm(a, k), L.jm(b, k)) -= c.A_mm * mab;
      }
    }
  }
  // shape derivatives of the mass-matrix products: d(sum_b m_ab x_b)/du_c = int N_a x_h (x) b_c dv
  // (lumped: d(l_a x_a)/du_c = int N_a x_a (x) b_c dv, the nodal values in place of x_h)
  for (const PointData& q : I.qp)
    for (int a = 0; a < 8; ++a) {
      const Vec3 w = step.lumped_flux_mass ? Vec3(x.w.row(a).transpose()) : q.w;
      const Vec3 jp = !L.ions                 ? Vec3::Zero()
                      : step.lumped_flux_mass ? Vec3(x.jp.row(a).transpose())
                                              : q.jp;
      const Vec3 jm = !L.ions                 ? Vec3::Zero()
                      : step.lumped_flux_mass ? Vec3(x.jm.row(a).transpose())
                                              : q.jm;
      const Vec3 zw = -c.A_ww * w + (L.ions ? Vec3(c.A_wp * jp + c.A_wm * jm) : Vec3::Zero());
      const Vec3 zp = c.A_wp * w - c.A_pp * jp;
      const Vec3 zm = c.A_wm * w - c.A_mm * jm;
      const Real s = q.N[a] * q.dv;
      for (int cc = 0; cc < 8; ++cc) {
        const Eigen::RowVector3d bc = q.b.row(cc);
        K.block<3, 3>(L.w(a, 0), L.u(cc, 0)) += s * zw * bc;
        if (L.ions) {
          K.block<3, 3>(L.jp(a, 0), L.u(cc, 0)) += s * zp * bc;
          K.block<3, 3>(L.jm(a, 0), L.u(cc, 0)) += s * zm * bc;
        }
      }
    }
  add_area_derivative(I, {-(x.p - step.prestress), c.mu_w, c.mu_plus, c.mu_minus}, {0, 24, 48, 72},
                      L.ions ? 4 : 2, K);
  if (L.ions)
    K.row(L.eta()) = (d.Qp - d.Qm).head(n).transpose();
}

/// Fields of MixtureFluxBlock's rows and columns.
enum FluxField { kWater = 0, kCation = 1, kAnion = 2 };

/// The friction blocks of tangent(): K(f_i(a,k), f_j(b,k)) = friction(i,j) m_ab.
Mat3 friction_matrix(const MixtureChemistry& c, bool ions) {
  Mat3 f = Mat3::Zero();
  f(kWater, kWater) = -c.A_ww;
  if (!ions)
    return f;
  f(kWater, kCation) = f(kCation, kWater) = c.A_wp;
  f(kWater, kAnion) = f(kAnion, kWater) = c.A_wm;
  f(kCation, kCation) = -c.A_pp;
  f(kAnion, kAnion) = -c.A_mm;
  return f;
}

/// The rank-one terms g_a ⊗ dμ̄_i of tangent() on the flux columns: the concentrations depend on
/// the ion fluxes through the outflows, dc±/dj±_b = −Δt g_b / V_w, and dμ̄_w/dc± = −RTΦ,
/// dμ̄_±/dc± = RT/c± (chemistry_gradients()); nothing depends on w.
Mat3 divergence_matrix(const MixtureChemistry& c, const material::MixtureProperties& mat,
                       const MixtureStep& step, bool ions) {
  Mat3 gamma = Mat3::Zero();
  if (!ions)
    return gamma;
  const Real RT = step.chem->RT();
  const Real dc = -step.dt / c.Vw; // dc±/d(Σ_b g_b · j±_b)
  gamma(kWater, kCation) = gamma(kWater, kAnion) = -RT * mat.osmotic * dc;
  gamma(kCation, kCation) = (RT / c.c_plus) * dc;
  gamma(kAnion, kAnion) = (RT / c.c_minus) * dc;
  return gamma;
}

/// d(coefficient)/d(div j) of a chemistry gradient `d` over the flux columns `column(b, k)` of
/// one field: their entries are that derivative times g_b[k] (read at the largest |g_b[k]|).
template <typename Column>
Real divergence_slope(const Grad& d, const Integrals& I, Column column) {
  Eigen::Index b = 0, k = 0;
  const Real g = I.g.cwiseAbs().maxCoeff(&b, &k);
  return g > 0.0 ? d[column(static_cast<int>(b), static_cast<int>(k))] / I.g(b, k) : 0.0;
}

/// MixtureFluxBlock::flux_rate: the tangent's rows W ⊗ dA_ww, P ⊗ dA_wp, … restricted to the ion
/// flux columns, which are multiples of g_b (the concentrations depend on the ion fluxes through
/// the cell's outflows; nothing depends on div w).
Eigen::Matrix<Real, 24, 9> flux_rate(const Integrals& I, const ChemistryGradients& d,
                                     const MixtureUnknowns& x, const MixtureLayout& L) {
  Eigen::Matrix<Real, 24, 9> rate = Eigen::Matrix<Real, 24, 9>::Zero();
  if (!L.ions)
    return rate;
  const Node3 W = mass_product(I, x.w), P = mass_product(I, x.jp), M = mass_product(I, x.jm);
  for (int j = kCation; j <= kAnion; ++j) {
    const auto slope = [&](const Grad& g) {
      return j == kCation ? divergence_slope(g, I, [&](int b, int k) { return L.jp(b, k); })
                          : divergence_slope(g, I, [&](int b, int k) { return L.jm(b, k); });
    };
    const Real ww = slope(d.A_ww), wp = slope(d.A_wp), wm = slope(d.A_wm);
    const Real pp = slope(d.A_pp), mm = slope(d.A_mm);
    for (int a = 0; a < 8; ++a)
      for (int k = 0; k < 3; ++k) {
        const int row = 3 * a + k;
        rate(row, 3 * kWater + j) = -W(a, k) * ww + P(a, k) * wp + M(a, k) * wm;
        rate(row, 3 * kCation + j) = W(a, k) * wp - P(a, k) * pp;
        rate(row, 3 * kAnion + j) = W(a, k) * wm - M(a, k) * mm;
      }
  }
  return rate;
}

} // namespace

bool mixture_hex8(const fe::HexGeometry& geo, const MixtureUnknowns& x,
                  const MixtureHistory& history, const material::MixtureProperties& mat,
                  const MixtureStep& step, const MixtureLayout& layout, LocalVector& r,
                  LocalMatrix* K) {
  Integrals I;
  if (!integrate(geo, x, layout.ions, step.lumped_flux_mass, I))
    return false;
  const MixtureChemistry c = chemistry(I, x, history, mat, step, layout.ions);
  if (!c.admissible)
    return false;
  HexVector f_int;
  HexMatrix K_solid;
  if (!solid_hex8(geo, x.u, *mat.solid, f_int, K ? &K_solid : nullptr))
    return false;
  residual(I, c, x, history, step, layout, f_int, r);
  if (K)
    tangent(I, c, x, history, mat, step, layout, K_solid, *K);
  return true;
}

std::optional<MixtureFluxBlock>
mixture_hex8_flux_block(const fe::HexGeometry& geo, const MixtureUnknowns& x,
                        const MixtureHistory& history, const material::MixtureProperties& mat,
                        const MixtureStep& step, const MixtureLayout& layout) {
  Integrals I;
  if (!integrate(geo, x, layout.ions, step.lumped_flux_mass, I))
    return std::nullopt;
  const MixtureChemistry c = chemistry(I, x, history, mat, step, layout.ions);
  if (!c.admissible)
    return std::nullopt;
  MixtureFluxBlock out;
  out.friction = friction_matrix(c, layout.ions);
  out.gamma = divergence_matrix(c, mat, step, layout.ions);
  if (layout.ions)
    out.flux_rate = flux_rate(I, chemistry_gradients(I, c, history, mat, step, layout), x, layout);
  out.coupling(0, kWater) = 1.0; // K^pw = g
  if (layout.ions) {
    out.coupling(1, kCation) = 1.0; // K^η± = ±g
    out.coupling(1, kAnion) = -1.0;
  }
  out.area = I.g;
  out.lumped_mass = I.m.rowwise().sum();
  return out;
}

MixtureCellOutput mixture_hex8_output(const fe::HexGeometry& geo, const MixtureUnknowns& x,
                                      const MixtureHistory& history,
                                      const material::MixtureProperties& mat,
                                      const MixtureStep& step, bool ions) {
  MixtureCellOutput out;
  Integrals I;
  if (!integrate(geo, x, ions, step.lumped_flux_mass, I))
    return out;
  out.chem = chemistry(I, x, history, mat, step, ions);
  for (const PointData& d : I.qp) {
    out.w += d.w * d.dv / I.V;
    if (ions) {
      out.j_plus += d.jp * d.dv / I.V;
      out.j_minus += d.jm * d.dv / I.V;
    }
  }
  const CellStress s = solid_hex8_stress(geo, x.u, *mat.solid);
  out.solid_stress = s.cauchy;
  out.J = s.J;
  return out;
}

} // namespace trifem::physics
