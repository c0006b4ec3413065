// SPDX-License-Identifier: MIT
#include "trifem/analysis/averages.hpp"

#include "trifem/analysis/probes.hpp"
#include "trifem/core/error.hpp"
#include "trifem/fe/hex8.hpp"
#include "trifem/fe/reference_element.hpp"

namespace trifem::analysis {
namespace {

/// The volumes of the quadrature points of a cell (its family's rule: 2x2x2 Gauss for a hex8),
/// det(dX/dξ) w_q in the reference and det(dx/dξ) w_q = J dV in the current configuration
/// [mm³].
struct GaussVolumes {
  const fe::CellRule* rule = nullptr;
  std::vector<Real> reference;
  std::vector<Real> current;
};

/// Those of a hex8 cell, by its own kernels (the bits of the hex8 path stay as they were).
GaussVolumes hex8_gauss_volumes(const model::Model& model, Index cell, const Vector& x) {
  const mesh::Hex8 nodes = model.mesh.cell(cell);
  fe::HexCoords X, current;
  for (int a = 0; a < 8; ++a) {
    X.row(a) = model.mesh.node(nodes[a]).transpose();
    for (int k = 0; k < 3; ++k)
      current(a, k) = X(a, k) + x[model.dofs.dof(model.fields.u, nodes[a], k)];
  }
  GaussVolumes v{&fe::reference_cell(mesh::CellType::Hex8).rule(), {}, {}};
  for (const fe::HexQuadraturePoint& p : fe::hex_gauss_2x2x2()) { // = the rule's points
    const fe::HexShapeGrad dN = fe::hex8_shape_grad(p.xi);
    v.reference.push_back((X.transpose() * dN).determinant() * p.weight);
    v.current.push_back((current.transpose() * dN).determinant() * p.weight);
  }
  return v;
}

GaussVolumes gauss_volumes(const model::Model& model, Index cell, const Vector& x) {
  if (model.mesh.cell_type(cell) == mesh::CellType::Hex8)
    return hex8_gauss_volumes(model, cell, x);
  const fe::ReferenceCell& ref = fe::reference_cell(model.mesh.cell_type(cell));
  const std::span<const Index> nodes = model.mesh.cell_nodes(cell);
  fe::CellNodeCoords X(ref.num_nodes(), 3), current(ref.num_nodes(), 3);
  for (int a = 0; a < ref.num_nodes(); ++a) {
    X.row(a) = model.mesh.node(nodes[static_cast<std::size_t>(a)]).transpose();
    for (int k = 0; k < 3; ++k)
      current(a, k) =
          X(a, k) + x[model.dofs.dof(model.fields.u, nodes[static_cast<std::size_t>(a)], k)];
  }
  GaussVolumes v{&ref.rule(), {}, {}};
  for (const fe::CellQuadraturePoint& p : ref.rule().points) {
    const fe::ShapeGrads dN = ref.shape_grad(p.xi);
    v.reference.push_back((X.transpose() * dN).determinant() * p.weight);
    v.current.push_back((current.transpose() * dN).determinant() * p.weight);
  }
  return v;
}

/// The sums Σ ∫ f w (per component) and Σ ∫ w of an average.
struct WeightedSum {
  std::vector<Real> integral;
  Real volume = 0.0;
};

/// Adds ∫ f w over the cell for the nodal quantity q, f interpolated at the Gauss points.
void add_nodal_cell(const model::Model& model, const io::ProbeQuantity& q, Index cell,
                    const Vector& x, const GaussVolumes& v, WeightedSum& sum) {
  TRIFEM_VERIFY(q.weight != io::AverageWeight::Water, "{} has no water-volume average", q.name);
  const auto& w = q.weight == io::AverageWeight::Reference ? v.reference : v.current;
  for (std::size_t p = 0; p < w.size(); ++p) {
    const Vec3 f = nodal_quantity(model, q, cell, v.rule->points[p].xi, x);
    for (int k = 0; k < 3; ++k)
      sum.integral[k] += f[k] * w[p];
    sum.volume += w[p];
  }
}

/// Adds ∫ f w over the cell for the cell quantity q: its value times the cell's weight.
void add_cell_value(const CellEvaluator& cells, const io::ProbeQuantity& q, Index cell,
                    const Vector& x, const GaussVolumes& v, WeightedSum& sum) {
  const CellValues values = cells.values(cell, x);
  Real weight = 0.0;
  for (std::size_t p = 0; p < v.reference.size(); ++p)
    weight += q.weight == io::AverageWeight::Reference ? v.reference[p] : v.current[p];
  if (q.weight == io::AverageWeight::Water)
    weight *= values.water_volume_fraction;
  std::vector<double> f;
  append_cell_quantity(values, q.name, f);
  for (std::size_t k = 0; k < f.size(); ++k)
    sum.integral[k] += f[k] * weight;
  sum.volume += weight;
}

} // namespace

std::vector<std::string> average_columns(const model::Average& average) {
  return quantity_columns(average.name, *average.quantity);
}

void append_average_values(const model::Model& model, const CellEvaluator& cells,
                           const model::Average& average, const Vector& x,
                           std::vector<double>& row) {
  const io::ProbeQuantity& q = *average.quantity;
  WeightedSum sum{std::vector<Real>(q.components, 0.0), 0.0};
  for (Index c : average.cells) {
    const GaussVolumes v = gauss_volumes(model, c, x);
    if (q.location == io::ProbeLocation::Node)
      add_nodal_cell(model, q, c, x, v, sum);
    else
      add_cell_value(cells, q, c, x, v, sum);
  }
  for (Real integral : sum.integral)
    row.push_back(integral / sum.volume);
}

} // namespace trifem::analysis
