// SPDX-License-Identifier: MIT
#include "trifem/analysis/contact_output.hpp"

#include "trifem/core/log.hpp"
#include "trifem/io/csv_writer.hpp"
#include "trifem/io/pvtu_writer.hpp"
#include "trifem/parallel/communicator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace trifem::analysis {
namespace {

using contact::SlaveNodeState;

/// One array of per-node values f(state).
template <class F>
io::DataArray scalar_array(std::string name, const std::vector<SlaveNodeState>& states, F&& f) {
  io::DataArray a{std::move(name), 1, std::vector<double>(states.size())};
  for (std::size_t k = 0; k < states.size(); ++k)
    a.values[k] = f(states[k]);
  return a;
}

/// Normal component `scale` f·n of the nodal vector field f at a slave node, n = the outward
/// normal of the slave surface (positive: out of the slave body).
Real normal_component(const model::Model& model, dofs::FieldId f, const SlaveNodeState& s,
                      Real scale) {
  const Vector& x = model.problem->state();
  const auto value = [&](Index node) {
    return Vec3(x[model.dofs.dof(f, node, 0)], x[model.dofs.dof(f, node, 1)],
                x[model.dofs.dof(f, node, 2)]);
  };
  // (the fluxes of quadratic cells are linear from the corners: at a mid-edge node, their mean)
  const Vec3 v = s.edge_corners[0] >= 0
                     ? Vec3(0.5 * (value(s.edge_corners[0]) + value(s.edge_corners[1])))
                     : value(s.node);
  return scale * v.dot(s.normal);
}

/// Mixture arrays: the water potential, the ion potentials (stored as c_ref mū_±) and the normal
/// fluxes at the slave nodes (ion flux DOFs hold j / c_ref).
void add_mixture_arrays(const model::Model& model, const std::vector<SlaveNodeState>& states,
                        std::vector<io::DataArray>& out) {
  const physics::MixtureFields& f = model.fields;
  const Real c_ref = model.chem.c_ref;
  const bool ions = f.j_plus.valid();
  out.push_back(scalar_array("fluid_chemical_potential [MPa]", states,
                             [](const SlaveNodeState& s) { return s.multiplier[1]; }));
  if (ions) {
    out.push_back(scalar_array("cation_electrochemical_potential [mJ/mmol]", states,
                               [&](const SlaveNodeState& s) { return s.multiplier[2] / c_ref; }));
    out.push_back(scalar_array("anion_electrochemical_potential [mJ/mmol]", states,
                               [&](const SlaveNodeState& s) { return s.multiplier[3] / c_ref; }));
  }
  out.push_back(scalar_array("normal_fluid_flux [mm/s]", states, [&](const SlaveNodeState& s) {
    return normal_component(model, f.w, s, 1.0);
  }));
  if (!ions)
    return;
  out.push_back(
      scalar_array("normal_cation_flux [mmol/(mm^2 s)]", states, [&](const SlaveNodeState& s) {
        return normal_component(model, f.j_plus, s, c_ref);
      }));
  out.push_back(
      scalar_array("normal_anion_flux [mmol/(mm^2 s)]", states, [&](const SlaveNodeState& s) {
        return normal_component(model, f.j_minus, s, c_ref);
      }));
}

/// VTK cell type of a facet type (VTK's quadratic triangle and quad number their nodes as
/// tri6 and quad8 do: corners, then mid-edge nodes).
std::uint8_t vtk_facet_type(mesh::FacetType type) {
  switch (type) {
  case mesh::FacetType::Tri3:
    return io::vtk_cell::kTriangle;
  case mesh::FacetType::Tri6:
    return io::vtk_cell::kQuadraticTriangle;
  case mesh::FacetType::Quad8:
    return io::vtk_cell::kQuadraticQuad;
  case mesh::FacetType::Quad4:
    break;
  }
  return io::vtk_cell::kQuad;
}

/// The slave surface as VTK cells of its facets' types (points: the slave nodes at their
/// current positions).
io::UnstructuredGrid surface_grid(const contact::ContactTerm& pair,
                                  const std::vector<SlaveNodeState>& states) {
  io::UnstructuredGrid grid;
  for (const SlaveNodeState& s : states)
    grid.points.push_back(s.position);
  const contact::ContactSurface& slave = pair.slave();
  for (Index f = 0; f < slave.num_facets(); ++f) {
    std::vector<Index> local;
    for (const Index node : slave.facet_nodes(f))
      local.push_back(slave.local_node(node));
    grid.add_cell(vtk_facet_type(slave.facet_type(f)), local);
  }
  return grid;
}

/// "name.c [unit]" for component c of the vector array "name [unit]".
std::string component_name(const std::string& name, char c) {
  const auto unit = name.find(" [");
  if (unit == std::string::npos)
    return fmt::format("{}.{}", name, c);
  return fmt::format("{}.{}{}", name.substr(0, unit), c, name.substr(unit));
}

/// The slave facets of `pair` that process `rank` writes: those whose first node with an owner
/// (model::node_owner) it owns; facets of nodes without one go to rank 0.
std::vector<Index> facets_of_process(const model::Model& model, const contact::ContactTerm& pair,
                                     int rank) {
  std::vector<Index> mine;
  const auto& facets = pair.slave().facets();
  for (std::size_t f = 0; f < facets.size(); ++f) {
    int owner = -1;
    for (const Index node : facets[f].nodes)
      if ((owner = model::node_owner(model, node)) >= 0)
        break;
    if (std::max(owner, 0) == rank)
      mine.push_back(static_cast<Index>(f));
  }
  return mine;
}

std::vector<std::string> csv_columns(const std::vector<io::DataArray>& arrays) {
  std::vector<std::string> cols = {"time [s]", "X [mm]", "Y [mm]", "Z [mm]",
                                   "x [mm]",   "y [mm]", "z [mm]"};
  for (const io::DataArray& a : arrays) {
    if (a.components == 1)
      cols.push_back(a.name);
    else
      for (const char c : {'x', 'y', 'z'})
        cols.push_back(component_name(a.name, c));
  }
  cols.emplace_back("node");
  return cols;
}

} // namespace

std::vector<io::DataArray> contact_arrays(const model::Model& model,
                                          const std::vector<SlaveNodeState>& states) {
  std::vector<io::DataArray> out;
  out.push_back(
      scalar_array("contact_gap [mm]", states, [](const SlaveNodeState& s) { return s.gap; }));
  out.push_back(scalar_array("contact_traction [MPa]", states,
                             [](const SlaveNodeState& s) { return s.multiplier[0]; }));
  if (model.fields.w.valid())
    add_mixture_arrays(model, states, out);
  out.push_back(scalar_array("contact_active", states,
                             [](const SlaveNodeState& s) { return s.active ? 1.0 : 0.0; }));
  out.push_back(scalar_array("contact_projected", states,
                             [](const SlaveNodeState& s) { return s.projected ? 1.0 : 0.0; }));
  if (!states.empty() && states.front().frictional) {
    io::DataArray friction{"friction_traction [MPa]", 3, std::vector<double>(3 * states.size())};
    for (std::size_t k = 0; k < states.size(); ++k)
      for (int i = 0; i < 3; ++i)
        friction.values[3 * k + i] = states[k].multiplier[1 + i];
    out.push_back(std::move(friction));
    out.push_back(scalar_array("contact_slipping", states,
                               [](const SlaveNodeState& s) { return s.slipping ? 1.0 : 0.0; }));
    out.push_back(scalar_array("accumulated_slip [mm]", states,
                               [](const SlaveNodeState& s) { return s.accumulated_slip; }));
  }
  io::DataArray normal{"normal", 3, std::vector<double>(3 * states.size())};
  for (std::size_t k = 0; k < states.size(); ++k)
    for (int i = 0; i < 3; ++i)
      normal.values[3 * k + i] = states[k].normal[i];
  out.push_back(std::move(normal));
  out.push_back(scalar_array("nodal_area [mm^2]", states,
                             [](const SlaveNodeState& s) { return s.area_vector.norm(); }));
  return out;
}

std::vector<Index> surface_order(const mesh::Mesh& mesh, const std::vector<Index>& nodes) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<Real>::infinity()), hi = -lo;
  for (Index n : nodes) {
    lo = lo.cwiseMin(mesh.node(n));
    hi = hi.cwiseMax(mesh.node(n));
  }
  const Vec3 extent = nodes.empty() ? Vec3::Zero() : Vec3(hi - lo);
  std::array<int, 3> axes{0, 1, 2};
  std::stable_sort(axes.begin(), axes.end(), [&](int a, int b) { return extent[a] > extent[b]; });
  const Real tie = extent.maxCoeff() > 0 ? 1e-9 * extent.maxCoeff() : 1.0;
  const auto key = [&](Index n) {
    std::array<long long, 3> k{};
    for (int i = 0; i < 3; ++i)
      k[i] = std::llround((mesh.node(n)[axes[i]] - lo[axes[i]]) / tie);
    return k;
  };
  std::vector<Index> order(nodes.size());
  std::iota(order.begin(), order.end(), Index{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](Index a, Index b) { return key(nodes[a]) < key(nodes[b]); });
  return order;
}

std::vector<std::string> contact_history_columns(const model::Model& model) {
  std::vector<std::string> cols;
  for (std::size_t i = 1; i <= model.contacts.size(); ++i) {
    for (const char* c : {"Fx", "Fy", "Fz"})
      cols.push_back(fmt::format("contact{}.{} [N]", i, c));
    for (const char* c : {"Fx", "Fy", "Fz"})
      cols.push_back(fmt::format("contact{}.master_{} [N]", i, c));
    cols.push_back(fmt::format("contact{}.area [mm^2]", i));
    cols.push_back(fmt::format("contact{}.active_nodes", i));
    if (!model.contacts[i - 1]->frictional())
      continue;
    for (const char* c : {"Fx", "Fy", "Fz"})
      cols.push_back(fmt::format("contact{}.friction_{} [N]", i, c));
    cols.push_back(fmt::format("contact{}.slipping_nodes", i));
    cols.push_back(fmt::format("contact{}.friction_dissipation [mJ]", i));
  }
  return cols;
}

void append_contact_history(const model::Model& model, std::vector<double>& row) {
  const Vector& x = model.problem->state();
  for (const contact::ContactTerm* pair : model.contacts) {
    const Vec3 slave = pair->slave_force(x), master = pair->master_force(x);
    row.insert(row.end(), {slave.x(), slave.y(), slave.z(), master.x(), master.y(), master.z()});
    row.push_back(pair->contact_area(x));
    row.push_back(static_cast<double>(pair->active_set().num_active()));
    if (!pair->frictional())
      continue;
    const Vec3 friction = pair->slave_force(x, true);
    row.insert(row.end(), {friction.x(), friction.y(), friction.z()});
    Index slipping = 0;
    for (Index k = 0; k < pair->slave().num_nodes(); ++k)
      slipping += pair->active_set().slipping(k) ? 1 : 0;
    row.push_back(static_cast<double>(slipping));
    row.push_back(pair->friction_dissipation());
  }
}

ContactOutput::ContactOutput(const model::Model& model, std::filesystem::path directory,
                             bool writes_files)
    : model_(model), directory_(std::move(directory)), writes_files_(writes_files) {
  for (std::size_t i = 1; writes_files_ && i <= model.contacts.size(); ++i)
    pvd_.push_back(std::make_unique<io::PvdWriter>(directory_ / fmt::format("contact{}.pvd", i)));
  if (parallel::active())
    for (const contact::ContactTerm* pair : model.contacts)
      piece_facets_.push_back(facets_of_process(model, *pair, parallel::rank()));
}

void ContactOutput::write(Real time, int number, bool vtu) {
  for (std::size_t i = 0; i < model_.contacts.size(); ++i) {
    const contact::ContactTerm& pair = *model_.contacts[i];
    const std::vector<SlaveNodeState> states = pair.slave_states(model_.problem->state());
    std::vector<io::DataArray> arrays = contact_arrays(model_, states);
    if (writes_files_)
      write_csv(directory_ / fmt::format("contact{}_surface_{:04d}.csv", i + 1, number), time, pair,
                states, arrays);
    if (!vtu)
      continue;
    io::UnstructuredGrid grid = surface_grid(pair, states);
    grid.point_data = std::move(arrays);
    write_vtu(directory_ / fmt::format("contact{}_{:04d}", i + 1, number), time, i,
              std::move(grid));
  }
}

void ContactOutput::write_vtu(const std::filesystem::path& stem, Real time, std::size_t pair,
                              io::UnstructuredGrid grid) {
  const auto warn_if_not_finite = [](const std::filesystem::path& file, std::size_t bad) {
    if (bad > 0)
      log::warn("  {} non-finite values written to {}", bad, file.string());
  };
  if (piece_facets_.empty()) { // one process: the whole surface
    const auto file = stem.string() + ".vtu";
    warn_if_not_finite(file, io::write_vtu(file, grid));
    pvd_[pair]->add(time, file);
    return;
  }
  const auto piece = [&](int p) { return fmt::format("{}_{}.vtu", stem.filename().string(), p); };
  const auto mine = directory_ / piece(parallel::rank());
  warn_if_not_finite(mine, io::write_vtu(mine, io::piece_of(grid, piece_facets_[pair])));
  if (!writes_files_)
    return;
  std::vector<std::string> pieces;
  for (int p = 0; p < parallel::size(); ++p)
    pieces.push_back(piece(p));
  const auto file = stem.string() + ".pvtu";
  io::write_pvtu(file, grid, pieces);
  pvd_[pair]->add(time, file);
}

void ContactOutput::write_csv(const std::filesystem::path& file, Real time,
                              const contact::ContactTerm& pair,
                              const std::vector<SlaveNodeState>& states,
                              const std::vector<io::DataArray>& arrays) const {
  io::CsvWriter csv(file, csv_columns(arrays));
  std::vector<double> row;
  for (const Index k : surface_order(model_.mesh, pair.slave().nodes())) {
    const SlaveNodeState& s = states[k];
    const Vec3& X = model_.mesh.node(s.node);
    row.assign({time, X.x(), X.y(), X.z(), s.position.x(), s.position.y(), s.position.z()});
    for (const io::DataArray& a : arrays)
      for (int c = 0; c < a.components; ++c)
        row.push_back(a.values[a.components * k + c]);
    row.push_back(static_cast<double>(s.node));
    csv.write_row(row);
  }
}

} // namespace trifem::analysis
