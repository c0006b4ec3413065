// SPDX-License-Identifier: MIT
#include "trifem/model/conditions.hpp"

#include "trifem/core/error.hpp"
#include "trifem/dofs/nodal_frames.hpp"
#include "trifem/fe/point_location.hpp"
#include "trifem/model/rigid_bodies.hpp"
#include "trifem/physics/bath_term.hpp"
#include "trifem/physics/body_force_term.hpp"
#include "trifem/physics/cell_mass.hpp"
#include "trifem/physics/facet_area_any.hpp"
#include "trifem/physics/surface_load_term.hpp"

#include <algorithm>
#include <unordered_map>

namespace trifem::model {
namespace {

dofs::FieldId field_id(const Model& model, io::FieldKind kind) {
  switch (kind) {
  case io::FieldKind::Displacement:
    return model.fields.u;
  case io::FieldKind::FluidFlux:
    return model.fields.w;
  case io::FieldKind::CationFlux:
    return model.fields.j_plus;
  case io::FieldKind::AnionFlux:
    return model.fields.j_minus;
  }
  return {};
}

/// Stored value of a prescribed flux: ion flux DOFs hold j / c_ref (see MixtureFields).
Real stored_value(const Model& model, io::FieldKind kind, Real value) {
  const bool ion = kind == io::FieldKind::CationFlux || kind == io::FieldKind::AnionFlux;
  return ion ? value / model.chem.c_ref : value;
}

const std::vector<Index>& node_set(const Model& model, const std::string& key,
                                   const std::string& name) {
  return with_context(key,
                      [&]() -> const std::vector<Index>& { return model.mesh.node_set(name); });
}

/// A DOF may take one value: a DOF of a [[boundary.prescribed]] entry that another entry also
/// constrains (through other sets sharing nodes) is an input error. Fixing a DOF twice is fine.
void check_single_value_per_dof(const Model& model, const std::vector<dofs::DirichletCondition>& c,
                                const std::vector<std::string>& keys,
                                std::size_t first_prescribed) {
  std::unordered_map<Index, std::size_t> owner;
  for (std::size_t i = 0; i < c.size(); ++i)
    for (Index d : c[i].dofs) {
      const auto [it, inserted] = owner.emplace(d, i);
      if (inserted || it->second == i || std::max(it->second, i) < first_prescribed)
        continue;
      const dofs::FieldInfo& field = model.dofs.field(model.dofs.field_of(d));
      const Index node = (d - field.offset) / field.components;
      const Vec3& x = model.mesh.node(node);
      throw InputError(fmt::format(
          "{} and {} both constrain {} component {} of the node at ({:.6g}, {:.6g}, {:.6g}): a "
          "degree of freedom takes one value; use node sets that do not share this node",
          keys[it->second], keys[i], field.name, "xyz"[(d - field.offset) % field.components],
          x.x(), x.y(), x.z()));
    }
}

} // namespace

dofs::LoadCurve make_curve(const io::CaseSpec& spec, const std::string& name) {
  if (name.empty())
    return dofs::LoadCurve::constant(1.0);
  const io::CurveSpec& c = spec.curves.at(name); // existence checked by the reader
  return dofs::LoadCurve(c.points, c.interpolation, "curves." + name, c.extension);
}

ConditionSet conditions_of(const io::CaseSpec& spec, const std::vector<io::FixedSpec>& fixed,
                           const std::vector<io::PrescribedSpec>& prescribed,
                           const std::string& prescribed_key, const Model& model) {
  ConditionSet out;
  for (const auto& f : fixed) {
    out.keys.push_back(fmt::format("{}.set '{}'", f.key, f.set));
    const auto& nodes = node_set(model, f.key + ".set", f.set);
    dofs::DirichletCondition c;
    for (io::FieldKind kind : f.fields) {
      const dofs::FieldId id = field_id(model, kind);
      if (!id.valid())
        continue; // "fluxes" on a model without ions acts on the fields that exist
      for (Index n : nodes)
        for (int k : f.components)
          c.dofs.push_back(model.dofs.dof(id, n, k));
    }
    out.conditions.push_back(std::move(c));
    out.relative.push_back(false);
  }
  for (std::size_t i = 0; i < prescribed.size(); ++i) {
    const auto& p = prescribed[i];
    const std::string key = fmt::format("{}[{}]", prescribed_key, i + 1);
    out.keys.push_back(fmt::format("{}.set '{}'", key, p.set));
    const auto& nodes = node_set(model, key + ".set", p.set);
    const dofs::FieldId id = field_id(model, p.field);
    TRIFEM_CHECK(id.valid(), "{}.field: the model has no such field", key);
    dofs::DirichletCondition c{
        {}, stored_value(model, p.field, p.value), make_curve(spec, p.curve), {}};
    for (Index n : nodes)
      c.dofs.push_back(model.dofs.dof(id, n, p.component));
    out.conditions.push_back(std::move(c));
    out.relative.push_back(p.relative);
  }
  check_single_value_per_dof(model, out.conditions, out.keys, fixed.size());
  return out;
}

std::vector<dofs::DirichletCondition> boundary_conditions(const io::CaseSpec& spec,
                                                          const Model& model) {
  return conditions_of(spec, spec.fixed, spec.prescribed, "boundary.prescribed", model).conditions;
}

dofs::NodalFrames impermeable_surfaces(const io::CaseSpec& spec, const Model& model,
                                       std::vector<dofs::DirichletCondition>& conditions) {
  if (spec.impermeable_surfaces.empty())
    return {};
  std::vector<std::vector<mesh::Facet>> faces;
  for (const auto& s : spec.impermeable_surfaces)
    faces.push_back(with_context(s.key + ".surface", [&] {
      return model.mesh.surface(s.surface).facets; // (normals from the corners: any facet)
    }));
  std::vector<dofs::FieldId> fields;
  for (dofs::FieldId f : {model.fields.w, model.fields.j_plus, model.fields.j_minus})
    if (f.valid())
      fields.push_back(f);
  std::vector<Index> constrained;
  dofs::NodalFrames frames(dofs::normal_frames(model.mesh, model.dofs, fields, faces, constrained),
                           model.dofs.num_dofs());
  for (const auto& c : conditions)
    for (Index d : c.dofs)
      TRIFEM_CHECK(frames.frame_of(d) < 0,
                   "{}: a node of this surface also has an axis-aligned flux condition; use "
                   "'surface' (any orientation) for all impermeable faces that meet there",
                   spec.impermeable_surfaces.front().key);
  conditions.push_back({constrained, 0.0, dofs::LoadCurve::constant()});
  return frames;
}

std::vector<std::unique_ptr<physics::Term>>
surface_load_terms(const io::CaseSpec& spec, const std::vector<io::PressureSpec>& pressures,
                   const std::vector<io::TractionSpec>& tractions, const std::string& prefix,
                   const Model& model) {
  std::vector<std::unique_ptr<physics::Term>> terms;
  for (std::size_t i = 0; i < pressures.size(); ++i) {
    const auto& p = pressures[i];
    const auto& surface = with_context(fmt::format("{}loads.pressure[{}].surface", prefix, i + 1),
                                       [&] { return model.mesh.surface(p.surface); });
    terms.push_back(std::make_unique<physics::PressureTerm>(
        model.mesh, model.dofs, model.fields.u, surface.facets, p.value, make_curve(spec, p.curve),
        p.follower ? physics::PressureNormal::Current : physics::PressureNormal::Reference));
  }
  for (std::size_t i = 0; i < tractions.size(); ++i) {
    const auto& t = tractions[i];
    const auto& surface = with_context(fmt::format("{}loads.traction[{}].surface", prefix, i + 1),
                                       [&] { return model.mesh.surface(t.surface); });
    Vec3 traction = t.value;
    if (t.total_force) { // spread over the reference area
      const Real area = physics::reference_area(model.mesh, surface.facets);
      TRIFEM_CHECK(area > 0.0,
                   "{}loads.traction[{}].surface: '{}' has no area to spread the force "
                   "over",
                   prefix, i + 1, t.surface);
      traction /= area;
    }
    terms.push_back(std::make_unique<physics::TractionTerm>(
        model.mesh, model.dofs, model.fields.u, surface.facets, traction, make_curve(spec, t.curve),
        t.per_current_area ? physics::TractionArea::Current : physics::TractionArea::Reference));
  }
  return terms;
}

namespace {

/// The term of [[loads.body_force]] `b`: the cells of its blocks with a mass (without blocks:
/// of the mesh, and the shells of the rigid bodies). InputError naming its key if a block does
/// not exist, a cell is a mixture or a solid without a density, or nothing has a mass (rigid
/// cells without a density are skipped).
std::unique_ptr<physics::Term> body_force_term(const io::CaseSpec& spec, const io::BodyForceSpec& b,
                                               const Model& model) {
  std::vector<Index> chosen;
  for (std::size_t i = 0; i < b.blocks.size(); ++i) {
    const auto& cells = with_context(fmt::format("{}.blocks[{}]", b.key, i + 1),
                                     [&] { return model.mesh.cell_block(b.blocks[i]); });
    chosen.insert(chosen.end(), cells.begin(), cells.end());
  }
  if (b.blocks.empty())
    for (Index c = 0; c < model.mesh.num_cells(); ++c)
      chosen.push_back(c);
  std::sort(chosen.begin(), chosen.end());
  chosen.erase(std::unique(chosen.begin(), chosen.end()), chosen.end());
  std::vector<Index> cells;
  std::vector<Real> densities;
  for (Index c : chosen) {
    const CellMaterial& m = model.materials[c];
    TRIFEM_CHECK(!m.mixture,
                 "{}: {} has the mixture material '{}': body forces act on solid and rigid "
                 "cells only (in a mixture the force also drives the fluid through Darcy's law, "
                 "which trifem does not model){}",
                 b.key, model.mesh.describe(c), m.name,
                 b.blocks.empty() ? "; name the solid blocks it acts on in 'blocks'" : "");
    TRIFEM_CHECK(m.rigid() || m.density > 0.0,
                 "{}: the material '{}' of {} has no density: give `density` (t/mm^3) in "
                 "[materials.{}] (the body force is a force per unit mass)",
                 b.key, m.name, model.mesh.describe(c), m.name);
    if (m.density > 0.0) { // rigid cells without a density are massless
      cells.push_back(c);
      densities.push_back(m.density);
    }
  }
  std::vector<physics::MassElement> masses =
      physics::cell_mass_elements(model.mesh, cells, densities);
  if (b.blocks.empty())
    for (physics::MassElement& shell : rigid_shell_masses(spec, model))
      masses.push_back(std::move(shell));
  TRIFEM_CHECK(!masses.empty(),
               "{}: the body force acts on no mass (its cells are those of rigid bodies without a "
               "density: give `density` in their [[rigid_body]])",
               b.key);
  if (spec.lumps_the_mass()) // f_a = m_a b with the lumped m_a: a free body falls with b
    for (physics::MassElement& e : masses)
      if (!(e.mass.rowwise().sum().array() > 0.0).all()) { // (the row sums are: unchanged)
        const Eigen::VectorXd lumped = physics::lumped_mass(e.mass);
        e.mass = lumped.asDiagonal();
      }
  return std::make_unique<physics::BodyForceTerm>(model.dofs, model.fields.u, masses, b.force,
                                                  make_curve(spec, b.curve));
}

/// The term of [[loads.nodal_force]] `f`: its value on every node of its set, one force per
/// non-zero component (a node carried by a rigid body passes its force to the body as any load
/// on its DOFs does). InputError naming its key if the set does not exist.
std::unique_ptr<physics::Term> nodal_force_term(const io::CaseSpec& spec,
                                                const io::NodalForceSpec& f, const Model& model) {
  const auto& nodes =
      with_context(fmt::format("{}.set", f.key), [&] { return model.mesh.node_set(f.set); });
  const dofs::LoadCurve curve = make_curve(spec, f.curve);
  std::vector<physics::NodalForce> forces;
  for (const Index a : nodes)
    for (int k = 0; k < 3; ++k)
      if (f.value[k] != 0.0)
        forces.push_back({model.dofs.dof(model.fields.u, a, k), f.value[k], curve});
  return std::make_unique<physics::NodalForceTerm>(std::move(forces));
}

} // namespace

std::vector<std::unique_ptr<physics::Term>> load_terms(const io::CaseSpec& spec,
                                                       const Model& model) {
  auto terms = surface_load_terms(spec, spec.pressures, spec.tractions, "", model);
  for (const io::BodyForceSpec& b : spec.body_forces)
    terms.push_back(body_force_term(spec, b, model));
  for (const io::NodalForceSpec& f : spec.nodal_forces)
    terms.push_back(nodal_force_term(spec, f, model));
  for (std::size_t i = 0; i < spec.baths.size(); ++i) {
    const auto& b = spec.baths[i];
    const auto& surface =
        with_context(fmt::format("boundary.bath[{}].surface", i + 1),
                     [&]() -> const mesh::Surface& { return model.mesh.surface(b.surface); });
    terms.push_back(std::make_unique<physics::BathTerm>(
        model.mesh, model.dofs, model.fields, surface.facets, model.chem,
        b.concentration > 0.0 ? b.concentration : model.chem.c_ref, make_curve(spec, b.curve),
        b.pressure));
  }
  return terms;
}

namespace {

/// The probe `p` (the i-th): InputError naming its key if its point lies outside the mesh or
/// the material there does not have its quantity.
Probe make_probe(const io::ProbeSpec& p, std::size_t i, const Model& model) {
  const io::ProbeQuantity* q = io::find_probe_quantity(p.quantity);
  TRIFEM_VERIFY(q, "unknown probe quantity {}", p.quantity); // the reader checked it
  const auto where = fe::locate_point(model.mesh, p.point);
  TRIFEM_CHECK(where,
               "output.probe[{}].point = [{}, {}, {}]: outside the mesh (no cell contains "
               "it in the reference configuration)",
               i + 1, p.point.x(), p.point.y(), p.point.z());
  const auto& mixture = model.materials[where->cell].mixture;
  const bool has =
      q->requirement == io::ProbeRequirement::None ||
      (mixture && (q->requirement == io::ProbeRequirement::Mixture || mixture->charged));
  TRIFEM_CHECK(has,
               "output.probe[{}].quantity = '{}': the material at the probe's point (cell "
               "{}) has no {} (it needs a {} material)",
               i + 1, q->name, where->cell, q->name,
               q->requirement == io::ProbeRequirement::Ions ? "triphasic"
                                                            : "biphasic or triphasic");
  return {p.name, q, where->cell, where->xi};
}

} // namespace

void add_outputs(const io::CaseSpec& spec, Model& model) {
  for (std::size_t i = 0; i < spec.output.reactions.size(); ++i) {
    const auto& r = spec.output.reactions[i];
    const auto& nodes = node_set(model, fmt::format("output.reaction[{}].set", i + 1), r.set);
    ReactionSet set{r.set, {false, false, false}, {}};
    for (Index n : nodes)
      for (int k = 0; k < 3; ++k)
        set.dofs[k].push_back(model.dofs.dof(model.fields.u, n, k));
    model.reactions.push_back(std::move(set));
  }
  for (std::size_t i = 0; i < spec.output.probes.size(); ++i)
    model.probes.push_back(make_probe(spec.output.probes[i], i, model));
}

} // namespace trifem::model
