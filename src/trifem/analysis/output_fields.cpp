// SPDX-License-Identifier: MIT
#include "trifem/analysis/output_fields.hpp"

#include "trifem/analysis/axis_fields.hpp"
#include "trifem/analysis/cell_values.hpp"

#include <fmt/format.h>

namespace trifem::analysis {
namespace {

io::DataArray array(std::string name, int components, Index count) {
  return {std::move(name), components, std::vector<double>(std::size_t(components) * count, 0.0)};
}

/// Nodal field values (physical units: ion fluxes are stored divided by c_ref).
io::DataArray nodal_vector(const model::Model& model, dofs::FieldId f, std::string name,
                           Real scale) {
  const Index n = model.mesh.num_nodes();
  io::DataArray a = array(std::move(name), 3, n);
  const Vector& x = model.problem->state();
  for (Index node = 0; node < n; ++node)
    for (int k = 0; k < 3; ++k)
      a.values[3 * node + k] = scale * x[model.dofs.dof(f, node, k)];
  return a;
}

/// A flux field (stored at the corners of the cells: physics::mixture_flux_map) with the values
/// of its linear interpolation at the mid-edge nodes of tet10 and hex20 cells, so that the
/// quadratic cells of the output draw it as the model interpolates it.
io::DataArray nodal_flux(const model::Model& model, dofs::FieldId f, std::string name, Real scale) {
  io::DataArray a = nodal_vector(model, f, std::move(name), scale);
  for (Index c = 0; c < model.mesh.num_cells(); ++c) {
    const mesh::CellType type = model.mesh.cell_type(c);
    const std::span<const mesh::Edge> mids = mesh::mid_edges(type);
    const std::span<const Index> nodes = model.mesh.cell_nodes(c);
    for (std::size_t m = 0; m < mids.size(); ++m) {
      const auto node = [&](int local) { return nodes[static_cast<std::size_t>(local)]; };
      const Index mid = node(mesh::num_corners(type) + static_cast<int>(m));
      for (int k = 0; k < 3; ++k)
        a.values[3 * mid + k] =
            0.5 * (a.values[3 * node(mids[m][0]) + k] + a.values[3 * node(mids[m][1]) + k]);
    }
  }
  return a;
}

/// Average of a cell array over the cells around each node.
io::DataArray nodal_average(const model::Model& model, const io::DataArray& cells,
                            std::string name) {
  const Index n = model.mesh.num_nodes();
  io::DataArray a = array(std::move(name), 1, n);
  std::vector<int> count(n, 0);
  for (Index c = 0; c < model.mesh.num_cells(); ++c)
    for (Index node : model.mesh.cell_nodes(c)) {
      a.values[node] += cells.values[c];
      ++count[node];
    }
  for (Index node = 0; node < n; ++node)
    if (count[node] > 0)
      a.values[node] /= count[node];
  return a;
}

} // namespace

std::vector<io::DataArray> point_fields(const model::Model& model, const Vector& R) {
  const Vector& x = model.problem->state();
  std::vector<io::DataArray> out;
  out.push_back(nodal_vector(model, model.fields.u, "displacement [mm]", 1.0));
  io::DataArray reaction = array("reaction_forces [N]", 3, model.mesh.num_nodes());
  for (Index a = 0; a < model.mesh.num_nodes(); ++a)
    for (int k = 0; k < 3; ++k)
      if (const Index d = model.dofs.dof(model.fields.u, a, k);
          model.problem->dof_map().is_constrained(d))
        reaction.values[3 * a + k] = R[d];
  out.push_back(std::move(reaction));
  if (!model.mixture)
    return out;
  out.push_back(nodal_flux(model, model.fields.w, "fluid_flux [mm/s]", 1.0));
  if (model.fields.j_plus.valid()) {
    out.push_back(
        nodal_flux(model, model.fields.j_plus, "cation_flux [mmol/(mm^2 s)]", model.chem.c_ref));
    out.push_back(
        nodal_flux(model, model.fields.j_minus, "anion_flux [mmol/(mm^2 s)]", model.chem.c_ref));
  }
  // nodal averages of the element-constant pressure and potential (for smooth contours)
  io::DataArray p = array("p", 1, model.mesh.num_cells()), psi = p;
  for (Index e = 0; e < model.mixture->num_elements(); ++e) {
    const Index c = model.mixture->cell(e);
    const auto [pressure, eta] =
        physics::cell_potentials(model.mesh, model.dofs, model.fields, x, c);
    p.values[c] = pressure;
    psi.values[c] = eta / model.chem.c_ref / model.chem.faraday;
  }
  out.push_back(nodal_average(model, p, "fluid_pressure [MPa]"));
  if (model.fields.eta.valid())
    out.push_back(nodal_average(model, psi, "electric_potential [mV]"));
  return out;
}

namespace {

/// The cell arrays of the VTU files, in their order: name (also the probe quantity), unit,
/// components, and whether only mixture (ion) models write them.
struct CellArray {
  std::string_view name, unit;
  int components;
  io::ProbeRequirement requirement;
};

constexpr CellArray kCellArrays[] = {
    {"stress", "MPa", 6, io::ProbeRequirement::None},
    {"solid_stress", "MPa", 6, io::ProbeRequirement::None},
    {"relative_volume", "", 1, io::ProbeRequirement::None},
    {"fluid_pressure", "MPa", 1, io::ProbeRequirement::Mixture},
    {"fluid_chemical_potential", "MPa", 1, io::ProbeRequirement::Mixture},
    {"water_volume_fraction", "", 1, io::ProbeRequirement::Mixture},
    {"fluid_flux", "mm/s", 3, io::ProbeRequirement::Mixture},
    {"electric_potential", "mV", 1, io::ProbeRequirement::Ions},
    {"cation_concentration", "mM", 1, io::ProbeRequirement::Ions},
    {"anion_concentration", "mM", 1, io::ProbeRequirement::Ions},
    {"fixed_charge_density", "mEq/L", 1, io::ProbeRequirement::Ions},
    {"cation_electrochemical_potential", "mJ/mmol", 1, io::ProbeRequirement::Ions},
    {"anion_electrochemical_potential", "mJ/mmol", 1, io::ProbeRequirement::Ions},
    {"current_density", "A/mm^2", 3, io::ProbeRequirement::Ions},
};

} // namespace

std::vector<io::DataArray> cell_fields(const model::Model& model) {
  const bool mixture = model.mixture != nullptr, ions = model.fields.j_plus.valid();
  std::vector<const CellArray*> written;
  std::vector<io::DataArray> out;
  for (const CellArray& a : kCellArrays)
    if (a.requirement == io::ProbeRequirement::None ||
        (a.requirement == io::ProbeRequirement::Mixture && mixture) ||
        (a.requirement == io::ProbeRequirement::Ions && ions)) {
      written.push_back(&a);
      out.push_back(
          array(a.unit.empty() ? std::string(a.name) : fmt::format("{} [{}]", a.name, a.unit),
                a.components, model.mesh.num_cells()));
    }
  const CellEvaluator evaluator(model);
  const Vector& x = model.problem->state();
  std::vector<double> values;
  for (Index c = 0; c < model.mesh.num_cells(); ++c) {
    const CellValues v = evaluator.values(c, x);
    for (std::size_t i = 0; i < written.size(); ++i) {
      values.clear();
      append_cell_quantity(v, written[i]->name, values);
      std::copy(values.begin(), values.end(), out[i].values.begin() + c * written[i]->components);
    }
  }
  for (io::DataArray& a : axis_fields(model, x))
    out.push_back(std::move(a));
  return out;
}

} // namespace trifem::analysis
