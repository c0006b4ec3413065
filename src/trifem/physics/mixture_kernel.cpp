// SPDX-License-Identifier: MIT
#include "trifem/physics/mixture_kernel.hpp"

#include "trifem/core/error.hpp"
#include "trifem/physics/solid_kernel.hpp"

#include <cmath>
#include <span>

namespace trifem::physics {

namespace {

/// Rows: corners; columns: nodes (corners, then the mid-edge nodes of `mids`).
MixtureFluxMap corner_map(int nodes, int corners, std::span<const mesh::Edge> mids) {
  MixtureFluxMap P = MixtureFluxMap::Zero(corners, nodes);
  P.leftCols(corners).setIdentity();
  for (std::size_t m = 0; m < mids.size(); ++m)
    for (const int corner : mids[m])
      P(corner, corners + static_cast<int>(m)) = 0.5;
  return P;
}

} // namespace

const MixtureFluxMap& mixture_flux_map(fe::CellType type) {
  static const std::array<MixtureFluxMap, 5> maps = [] {
    std::array<MixtureFluxMap, 5> out;
    for (const fe::CellType t : {fe::CellType::Hex8, fe::CellType::Tet4, fe::CellType::Tet10,
                                 fe::CellType::Penta6, fe::CellType::Hex20})
      out[static_cast<std::size_t>(t)] =
          corner_map(mesh::num_nodes(t), mesh::num_corners(t), mesh::mid_edges(t));
    return out;
  }();
  return maps[static_cast<std::size_t>(type)];
}

const MixtureFluxMap& mixture_flux_map(fe::FacetType type) {
  static const std::array<MixtureFluxMap, 4> maps = [] {
    std::array<MixtureFluxMap, 4> out;
    for (const fe::FacetType t :
         {fe::FacetType::Tri3, fe::FacetType::Tri6, fe::FacetType::Quad4, fe::FacetType::Quad8})
      out[static_cast<std::size_t>(t)] =
          corner_map(mesh::num_nodes(t), mesh::num_corners(t), mesh::mid_edges(t));
    return out;
  }();
  return maps[static_cast<std::size_t>(type)];
}

namespace {

const std::array<fe::HexShape, 8>& shape_at_gauss_points() {
  static const std::array<fe::HexShape, 8> N = [] {
    std::array<fe::HexShape, 8> out;
    for (int q = 0; q < 8; ++q)
      out[q] = fe::hex8_shape(fe::hex_gauss_2x2x2()[q].xi);
    return out;
  }();
  return N;
}

/// The hex8 cell's fixed-size types and kernels (the hex8 element's sizes and order of
/// operations).
struct Hex8Mixture {
  using Geometry = fe::HexGeometry;
  using Node3 = fe::HexCoords;
  using NodeValues = fe::HexShape;
  using NodeMatrix = Eigen::Matrix<Real, 8, 8>;
  using Grad = Eigen::Matrix<Real, 98, 1>;
  using SolidVector = HexVector;
  using SolidMatrix = HexMatrix;
  static constexpr int kMaxPoints = 8;
  /// The fluxes are interpolated by the displacement's shape functions.
  static constexpr bool kSameShapes = true;

  static int nodes(const Geometry&) { return 8; }
  static int flux_nodes(const Geometry&) { return 8; }
  static int points(const Geometry&) { return 8; }
  static const NodeValues& shape(const Geometry&, int q) { return shape_at_gauss_points()[q]; }
  static const fe::HexShapeGrad& grad(const Geometry& geo, int q) { return geo.dN_dX[q]; }
  static Real volume(const Geometry& geo, int q) { return geo.dV[q]; }
  static bool solid(const Geometry& geo, const Node3& u, const material::ElasticLaw& law,
                    SolidVector& f, SolidMatrix* K) {
    return solid_hex8(geo, u, law, f, K);
  }
  static CellStress stress(const Geometry& geo, const Node3& u, const material::ElasticLaw& law) {
    return solid_hex8_stress(geo, u, law);
  }
};

/// A cell of any family (solid_cell.hpp), sized at run time.
struct AnyCellMixture {
  using Geometry = CellGeometry;
  using Node3 = fe::CellNodeCoords;
  using NodeValues = fe::ShapeValues;
  using NodeMatrix =
      Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic, 0, fe::kMaxCellNodes, fe::kMaxCellNodes>;
  using Grad = Eigen::Matrix<Real, Eigen::Dynamic, 1, 0, 12 * fe::kMaxCellNodes + 2, 1>;
  using SolidVector = CellVectorX;
  using SolidMatrix = CellMatrixX;
  static constexpr int kMaxPoints = 27; // hex20's 3x3x3 Gauss rule
  /// The fluxes are interpolated linearly from the corners (mixture_flux_map).
  static constexpr bool kSameShapes = false;

  static int nodes(const Geometry& geo) { return geo.num_nodes(); }
  static int flux_nodes(const Geometry& geo) {
    return static_cast<int>(mixture_flux_map(geo.reference->type()).rows());
  }
  static const MixtureFluxMap& flux_map(const Geometry& geo) {
    return mixture_flux_map(geo.reference->type());
  }
  static int points(const Geometry& geo) { return static_cast<int>(geo.dV.size()); }
  static const NodeValues& shape(const Geometry& geo, int q) {
    return geo.reference->rule_shapes()[static_cast<std::size_t>(q)];
  }
  static const fe::ShapeGrads& grad(const Geometry& geo, int q) {
    return geo.dN_dX[static_cast<std::size_t>(q)];
  }
  static Real volume(const Geometry& geo, int q) { return geo.dV[static_cast<std::size_t>(q)]; }
  static bool solid(const Geometry& geo, const Node3& u, const material::ElasticLaw& law,
                    SolidVector& f, SolidMatrix* K) {
    return solid_cell(geo, u, law, f, K);
  }
  static CellStress stress(const Geometry& geo, const Node3& u, const material::ElasticLaw& law) {
    return solid_cell_stress(geo, u, law);
  }
};

/// Current-configuration values at one quadrature point.
template <class Cell>
struct PointData {
  typename Cell::NodeValues N; ///< the fluxes' shape functions N_a
  typename Cell::Node3 b;      ///< spatial gradients of the displacement's, F^-T Grad N_a
  typename Cell::Node3 bf;     ///< those of the fluxes' (unless Cell::kSameShapes: then b)
  Real dv;                     ///< J dV
  Vec3 w, jp, jm;              ///< interpolated fluxes
  Mat3 Gw, Gp, Gm;             ///< flux gradients sum_a x_a (x) bf_a
};

/// The spatial gradients of the fluxes' shape functions at a point.
template <class Cell>
const typename Cell::Node3& flux_gradients(const PointData<Cell>& d) {
  if constexpr (Cell::kSameShapes)
    return d.b;
  else
    return d.bf;
}

/// Element integrals in the current configuration (docs/theory/triphasic.md §3, §4).
template <class Cell>
struct Integrals {
  using Node3 = typename Cell::Node3;
  std::array<PointData<Cell>, Cell::kMaxPoints> qp;
  int num_points = 0;
  Real V = 0.0;
  Node3 g;                     ///< g_a = int b_a dv (displacement nodes)
  Node3 gf;                    ///< int bf_a dv (flux nodes; unless Cell::kSameShapes: then g)
  typename Cell::NodeMatrix m; ///< int N_a N_b dv (flux nodes)
  std::span<const PointData<Cell>> points() const {
    return {qp.data(), static_cast<std::size_t>(num_points)};
  }
};

/// The flux nodes' area vectors: the outflow of a nodal flux field j is sum_a gf_a . j_a.
template <class Cell>
const typename Cell::Node3& flux_areas(const Integrals<Cell>& I) {
  if constexpr (Cell::kSameShapes)
    return I.g;
  else
    return I.gf;
}

template <class Cell>
bool integrate(const typename Cell::Geometry& geo, const MixtureUnknownsOf<typename Cell::Node3>& x,
               bool ions, bool lumped, Integrals<Cell>& I) {
  const int n = Cell::nodes(geo), nf = Cell::flux_nodes(geo);
  I.num_points = Cell::points(geo);
  I.g.setZero(n, 3);
  if constexpr (!Cell::kSameShapes)
    I.gf.setZero(nf, 3);
  I.m.setZero(nf, nf);
  for (int q = 0; q < I.num_points; ++q) {
    PointData<Cell>& d = I.qp[static_cast<std::size_t>(q)];
    const auto& dN_dX = Cell::grad(geo, q);
    const Mat3 F = Mat3::Identity() + x.u.transpose() * dN_dX;
    const Real J = F.determinant();
    if (!(J > 0.0))
      return false;
    d.b = dN_dX * F.inverse();
    if constexpr (Cell::kSameShapes) {
      d.N = Cell::shape(geo, q);
    } else {
      d.N = Cell::flux_map(geo) * Cell::shape(geo, q);
      d.bf = Cell::flux_map(geo) * d.b;
    }
    const typename Cell::Node3& bf = flux_gradients(d);
    d.dv = J * Cell::volume(geo, q);
    d.w = x.w.transpose() * d.N;
    d.Gw = x.w.transpose() * bf;
    if (ions) {
      d.jp = x.jp.transpose() * d.N;
      d.jm = x.jm.transpose() * d.N;
      d.Gp = x.jp.transpose() * bf;
      d.Gm = x.jm.transpose() * bf;
    }
    I.V += d.dv;
    I.g += d.b * d.dv;
    if constexpr (!Cell::kSameShapes)
      I.gf += d.bf * d.dv;
    I.m += d.N * d.N.transpose() * d.dv;
  }
  if (lumped) {
    const typename Cell::NodeValues row_sums = I.m.rowwise().sum();
    I.m = row_sums.asDiagonal();
  }
  return true;
}

/// Flux of a nodal field out of the element: sum_a g_a . j_a.
template <class Node3>
Real outflow(const Node3& g, const Node3& j) {
  return (g.array() * j.array()).sum();
}

template <class Cell>
MixtureChemistry chemistry(const Integrals<Cell>& I,
                           const MixtureUnknownsOf<typename Cell::Node3>& x,
                           const MixtureHistory& h, const material::MixtureProperties& mat,
                           const MixtureStep& step, bool ions) {
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
  const Real N_plus = h.N_plus - step.dt * outflow(flux_areas(I), x.jp);
  const Real N_minus = h.N_minus - step.dt * outflow(flux_areas(I), x.jm);
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
  // the water-ion friction of the free diffusivity d0 (d itself without one), the ion's own of d
  c.A_wp = RT / (c.phi_w * (mat.free_d_plus > 0.0 ? mat.free_d_plus : c.d_plus));
  c.A_wm = RT / (c.phi_w * (mat.free_d_minus > 0.0 ? mat.free_d_minus : c.d_minus));
  c.A_ww += c.A_wp * c.c_plus + c.A_wm * c.c_minus;
  c.A_pp = mat.free_d_plus > 0.0 ? RT / (c.phi_w * c.c_plus * c.d_plus) : c.A_wp / c.c_plus;
  c.A_mm = mat.free_d_minus > 0.0 ? RT / (c.phi_w * c.c_minus * c.d_minus) : c.A_wm / c.c_minus;
  return c;
}

/// Mass-matrix products W_a = sum_b m_ab x_b (rows = nodes).
template <class Cell>
typename Cell::Node3 mass_product(const Integrals<Cell>& I, const typename Cell::Node3& x) {
  return I.m * x;
}

template <class Cell>
void residual(const Integrals<Cell>& I, const MixtureChemistry& c,
              const MixtureUnknownsOf<typename Cell::Node3>& x, const MixtureHistory& h,
              const MixtureStep& step, const MixtureLayout& L,
              const typename Cell::SolidVector& f_int, LocalVector& r) {
  using Node3 = typename Cell::Node3;
  const Node3& gf = flux_areas(I);
  r.setZero(L.size());
  const Node3 W = mass_product(I, x.w);
  Node3 Rw = c.mu_w * gf - c.A_ww * W;
  for (int a = 0; a < L.nodes; ++a)
    r.segment<3>(L.u(a, 0)) =
        f_int.template segment<3>(3 * a) - (x.p - step.prestress) * I.g.row(a).transpose();
  r[L.p()] = (I.V - h.V_old) / step.dt + outflow(gf, x.w);
  if (L.ions) {
    const Node3 P = mass_product(I, x.jp), M = mass_product(I, x.jm);
    Rw += c.A_wp * P + c.A_wm * M;
    const Node3 Rp = c.mu_plus * gf + c.A_wp * W - c.A_pp * P;
    const Node3 Rm = c.mu_minus * gf + c.A_wm * W - c.A_mm * M;
    for (int a = 0; a < L.flux_nodes; ++a) {
      r.segment<3>(L.jp(a, 0)) = Rp.row(a).transpose();
      r.segment<3>(L.jm(a, 0)) = Rm.row(a).transpose();
    }
    r[L.eta()] =
        outflow(gf, x.jp) - outflow(gf, x.jm) - (h.N_plus - h.N_minus - h.N_fixed) / step.dt;
  }
  for (int a = 0; a < L.flux_nodes; ++a)
    r.segment<3>(L.w(a, 0)) = Rw.row(a).transpose();
}

/// d(outflow)/du_c = int [(div j) b_c - (grad j)^T b_c] dv  (docs/theory/triphasic.md §4, q_b;
/// c runs over the displacement's nodes, grad j is that of the interpolated flux).
template <class Cell>
typename Cell::Node3 outflow_shape_derivative(const Integrals<Cell>& I,
                                              Mat3 PointData<Cell>::*grad) {
  typename Cell::Node3 q;
  q.setZero(I.g.rows(), 3);
  for (const PointData<Cell>& d : I.points()) {
    const Mat3& G = d.*grad;
    q += (G.trace() * d.b - d.b * G) * d.dv;
  }
  return q;
}

/// Derivatives of the element-constant chemistry w.r.t. the local unknowns.
/// (Sized for the cell's triphasic layout; a biphasic one uses the head.)
template <class Cell>
struct ChemistryGradients {
  using Grad = typename Cell::Grad;
  Grad V, mu_w, mu_plus, mu_minus, A_ww, A_wp, A_wm, A_pp, A_mm, Qp, Qm;
};

template <class Cell>
ChemistryGradients<Cell> chemistry_gradients(const Integrals<Cell>& I, const MixtureChemistry& c,
                                             const MixtureHistory& h,
                                             const material::MixtureProperties& mat,
                                             const MixtureStep& step, const MixtureLayout& L) {
  using Grad = typename Cell::Grad;
  using Node3 = typename Cell::Node3;
  ChemistryGradients<Cell> d;
  for (Grad* v : {&d.V, &d.mu_w, &d.mu_plus, &d.mu_minus, &d.A_ww, &d.A_wp, &d.A_wm, &d.A_pp,
                  &d.A_mm, &d.Qp, &d.Qm})
    v->setZero(L.size_with_ions());
  for (int a = 0; a < L.nodes; ++a)
    d.V.template segment<3>(L.u(a, 0)) = I.g.row(a).transpose();
  d.mu_w[L.p()] = 1.0;
  // 1/kappa(J), J = V/V0 (skipped for a constant permeability: the same arithmetic as before)
  const bool kappa_varies = !mat.permeability_law->is_constant();
  if (kappa_varies)
    d.A_ww = (-mat.permeability_law->derivative(c.V / h.V0) / (c.kappa * c.kappa * h.V0)) * d.V;
  if (!L.ions)
    return d;
  const Real RT = step.chem->RT();
  const Node3 qp = outflow_shape_derivative(I, &PointData<Cell>::Gp);
  const Node3 qm = outflow_shape_derivative(I, &PointData<Cell>::Gm);
  for (int a = 0; a < L.nodes; ++a) {
    d.Qp.template segment<3>(L.u(a, 0)) = qp.row(a).transpose();
    d.Qm.template segment<3>(L.u(a, 0)) = qm.row(a).transpose();
  }
  for (int a = 0; a < L.flux_nodes; ++a) {
    d.Qp.template segment<3>(L.jp(a, 0)) = flux_areas(I).row(a).transpose();
    d.Qm.template segment<3>(L.jm(a, 0)) = flux_areas(I).row(a).transpose();
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
  // d±(phi_w): dA_±± and, if d± is also the water-ion friction's (no free diffusivity), dA_w±
  // gain -A (dd±/dphi_w / d±) dphi_w (skipped if d± is constant)
  if (!mat.d_plus_law->is_constant()) {
    const Real dlnd = mat.d_plus_law->derivative(c.phi_w) / c.d_plus;
    if (mat.free_d_plus == 0.0)
      d.A_wp -= (c.A_wp * dlnd) * dphi;
    d.A_pp -= (c.A_pp * dlnd) * dphi;
  }
  if (!mat.d_minus_law->is_constant()) {
    const Real dlnd = mat.d_minus_law->derivative(c.phi_w) / c.d_minus;
    if (mat.free_d_minus == 0.0)
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

/// dg_a/du_b = int (b_a (x) b_b - b_b (x) b_a) dv for the gradients b_a of node a's shape
/// function (of the displacement or of the fluxes) and b_b of the displacement's node b.
inline Mat3 area_derivative(const Eigen::RowVector3d& b_a, const Eigen::RowVector3d& b_b, Real dv) {
  return (b_a.transpose() * b_b - b_b.transpose() * b_a) * dv;
}

/// Adds s[0] dg_a/du_b to the rows of u_a and s[f] dgf_a/du_b to those of the flux field f
/// (w, j+, j-) at flux node a, for the first `rows` of them.
template <class Cell>
void add_area_derivative(const Integrals<Cell>& I, const MixtureLayout& L,
                         const std::array<Real, 4>& s, int rows, LocalMatrix& K) {
  const std::array<int, 4> row_offset = {L.u(0, 0), L.w(0, 0), L.jp(0, 0), L.jm(0, 0)};
  for (const PointData<Cell>& d : I.points()) {
    if constexpr (Cell::kSameShapes) { // one H_ab for every field's rows
      for (int a = 0; a < L.nodes; ++a)
        for (int b = 0; b < L.nodes; ++b) {
          if (a == b)
            continue;
          const Mat3 H = area_derivative(d.b.row(a), d.b.row(b), d.dv);
          for (int f = 0; f < rows; ++f)
            K.block<3, 3>(row_offset[f] + 3 * a, L.u(b, 0)) += s[f] * H;
        }
      continue;
    }
    for (int a = 0; a < L.nodes; ++a)
      for (int b = 0; b < L.nodes; ++b)
        K.block<3, 3>(L.u(a, 0), L.u(b, 0)) += s[0] * area_derivative(d.b.row(a), d.b.row(b), d.dv);
    for (int a = 0; a < L.flux_nodes; ++a)
      for (int b = 0; b < L.nodes; ++b) {
        const Mat3 H = area_derivative(flux_gradients(d).row(a), d.b.row(b), d.dv);
        for (int f = 1; f < rows; ++f)
          K.block<3, 3>(row_offset[f] + 3 * a, L.u(b, 0)) += s[f] * H;
      }
  }
}

template <class Cell>
void tangent(const Integrals<Cell>& I, const MixtureChemistry& c,
             const MixtureUnknownsOf<typename Cell::Node3>& x, const MixtureHistory& h,
             const material::MixtureProperties& mat, const MixtureStep& step,
             const MixtureLayout& L, const typename Cell::SolidMatrix& K_solid, LocalMatrix& K) {
  using Node3 = typename Cell::Node3;
  const int n = L.size();
  K.setZero(n, n);
  K.topLeftCorner(3 * L.nodes, 3 * L.nodes) = K_solid;
  const ChemistryGradients<Cell> d = chemistry_gradients(I, c, h, mat, step, L);
  const Node3 W = mass_product(I, x.w);
  const Node3 P = L.ions ? mass_product(I, x.jp) : Node3(Node3::Zero(L.flux_nodes, 3));
  const Node3 M = L.ions ? mass_product(I, x.jm) : Node3(Node3::Zero(L.flux_nodes, 3));
  const Node3 qw = outflow_shape_derivative(I, &PointData<Cell>::Gw);
  for (int a = 0; a < L.nodes; ++a) {
    const Vec3 ga = I.g.row(a).transpose();
    K.block<3, 1>(L.u(a, 0), L.p()) = -ga;
    K.block<1, 3>(L.p(), L.u(a, 0)) = ga.transpose() / step.dt + qw.row(a);
  }
  for (int a = 0; a < L.flux_nodes; ++a) {
    const Vec3 ga = flux_areas(I).row(a).transpose();
    K.block<1, 3>(L.p(), L.w(a, 0)) = ga.transpose();
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
    for (int b = 0; b < L.flux_nodes; ++b) {
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
  for (const PointData<Cell>& q : I.points())
    for (int a = 0; a < L.flux_nodes; ++a) {
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
      for (int cc = 0; cc < L.nodes; ++cc) {
        const Eigen::RowVector3d bc = q.b.row(cc);
        K.block<3, 3>(L.w(a, 0), L.u(cc, 0)) += s * zw * bc;
        if (L.ions) {
          K.block<3, 3>(L.jp(a, 0), L.u(cc, 0)) += s * zp * bc;
          K.block<3, 3>(L.jm(a, 0), L.u(cc, 0)) += s * zm * bc;
        }
      }
    }
  add_area_derivative(I, L, {-(x.p - step.prestress), c.mu_w, c.mu_plus, c.mu_minus},
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
Real divergence_slope(const Hex8Mixture::Grad& d, const Integrals<Hex8Mixture>& I, Column column) {
  Eigen::Index b = 0, k = 0;
  const Real g = I.g.cwiseAbs().maxCoeff(&b, &k);
  return g > 0.0 ? d[column(static_cast<int>(b), static_cast<int>(k))] / I.g(b, k) : 0.0;
}

/// MixtureFluxBlock::flux_rate: the tangent's rows W ⊗ dA_ww, P ⊗ dA_wp, … restricted to the ion
/// flux columns, which are multiples of g_b (the concentrations depend on the ion fluxes through
/// the cell's outflows; nothing depends on div w).
Eigen::Matrix<Real, 24, 9> flux_rate(const Integrals<Hex8Mixture>& I,
                                     const ChemistryGradients<Hex8Mixture>& d,
                                     const MixtureUnknowns& x, const MixtureLayout& L) {
  using Node3 = Hex8Mixture::Node3;
  Eigen::Matrix<Real, 24, 9> rate = Eigen::Matrix<Real, 24, 9>::Zero();
  if (!L.ions)
    return rate;
  const Node3 W = mass_product(I, x.w), P = mass_product(I, x.jp), M = mass_product(I, x.jm);
  for (int j = kCation; j <= kAnion; ++j) {
    const auto slope = [&](const Hex8Mixture::Grad& g) {
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

/// The element's residual and tangent (mixture_hex8, mixture_cell).
template <class Cell>
bool evaluate_cell(const typename Cell::Geometry& geo,
                   const MixtureUnknownsOf<typename Cell::Node3>& x, const MixtureHistory& history,
                   const material::MixtureProperties& mat, const MixtureStep& step,
                   const MixtureLayout& layout, LocalVector& r, LocalMatrix* K) {
  Integrals<Cell> I;
  if (!integrate(geo, x, layout.ions, step.lumped_flux_mass, I))
    return false;
  const MixtureChemistry c = chemistry(I, x, history, mat, step, layout.ions);
  if (!c.admissible)
    return false;
  typename Cell::SolidVector f_int;
  typename Cell::SolidMatrix K_solid;
  if (!Cell::solid(geo, x.u, *mat.solid, f_int, K ? &K_solid : nullptr))
    return false;
  residual(I, c, x, history, step, layout, f_int, r);
  if (K)
    tangent(I, c, x, history, mat, step, layout, K_solid, *K);
  return true;
}

/// The potentials of a tet cell linear from its corners (mixture_tet): reduces the rows and
/// columns of its constant p and η to those of the corners' values (R' = Eᵀ R, K' = Eᵀ K E with
/// p̄ = Σ_b p_b / 4), then adds what p(x) − p̄ does to the momentum and what the corners' volumes
/// V_b − V/4 do to the water balances.
void to_corner_potentials(const Integrals<AnyCellMixture>& I, const CornerPotentials& corners,
                          const MixtureHistory& h, const MixtureStep& step, const MixtureLayout& L,
                          LocalVector& r, LocalMatrix* K) {
  const int head = L.p(), potentials = L.ions ? 2 : 1;
  Eigen::MatrixXd E = Eigen::MatrixXd::Zero(L.size(), head + 4 * potentials);
  E.topLeftCorner(head, head).setIdentity();
  for (int i = 0; i < potentials; ++i)
    E.block(head + i, head + 4 * i, 1, 4).setConstant(0.25);
  r = E.transpose() * r;
  if (K)
    *K = E.transpose() * (*K) * E;
  const Real p_mean = 0.25 * (corners.p[0] + corners.p[1] + corners.p[2] + corners.p[3]);
  for (const PointData<AnyCellMixture>& d : I.points()) {
    Real p_point = 0.0;
    for (int b = 0; b < 4; ++b)
      p_point += d.N[b] * corners.p[static_cast<std::size_t>(b)];
    for (int b = 0; b < 4; ++b) {
      const Real weight = (d.N[b] - 0.25) * d.dv; // of G_ab − g_a/4 and V_b − V/4
      r[head + b] += weight / step.dt;
      for (int a = 0; a < L.nodes; ++a) {
        const Vec3 G = d.b.row(a).transpose() * weight;
        r.segment<3>(L.u(a, 0)) -= corners.p[static_cast<std::size_t>(b)] * G;
        if (!K)
          continue;
        K->block<3, 1>(L.u(a, 0), head + b) -= G;
        K->block<1, 3>(head + b, L.u(a, 0)) += G.transpose() / step.dt;
      }
    }
    if (K)
      for (int a = 0; a < L.nodes; ++a)
        for (int c = 0; c < L.nodes; ++c)
          K->block<3, 3>(L.u(a, 0), L.u(c, 0)) -=
              (p_point - p_mean) * area_derivative(d.b.row(a), d.b.row(c), d.dv);
  }
  for (int b = 0; b < 4; ++b) // the old volumes: V_b^n − V^n/4
    r[head + b] -= (corners.volume_old[static_cast<std::size_t>(b)] - 0.25 * h.V_old) / step.dt;
}

/// The element's chemistry, mean fluxes and stress (mixture_hex8_output, mixture_cell_output).
template <class Cell>
MixtureCellOutput
output_of_cell(const typename Cell::Geometry& geo, const MixtureUnknownsOf<typename Cell::Node3>& x,
               const MixtureHistory& history, const material::MixtureProperties& mat,
               const MixtureStep& step, bool ions) {
  MixtureCellOutput out;
  Integrals<Cell> I;
  if (!integrate(geo, x, ions, step.lumped_flux_mass, I))
    return out;
  out.chem = chemistry(I, x, history, mat, step, ions);
  for (const PointData<Cell>& d : I.points()) {
    out.w += d.w * d.dv / I.V;
    if (ions) {
      out.j_plus += d.jp * d.dv / I.V;
      out.j_minus += d.jm * d.dv / I.V;
    }
  }
  const CellStress s = Cell::stress(geo, x.u, *mat.solid);
  out.solid_stress = s.cauchy;
  out.J = s.J;
  return out;
}

} // namespace

bool mixture_hex8(const fe::HexGeometry& geo, const MixtureUnknowns& x,
                  const MixtureHistory& history, const material::MixtureProperties& mat,
                  const MixtureStep& step, const MixtureLayout& layout, LocalVector& r,
                  LocalMatrix* K) {
  return evaluate_cell<Hex8Mixture>(geo, x, history, mat, step, layout, r, K);
}

bool mixture_cell(const CellGeometry& geo, const CellMixtureUnknowns& x,
                  const MixtureHistory& history, const material::MixtureProperties& mat,
                  const MixtureStep& step, const MixtureLayout& layout, LocalVector& r,
                  LocalMatrix* K) {
  TRIFEM_VERIFY(layout.nodes == geo.num_nodes(), "the mixture layout has {} nodes, the cell {}",
                layout.nodes, geo.num_nodes());
  return evaluate_cell<AnyCellMixture>(geo, x, history, mat, step, layout, r, K);
}

std::array<Real, 4> corner_volumes(const CellGeometry& geo, const fe::CellNodeCoords& u) {
  TRIFEM_VERIFY(mesh::linear_type(geo.reference->type()) == fe::CellType::Tet4,
                "corner potentials on a {} cell", mesh::name(geo.reference->type()));
  const MixtureFluxMap& P = mixture_flux_map(geo.reference->type());
  std::array<Real, 4> V{};
  for (std::size_t q = 0; q < geo.dV.size(); ++q) {
    const Real dv = (Mat3::Identity() + u.transpose() * geo.dN_dX[q]).determinant() * geo.dV[q];
    const fe::ShapeValues N = P * geo.reference->rule_shapes()[q];
    for (int b = 0; b < 4; ++b)
      V[static_cast<std::size_t>(b)] += N[b] * dv;
  }
  return V;
}

bool mixture_tet(const CellGeometry& geo, const CellMixtureUnknowns& x,
                 const CornerPotentials& corners, const MixtureHistory& history,
                 const material::MixtureProperties& mat, const MixtureStep& step,
                 const MixtureLayout& layout, LocalVector& r, LocalMatrix* K) {
  TRIFEM_VERIFY(layout.nodes == geo.num_nodes() && layout.flux_nodes == 4 &&
                    mesh::linear_type(geo.reference->type()) == fe::CellType::Tet4,
                "corner potentials on a {} cell", mesh::name(geo.reference->type()));
  CellMixtureUnknowns mean = x;
  mean.p = mean.eta = 0.0;
  for (std::size_t b = 0; b < 4; ++b) {
    mean.p += 0.25 * corners.p[b];
    mean.eta += 0.25 * corners.eta[b];
  }
  Integrals<AnyCellMixture> I;
  if (!integrate(geo, mean, layout.ions, step.lumped_flux_mass, I))
    return false;
  const MixtureChemistry c = chemistry(I, mean, history, mat, step, layout.ions);
  if (!c.admissible)
    return false;
  CellVectorX f_int;
  CellMatrixX K_solid;
  if (!solid_cell(geo, mean.u, *mat.solid, f_int, K ? &K_solid : nullptr))
    return false;
  residual(I, c, mean, history, step, layout, f_int, r);
  if (K)
    tangent(I, c, mean, history, mat, step, layout, K_solid, *K);
  to_corner_potentials(I, corners, history, step, layout, r, K);
  return true;
}

std::optional<MixtureFluxBlock>
mixture_hex8_flux_block(const fe::HexGeometry& geo, const MixtureUnknowns& x,
                        const MixtureHistory& history, const material::MixtureProperties& mat,
                        const MixtureStep& step, const MixtureLayout& layout) {
  Integrals<Hex8Mixture> I;
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
  return output_of_cell<Hex8Mixture>(geo, x, history, mat, step, ions);
}

MixtureCellOutput mixture_cell_output(const CellGeometry& geo, const CellMixtureUnknowns& x,
                                      const MixtureHistory& history,
                                      const material::MixtureProperties& mat,
                                      const MixtureStep& step, bool ions) {
  return output_of_cell<AnyCellMixture>(geo, x, history, mat, step, ions);
}

} // namespace trifem::physics
