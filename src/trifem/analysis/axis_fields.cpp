// SPDX-License-Identifier: MIT
#include "trifem/analysis/axis_fields.hpp"

#include "trifem/fe/hex8.hpp"

namespace trifem::analysis {

Mat3 centre_deformation_gradient(const model::Model& model, Index cell, const Vector& x) {
  const mesh::Hex8 nodes = model.mesh.cell(cell);
  fe::HexCoords X, u;
  for (int a = 0; a < 8; ++a) {
    X.row(a) = model.mesh.node(nodes[a]).transpose();
    for (int k = 0; k < 3; ++k)
      u(a, k) = x[model.dofs.dof(model.fields.u, nodes[a], k)];
  }
  const fe::HexShapeGrad dN_dxi = fe::hex8_shape_grad(Vec3::Zero());
  const Mat3 dX_dxi = X.transpose() * dN_dxi;
  const fe::HexShapeGrad dN_dX = dN_dxi * dX_dxi.inverse();
  return Mat3::Identity() + u.transpose() * dN_dX;
}

std::vector<io::DataArray> axis_fields(const model::Model& model, const Vector& x) {
  if (model.axes.empty())
    return {};
  const Index n = model.mesh.num_cells();
  io::DataArray axis{"material_axis", 3, std::vector<double>(std::size_t(3) * n)};
  io::DataArray fibre{"fibre_direction", 3, std::vector<double>(std::size_t(3) * n)};
  for (Index c = 0; c < n; ++c) {
    const Vec3 e1 = model.axes[static_cast<std::size_t>(c)].col(0);
    const Vec3 current = (centre_deformation_gradient(model, c, x) * e1).normalized();
    for (int k = 0; k < 3; ++k) {
      axis.values[std::size_t(3 * c + k)] = e1[k];
      fibre.values[std::size_t(3 * c + k)] = current[k];
    }
  }
  return {std::move(axis), std::move(fibre)};
}

} // namespace trifem::analysis
