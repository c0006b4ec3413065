// SPDX-License-Identifier: MIT
// Locking-free solid for nearly incompressible materials: the mean-dilatation (Q1/P0
// three-field) element, condensed per cell, for any hyperelastic law.
#pragma once

#include "trifem/physics/solid_cell.hpp"
#include "trifem/physics/solid_kernel.hpp"

namespace trifem::physics {

/// Mean-dilatation hex8 (Simo, Taylor & Pister 1985; Q1/P0/P0 Hu-Washizu with the cell
/// pressure and dilatation condensed). Every Gauss point sees the modified deformation
///   F̄ = (J̄/J)^(1/3) F,   J̄ = v/V (current over reference cell volume),
/// so that the volume change is constant over the cell while the isochoric part of F is the
/// displacement element's. The element is the potential Π(u) = Σ_q W(C̄_q) w_q, hence its
/// tangent is symmetric. For an uncoupled law W = W_iso(C̃) + U(J) this is W_iso(C̃) + U(J̄)
/// exactly; for coupled laws it is the F̄ form of the same three-field principle.
/// Internal force f = Σ_q B_q^T T_q w_q with the effective second Piola-Kirchhoff stress
///   T = α² S̄ + (p̄ J − s/3) C⁻¹,  α = (J̄/J)^(1/3),  s = S̄ : C̄,  p̄ = Σ_q s_q w_q / (3 v),
/// and K its exact derivative (docs/theory/solid.md). DOF order as solid_hex8. Returns false
/// if J <= 0 at a Gauss point.
bool mean_dilatation_hex8(const fe::HexGeometry& geo, const fe::HexCoords& u,
                          const material::ElasticLaw& law, HexVector& f, HexMatrix* K);

/// Volume-averaged Cauchy stress (1/v) Σ_q F T Fᵀ w_q and J̄ of a mean-dilatation hex8.
CellStress mean_dilatation_hex8_stress(const fe::HexGeometry& geo, const fe::HexCoords& u,
                                       const material::ElasticLaw& law);

/// The same element for a cell of any family (solid_cell.hpp) and its family's rule: hex20
/// with a constant dilatation (Q2/P0), tet10 (P2/P0), penta6 (the wedge's analogue of Q1/P0).
/// A tet4 has one strain per cell already: there it is the displacement element.
bool mean_dilatation_cell(const CellGeometry& geo, const fe::CellNodeCoords& u,
                          const material::ElasticLaw& law, CellVectorX& f, CellMatrixX* K);

/// Volume-averaged Cauchy stress and J̄ of mean_dilatation_cell.
CellStress mean_dilatation_cell_stress(const CellGeometry& geo, const fe::CellNodeCoords& u,
                                       const material::ElasticLaw& law);

/// The cell's energy Π(u, J̄) = Σ_q W(C̄_q) w_q, C̄ = (J̄/J)^(2/3) C, with the dilatation J̄ an
/// independent variable (given, not v/V): the pieces from which an element whose J̄ is averaged
/// over more than one cell builds its force and tangent (nodal_dilatation.hpp). The
/// mean-dilatation element is f = f_u + π ∇J̄, K = K_uu + f_uJ ∇J̄ᵀ + ∇J̄ f_uJᵀ + π_J ∇J̄ ∇J̄ᵀ +
/// π ∇²J̄ with J̄ = v/V (docs/theory/elements.md).
struct DilatationSplit {
  CellVectorX f_u;  ///< ∂Π/∂u at fixed J̄ = Σ Bᵀ (α² S̄ − s/3 C⁻¹) w [N]
  CellMatrixX K_uu; ///< ∂²Π/∂u² at fixed J̄ (with tangent)
  CellVectorX f_uJ; ///< ∂²Π/∂u∂J̄ (with tangent)
  Real pi = 0.0;    ///< ∂Π/∂J̄ = Σ s w / (3 J̄) [N mm]
  Real pi_J = 0.0;  ///< ∂²Π/∂J̄² (with tangent)
};

/// Fills `out` at displacement u and dilatation J̄ > 0; false if J <= 0 at a point of the rule.
bool dilatation_split(const CellGeometry& geo, const fe::CellNodeCoords& u,
                      const material::ElasticLaw& law, Real Jbar, bool tangent,
                      DilatationSplit& out);

/// The Cauchy stress averaged over the cell, (1/v) Σ_q F T Fᵀ w_q with
/// T = α² S̄ + (P J − s/3) C⁻¹, of a cell of dilatation J̄ whose volume v is loaded by the
/// pressure P = ∂Π/∂v of the element it belongs to (the homogeneous state: P = s/(3J)).
CellStress dilatation_split_stress(const CellGeometry& geo, const fe::CellNodeCoords& u,
                                   const material::ElasticLaw& law, Real Jbar, Real pressure);

/// The current volume v = Σ_q J_q w_q of a cell with its gradient Σ Bᵀ J C⁻¹ w and, with
/// `hessian`, its second derivative by the nodal displacements.
struct CellVolume {
  Real v = 0.0;
  CellVectorX grad;
  CellMatrixX hess;
};

/// Fills `out` at displacement u; false if J <= 0 at a point of the rule.
bool cell_volume(const CellGeometry& geo, const fe::CellNodeCoords& u, bool hessian,
                 CellVolume& out);

} // namespace trifem::physics
