// SPDX-License-Identifier: MIT
#include "trifem/physics/cell_mass.hpp"

#include "trifem/core/error.hpp"
#include "trifem/physics/solid_cell.hpp"

#include <cmath>

namespace trifem::physics {

std::optional<Eigen::Matrix<Real, 8, 8>> consistent_cell_mass(const fe::HexCoords& X,
                                                              Real density) {
  Eigen::Matrix<Real, 8, 8> m = Eigen::Matrix<Real, 8, 8>::Zero();
  for (const fe::HexQuadraturePoint& q : fe::hex_gauss_2x2x2()) {
    const fe::HexShape N = fe::hex8_shape(q.xi);
    const Real detJ = (fe::hex8_shape_grad(q.xi).transpose() * X).determinant();
    if (!(detJ > 0.0))
      return std::nullopt;
    m.noalias() += (density * detJ * q.weight) * (N * N.transpose());
  }
  return m;
}

Eigen::MatrixXd consistent_cell_mass(const CellGeometry& geo, Real density) {
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(geo.num_nodes(), geo.num_nodes());
  for (std::size_t q = 0; q < geo.dV.size(); ++q) {
    const fe::ShapeValues& N = geo.reference->rule_shapes()[q];
    m.noalias() += (density * geo.dV[q]) * (N * N.transpose());
  }
  return m;
}

Eigen::VectorXd lumped_mass(const Eigen::MatrixXd& m) {
  Eigen::VectorXd rows = m.rowwise().sum();
  if ((rows.array() > 0.0).all())
    return rows;
  const Eigen::VectorXd diagonal = m.diagonal();
  return (rows.sum() / diagonal.sum()) * diagonal;
}

namespace {

/// The mass element of a cell of a family other than hex8.
MassElement family_cell_mass(const mesh::Mesh& mesh, Index c, Real density) {
  const AnyCellGeometry geometry = reference_geometry(mesh, c); // (throws for an inverted cell)
  const std::span<const Index> nodes = mesh.cell_nodes(c);
  return {{nodes.begin(), nodes.end()},
          consistent_cell_mass(std::get<CellGeometry>(geometry), density)};
}

} // namespace

std::vector<MassElement> cell_mass_elements(const mesh::Mesh& mesh, const std::vector<Index>& cells,
                                            const std::vector<Real>& densities) {
  TRIFEM_VERIFY(cells.size() == densities.size(), "one density per cell expected");
  std::vector<MassElement> out;
  out.reserve(cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i) {
    TRIFEM_VERIFY(densities[i] > 0.0 && std::isfinite(densities[i]), "density must be positive");
    if (mesh.cell_type(cells[i]) != mesh::CellType::Hex8) {
      out.push_back(family_cell_mass(mesh, cells[i], densities[i]));
      continue;
    }
    const auto m = consistent_cell_mass(fe::cell_coordinates(mesh, cells[i]), densities[i]);
    TRIFEM_CHECK(m.has_value(),
                 "{} is inverted or degenerate (det(dX/dxi) <= 0 at a Gauss point); "
                 "check its node order",
                 mesh.describe(cells[i]));
    const auto& nodes = mesh.cell(cells[i]);
    out.push_back({{nodes.begin(), nodes.end()}, *m});
  }
  return out;
}

Eigen::Matrix<Real, 4, 4> consistent_shell_mass(const fe::QuadCoords& X, Real areal_density) {
  Eigen::Matrix<Real, 4, 4> m = Eigen::Matrix<Real, 4, 4>::Zero();
  for (const fe::QuadQuadraturePoint& q : fe::quad_gauss_2x2()) {
    const fe::QuadShape N = fe::quad4_shape(q.xi);
    const Eigen::Matrix<Real, 2, 3> tangents = fe::quad4_shape_grad(q.xi).transpose() * X;
    const Real dA = tangents.row(0).cross(tangents.row(1)).norm();
    m.noalias() += (areal_density * dA * q.weight) * (N * N.transpose());
  }
  return m;
}

} // namespace trifem::physics
