// SPDX-License-Identifier: MIT
#include "trifem/analysis/averages.hpp"

#include "trifem/analysis/probes.hpp"
#include "trifem/core/error.hpp"
#include "trifem/fe/hex8.hpp"

#include <array>

namespace trifem::analysis {
namespace {

/// The volumes of the 2x2x2 Gauss points of a cell, det(dX/dξ) w_q in the reference and
/// det(dx/dξ) w_q = J dV in the current configuration [mm³].
struct GaussVolumes {
  std::array<Real, 8> reference{};
  std::array<Real, 8> current{};
};

GaussVolumes gauss_volumes(const model::Model& model, Index cell, const Vector& x) {
  const mesh::Hex8& nodes = model.mesh.cell(cell);
  fe::HexCoords X, current;
  for (int a = 0; a < 8; ++a) {
    X.row(a) = model.mesh.node(nodes[a]).transpose();
    for (int k = 0; k < 3; ++k)
      current(a, k) = X(a, k) + x[model.dofs.dof(model.fields.u, nodes[a], k)];
  }
  GaussVolumes v;
  const auto& rule = fe::hex_gauss_2x2x2();
  for (int q = 0; q < 8; ++q) {
    const fe::HexShapeGrad dN = fe::hex8_shape_grad(rule[q].xi);
    v.reference[q] = (X.transpose() * dN).determinant() * rule[q].weight;
    v.current[q] = (current.transpose() * dN).determinant() * rule[q].weight;
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
  const auto& rule = fe::hex_gauss_2x2x2();
  const auto& w = q.weight == io::AverageWeight::Reference ? v.reference : v.current;
  for (int p = 0; p < 8; ++p) {
    const Vec3 f = nodal_quantity(model, q, cell, rule[p].xi, x);
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
  for (int p = 0; p < 8; ++p)
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
