// SPDX-License-Identifier: MIT
#include "trifem/model/explicit_case.hpp"

#include "trifem/core/error.hpp"
#include "trifem/material/registry.hpp"
#include "trifem/model/conditions.hpp"

#include <algorithm>
#include <map>

namespace trifem::model {
namespace {

namespace ed = explicit_dynamics;

/// The materials the mesh uses (one law and density each) and every cell's index into them.
void add_materials(const io::CaseSpec& spec, const mesh::Mesh& mesh,
                   const std::map<std::string, std::string>& blocks, ed::ModelSpec& model,
                   std::vector<std::string>& names) {
  std::map<std::string, int> index;
  model.cell_material.assign(mesh.num_cells(), -1);
  for (const auto& [block, name] : blocks) {
    const auto [it, added] = index.try_emplace(name, static_cast<int>(model.materials.size()));
    if (added) {
      const io::MaterialSpec& m = spec.materials.at(name); // existence checked by the reader
      const std::string key = "materials." + name;
      TRIFEM_CHECK(!m.is_mixture() && m.density.has_value(),
                   "{}: dynamic-explicit analyses need a solid law with a density", key);
      model.materials.push_back({material::create_law(m.solid_law(), key), *m.density});
      names.push_back(name);
    }
    const std::string& block_name = block; // a lambda may not capture a structured binding
    for (Index c : with_context("mesh", [&] { return mesh.cell_block(block_name); }))
      model.cell_material[c] = it->second;
  }
  for (Index c = 0; c < mesh.num_cells(); ++c)
    TRIFEM_CHECK(model.cell_material[c] >= 0,
                 "mesh: cell {} has no material (assign one to its cell block)", c);
}

/// Zero displacement components of [[boundary.fixed]] and [[boundary.bonded]].
std::vector<ed::Fixity> fixities(const io::CaseSpec& spec, const mesh::Mesh& mesh) {
  std::vector<ed::Fixity> out;
  for (const io::FixedSpec& f : spec.fixed) {
    const auto& fields = f.fields;
    if (std::find(fields.begin(), fields.end(), io::FieldKind::Displacement) == fields.end())
      continue;
    with_context(f.key + ".set", [&] { return mesh.node_set(f.set).size(); });
    for (const io::Component k : f.components)
      out.push_back({f.set, k});
  }
  return out;
}

/// [[loads.pressure]] as follower pressures and [[loads.traction]] as dead tractions.
std::vector<ed::SurfaceLoad> surface_loads(const io::CaseSpec& spec, const mesh::Mesh& mesh) {
  std::vector<ed::SurfaceLoad> out;
  const auto check = [&](const std::string& key, const std::string& surface) {
    with_context(key, [&] { return mesh.surface(surface).facets.size(); });
  };
  for (std::size_t i = 0; i < spec.pressures.size(); ++i) {
    const io::PressureSpec& p = spec.pressures[i];
    check(fmt::format("loads.pressure[{}].surface", i + 1), p.surface);
    ed::SurfaceLoad load;
    load.kind = ed::LoadKind::FollowerPressure;
    load.surface = p.surface;
    load.pressure = p.value;
    load.curve = make_curve(spec, p.curve);
    out.push_back(std::move(load));
  }
  for (std::size_t i = 0; i < spec.tractions.size(); ++i) {
    const io::TractionSpec& t = spec.tractions[i];
    check(fmt::format("loads.traction[{}].surface", i + 1), t.surface);
    ed::SurfaceLoad load;
    load.kind = ed::LoadKind::DeadTraction;
    load.surface = t.surface;
    load.traction = t.value;
    load.curve = make_curve(spec, t.curve);
    out.push_back(std::move(load));
  }
  return out;
}

/// Reaction sets (DOFs 3 a + k) and probes (nearest node in the reference configuration).
void add_history_outputs(const io::CaseSpec& spec, const mesh::Mesh& mesh, ExplicitCase& c) {
  for (std::size_t i = 0; i < spec.output.reactions.size(); ++i) {
    const io::ReactionSpec& r = spec.output.reactions[i];
    const auto& nodes = with_context(fmt::format("output.reaction[{}].set", i + 1),
                                     [&] { return mesh.node_set(r.set); });
    ExplicitReaction set{r.set, {}};
    for (Index n : nodes)
      for (int k = 0; k < 3; ++k)
        set.dofs[k].push_back(3 * n + k);
    c.reactions.push_back(std::move(set));
  }
  for (std::size_t i = 0; i < spec.output.probes.size(); ++i) {
    const io::ProbeSpec& p = spec.output.probes[i];
    TRIFEM_CHECK(p.quantity == "displacement" || p.quantity == "position",
                 "output.probe[{}].quantity = '{}': dynamic-explicit analyses probe only "
                 "'displacement' and 'position'",
                 i + 1, p.quantity);
    Index best = 0;
    for (Index n = 1; n < mesh.num_nodes(); ++n)
      if ((mesh.node(n) - p.point).squaredNorm() < (mesh.node(best) - p.point).squaredNorm())
        best = n;
    c.probes.push_back({p.name, p.quantity == "position", best});
  }
}

} // namespace

ed::ExplicitSettings explicit_settings(const io::CaseSpec& spec) {
  const io::ExplicitSpec& e = spec.explicit_dynamics;
  ed::ExplicitSettings s;
  s.reading = e.reading == io::ExplicitReading::A ? ed::Reading::A : ed::Reading::B;
  s.constraint =
      e.constraint == io::VolumeConstraint::LogJ ? ed::Constraint::LogJ : ed::Constraint::JMinusOne;
  s.multiplier = e.multiplier;
  s.penalty = e.penalty;
  s.damping = e.damping;
  s.time_step = spec.time.dt;
  s.safety_factor = e.safety_factor;
  s.max_factorization_age = e.factorization_age;
  switch (e.stable_step) {
  case io::StableStepEstimate::PowerIteration:
    s.stable_step = ed::StableStepMethod::PowerIteration;
    break;
  case io::StableStepEstimate::ElementBound:
    s.stable_step = ed::StableStepMethod::ElementBound;
    break;
  case io::StableStepEstimate::None:
    s.stable_step = ed::StableStepMethod::None;
    break;
  }
  s.stable_step_interval = e.stable_step_interval;
  s.displacement_tolerance = e.displacement_tolerance;
  s.constraint_tolerance = e.constraint_tolerance;
  s.max_iterations = e.max_iterations;
  s.max_halvings = e.max_halvings;
  s.validate();
  return s;
}

io::CaseSpec quasi_static_part(const io::CaseSpec& spec) {
  TRIFEM_CHECK(spec.has_explicit_step() && spec.steps.size() >= 2,
               "step: no dynamic-explicit step after a quasi-static one");
  io::CaseSpec part = spec;
  part.steps.pop_back();
  part.time.end_time = part.steps.back().time.end_time;
  return part;
}

io::CaseSpec explicit_step_part(const io::CaseSpec& spec) {
  TRIFEM_CHECK(spec.has_explicit_step(), "step: no dynamic-explicit step");
  const io::StepSpec& step = spec.steps.back();
  io::CaseSpec part = spec;
  part.analysis.type = io::AnalysisType::DynamicExplicit;
  part.steps.clear();
  part.time = io::TimeSpec{};
  part.time.end_time = step.time.end_time;
  part.time.dt = step.time.dt;
  part.fixed.insert(part.fixed.end(), step.fixed.begin(), step.fixed.end());
  part.pressures.insert(part.pressures.end(), step.pressures.begin(), step.pressures.end());
  part.tractions.insert(part.tractions.end(), step.tractions.begin(), step.tractions.end());
  return part;
}

ExplicitCase build_explicit_case(const io::CaseSpec& spec) {
  TRIFEM_CHECK(spec.is_explicit(), "analysis.type: not a dynamic-explicit analysis");
  ExplicitCase c;
  c.settings = explicit_settings(spec);
  std::map<std::string, std::string> blocks;
  mesh::Mesh mesh = build_mesh(spec, blocks);
  ed::ModelSpec model;
  add_materials(spec, mesh, blocks, model, c.material_names);
  model.fixities = fixities(spec, mesh);
  model.loads = surface_loads(spec, mesh);
  add_history_outputs(spec, mesh, c);
  c.model = std::make_unique<ed::ExplicitModel>(std::move(mesh), std::move(model));
  return c;
}

} // namespace trifem::model
