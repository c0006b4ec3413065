// SPDX-License-Identifier: MIT
// Geometric stiffness of the multiplier force H Λ of one cell (hex8, tet10, hex20)
// (docs/theory/explicit.md §5): the part of the tangent that central differences treat explicitly,
// since H is held at t_n.
#pragma once

#include "trifem/explicit/settings.hpp"
#include "trifem/fe/hex8.hpp"
#include "trifem/physics/solid_cell.hpp"
#include "trifem/physics/solid_kernel.hpp"

namespace trifem::explicit_dynamics {

/// K_Λ,e = Λ_e ∂h_e/∂u_e with h_e,a = ∫ ∂Ψ/∂F ∇N_a dV, symmetric 3n × 3n for n nodes,
/// node-major.
/// With the spatial gradients s_a = F⁻ᵀ ∇N_a:
///   Ψ = J − 1: K_ab,ik = Λ ∫ J (s_a,i s_b,k − s_a,k s_b,i) dV,
///   Ψ = ln J:  K_ab,ik = −Λ ∫ s_a,k s_b,i dV.
/// Returns false (K untouched) if det F ≤ 0 at a Gauss point.
bool multiplier_stiffness(const fe::HexGeometry& geo, const fe::HexCoords& u, Constraint constraint,
                          Real lambda, physics::HexMatrix& K);
/// The same for a cell of another family (tet10, hex20) at the points of its rule.
bool multiplier_stiffness(const physics::CellGeometry& geo, const fe::CellNodeCoords& u,
                          Constraint constraint, Real lambda, physics::CellMatrixX& K);

} // namespace trifem::explicit_dynamics
