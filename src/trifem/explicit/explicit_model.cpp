// SPDX-License-Identifier: MIT
#include "trifem/explicit/explicit_model.hpp"

#include "trifem/core/error.hpp"
#include "trifem/fe/quadrature.hpp"
#include "trifem/mesh/hex_faces.hpp"
#include "trifem/model/model.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace trifem::explicit_dynamics {

namespace {

/// One ExplicitMaterial per distinct law of the model's cells (in the order of their first
/// cell) and every cell's index into them.
ModelSpec materials_of(const model::Model& model) {
  ModelSpec spec;
  std::map<const material::ElasticLaw*, int> index;
  for (Index c = 0; c < model.mesh.num_cells(); ++c) {
    const model::CellMaterial& m = model.materials[c];
    TRIFEM_CHECK(m.solid && !m.mixture && m.density > 0.0,
                 "materials.{}: dynamic-explicit analyses need a solid law with a density", m.name);
    const auto [it, added] = index.try_emplace(m.solid.get(), static_cast<int>(index.size()));
    if (added)
      spec.materials.push_back({m.solid, m.density});
    spec.cell_material.push_back(it->second);
  }
  return spec;
}

/// The displacement DOFs (3 a + k) that `model` constrains in its current step.
std::vector<char> constrained_displacements(const model::Model& model) {
  TRIFEM_CHECK(!model.dofs.has_ties(), "dynamic-explicit analyses do not take rigid bodies");
  std::vector<char> fixed(3 * model.mesh.num_nodes(), 0);
  for (Index a = 0; a < model.mesh.num_nodes(); ++a)
    for (int k = 0; k < 3; ++k)
      fixed[3 * a + k] = model.dofs.is_constrained(model.dofs.dof(model.fields.u, a, k)) ? 1 : 0;
  for (const dofs::DirichletCondition& c : model.problem->conditions())
    TRIFEM_CHECK(c.dofs.empty() || c.magnitude == 0.0,
                 "dynamic-explicit analyses take fixed displacements only, not prescribed ones");
  return fixed;
}

} // namespace

ExplicitModel::ExplicitModel(mesh::Mesh mesh, ModelSpec spec)
    : mesh_(std::move(mesh)), spec_(std::move(spec)) {
  TRIFEM_CHECK(mesh_.num_cells() > 0, "explicit model: the mesh has no cells");
  check_materials();
  build_geometry();
  build_mass();
  std::vector<char> fixed(num_dofs(), 0);
  for (const Fixity& f : spec_.fixities) {
    TRIFEM_CHECK(f.component >= 0 && f.component < 3,
                 "explicit model: fixity on '{}' has component {} (expected 0, 1 or 2)", f.node_set,
                 f.component);
    for (Index a : mesh_.node_set(f.node_set))
      fixed[3 * a + f.component] = 1;
  }
  fix(fixed);
  build_incidence();
  resolve_loads();
}

ExplicitModel::ExplicitModel(const model::Model& model, std::vector<SurfaceLoad> loads)
    : mesh_(model.mesh), spec_(materials_of(model)) {
  spec_.loads = std::move(loads);
  check_materials();
  build_geometry();
  build_mass();
  fix(constrained_displacements(model));
  build_incidence();
  resolve_loads();
}

fe::HexCoords ExplicitModel::cell_values(Index c, const Vector& U) const {
  const mesh::Hex8& nodes = mesh_.cell(c);
  fe::HexCoords u;
  for (int a = 0; a < 8; ++a)
    u.row(a) = U.segment<3>(3 * nodes[a]).transpose();
  return u;
}

void ExplicitModel::check_materials() {
  if (spec_.law) {
    TRIFEM_CHECK(spec_.materials.empty() && spec_.cell_material.empty(),
                 "explicit model: give either law and density or materials, not both");
    spec_.materials = {{spec_.law, spec_.density}};
    spec_.cell_material.assign(mesh_.num_cells(), 0);
  }
  TRIFEM_CHECK(!spec_.materials.empty(), "explicit model: no material law given");
  for (std::size_t i = 0; i < spec_.materials.size(); ++i) {
    const ExplicitMaterial& m = spec_.materials[i];
    TRIFEM_CHECK(m.law != nullptr, "explicit model: material {} has no law", i);
    TRIFEM_CHECK(std::isfinite(m.density) && m.density > 0.0,
                 "explicit model: density = {} t/mm^3 (material {}), must be > 0", m.density, i);
  }
  TRIFEM_CHECK(static_cast<Index>(spec_.cell_material.size()) == mesh_.num_cells(),
               "explicit model: {} cell materials given for {} cells", spec_.cell_material.size(),
               mesh_.num_cells());
  const int n = static_cast<int>(spec_.materials.size());
  for (Index c = 0; c < mesh_.num_cells(); ++c)
    TRIFEM_CHECK(spec_.cell_material[c] >= 0 && spec_.cell_material[c] < n,
                 "explicit model: cell {} has material {} (expected 0 to {})", c,
                 spec_.cell_material[c], n - 1);
}

void ExplicitModel::build_geometry() {
  const Index n = mesh_.num_cells();
  geometry_.resize(n);
  volumes_.resize(n);
  lengths_.resize(n);
  for (Index c = 0; c < n; ++c) {
    fe::HexCoords X;
    for (int a = 0; a < 8; ++a)
      X.row(a) = mesh_.node(mesh_.cell(c)[a]).transpose();
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

void ExplicitModel::fix(const std::vector<char>& fixed) {
  fixed_ = fixed;
  inverse_mass_.resize(num_dofs());
  for (Index i = 0; i < num_dofs(); ++i) {
    TRIFEM_CHECK(fixed_[i] || mass_[i] > 0.0, "explicit model: node {} belongs to no cell", i / 3);
    inverse_mass_[i] = fixed_[i] ? 0.0 : 1.0 / mass_[i];
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

void ExplicitModel::resolve_loads() {
  const auto& rule = fe::quad_gauss_2x2();
  for (const SurfaceLoad& load : spec_.loads) {
    TRIFEM_CHECK(std::isfinite(load.pressure) && load.traction.allFinite(),
                 "explicit model: load on '{}' is not finite", load.surface);
    ResolvedLoad r{load, mesh_.surface(load.surface).facets, {}};
    for (const mesh::Facet& f : r.facets) {
      fe::QuadCoords X;
      for (int a = 0; a < 4; ++a)
        X.row(a) = mesh_.node(f.nodes[a]).transpose();
      Eigen::Matrix<Real, 4, 1> w = Eigen::Matrix<Real, 4, 1>::Zero();
      for (const auto& qp : rule) {
        const fe::QuadShapeGrad dN = fe::quad4_shape_grad(qp.xi);
        const Vec3 T1 = X.transpose() * dN.col(0), T2 = X.transpose() * dN.col(1);
        w += fe::quad4_shape(qp.xi) * T1.cross(T2).norm() * qp.weight;
      }
      r.nodal_area.push_back(w);
    }
    loads_.push_back(std::move(r));
  }
}

} // namespace trifem::explicit_dynamics
