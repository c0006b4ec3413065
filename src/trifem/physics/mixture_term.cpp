// SPDX-License-Identifier: MIT
#include "trifem/physics/mixture_term.hpp"

#include "trifem/core/error.hpp"
#include "trifem/physics/folded_cells.hpp"
#include "trifem/physics/solid_kernel.hpp"

#include <cmath>

namespace trifem::physics {
namespace {

/// Donnan equilibrium with a bath of concentration c_bath (docs/theory/triphasic.md §6,
/// docs/theory/reference-solutions.md §R3.1).
struct Donnan {
  Real c_plus, c_minus, pressure, eta;
};

Donnan donnan(Real c_fixed, const material::MixtureProperties& m,
              const material::Electrochemistry& chem, Real c_bath) {
  const Real K = chem.gamma_bath * chem.gamma_bath / (m.gamma_plus * m.gamma_minus);
  Donnan d;
  d.c_plus = 0.5 * (c_fixed + std::sqrt(c_fixed * c_fixed + 4.0 * K * c_bath * c_bath));
  d.c_minus = d.c_plus - c_fixed;
  d.pressure = chem.RT() * (m.osmotic * (d.c_plus + d.c_minus) - 2.0 * chem.osmotic_bath * c_bath);
  d.eta = -chem.RT() * std::log(m.gamma_plus * d.c_plus / (chem.gamma_bath * c_bath));
  return d;
}

/// Row and column factors of the scaled equations (docs/theory/triphasic.md §5); the other rows
/// and columns keep a factor 1.
struct Scaling {
  Real water_row, ion_row, ion_column, p_row, eta_row, eta_column;
};

Scaling scaling(Real dt, Real c_ref) {
  return {-dt, -dt * c_ref, c_ref, -dt, -dt / c_ref, 1.0 / c_ref};
}

/// The flux block in the scaled rows (w, j+, j−, p, η) and columns (w, ĵ+, ĵ−).
MixtureFluxBlock scaled(MixtureFluxBlock b, Real dt, Real c_ref) {
  const Scaling f = scaling(dt, c_ref);
  const Vec3 row(f.water_row, f.ion_row, f.ion_row), col(1.0, f.ion_column, f.ion_column);
  const Eigen::Vector2d potential_row(f.p_row, f.eta_row);
  b.friction = row.asDiagonal() * b.friction * col.asDiagonal();
  b.gamma = row.asDiagonal() * b.gamma * col.asDiagonal();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      b.flux_rate.col(3 * i + j) *= row[i] * col[j];
  b.coupling = potential_row.asDiagonal() * b.coupling * col.asDiagonal();
  return b;
}

} // namespace

MixtureTerm::MixtureTerm(const mesh::Mesh& mesh, const dofs::DofMap& dofs, MixtureFields fields,
                         std::vector<Index> cells,
                         std::vector<std::shared_ptr<const material::MixtureProperties>> props,
                         const material::Electrochemistry& chem,
                         std::optional<dofs::LoadCurve> fixed_charge_curve)
    : mesh_(mesh), dofs_(dofs), fields_(fields), cells_(std::move(cells)), props_(std::move(props)),
      chem_(chem), fixed_charge_curve_(std::move(fixed_charge_curve)) {
  TRIFEM_VERIFY(cells_.size() == props_.size(), "one mixture per cell expected");
  geometry_.reserve(cells_.size());
  history_.resize(cells_.size());
  corner_volume_old_.resize(cells_.size());
  prestress_.assign(cells_.size(), 0.0);
  for (std::size_t e = 0; e < cells_.size(); ++e) {
    TRIFEM_CHECK(!props_[e]->charged || has_ions(),
                 "cell {} is triphasic but the model has no ion fields", cells_[e]);
    geometry_.push_back(reference_geometry(mesh, cells_[e]));
    MixtureHistory& h = history_[e];
    std::visit(
        [&h](const auto& geo) {
          for (Real dV : geo.dV)
            h.V0 += dV;
        },
        geometry_.back());
    h.V_old = h.V0;
    if (corner_potentials(static_cast<Index>(e)))
      corner_volume_old_[e] =
          corner_volumes(std::get<CellGeometry>(geometry_.back()),
                         fe::CellNodeCoords::Zero(mesh::num_nodes(mesh_.cell_type(cells_[e])), 3));
    h.N_fixed = h.N_fixed_old = props_[e]->fixed_charge * props_[e]->phi_w0() * h.V0;
  }
}

MixtureLayout MixtureTerm::layout(Index e) const {
  const mesh::CellType type = mesh_.cell_type(cells_[e]);
  return {ions(e), mesh::num_nodes(type), static_cast<int>(mixture_flux_map(type).rows())};
}

void MixtureTerm::element_dofs(Index e, std::vector<Index>& dofs) const {
  const bool charged = ions(e);
  dofs.clear();
  const std::span<const Index> nodes = mesh_.cell_nodes(cells_[e]);
  const MixtureLayout L = layout(e);
  for (dofs::FieldId f : {fields_.u, fields_.w, fields_.j_plus, fields_.j_minus}) {
    if (!charged && (f == fields_.j_plus || f == fields_.j_minus))
      continue;
    const auto count = static_cast<std::size_t>(f == fields_.u ? L.nodes : L.flux_nodes);
    for (const Index node : nodes.first(count))
      for (int k = 0; k < 3; ++k)
        dofs.push_back(dofs_.dof(f, node, k));
  }
  if (corner_potentials(e)) {
    for (const dofs::FieldId f : {fields_.p_corner, fields_.eta_corner})
      if (f == fields_.p_corner || charged)
        for (const Index node : nodes.first(4))
          dofs.push_back(dofs_.dof(f, node, 0));
    return;
  }
  dofs.push_back(dofs_.dof(fields_.p, cells_[e], 0));
  if (charged)
    dofs.push_back(dofs_.dof(fields_.eta, cells_[e], 0));
}

bool MixtureTerm::corner_potentials(Index e) const {
  return has_corner_potentials(fields_, mesh_.cell_type(cells_[e]));
}

bool has_corner_potentials(const MixtureFields& fields, mesh::CellType type) {
  return fields.p_corner.valid() && mesh::linear_type(type) == mesh::CellType::Tet4;
}

std::pair<Real, Real> cell_potentials(const mesh::Mesh& mesh, const dofs::DofMap& dofs,
                                      const MixtureFields& fields, const Vector& x, Index c) {
  if (!has_corner_potentials(fields, mesh.cell_type(c)))
    return {x[dofs.dof(fields.p, c, 0)], fields.eta.valid() ? x[dofs.dof(fields.eta, c, 0)] : 0.0};
  Real p = 0.0, eta = 0.0;
  for (const Index node : mesh.cell_nodes(c).first(4)) {
    p += 0.25 * x[dofs.dof(fields.p_corner, node, 0)];
    if (fields.eta_corner.valid())
      eta += 0.25 * x[dofs.dof(fields.eta_corner, node, 0)];
  }
  return {p, eta};
}

template <class Coords>
void MixtureTerm::gather(Index e, const Vector& x, MixtureUnknownsOf<Coords>& v) const {
  const std::span<const Index> nodes = mesh_.cell_nodes(cells_[e]);
  const MixtureLayout L = layout(e);
  const bool charged = ions(e);
  v.u.resize(L.nodes, 3);
  for (Index a = 0; a < L.nodes; ++a)
    for (int k = 0; k < 3; ++k)
      v.u(a, k) = x[dofs_.dof(fields_.u, nodes[a], k)];
  v.w.resize(L.flux_nodes, 3);
  v.jp.setZero(L.flux_nodes, 3);
  v.jm.setZero(L.flux_nodes, 3);
  for (Index a = 0; a < L.flux_nodes; ++a)
    for (int k = 0; k < 3; ++k) {
      v.w(a, k) = x[dofs_.dof(fields_.w, nodes[a], k)];
      if (charged) {
        v.jp(a, k) = chem_.c_ref * x[dofs_.dof(fields_.j_plus, nodes[a], k)];
        v.jm(a, k) = chem_.c_ref * x[dofs_.dof(fields_.j_minus, nodes[a], k)];
      }
    }
  const auto [p, eta] = cell_potentials(mesh_, dofs_, fields_, x, cells_[e]);
  v.p = p;
  v.eta = charged ? eta / chem_.c_ref : 0.0;
}

Real MixtureTerm::current_volume(Index e, const Vector& x) const {
  Real V = 0.0;
  if (const auto* hex = std::get_if<fe::HexGeometry>(&geometry_[e])) {
    MixtureUnknowns v;
    gather(e, x, v);
    for (int q = 0; q < 8; ++q)
      V += deformation_gradient(hex->dN_dX[q], v.u).determinant() * hex->dV[q];
    return V;
  }
  const auto& geo = std::get<CellGeometry>(geometry_[e]);
  CellMixtureUnknowns v;
  gather(e, x, v);
  for (std::size_t q = 0; q < geo.dV.size(); ++q)
    V += (Mat3::Identity() + v.u.transpose() * geo.dN_dX[q]).determinant() * geo.dV[q];
  return V;
}

MixtureCellOutput MixtureTerm::cell_output(Index e, const Vector& x, const MixtureHistory& h,
                                           const MixtureStep& s) const {
  if (const auto* hex = std::get_if<fe::HexGeometry>(&geometry_[e])) {
    MixtureUnknowns v;
    gather(e, x, v);
    return mixture_hex8_output(*hex, v, h, *props_[e], s, ions(e));
  }
  CellMixtureUnknowns v;
  gather(e, x, v);
  return mixture_cell_output(std::get<CellGeometry>(geometry_[e]), v, h, *props_[e], s, ions(e));
}

MixtureHistory MixtureTerm::history_at(Index e, Real time) const {
  MixtureHistory h = history_[e];
  if (fixed_charge_curve_)
    h.N_fixed = props_[e]->fixed_charge * props_[e]->phi_w0() * h.V0 * (*fixed_charge_curve_)(time);
  return h;
}

MixtureStep MixtureTerm::step(Index e, Real dt) const {
  return {dt > 0.0 ? dt : 1.0, prestress_[e], &chem_, lumped_flux_mass_};
}

void MixtureTerm::scale(Index e, Real dt, LocalVector& r, LocalMatrix* K) const {
  const MixtureLayout L = layout(e);
  const bool at_corners = corner_potentials(e);
  const int n = at_corners ? corner_layout_size(L) : L.size(), flux = 3 * L.flux_nodes;
  const int potentials = at_corners ? 4 : 1; // values of p and of η
  const Scaling f = scaling(dt, chem_.c_ref);
  Eigen::VectorXd row = Eigen::VectorXd::Ones(n), col = Eigen::VectorXd::Ones(n);
  row.segment(L.w(0, 0), flux).setConstant(f.water_row);
  row.segment(L.p(), potentials).setConstant(f.p_row);
  if (L.ions) {
    row.segment(L.jp(0, 0), 2 * flux).setConstant(f.ion_row);
    col.segment(L.jp(0, 0), 2 * flux).setConstant(f.ion_column);
    row.segment(L.p() + potentials, potentials).setConstant(f.eta_row);
    col.segment(L.p() + potentials, potentials).setConstant(f.eta_column);
  }
  r.array() *= row.array();
  if (K)
    *K = row.asDiagonal() * (*K) * col.asDiagonal();
}

CornerPotentials MixtureTerm::corners(Index e, const Vector& x) const {
  CornerPotentials c;
  c.volume_old = corner_volume_old_[static_cast<std::size_t>(e)];
  const std::span<const Index> nodes = mesh_.cell_nodes(cells_[e]);
  for (std::size_t b = 0; b < 4; ++b) {
    c.p[b] = x[dofs_.dof(fields_.p_corner, nodes[b], 0)];
    if (ions(e))
      c.eta[b] = x[dofs_.dof(fields_.eta_corner, nodes[b], 0)] / chem_.c_ref;
  }
  return c;
}

std::array<Real, 4> MixtureTerm::corner_volumes_at(Index e, const Vector& x) const {
  CellMixtureUnknowns v;
  gather(e, x, v);
  return corner_volumes(std::get<CellGeometry>(geometry_[e]), v.u);
}

bool MixtureTerm::evaluate(Index e, const EvalState& state, LocalVector& r, LocalMatrix* K) const {
  const MixtureStep s = step(e, state.dt);
  const MixtureHistory h = history_at(e, state.time);
  bool ok = false;
  if (const auto* hex = std::get_if<fe::HexGeometry>(&geometry_[e])) {
    MixtureUnknowns v;
    gather(e, state.x, v);
    ok = mixture_hex8(*hex, v, h, *props_[e], s, layout(e), r, K);
  } else if (corner_potentials(e)) {
    CellMixtureUnknowns v;
    gather(e, state.x, v);
    ok = mixture_tet(std::get<CellGeometry>(geometry_[e]), v, corners(e, state.x), h, *props_[e], s,
                     layout(e), r, K);
  } else {
    CellMixtureUnknowns v;
    gather(e, state.x, v);
    ok = mixture_cell(std::get<CellGeometry>(geometry_[e]), v, h, *props_[e], s, layout(e), r, K);
  }
  if (!ok)
    return false;
  scale(e, s.dt, r, K);
  return true;
}

CellTransport MixtureTerm::cell_transport(Index e, const MixtureFluxBlock& scaled_block) const {
  const bool charged = ions(e);
  CellTransport t;
  t.potential = {dofs_.dof(fields_.p, cells_[e], 0),
                 charged ? dofs_.dof(fields_.eta, cells_[e], 0) : Index(-1)};
  t.coupling = scaled_block.coupling;
  t.friction = scaled_block.friction;
  t.gamma = scaled_block.gamma;
  t.flux_rate = scaled_block.flux_rate;
  t.area = scaled_block.area;
  t.lumped_mass = scaled_block.lumped_mass;
  t.flux_dof.setConstant(-1);
  const mesh::Hex8 nodes = mesh_.cell(cells_[e]);
  const std::array<dofs::FieldId, 3> flux = {fields_.w, fields_.j_plus, fields_.j_minus};
  for (int a = 0; a < 8; ++a) {
    t.node[a] = nodes[a];
    for (int field = 0; field < (charged ? 3 : 1); ++field)
      for (int k = 0; k < 3; ++k)
        t.flux_dof(3 * a + k, field) = dofs_.dof(flux[field], nodes[a], k);
  }
  return t;
}

void MixtureTerm::transport_cells(const EvalState& state, std::vector<CellTransport>& out) const {
  out.reserve(out.size() + cells_.size());
  for (Index e = 0; e < num_elements(); ++e) {
    const auto* hex = std::get_if<fe::HexGeometry>(&geometry_[e]);
    TRIFEM_CHECK(hex != nullptr,
                 "the drained-Schur preconditioner takes the mixture on hex8 cells only, and "
                 "cell {} is a {}; use another preconditioner or a direct solver",
                 cells_[e], mesh::name(mesh_.cell_type(cells_[e])));
    const MixtureStep s = step(e, state.dt);
    MixtureUnknowns v;
    gather(e, state.x, v);
    const std::optional<MixtureFluxBlock> block =
        mixture_hex8_flux_block(*hex, v, history_at(e, state.time), *props_[e], s, layout(e));
    if (block) // always, at a state the term could evaluate
      out.push_back(cell_transport(e, scaled(*block, s.dt, chem_.c_ref)));
  }
}

MixtureCellOutput MixtureTerm::output(Index e, const Vector& x) const {
  // dt = 0: concentrations from the committed moles, without a pending flux update
  const MixtureStep s{0.0, prestress_[e], &chem_, lumped_flux_mass_};
  return cell_output(e, x, history_[e], s);
}

namespace {
constexpr std::size_t kHistoryValues = 6; ///< numbers per MixtureHistory
} // namespace

std::vector<double> MixtureTerm::history() const {
  std::vector<double> out;
  out.reserve(kHistoryValues * history_.size());
  for (const MixtureHistory& h : history_)
    out.insert(out.end(), {h.V0, h.V_old, h.N_plus, h.N_minus, h.N_fixed, h.N_fixed_old});
  if (fields_.p_corner.valid()) // the corners' volumes after every element's history
    for (const std::array<Real, 4>& v : corner_volume_old_)
      out.insert(out.end(), v.begin(), v.end());
  return out;
}

void MixtureTerm::restore_history(const std::vector<double>& values) {
  const std::size_t corner_values = fields_.p_corner.valid() ? 4 * history_.size() : 0;
  TRIFEM_CHECK(values.size() == kHistoryValues * history_.size() + corner_values,
               "the restart file holds {} mixture history values, this model needs {}",
               values.size(), kHistoryValues * history_.size() + corner_values);
  for (std::size_t e = 0; e < history_.size(); ++e) {
    const double* v = values.data() + kHistoryValues * e;
    history_[e] = {v[0], v[1], v[2], v[3], v[4], v[5]};
  }
  const double* v = values.data() + kHistoryValues * history_.size();
  for (std::size_t e = 0; e < history_.size() && corner_values > 0; ++e)
    for (std::size_t b = 0; b < 4; ++b)
      corner_volume_old_[e][b] = v[4 * e + b];
}

std::string MixtureTerm::step_rejection(const EvalState& state) const {
  return folded_cell_rejection(mesh_, dofs_, fields_.u, cells_, state.x);
}

void MixtureTerm::commit(const EvalState& state) {
  for (Index e = 0; e < num_elements(); ++e) {
    const MixtureHistory h = history_at(e, state.time);
    const MixtureCellOutput out = cell_output(e, state.x, h, step(e, state.dt));
    MixtureHistory& next = history_[e];
    next.V_old = out.chem.V;
    if (corner_potentials(e))
      corner_volume_old_[static_cast<std::size_t>(e)] = corner_volumes_at(e, state.x);
    if (ions(e)) {
      next.N_plus = out.chem.c_plus * out.chem.Vw;
      next.N_minus = out.chem.c_minus * out.chem.Vw;
      next.N_fixed_old = next.N_fixed = h.N_fixed;
    }
  }
}

void MixtureTerm::initialize(InitialState kind, Real time, Vector& x) {
  // the corner potentials: the volume-weighted mean of the cells' Donnan values at the node
  std::vector<Real> weight, p_sum, eta_sum;
  if (fields_.p_corner.valid()) {
    weight.assign(static_cast<std::size_t>(mesh_.num_nodes()), 0.0);
    p_sum = eta_sum = weight;
  }
  for (Index e = 0; e < num_elements(); ++e) {
    const material::MixtureProperties& m = *props_[e];
    MixtureHistory& h = history_[e];
    h = history_at(e, time);
    h.N_fixed_old = h.N_fixed;
    h.V_old = current_volume(e, x);
    if (corner_potentials(e))
      corner_volume_old_[static_cast<std::size_t>(e)] = corner_volumes_at(e, x);
    Real pressure = 0.0, eta = 0.0;
    prestress_[e] = 0.0;
    if (ions(e)) {
      const Real Vw = h.V_old - m.phi_s0 * h.V0;
      TRIFEM_CHECK(Vw > 0.0, "{}: the initial state has no water volume (J <= phi_s0)",
                   mesh_.describe(cells_[e]));
      const Donnan d = donnan(h.N_fixed / Vw, m, chem_, chem_.c_ref);
      h.N_plus = d.c_plus * Vw;
      h.N_minus = d.c_minus * Vw;
      pressure = d.pressure;
      eta = chem_.c_ref * d.eta;
      if (kind == InitialState::DonnanPrestressed)
        prestress_[e] = d.pressure;
    }
    if (!corner_potentials(e)) {
      x[dofs_.dof(fields_.p, cells_[e], 0)] = pressure;
      if (ions(e))
        x[dofs_.dof(fields_.eta, cells_[e], 0)] = eta;
      continue;
    }
    for (const Index node : mesh_.cell_nodes(cells_[e]).first(4)) {
      const auto a = static_cast<std::size_t>(node);
      weight[a] += h.V_old;
      p_sum[a] += h.V_old * pressure;
      eta_sum[a] += h.V_old * eta;
    }
  }
  for (std::size_t a = 0; a < weight.size(); ++a) {
    if (weight[a] == 0.0)
      continue;
    x[dofs_.dof(fields_.p_corner, static_cast<Index>(a), 0)] = p_sum[a] / weight[a];
    if (fields_.eta_corner.valid())
      x[dofs_.dof(fields_.eta_corner, static_cast<Index>(a), 0)] = eta_sum[a] / weight[a];
  }
}

Real MixtureTerm::total_moles(bool cation) const {
  Real n = 0.0;
  for (const auto& h : history_)
    n += cation ? h.N_plus : h.N_minus;
  return n;
}

Real MixtureTerm::water_volume(Index e) const {
  return history_[e].V_old - props_[e]->phi_s0 * history_[e].V0;
}

} // namespace trifem::physics
