// SPDX-License-Identifier: MIT
#include "trifem/physics/mean_dilatation_kernel.hpp"

#include <array>
#include <cmath>

namespace trifem::physics {
namespace {

/// The hex8 cell's fixed-size types and kernels (its bits stay those of the hex8 element).
struct Hex8Cell {
  using Geometry = fe::HexGeometry;
  using Displacements = fe::HexCoords;
  using Vector = HexVector;
  using Matrix = HexMatrix;
  using Strain = BMatrix;
  static constexpr int kMaxPoints = 8;

  static int points(const Geometry&) { return 8; }
  static const fe::HexShapeGrad& grad(const Geometry& geo, int q) { return geo.dN_dX[q]; }
  static Mat3 deformation(const Geometry& geo, int q, const Displacements& u) {
    return deformation_gradient(geo.dN_dX[q], u);
  }
  static Vector zero(const Geometry&) { return Vector::Zero(); }
  static void strain(const Mat3& F, const Geometry& geo, int q, Strain& B) {
    strain_displacement(F, geo.dN_dX[q], B);
  }
  static void geometric(const Geometry& geo, int q, const Mat3& T, Real w, Matrix& K) {
    add_geometric_stiffness(geo.dN_dX[q], T, w, K);
  }
};

/// A cell of any family (solid_cell.hpp), sized at run time.
struct AnyCell {
  using Geometry = CellGeometry;
  using Displacements = fe::CellNodeCoords;
  using Vector = CellVectorX;
  using Matrix = CellMatrixX;
  using Strain = StrainMatrixX;
  static constexpr int kMaxPoints = 27; // hex20's 3x3x3 Gauss rule

  static int points(const Geometry& geo) { return static_cast<int>(geo.dV.size()); }
  static Mat3 deformation(const Geometry& geo, int q, const Displacements& u) {
    return Mat3::Identity() + u.transpose() * geo.dN_dX[static_cast<std::size_t>(q)];
  }
  static Vector zero(const Geometry& geo) { return Vector::Zero(3 * geo.num_nodes()); }
  static void strain(const Mat3& F, const Geometry& geo, int q, Strain& B) {
    strain_displacement(F, geo.dN_dX[static_cast<std::size_t>(q)], B);
  }
  static void geometric(const Geometry& geo, int q, const Mat3& T, Real w, Matrix& K) {
    add_geometric_stiffness(geo.dN_dX[static_cast<std::size_t>(q)], T, w, K);
  }
};

/// Kinematics and modified-deformation stress at one Gauss point.
struct PointState {
  Mat3 F, C, Ci;
  Real J = 1.0, w = 0.0;
  Real alpha = 1.0;           ///< (J̄/J)^(1/3)
  material::StressTangent st; ///< S̄ and D̄ at C̄ = α² C
  Real s = 0.0;               ///< S̄ : C̄
};

/// The cell's points and its volume averages.
template <class Cell>
struct CellState {
  std::array<PointState, Cell::kMaxPoints> points;
  int n = 0;       ///< points used
  Real V = 0.0;    ///< reference volume
  Real v = 0.0;    ///< current volume
  Real Jbar = 1.0; ///< v / V
  Real pbar = 0.0; ///< Σ s w / (3 v): the mean Cauchy pressure-like stress of the cell
};

/// The kinematics of every point of `cell` at displacement u and its volumes V, v; false if
/// J <= 0 somewhere.
template <class Cell>
bool evaluate_kinematics(const typename Cell::Geometry& geo, const typename Cell::Displacements& u,
                         CellState<Cell>& cell) {
  cell.n = Cell::points(geo);
  for (int q = 0; q < cell.n; ++q) {
    PointState& p = cell.points[static_cast<std::size_t>(q)];
    p.F = Cell::deformation(geo, q, u);
    p.J = p.F.determinant();
    if (!(p.J > 0.0))
      return false;
    p.C = p.F.transpose() * p.F;
    p.Ci = p.C.inverse();
    p.w = geo.dV[static_cast<std::size_t>(q)];
    cell.V += p.w;
    cell.v += p.J * p.w;
  }
  return true;
}

/// The modified deformation of point p at the cell's dilatation J̄: α, S̄ (and with `tangent`
/// D̄) at C̄ = α² C, and s = S̄ : C̄.
void evaluate_modified_stress(Real Jbar, const material::ElasticLaw& law, bool tangent,
                              PointState& p) {
  p.alpha = std::cbrt(Jbar / p.J);
  const Mat3 Cbar = p.alpha * p.alpha * p.C;
  if (tangent)
    p.st = law.stress_tangent(Cbar);
  else
    p.st.S = law.stress(Cbar);
  p.s = (p.st.S.array() * Cbar.array()).sum();
}

/// Fills `cell` at displacement u; false if J <= 0 somewhere. With `tangent` the laws'
/// tangents are evaluated too.
template <class Cell>
bool evaluate_state(const typename Cell::Geometry& geo, const typename Cell::Displacements& u,
                    const material::ElasticLaw& law, bool tangent, CellState<Cell>& cell) {
  if (!evaluate_kinematics<Cell>(geo, u, cell))
    return false;
  cell.Jbar = cell.v / cell.V;
  Real sum_s = 0.0;
  for (int q = 0; q < cell.n; ++q) {
    PointState& p = cell.points[static_cast<std::size_t>(q)];
    evaluate_modified_stress(cell.Jbar, law, tangent, p);
    sum_s += p.s * p.w;
  }
  cell.pbar = sum_s / (3.0 * cell.v);
  return true;
}

/// Effective second Piola-Kirchhoff stress T = α² S̄ + (p̄ J − s/3) C⁻¹.
Mat3 effective_stress(const PointState& p, Real pbar) {
  return p.alpha * p.alpha * p.st.S + (pbar * p.J - p.s / 3.0) * p.Ci;
}

/// Adds the exact tangent of f = Σ B^T T w. Per point, ΔT = A ΔE + a ΔJ̄ + b Δp̄ with
/// ΔJ̄ = Σ j·ΔE and Δp̄ = Σ π·ΔE (docs/theory/solid.md), so that
/// K = Σ (Bᵀ A B + geometric) w + (Σ Bᵀ a w)(Σ Bᵀ j)ᵀ + (Σ Bᵀ b w)(Σ Bᵀ π)ᵀ.
template <class Cell>
void add_tangent(const typename Cell::Geometry& geo, const CellState<Cell>& cell,
                 typename Cell::Matrix& K) {
  const Real Jbar = cell.Jbar, pbar = cell.pbar;
  const Mat6 I6 = Mat6::Identity();
  typename Cell::Vector sum_a = Cell::zero(geo), sum_b = Cell::zero(geo);
  typename Cell::Vector grad_Jbar = Cell::zero(geo), grad_pbar = Cell::zero(geo);
  Real dpbar_dJbar = 0.0;
  typename Cell::Strain B;
  for (int q = 0; q < cell.n; ++q) {
    const PointState& p = cell.points[static_cast<std::size_t>(q)];
    const Real a2 = p.alpha * p.alpha;
    const Vec6 c = voigt::stress(p.Ci);                 // C⁻¹ : ΔE = c · ΔE
    const Vec6 Cv = voigt::strain(p.C);                 // c · Cv = 3
    const Vec6 S = voigt::stress(p.st.S);               // S̄
    const Mat6& D = p.st.D;                             // D̄
    const Vec6 h = D.transpose() * (a2 * Cv) + 2.0 * S; // Δs = α² h · ΔĒ/α²
    const Mat6 P = I6 - Cv * c.transpose() / 3.0;       // ΔĒ/α² = P ΔE + Cv ΔJ̄/(3 J̄)
    const Mat3 T = effective_stress(p, pbar);
    const Mat6 A = a2 * a2 * D * P - (2.0 / 3.0) * a2 * S * c.transpose() +
                   pbar * p.J * c * c.transpose() - (a2 / 3.0) * c * (h.transpose() * P) -
                   2.0 * (pbar * p.J - p.s / 3.0) * voigt::symmetric_product(p.Ci);
    const Vec6 a = (2.0 * a2 * S + a2 * a2 * D * Cv - (a2 / 3.0) * h.dot(Cv) * c) / (3.0 * Jbar);
    const Vec6 b = p.J * c;
    const Vec6 j = p.J * p.w / cell.V * c;
    const Vec6 pi = p.w * a2 / (3.0 * cell.v) * (P.transpose() * h) - pbar * p.w / cell.v * p.J * c;
    dpbar_dJbar += p.w * a2 * h.dot(Cv) / (9.0 * cell.v * Jbar);

    Cell::strain(p.F, geo, q, B);
    K.noalias() += B.transpose() * (A * p.w) * B;
    Cell::geometric(geo, q, T, p.w, K);
    sum_a.noalias() += B.transpose() * (a * p.w);
    sum_b.noalias() += B.transpose() * (b * p.w);
    grad_Jbar.noalias() += B.transpose() * j;
    grad_pbar.noalias() += B.transpose() * pi;
  }
  grad_pbar += dpbar_dJbar * grad_Jbar;
  K.noalias() += sum_a * grad_Jbar.transpose() + sum_b * grad_pbar.transpose();
}

template <class Cell>
bool mean_dilatation(const typename Cell::Geometry& geo, const typename Cell::Displacements& u,
                     const material::ElasticLaw& law, typename Cell::Vector& f,
                     typename Cell::Matrix* K) {
  f = Cell::zero(geo);
  if (K)
    K->setZero(f.size(), f.size());
  CellState<Cell> cell;
  if (!evaluate_state<Cell>(geo, u, law, K != nullptr, cell))
    return false;
  typename Cell::Strain B;
  for (int q = 0; q < cell.n; ++q) {
    const PointState& p = cell.points[static_cast<std::size_t>(q)];
    Cell::strain(p.F, geo, q, B);
    f.noalias() += B.transpose() * voigt::stress(effective_stress(p, cell.pbar)) * p.w;
  }
  if (K)
    add_tangent<Cell>(geo, cell, *K);
  return true;
}

template <class Cell>
CellStress mean_dilatation_stress(const typename Cell::Geometry& geo,
                                  const typename Cell::Displacements& u,
                                  const material::ElasticLaw& law) {
  CellState<Cell> cell;
  CellStress out;
  if (!evaluate_state<Cell>(geo, u, law, false, cell))
    return {Mat3::Zero(), 0.0}; // inverted: no converged state is (the residual fails there)
  for (int q = 0; q < cell.n; ++q) {
    const PointState& p = cell.points[static_cast<std::size_t>(q)];
    out.cauchy += p.F * effective_stress(p, cell.pbar) * p.F.transpose() * p.w;
  }
  out.cauchy /= cell.v;
  out.J = cell.Jbar;
  return out;
}

/// The points of a cell at displacement u with the dilatation J̄ given; false if J <= 0.
bool evaluate_split_state(const CellGeometry& geo, const fe::CellNodeCoords& u,
                          const material::ElasticLaw& law, Real Jbar, bool tangent,
                          CellState<AnyCell>& cell) {
  if (!evaluate_kinematics<AnyCell>(geo, u, cell))
    return false;
  cell.Jbar = Jbar;
  for (int q = 0; q < cell.n; ++q)
    evaluate_modified_stress(Jbar, law, tangent, cell.points[static_cast<std::size_t>(q)]);
  return true;
}

} // namespace

bool dilatation_split(const CellGeometry& geo, const fe::CellNodeCoords& u,
                      const material::ElasticLaw& law, Real Jbar, bool tangent,
                      DilatationSplit& out) {
  const int dofs = 3 * geo.num_nodes();
  out.f_u.setZero(dofs);
  out.pi = out.pi_J = 0.0;
  if (tangent) {
    out.K_uu.setZero(dofs, dofs);
    out.f_uJ.setZero(dofs);
  }
  CellState<AnyCell> cell;
  if (!evaluate_split_state(geo, u, law, Jbar, tangent, cell))
    return false;
  const Mat6 I6 = Mat6::Identity();
  StrainMatrixX B;
  for (int q = 0; q < cell.n; ++q) {
    const PointState& p = cell.points[static_cast<std::size_t>(q)];
    const Real a2 = p.alpha * p.alpha;
    const Mat3 T = a2 * p.st.S - (p.s / 3.0) * p.Ci; // the stress at fixed J̄
    AnyCell::strain(p.F, geo, q, B);
    out.f_u.noalias() += B.transpose() * voigt::stress(T) * p.w;
    out.pi += p.s * p.w / (3.0 * Jbar);
    if (!tangent)
      continue;
    // ΔĒ/α² = P ΔE + Cv ΔJ̄/(3 J̄), Δs = α² h · ΔĒ/α² (as the mean-dilatation tangent)
    const Vec6 c = voigt::stress(p.Ci);
    const Vec6 Cv = voigt::strain(p.C);
    const Vec6 S = voigt::stress(p.st.S);
    const Mat6& D = p.st.D;
    const Vec6 h = D.transpose() * (a2 * Cv) + 2.0 * S;
    const Mat6 P = I6 - Cv * c.transpose() / 3.0;
    const Mat6 A = a2 * a2 * D * P - (2.0 / 3.0) * a2 * S * c.transpose() -
                   (a2 / 3.0) * c * (h.transpose() * P) +
                   (2.0 / 3.0) * p.s * voigt::symmetric_product(p.Ci);
    const Vec6 a = (2.0 * a2 * S + a2 * a2 * D * Cv - (a2 / 3.0) * h.dot(Cv) * c) / (3.0 * Jbar);
    out.K_uu.noalias() += B.transpose() * (A * p.w) * B;
    AnyCell::geometric(geo, q, T, p.w, out.K_uu);
    out.f_uJ.noalias() += B.transpose() * (a * p.w);
    out.pi_J += (a2 * h.dot(Cv) / 3.0 - p.s) * p.w / (3.0 * Jbar * Jbar);
  }
  return true;
}

CellStress dilatation_split_stress(const CellGeometry& geo, const fe::CellNodeCoords& u,
                                   const material::ElasticLaw& law, Real Jbar, Real pressure) {
  CellState<AnyCell> cell;
  CellStress out;
  if (!evaluate_split_state(geo, u, law, Jbar, false, cell))
    return {Mat3::Zero(), 0.0}; // inverted: no converged state is (the residual fails there)
  for (int q = 0; q < cell.n; ++q) {
    const PointState& p = cell.points[static_cast<std::size_t>(q)];
    const Mat3 T = p.alpha * p.alpha * p.st.S + (pressure * p.J - p.s / 3.0) * p.Ci;
    out.cauchy += p.F * T * p.F.transpose() * p.w;
  }
  out.cauchy /= cell.v;
  out.J = Jbar;
  return out;
}

bool cell_volume(const CellGeometry& geo, const fe::CellNodeCoords& u, bool hessian,
                 CellVolume& out) {
  const int dofs = 3 * geo.num_nodes();
  out.v = 0.0;
  out.grad.setZero(dofs);
  if (hessian)
    out.hess.setZero(dofs, dofs);
  StrainMatrixX B;
  for (int q = 0; q < AnyCell::points(geo); ++q) {
    const Mat3 F = AnyCell::deformation(geo, q, u);
    const Real J = F.determinant();
    if (!(J > 0.0))
      return false;
    const Mat3 Ci = (F.transpose() * F).inverse();
    const Real w = geo.dV[static_cast<std::size_t>(q)];
    const Vec6 c = voigt::stress(Ci);
    AnyCell::strain(F, geo, q, B);
    out.v += J * w;
    out.grad.noalias() += B.transpose() * (J * w * c);
    if (!hessian)
      continue;
    // Δ(J C⁻¹) = J (C⁻¹ ⊗ C⁻¹ − 2 C⁻¹ ⊙ C⁻¹) ΔE, and the geometric part of the stress J C⁻¹
    const Mat6 A = J * (c * c.transpose() - 2.0 * voigt::symmetric_product(Ci));
    out.hess.noalias() += B.transpose() * (A * w) * B;
    AnyCell::geometric(geo, q, J * Ci, w, out.hess);
  }
  return true;
}

bool mean_dilatation_hex8(const fe::HexGeometry& geo, const fe::HexCoords& u,
                          const material::ElasticLaw& law, HexVector& f, HexMatrix* K) {
  return mean_dilatation<Hex8Cell>(geo, u, law, f, K);
}

CellStress mean_dilatation_hex8_stress(const fe::HexGeometry& geo, const fe::HexCoords& u,
                                       const material::ElasticLaw& law) {
  return mean_dilatation_stress<Hex8Cell>(geo, u, law);
}

bool mean_dilatation_cell(const CellGeometry& geo, const fe::CellNodeCoords& u,
                          const material::ElasticLaw& law, CellVectorX& f, CellMatrixX* K) {
  return mean_dilatation<AnyCell>(geo, u, law, f, K);
}

CellStress mean_dilatation_cell_stress(const CellGeometry& geo, const fe::CellNodeCoords& u,
                                       const material::ElasticLaw& law) {
  return mean_dilatation_stress<AnyCell>(geo, u, law);
}

} // namespace trifem::physics
