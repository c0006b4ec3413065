// SPDX-License-Identifier: MIT
#include "model.hpp"

#include "trifem/core/error.hpp"
#include "trifem/material/registry.hpp"
#include "trifem/mesh/gmsh_reader.hpp"
#include "trifem/physics/surface_load_term.hpp"

namespace trifem::app {
namespace {

/// Runs f, prefixing any InputError with the case key it concerns.
template <class F>
auto with_context(const std::string& key, F&& f) {
  try {
    return f();
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: {}", key, e.what()));
  }
}

dofs::LoadCurve make_curve(const io::CaseSpec& spec, const std::string& name) {
  if (name.empty())
    return dofs::LoadCurve::constant(1.0);
  const io::CurveSpec& c = spec.curves.at(name); // existence checked by the reader
  return dofs::LoadCurve(c.points, c.interpolation, "curves." + name);
}

/// Law of every cell, from the block -> material map.
std::vector<std::shared_ptr<const material::ElasticLaw>>
cell_laws(const io::CaseSpec& spec, const mesh::Mesh& mesh,
          const std::map<std::string, std::string>& block_materials) {
  std::map<std::string, std::shared_ptr<const material::ElasticLaw>> laws;
  for (const auto& [name, m] : spec.materials)
    laws[name] = material::create_law(m.type, m.parameters, "materials." + name);
  std::vector<std::shared_ptr<const material::ElasticLaw>> per_cell(mesh.num_cells());
  for (const auto& [block, material] : block_materials) {
    const auto& cells = with_context("mesh", [&] { return mesh.cell_block(block); });
    for (Index c : cells)
      per_cell[c] = laws.at(material);
  }
  for (Index c = 0; c < mesh.num_cells(); ++c)
    TRIFEM_CHECK(per_cell[c] != nullptr,
                 "mesh: cell {} has no material (assign one to its cell block)", c);
  return per_cell;
}

std::vector<dofs::DirichletCondition> conditions(const io::CaseSpec& spec, const Model& model) {
  std::vector<dofs::DirichletCondition> out;
  for (std::size_t i = 0; i < spec.fixed.size(); ++i) {
    const auto& f = spec.fixed[i];
    const auto& nodes = with_context(fmt::format("boundary.fixed[{}].set", i + 1),
                                     [&] { return model.mesh.node_set(f.set); });
    dofs::DirichletCondition c;
    for (Index n : nodes)
      for (int k : f.components)
        c.dofs.push_back(model.dofs.dof(model.displacement, n, k));
    out.push_back(std::move(c));
  }
  for (std::size_t i = 0; i < spec.prescribed.size(); ++i) {
    const auto& p = spec.prescribed[i];
    const auto& nodes = with_context(fmt::format("boundary.prescribed[{}].set", i + 1),
                                     [&] { return model.mesh.node_set(p.set); });
    dofs::DirichletCondition c{{}, p.value, make_curve(spec, p.curve)};
    for (Index n : nodes)
      c.dofs.push_back(model.dofs.dof(model.displacement, n, p.component));
    out.push_back(std::move(c));
  }
  return out;
}

/// Nodes that belong to no cell get all their DOFs fixed (they would make K singular).
dofs::DirichletCondition orphan_nodes(const Model& model) {
  std::vector<char> used(model.mesh.num_nodes(), 0);
  for (const auto& cell : model.mesh.cells())
    for (Index n : cell)
      used[n] = 1;
  dofs::DirichletCondition c;
  for (Index n = 0; n < model.mesh.num_nodes(); ++n)
    if (!used[n])
      for (int k = 0; k < 3; ++k)
        c.dofs.push_back(model.dofs.dof(model.displacement, n, k));
  return c;
}

std::vector<std::unique_ptr<physics::Term>>
load_terms(const io::CaseSpec& spec, const Model& model) {
  std::vector<std::unique_ptr<physics::Term>> terms;
  for (std::size_t i = 0; i < spec.pressures.size(); ++i) {
    const auto& p = spec.pressures[i];
    const auto& surface = with_context(fmt::format("loads.pressure[{}].surface", i + 1),
                                       [&] { return model.mesh.surface(p.surface); });
    terms.push_back(std::make_unique<physics::PressureTerm>(
        model.mesh, model.dofs, model.displacement, surface.facets, p.value,
        make_curve(spec, p.curve)));
  }
  for (std::size_t i = 0; i < spec.tractions.size(); ++i) {
    const auto& t = spec.tractions[i];
    const auto& surface = with_context(fmt::format("loads.traction[{}].surface", i + 1),
                                       [&] { return model.mesh.surface(t.surface); });
    terms.push_back(std::make_unique<physics::TractionTerm>(
        model.mesh, model.dofs, model.displacement, surface.facets, t.value,
        make_curve(spec, t.curve)));
  }
  return terms;
}

void add_outputs(const io::CaseSpec& spec, Model& model) {
  for (std::size_t i = 0; i < spec.output.reactions.size(); ++i) {
    const auto& r = spec.output.reactions[i];
    const auto& nodes = with_context(fmt::format("output.reaction[{}].set", i + 1),
                                     [&] { return model.mesh.node_set(r.set); });
    ReactionSet set{r.set, {}};
    for (Index n : nodes)
      for (int k = 0; k < 3; ++k)
        set.dofs[k].push_back(model.dofs.dof(model.displacement, n, k));
    model.reactions.push_back(std::move(set));
  }
  for (const auto& p : spec.output.probes) {
    Index best = 0;
    for (Index n = 1; n < model.mesh.num_nodes(); ++n)
      if ((model.mesh.node(n) - p.point).squaredNorm() <
          (model.mesh.node(best) - p.point).squaredNorm())
        best = n;
    model.probes.push_back({p.name, p.quantity, best});
  }
}

Real bounding_box_diagonal(const mesh::Mesh& mesh) {
  Vec3 lo = mesh.node(0), hi = mesh.node(0);
  for (const Vec3& x : mesh.nodes()) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  return (hi - lo).norm();
}

} // namespace

mesh::Mesh build_mesh(const io::CaseSpec& spec, std::map<std::string, std::string>& materials) {
  mesh::Mesh mesh;
  for (const auto& b : spec.boxes) {
    mesh.append(mesh::make_box(b.box));
    materials[b.box.name] = b.material;
  }
  for (std::size_t i = 0; i < spec.gmsh.size(); ++i) {
    const auto& g = spec.gmsh[i];
    const auto path = g.file.is_absolute() ? g.file : spec.file.parent_path() / g.file;
    mesh::Mesh part = mesh::read_gmsh(path);
    for (const auto& [block, material] : g.materials) {
      TRIFEM_CHECK(part.has_cell_block(block),
                   "mesh.gmsh[{}].materials: '{}' is not a physical volume of {}", i + 1, block,
                   path.string());
      materials[block] = material;
    }
    with_context(fmt::format("mesh.gmsh[{}]", i + 1), [&] {
      mesh.append(part);
      return 0;
    });
  }
  TRIFEM_CHECK(mesh.num_cells() > 0, "mesh: the model has no cells");
  return mesh;
}

std::unique_ptr<Model> build_model(const io::CaseSpec& spec) {
  auto model = std::make_unique<Model>();
  std::map<std::string, std::string> block_materials;
  model->mesh = build_mesh(spec, block_materials);
  const auto laws = cell_laws(spec, model->mesh, block_materials);
  model->displacement = model->dofs.add_field("displacement", model->mesh.num_nodes(), 3);
  auto bcs = conditions(spec, *model);
  bcs.push_back(orphan_nodes(*model));
  dofs::constrain_all(bcs, model->dofs);
  model->dofs.finalize();

  std::vector<Index> cells(model->mesh.num_cells());
  for (Index c = 0; c < model->mesh.num_cells(); ++c)
    cells[c] = c;
  std::vector<std::unique_ptr<physics::Term>> terms;
  auto solid = std::make_unique<physics::SolidTerm>(model->mesh, model->dofs,
                                                    model->displacement, cells, laws);
  model->solid = solid.get();
  terms.push_back(std::move(solid));
  for (auto& t : load_terms(spec, *model))
    terms.push_back(std::move(t));

  model->length_scale = bounding_box_diagonal(model->mesh);
  model->modulus_scale = 0.0;
  for (const auto& law : laws)
    model->modulus_scale = std::max(model->modulus_scale, law->p_wave_modulus());
  const Real L = model->length_scale;
  std::vector<solver::FieldScale> scales = {
      {"displacement", model->modulus_scale * L * L, L}};
  model->problem = std::make_unique<assembly::FeProblem>(model->dofs, std::move(bcs),
                                                         std::move(terms), std::move(scales));
  add_outputs(spec, *model);
  return model;
}

} // namespace trifem::app
