// SPDX-License-Identifier: MIT
#include "trifem/physics/solid_kernel.hpp"

#include "trifem/tensor/kinematics.hpp"

namespace trifem::physics {
void strain_displacement(const Mat3& F, const fe::HexShapeGrad& g, BMatrix& B) {
  fill_strain_displacement(F, g, B);
}

void add_geometric_stiffness(const fe::HexShapeGrad& g, const Mat3& S, Real dV, HexMatrix& K) {
  const Eigen::Matrix<Real, 8, 8> G = g * S * g.transpose() * dV;
  for (int a = 0; a < 8; ++a)
    for (int b = 0; b < 8; ++b)
      for (int k = 0; k < 3; ++k)
        K(3 * a + k, 3 * b + k) += G(a, b);
}

bool solid_hex8(const fe::HexGeometry& geo, const fe::HexCoords& u, const material::ElasticLaw& law,
                HexVector& f, HexMatrix* K) {
  f.setZero();
  if (K)
    K->setZero();
  BMatrix B;
  for (int q = 0; q < 8; ++q) {
    const fe::HexShapeGrad& g = geo.dN_dX[q];
    const Mat3 F = deformation_gradient(g, u);
    if (!(F.determinant() > 0.0))
      return false;
    const Mat3 C = F.transpose() * F;
    const Real dV = geo.dV[q];
    if (!K) {
      const Mat3 P = F * law.stress(C);
      for (int a = 0; a < 8; ++a)
        f.segment<3>(3 * a) += P * g.row(a).transpose() * dV;
      continue;
    }
    const material::StressTangent st = law.stress_tangent(C);
    strain_displacement(F, g, B);
    f.noalias() += B.transpose() * voigt::stress(st.S) * dV;
    K->noalias() += B.transpose() * (st.D * dV) * B;
    add_geometric_stiffness(g, st.S, dV, *K);
  }
  return true;
}

CellStress solid_hex8_stress(const fe::HexGeometry& geo, const fe::HexCoords& u,
                             const material::ElasticLaw& law) {
  CellStress out;
  Real volume = 0.0, current = 0.0;
  out.J = 0.0;
  for (int q = 0; q < 8; ++q) {
    const Mat3 F = deformation_gradient(geo.dN_dX[q], u);
    const Real J = F.determinant();
    const Mat3 S = law.stress(F.transpose() * F);
    out.cauchy += kinematics::cauchy_from_pk2(F, S) * J * geo.dV[q];
    volume += geo.dV[q];
    current += J * geo.dV[q];
  }
  out.cauchy /= current;
  out.J = current / volume;
  return out;
}

} // namespace trifem::physics
