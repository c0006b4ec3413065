// SPDX-License-Identifier: MIT
#include "trifem/explicit/explicit_model.hpp"

#include "trifem/core/error.hpp"
#include "trifem/fe/quadrature.hpp"
#include "trifem/linalg/nested_dissection.hpp"
#include "trifem/mesh/hex_faces.hpp"
#include "trifem/model/model.hpp"
#include "trifem/parallel/communicator.hpp"

#include <algorithm>

namespace trifem::explicit_dynamics {

ExplicitModel::ExplicitModel(const model::Model& model) : model_(model), mesh_(model.mesh) {
  TRIFEM_CHECK(mesh_.num_cells() > 0, "explicit model: the mesh has no cells");
  for (const model::CellMaterial& m : model.materials)
    TRIFEM_CHECK(m.solid && !m.mixture && m.density > 0.0,
                 "materials.{}: dynamic-explicit analyses need a solid law with a density", m.name);
  TRIFEM_CHECK(!model.dofs.has_ties(), "dynamic-explicit analyses do not take rigid bodies");
  for (const dofs::DirichletCondition& c : model.problem->conditions())
    prescribed_motion_ =
        prescribed_motion_ || (!c.dofs.empty() && c.magnitude != 0.0) ||
        std::any_of(c.offsets.begin(), c.offsets.end(), [](Real offset) { return offset != 0.0; });
  build_geometry();
  build_mass();
  fixed_.resize(num_dofs());
  local_.assign(model.dofs.num_dofs(), -1);
  inverse_mass_.resize(num_dofs());
  free_mass_.resize(num_dofs());
  for (Index a = 0; a < mesh_.num_nodes(); ++a)
    for (int k = 0; k < 3; ++k) {
      const Index i = 3 * a + k, dof = model.dofs.dof(model.fields.u, a, k);
      dofs_.push_back(dof);
      local_[dof] = i;
      fixed_[i] = model.dofs.is_constrained(dof) ? 1 : 0;
      TRIFEM_CHECK(fixed_[i] || mass_[i] > 0.0, "explicit model: node {} belongs to no cell", a);
      inverse_mass_[i] = fixed_[i] ? 0.0 : 1.0 / mass_[i];
      free_mass_[i] = fixed_[i] ? 0.0 : mass_[i];
    }
  build_incidence();
  build_partition();
}

void ExplicitModel::external_force(const Vector& U, Real time, Vector& f) const {
  f.setZero(num_dofs());
  if (model_.loads.empty())
    return;
  Vector x = Vector::Zero(model_.dofs.num_dofs());
  scatter(U, x);
  const physics::EvalState state{x, x, time, 0.0};
  std::vector<Index> dofs;
  physics::LocalVector r;
  for (const physics::Term* load : model_.loads)
    for (Index e = 0; e < load->num_elements(); ++e) {
      load->element_dofs(e, dofs);
      load->evaluate(e, state, r, nullptr);
      for (std::size_t j = 0; j < dofs.size(); ++j)
        f[local_[dofs[j]]] -= r[static_cast<Eigen::Index>(j)];
    }
}

void ExplicitModel::prescribe(Real time, Vector& U) const {
  Vector x = Vector::Zero(model_.dofs.num_dofs());
  dofs::prescribed_values(model_.problem->conditions(), time, x);
  for (Index i = 0; i < num_dofs(); ++i)
    if (fixed_[i])
      U[i] = x[dofs_[i]];
}

void ExplicitModel::scatter(const Vector& v, Vector& x) const {
  for (Index i = 0; i < num_dofs(); ++i)
    x[dofs_[i]] = v[i];
}

Vector ExplicitModel::gather(const Vector& x) const {
  Vector v(num_dofs());
  for (Index i = 0; i < num_dofs(); ++i)
    v[i] = x[dofs_[i]];
  return v;
}

const material::ElasticLaw& ExplicitModel::law(Index c) const {
  return *model_.materials[c].solid;
}

Real ExplicitModel::density(Index c) const {
  return model_.materials[c].density;
}

fe::HexCoords ExplicitModel::cell_values(Index c, const Vector& U) const {
  const mesh::Hex8& nodes = mesh_.cell(c);
  fe::HexCoords u;
  for (int a = 0; a < 8; ++a)
    u.row(a) = U.segment<3>(3 * nodes[a]).transpose();
  return u;
}

void ExplicitModel::build_geometry() {
  const Index n = mesh_.num_cells();
  geometry_.resize(n);
  volumes_.resize(n);
  lengths_.resize(n);
  for (Index c = 0; c < n; ++c) {
    const fe::HexCoords X = fe::cell_coordinates(mesh_, c);
    auto geo = fe::hex8_geometry(X);
    TRIFEM_CHECK(geo.has_value(), "explicit model: cell {} is inverted or degenerate", c);
    geometry_[c] = *geo;
    Real volume = 0.0;
    for (Real dV : geo->dV)
      volume += dV;
    Real max_area = 0.0;
    for (const auto& face : mesh::kHexFaces) {
      const Vec3 d1 = X.row(face[2]) - X.row(face[0]), d2 = X.row(face[3]) - X.row(face[1]);
      max_area = std::max(max_area, 0.5 * d1.cross(d2).norm());
    }
    volumes_[c] = volume;
    lengths_[c] = volume / max_area;
  }
}

void ExplicitModel::build_mass() {
  const auto& rule = fe::hex_gauss_2x2x2();
  Vector nodal = Vector::Zero(mesh_.num_nodes());
  for (Index c = 0; c < mesh_.num_cells(); ++c) {
    const Real rho = density(c);
    for (int q = 0; q < 8; ++q) {
      const fe::HexShape N = fe::hex8_shape(rule[q].xi);
      for (int a = 0; a < 8; ++a)
        nodal[mesh_.cell(c)[a]] += rho * N[a] * geometry_[c].dV[q];
    }
  }
  mass_.resize(num_dofs());
  for (Index a = 0; a < mesh_.num_nodes(); ++a)
    mass_.segment<3>(3 * a).setConstant(nodal[a]);
}

void ExplicitModel::build_partition() {
  if (!parallel::active())
    return;
  const Index nn = mesh_.num_nodes();
  rank_ = parallel::rank();
  node_owner_.assign(nn, 0);
  if (parallel::is_root()) { // the node graph: nodes sharing a cell
    std::vector<Index> start = {0}, column;
    for (Index a = 0; a < nn; ++a) {
      const auto first = static_cast<std::ptrdiff_t>(column.size());
      for (Index i = incidence_.offsets[a]; i < incidence_.offsets[a + 1]; ++i)
        for (Index b : mesh_.cell(incidence_.entries[i].first))
          column.push_back(b);
      std::sort(column.begin() + first, column.end());
      column.erase(std::unique(column.begin() + first, column.end()), column.end());
      start.push_back(static_cast<Index>(column.size()));
    }
    node_owner_ = linalg::partition_rows({nn, start.data(), column.data()}, parallel::size());
  }
  parallel::broadcast(node_owner_);
  const Index n = mesh_.num_cells();
  cell_owner_.resize(n);
  evaluated_.assign(n, 0);
  for (Index c = 0; c < n; ++c) {
    cell_owner_[c] = node_owner_[mesh_.cell(c)[0]];
    for (Index a : mesh_.cell(c))
      evaluated_[c] = evaluated_[c] || node_owner_[a] == rank_;
  }
}

void ExplicitModel::build_incidence() {
  const Index nn = mesh_.num_nodes();
  incidence_.offsets.assign(nn + 1, 0);
  for (const mesh::Hex8& cell : mesh_.cells())
    for (Index a : cell)
      ++incidence_.offsets[a + 1];
  for (Index a = 0; a < nn; ++a)
    incidence_.offsets[a + 1] += incidence_.offsets[a];
  incidence_.entries.resize(incidence_.offsets[nn]);
  std::vector<Index> next(incidence_.offsets.begin(), incidence_.offsets.end() - 1);
  for (Index c = 0; c < mesh_.num_cells(); ++c) // increasing c: entries sorted by cell
    for (int l = 0; l < 8; ++l)
      incidence_.entries[next[mesh_.cell(c)[l]]++] = {c, l};
}

} // namespace trifem::explicit_dynamics
