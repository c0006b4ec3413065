// SPDX-License-Identifier: MIT
#include "trifem/analysis/explicit_case.hpp"

#include "trifem/core/error.hpp"
#include "trifem/model/conditions.hpp"

namespace trifem::analysis {
namespace {

namespace ed = explicit_dynamics;

/// [[loads.pressure]] as follower pressures and [[loads.traction]] as dead tractions.
std::vector<ed::SurfaceLoad> surface_loads(const io::CaseSpec& spec, const mesh::Mesh& mesh) {
  std::vector<ed::SurfaceLoad> out;
  const auto check = [&](const std::string& key, const std::string& surface) {
    model::with_context(key, [&] { return mesh.surface(surface).facets.size(); });
  };
  for (std::size_t i = 0; i < spec.pressures.size(); ++i) {
    const io::PressureSpec& p = spec.pressures[i];
    check(fmt::format("loads.pressure[{}].surface", i + 1), p.surface);
    ed::SurfaceLoad load;
    load.kind = ed::LoadKind::FollowerPressure;
    load.surface = p.surface;
    load.pressure = p.value;
    load.curve = model::make_curve(spec, p.curve);
    out.push_back(std::move(load));
  }
  for (std::size_t i = 0; i < spec.tractions.size(); ++i) {
    const io::TractionSpec& t = spec.tractions[i];
    check(fmt::format("loads.traction[{}].surface", i + 1), t.surface);
    ed::SurfaceLoad load;
    load.kind = ed::LoadKind::DeadTraction;
    load.surface = t.surface;
    load.traction = t.value;
    load.curve = model::make_curve(spec, t.curve);
    out.push_back(std::move(load));
  }
  return out;
}

/// Reaction sets (DOFs 3 a + k) and probes (nearest node in the reference configuration).
void add_history_outputs(const io::CaseSpec& spec, const mesh::Mesh& mesh, ExplicitCase& c) {
  for (std::size_t i = 0; i < spec.output.reactions.size(); ++i) {
    const io::ReactionSpec& r = spec.output.reactions[i];
    const auto& nodes = model::with_context(fmt::format("output.reaction[{}].set", i + 1),
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

ExplicitCase explicit_case(const io::CaseSpec& spec, const mesh::Mesh& mesh) {
  ExplicitCase c;
  static_cast<io::ExplicitSpec&>(c.settings) = spec.explicit_dynamics;
  c.settings.time_step = spec.time.dt;
  c.loads = surface_loads(spec, mesh);
  add_history_outputs(spec, mesh, c);
  return c;
}

void build_explicit_model(ExplicitCase& c, const model::Model& model) {
  c.model = std::make_unique<ed::ExplicitModel>(model, c.loads);
  c.material_names.assign(c.model->materials().size(), "");
  for (Index cell = 0; cell < model.mesh.num_cells(); ++cell)
    c.material_names[c.model->material_of(cell)] = model.materials[cell].name;
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
  part.pressures.insert(part.pressures.end(), step.pressures.begin(), step.pressures.end());
  part.tractions.insert(part.tractions.end(), step.tractions.begin(), step.tractions.end());
  return part;
}

} // namespace trifem::analysis
