// SPDX-License-Identifier: MIT
#include "trifem/analysis/probes.hpp"

#include "trifem/fe/reference_element.hpp"
#include "trifem/physics/mixture_kernel.hpp"

#include <fmt/format.h>

namespace trifem::analysis {
namespace {

/// The nodal field a nodal probe quantity interpolates and its factor to physical units (ion
/// fluxes are stored divided by c_ref).
std::pair<dofs::FieldId, Real> nodal_field(const model::Model& model, std::string_view name) {
  const physics::MixtureFields& f = model.fields;
  if (name == "fluid_flux")
    return {f.w, 1.0};
  if (name == "cation_flux")
    return {f.j_plus, model.chem.c_ref};
  if (name == "anion_flux")
    return {f.j_minus, model.chem.c_ref};
  return {f.u, 1.0}; // displacement, position
}

} // namespace

Vec3 nodal_quantity(const model::Model& model, const io::ProbeQuantity& q, Index cell,
                    const Vec3& xi, const Vector& x) {
  const auto [field, scale] = nodal_field(model, q.name);
  const mesh::CellType type = model.mesh.cell_type(cell);
  fe::ShapeValues N = fe::reference_cell(type).shape(xi);
  if (field != model.fields.u) // the fluxes: linear from the corners on a tet10 or hex20
    N = physics::mixture_flux_map(type) * N;
  const std::span<const Index> nodes = model.mesh.cell_nodes(cell);
  Vec3 value = Vec3::Zero();
  for (Index a = 0; a < N.size(); ++a) {
    if (N[a] == 0.0)
      continue; // a point on a node or an edge takes exactly the nodal values there
    for (int k = 0; k < 3; ++k)
      value[k] += N[a] * x[model.dofs.dof(field, nodes[static_cast<std::size_t>(a)], k)];
  }
  value *= scale;
  if (q.name == "position") {
    Vec3 X = Vec3::Zero();
    for (Index a = 0; a < N.size(); ++a)
      X += N[a] * model.mesh.node(nodes[static_cast<std::size_t>(a)]);
    value += X;
  }
  return value;
}

std::vector<std::string> quantity_columns(std::string_view name, const io::ProbeQuantity& q) {
  const std::string unit = q.unit.empty() ? "" : fmt::format(" [{}]", q.unit);
  std::vector<std::string> cols;
  if (q.components == 1)
    cols.push_back(fmt::format("{}.{}{}", name, q.name, unit));
  // displacement and position keep their short names: top.ux, top.x
  const std::string prefix = q.name == "displacement" ? "u"
                             : q.name == "position"   ? ""
                                                      : fmt::format("{}_", q.name);
  if (q.components > 1)
    for (int k = 0; k < q.components; ++k)
      cols.push_back(
          fmt::format("{}.{}{}{}", name, prefix, io::component_suffix(q.components, k), unit));
  return cols;
}

std::vector<std::string> probe_columns(const model::Probe& probe) {
  return quantity_columns(probe.name, *probe.quantity);
}

void append_probe_values(const model::Model& model, const CellEvaluator& cells,
                         const model::Probe& probe, const Vector& x, std::vector<double>& row) {
  if (probe.quantity->location == io::ProbeLocation::Node) {
    const Vec3 v = nodal_quantity(model, *probe.quantity, probe.cell, probe.xi, x);
    row.insert(row.end(), {v.x(), v.y(), v.z()});
    return;
  }
  append_cell_quantity(cells.values(probe.cell, x), probe.quantity->name, row);
}

} // namespace trifem::analysis
