// SPDX-License-Identifier: MIT
#include "trifem/analysis/output_writer.hpp"

#include "trifem/analysis/averages.hpp"
#include "trifem/analysis/contact_output.hpp"
#include "trifem/analysis/output_fields.hpp"
#include "trifem/analysis/probes.hpp"
#include "trifem/model/rigid_bodies.hpp"

#include "trifem/core/error.hpp"
#include "trifem/core/log.hpp"
#include "trifem/core/timer.hpp"
#include "trifem/fe/reference_element.hpp"
#include "trifem/io/pvtu_writer.hpp"
#include "trifem/io/vtu_writer.hpp"
#include "trifem/parallel/communicator.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>

namespace trifem::analysis {
namespace {

/// The history columns of `model` after time, step, dt and iterations.
std::vector<std::string> model_columns(const model::Model& model) {
  std::vector<std::string> cols;
  for (const auto& r : model.reactions)
    for (const char* c : {"Rx", "Ry", "Rz"})
      cols.push_back(fmt::format("{}.{} [N]", r.name, c));
  for (const auto& p : model.probes)
    for (std::string& c : probe_columns(p))
      cols.push_back(std::move(c));
  for (const auto& a : model.averages)
    for (std::string& c : average_columns(a))
      cols.push_back(std::move(c));
  for (std::string& c : contact_history_columns(model))
    cols.push_back(std::move(c));
  for (const model::RigidBody& b : model.rigid_bodies) {
    for (const char* c : {"ux", "uy", "uz"})
      cols.push_back(fmt::format("{}.{} [mm]", b.name, c));
    for (const char* c : {"Fx", "Fy", "Fz"})
      cols.push_back(fmt::format("{}.{} [N]", b.name, c));
    if (b.rotating < 0)
      continue;
    for (const char* c : {"rx", "ry", "rz"})
      cols.push_back(fmt::format("{}.{} [rad]", b.name, c));
    for (const char* c : {"Mx", "My", "Mz"})
      cols.push_back(fmt::format("{}.{} [N mm]", b.name, c));
  }
  if (model.connectors)
    for (const physics::Connector& c : model.connectors->connectors()) {
      for (const char* k : {"Fx", "Fy", "Fz"})
        cols.push_back(fmt::format("{}.{} [N]", c.name, k));
      for (const char* k : {"Mx", "My", "Mz"})
        cols.push_back(fmt::format("{}.{} [N mm]", c.name, k));
      for (const physics::ReportedMeasure& m : c.reported)
        cols.push_back(fmt::format("{}.{} [{}]", c.name, m.name, m.unit));
    }
  for (const model::RigidWall& w : model.walls) {
    for (const char* k : {"Fx", "Fy", "Fz"})
      cols.push_back(fmt::format("{}.{} [N]", w.name, k));
    cols.push_back(fmt::format("{}.nodes", w.name));
  }
  if (model.mixture) {
    cols.push_back("water_outflow [mm^3/s]");
    cols.push_back("water_volume [mm^3]");
  }
  if (model.fields.j_plus.valid())
    for (const char* c : {"cation_outflow [mmol/s]", "anion_outflow [mmol/s]",
                          "cation_moles [mmol]", "anion_moles [mmol]"})
      cols.push_back(c);
  return cols;
}

/// Per connector: the force and moment it applies to its body b (in the last committed state)
/// and its reported measures.
void append_connector_values(const physics::RigidConnectorTerm& term, const Vector& x,
                             std::vector<double>& row) {
  for (Index e = 0; e < term.num_elements(); ++e) {
    const physics::ConnectorWrench& w = term.committed_wrenches()[e];
    row.insert(row.end(),
               {w.force.x(), w.force.y(), w.force.z(), w.moment.x(), w.moment.y(), w.moment.z()});
    for (const physics::ReportedMeasure& m : term.connectors()[e].reported)
      row.push_back(term.measure(e, m.measure, x));
  }
}

/// Per-body water columns (when the model has several mixture bodies).
void add_body_columns(const MassBalance& balance, std::vector<std::string>& cols) {
  for (std::size_t i = 1; i < balance.regions().size(); ++i) {
    cols.push_back(fmt::format("{}.water_outflow [mm^3/s]", balance.regions()[i].name));
    cols.push_back(fmt::format("{}.water_volume [mm^3]", balance.regions()[i].name));
  }
}

io::UnstructuredGrid volume_grid(const model::Model& model) {
  io::UnstructuredGrid grid;
  grid.points = model.mesh.nodes();
  std::vector<Index> vtk_nodes;
  for (Index c = 0; c < model.mesh.num_cells(); ++c) {
    const fe::ReferenceCell& reference = fe::reference_cell(model.mesh.cell_type(c));
    const std::span<const Index> nodes = model.mesh.cell_nodes(c);
    vtk_nodes.clear();
    for (int a : reference.vtk_order())
      vtk_nodes.push_back(nodes[static_cast<std::size_t>(a)]);
    grid.add_cell(static_cast<std::uint8_t>(reference.vtk_type()), vtk_nodes);
  }
  return grid;
}

/// The facets of the mesh's surfaces that bound no cell, each once, as VTK quads or triangles
/// (a quad whose last node repeats the third) on the points of the nodes they use (`nodes`: the
/// mesh node of each point).
io::UnstructuredGrid free_surface_grid(const model::Model& model, std::vector<Index>& nodes) {
  io::UnstructuredGrid grid;
  std::set<std::array<Index, 4>> seen;
  std::vector<Index> point_of(model.mesh.num_nodes(), -1);
  std::vector<Index> corners;
  for (const auto& [name, surface] : model.mesh.surfaces())
    for (const mesh::Facet& f : surface.facets) {
      std::array<Index, 4> key = f.nodes;
      std::sort(key.begin(), key.end());
      if (f.bounds_cell() || !seen.insert(key).second)
        continue;
      const bool triangle = f.nodes[3] == f.nodes[2];
      corners.clear();
      for (int a = 0; a < (triangle ? 3 : 4); ++a) {
        Index& point = point_of[f.nodes[a]];
        if (point < 0) {
          point = static_cast<Index>(grid.points.size());
          grid.points.push_back(model.mesh.node(f.nodes[a]));
          nodes.push_back(f.nodes[a]);
        }
        corners.push_back(point);
      }
      grid.add_cell(triangle ? io::vtk_cell::kTriangle : io::vtk_cell::kQuad, corners);
    }
  return grid;
}

/// On several processes: the cells whose VTU piece process `rank` writes (a cell goes with the
/// owner of its first node that has one; rank 0 if none has).
std::vector<Index> cells_of_process(const model::Model& model, int rank) {
  std::vector<Index> mine;
  for (Index c = 0; c < model.mesh.num_cells(); ++c) {
    int cell_owner = -1;
    for (Index node : model.mesh.cell_nodes(c))
      if ((cell_owner = model::node_owner(model, node)) >= 0)
        break;
    if (std::max(cell_owner, 0) == rank)
      mine.push_back(c);
  }
  return mine;
}

} // namespace

OutputWriter::OutputWriter(const model::Model& model, const io::OutputSpec& spec,
                           std::filesystem::path directory, Real end_time)
    : model_(model), spec_(spec), directory_(std::move(directory)), end_time_(end_time),
      next_default_(end_time / io::kDefaultOutputCount), writes_files_(parallel::is_root()) {
  if (model.mixture)
    balance_ = std::make_unique<MassBalance>(model);
  if (parallel::active())
    piece_cells_ = cells_of_process(model, parallel::rank());
  parallel::agree_on_output([&] { // rank 0 creates the directory; every process learns if it could
    if (!writes_files_)
      return;
    std::error_code ec;
    std::filesystem::create_directories(directory_, ec);
    TRIFEM_CHECK_OUTPUT(!ec, "cannot create the output directory {}: {}", directory_.string(),
                        ec.message());
  });
  if (!writes_files_) { // another process than rank 0: its pieces of the VTU states only
    if (!model.contacts.empty())
      contact_ = std::make_unique<ContactOutput>(model, directory_, false);
    return;
  }
  pvd_ = std::make_unique<io::PvdWriter>(directory_ / "results.pvd");
  cells_ = std::make_unique<CellEvaluator>(model);
  history_ = std::make_unique<io::CsvWriter>(history_file(), history_columns());
  if (!model.contacts.empty())
    contact_ = std::make_unique<ContactOutput>(model, directory_, true);
  free_surfaces_ = free_surface_grid(model, free_surface_nodes_);
  if (free_surfaces_.cell_count() > 0 && spec_.vtu)
    surfaces_pvd_ = std::make_unique<io::PvdWriter>(directory_ / "surfaces.pvd");
}

OutputWriter::~OutputWriter() = default;

void OutputWriter::write_free_surfaces(Real time, int number) {
  const Vector& x = model_.problem->state();
  io::DataArray u{"displacement [mm]", 3, {}};
  for (Index n : free_surface_nodes_)
    for (int k = 0; k < 3; ++k)
      u.values.push_back(x[model_.dofs.dof(model_.fields.u, n, k)]);
  io::UnstructuredGrid grid = free_surfaces_;
  grid.point_data.push_back(std::move(u));
  const auto file = directory_ / fmt::format("surfaces_{:04d}.vtu", number);
  if (const auto bad = io::write_vtu(file, grid); bad > 0)
    log::warn("  {} non-finite values written to {}", bad, file.string());
  surfaces_pvd_->add(time, file);
}

std::vector<std::string> OutputWriter::history_columns() const {
  std::vector<std::string> cols = {"time [s]", "step", "dt [s]", "iterations"};
  if (results_)
    for (std::string& c : results_->columns())
      cols.push_back(std::move(c));
  for (std::string& c : model_columns(model_))
    cols.push_back(std::move(c));
  if (balance_)
    add_body_columns(*balance_, cols);
  return cols;
}

void OutputWriter::use_history(const std::string& file_name, const StepResults* results) {
  results_ = results;
  history_name_ = file_name;
  step_history_.reset();
  if (!writes_files_)
    return;
  if (file_name != "history.csv")
    step_history_ = std::make_unique<io::CsvWriter>(history_file(), history_columns());
  else if (results || history_->columns() != history_columns())
    history_ = std::make_unique<io::CsvWriter>(history_file(), history_columns());
}

bool OutputWriter::is_output_time(Real time) {
  for (Real t : spec_.times)
    if (std::abs(t - time) <= 1e-10 * std::max(1.0, std::abs(t)))
      return true;
  if (!spec_.interval_given) {
    const Real part = end_time_ / io::kDefaultOutputCount;
    if (time < next_default_ - 1e-10 * end_time_)
      return false;
    while (next_default_ <= time + 1e-10 * end_time_)
      next_default_ += part;
    return true;
  }
  if (spec_.interval <= 0.0)
    return true;
  const Real k = time / spec_.interval;
  return std::abs(k - std::round(k)) <= 1e-8;
}

std::vector<double> OutputWriter::history_row(Real time, int step, Real dt, int iterations) const {
  const Vector& x = model_.problem->state();
  const Vector& R = results_ ? results_->full_residual() : model_.problem->full_residual();
  std::vector<double> row = {time, double(step), dt, double(iterations)};
  if (results_)
    results_->append_values(row);
  for (const auto& r : model_.reactions)
    for (int k = 0; k < 3; ++k) {
      double sum = 0.0;
      for (Index d : r.dofs[k])
        sum += R[d];
      row.push_back(sum);
    }
  for (const auto& p : model_.probes)
    append_probe_values(model_, *cells_, p, x, row);
  for (const auto& a : model_.averages)
    append_average_values(model_, *cells_, a, x, row);
  append_contact_history(model_, row);
  for (const model::RigidBody& b : model_.rigid_bodies) {
    const Vec3 u = model::rigid_body_displacement(model_, b),
               f = model::rigid_body_force(b, time, R);
    row.insert(row.end(), {u.x(), u.y(), u.z(), f.x(), f.y(), f.z()});
    if (b.rotating < 0)
      continue;
    const Vec3 r = model::rigid_body_rotation(model_, b),
               m = model::rigid_body_moment(model_, b, R);
    row.insert(row.end(), {r.x(), r.y(), r.z(), m.x(), m.y(), m.z()});
  }
  if (model_.connectors)
    append_connector_values(*model_.connectors, x, row);
  for (const model::RigidWall& w : model_.walls) { // force on the body, nodes in contact
    const Vec3 f = w.term->force(x);
    row.insert(row.end(), {f.x(), f.y(), f.z(), static_cast<double>(w.term->num_active())});
  }
  if (balance_) {
    const Balance b = balance_->measure();
    row.push_back(b.outflow[0]);
    row.push_back(b.total[0]);
    if (balance_->has_ions())
      for (double v : {b.outflow[1], b.outflow[2], b.total[1], b.total[2]})
        row.push_back(v);
    for (std::size_t i = 1; i < balance_->regions().size(); ++i) {
      const Balance& body = balance_->regions()[i].last; // of the last recorded step
      row.insert(row.end(), {body.outflow[0], body.total[0]});
    }
  }
  return row;
}

void OutputWriter::write_vtu(Real time, int number) {
  io::UnstructuredGrid grid = volume_grid(model_);
  grid.point_data =
      point_fields(model_, results_ ? results_->full_residual() : model_.problem->full_residual());
  grid.cell_data = cell_fields(model_);
  if (results_)
    results_->add_arrays(grid.point_data, grid.cell_data);
  if (piece_cells_) { // several processes: a piece each, listed by rank 0's .pvtu file
    const auto piece = fmt::format("volume_{:04d}_{}.vtu", number, parallel::rank());
    parallel::agree_on_output([&] { // no list names a state before all its pieces are written
      if (const auto bad = io::write_vtu(directory_ / piece, io::piece_of(grid, *piece_cells_));
          bad > 0)
        log::warn("  {} non-finite values written to {}", bad, piece);
    });
    if (!writes_files_)
      return;
    std::vector<std::string> pieces;
    for (int p = 0; p < parallel::size(); ++p)
      pieces.push_back(fmt::format("volume_{:04d}_{}.vtu", number, p));
    const auto file = directory_ / fmt::format("volume_{:04d}.pvtu", number);
    io::write_pvtu(file, grid, pieces);
    pvd_->add(time, file);
    ++vtu_count_;
    return;
  }
  const auto file = directory_ / fmt::format("volume_{:04d}.vtu", number);
  if (const auto bad = io::write_vtu(file, grid); bad > 0)
    log::warn("  {} non-finite values written to {}", bad, file.string());
  pvd_->add(time, file);
  ++vtu_count_;
}

void OutputWriter::write_state(Real time) {
  const int number = state_count_++; // counted on every process, even if a write fails
  last_state_time_ = time;
  if (spec_.vtu && (writes_files_ || piece_cells_))
    write_vtu(time, number);
  if (surfaces_pvd_) // (rank 0 only: the surface meshes are small)
    write_free_surfaces(time, number);
  if (contact_ && (writes_files_ || spec_.vtu)) // others: their pieces of the VTU states only
    contact_->write(time, number, spec_.vtu);
}

void OutputWriter::write_last_state(Real time) {
  if (state_count_ > 0 && last_state_time_ == time)
    return;
  ScopedTimer timer(seconds_);
  parallel::agree_on_output([&] { write_state(time); });
}

void OutputWriter::write(Real time, int step, Real dt, int iterations, bool volume) {
  ScopedTimer timer(seconds_);
  parallel::agree_on_output([&] { // all go on, or all stop, if one process cannot write
    if (writes_files_)
      (step_history_ ? *step_history_ : *history_)
          .write_row(history_row(time, step, dt, iterations));
  });
  if (volume) // every process writes its part (write_vtu agrees on the pieces first)
    parallel::agree_on_output([&] { write_state(time); });
}

} // namespace trifem::analysis
