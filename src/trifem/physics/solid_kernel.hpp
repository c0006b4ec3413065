// SPDX-License-Identifier: MIT
// Total Lagrangian hex8 solid element: internal force and consistent tangent.
#pragma once

#include "trifem/fe/hex8.hpp"
#include "trifem/material/elastic_law.hpp"

namespace trifem::physics {

using HexVector = Eigen::Matrix<Real, 24, 1>;
using HexMatrix = Eigen::Matrix<Real, 24, 24>;
using BMatrix = Eigen::Matrix<Real, 6, 24>;

/// Deformation gradient F = I + sum_a u_a (x) dN_a/dX at one Gauss point.
inline Mat3 deformation_gradient(const fe::HexShapeGrad& dN_dX, const fe::HexCoords& u) {
  return Mat3::Identity() + u.transpose() * dN_dX;
}

/// Fills the nonlinear strain-displacement matrix B (6 x 3n, sized by the caller) of the n nodes
/// whose gradients ∇N_a are the rows of g: {dE} = B {du} (strain-like Voigt rows, node-major DOF
/// columns). Shared by the hex8 and the other families' elements.
template <class Grads, class Strain>
void fill_strain_displacement(const Mat3& F, const Grads& g, Strain& B) {
  for (Index a = 0; a < static_cast<Index>(g.rows()); ++a)
    for (int k = 0; k < 3; ++k) {
      const Index c = 3 * a + k;
      B(0, c) = F(k, 0) * g(a, 0);
      B(1, c) = F(k, 1) * g(a, 1);
      B(2, c) = F(k, 2) * g(a, 2);
      B(3, c) = F(k, 0) * g(a, 1) + F(k, 1) * g(a, 0);
      B(4, c) = F(k, 1) * g(a, 2) + F(k, 2) * g(a, 1);
      B(5, c) = F(k, 0) * g(a, 2) + F(k, 2) * g(a, 0);
    }
}

/// Nonlinear strain-displacement matrix at a point: {dE} = B {du} (strain-like Voigt rows,
/// node-major DOF columns).
void strain_displacement(const Mat3& F, const fe::HexShapeGrad& dN_dX, BMatrix& B);

/// Adds the geometric stiffness of the stress S over dV: K_ab += (dN_a . S dN_b) dV I.
void add_geometric_stiffness(const fe::HexShapeGrad& dN_dX, const Mat3& S, Real dV, HexMatrix& K);

/// Internal force f_a = int F S dN_a/dX dV and, if K is given,
/// K_ab = int [ (dN_a . S dN_b) I + B_a^T D B_b ] dV (Bonet & Wood eqs 9.13, 9.44).
/// DOF order: node-major (u_0x, u_0y, u_0z, u_1x, ...). Returns false if J <= 0 at a Gauss
/// point.
bool solid_hex8(const fe::HexGeometry& geo, const fe::HexCoords& u, const material::ElasticLaw& law,
                HexVector& f, HexMatrix* K);

/// Volume-averaged Cauchy stress and J of a hex8 (for output).
struct CellStress {
  Mat3 cauchy = Mat3::Zero();
  Real J = 1.0;
};
CellStress solid_hex8_stress(const fe::HexGeometry& geo, const fe::HexCoords& u,
                             const material::ElasticLaw& law);

} // namespace trifem::physics
