// SPDX-License-Identifier: MIT
#include "trifem/analysis/restart_fingerprint.hpp"

#include <map>
#include <string>
#include <vector>

namespace trifem::analysis {
namespace {

/// Feeds typed values to FNV-1a. Strings and lists are preceded by their length, so that no two
/// different sequences of values give the same bytes.
class PartHasher {
public:
  void integer(std::int64_t v) { fnv_.add(&v, sizeof v); }
  void real(Real v) { fnv_.add(&v, sizeof v); } // bitwise: the same case gives the same bits
  void flag(bool v) { integer(v ? 1 : 0); }
  template <class Enum>
  void kind(Enum v) {
    integer(static_cast<std::int64_t>(v));
  }
  void text(std::string_view s) {
    integer(static_cast<std::int64_t>(s.size()));
    fnv_.add(s.data(), s.size());
  }
  void vec3(const Vec3& v) {
    for (int i = 0; i < 3; ++i)
      real(v[i]);
  }
  template <class Int>
  void indices(const std::vector<Int>& v) {
    integer(static_cast<std::int64_t>(v.size()));
    for (const Int i : v)
      integer(i);
  }
  void reals(const std::vector<Real>& v) {
    integer(static_cast<std::int64_t>(v.size()));
    for (const Real x : v)
      real(x);
  }
  void names(const std::map<std::string, std::string>& m) {
    integer(static_cast<std::int64_t>(m.size()));
    for (const auto& [key, value] : m) {
      text(key);
      text(value);
    }
  }
  std::uint64_t value() const { return fnv_.value(); }

private:
  Fnv1a64 fnv_;
};

std::uint64_t mesh_hash(const mesh::Mesh& mesh) {
  PartHasher h;
  h.integer(mesh.num_nodes());
  for (const Vec3& x : mesh.nodes())
    h.vec3(x);
  h.integer(mesh.num_cells());
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    if (mesh.cell_type(c) != mesh::CellType::Hex8) // (a hex8 mesh hashes as before)
      h.integer(-1 - static_cast<std::int64_t>(mesh.cell_type(c)));
    for (const Index node : mesh.cell_nodes(c))
      h.integer(node);
  }
  h.integer(static_cast<std::int64_t>(mesh.cell_blocks().size()));
  for (const auto& [name, cells] : mesh.cell_blocks()) {
    h.text(name);
    h.indices(cells);
  }
  h.integer(static_cast<std::int64_t>(mesh.node_sets().size()));
  for (const auto& [name, nodes] : mesh.node_sets()) {
    h.text(name);
    h.indices(nodes);
  }
  h.integer(static_cast<std::int64_t>(mesh.surfaces().size()));
  for (const auto& [name, surface] : mesh.surfaces()) {
    h.text(name);
    h.integer(static_cast<std::int64_t>(surface.facets.size()));
    for (const mesh::Facet& f : surface.facets) {
      for (const Index node : f.nodes)
        h.integer(node);
      h.integer(f.cell);
      h.integer(f.local_face);
      if (!f.is_quad4()) { // (the facets of hex8 cells hash as before)
        h.integer(static_cast<std::int64_t>(f.type));
        for (const Index node : f.mid_edge_nodes)
          h.integer(node);
      }
    }
  }
  h.integer(static_cast<std::int64_t>(mesh.cell_data().size()));
  for (const auto& [name, data] : mesh.cell_data()) {
    h.text(name);
    h.integer(data.components);
    h.reals(data.values);
  }
  return h.value();
}

/// The layout of the unknowns and which of them the case and each step hold: not the current
/// constraints, which depend on the active step.
std::uint64_t dofs_hash(const model::Model& model) {
  const dofs::DofMap& map = model.dofs;
  PartHasher h;
  h.integer(map.num_dofs());
  h.integer(map.num_fields());
  for (int f = 0; f < map.num_fields(); ++f) {
    const dofs::FieldInfo& field = map.field(dofs::FieldId{f});
    h.text(field.name);
    h.integer(field.num_entities);
    h.integer(field.components);
    h.integer(field.offset);
  }
  h.flag(map.has_ties());
  if (map.has_ties())
    for (Index d = 0; d < map.num_dofs(); ++d)
      h.integer(map.leader(d));
  h.integer(static_cast<std::int64_t>(model.case_conditions.size()));
  for (const dofs::DirichletCondition& c : model.case_conditions)
    h.indices(c.dofs);
  h.integer(static_cast<std::int64_t>(model.steps.size()));
  for (const model::ModelStep& step : model.steps) {
    h.integer(static_cast<std::int64_t>(step.conditions.size()));
    for (std::size_t i = 0; i < step.conditions.size(); ++i) {
      h.indices(step.conditions[i].dofs);
      h.flag(step.relative[i]);
    }
  }
  return h.value();
}

void hash_parameters(const material::ParameterValues& parameters, PartHasher& h) {
  h.integer(static_cast<std::int64_t>(parameters.size()));
  for (const auto& [key, value] : parameters) {
    h.text(key);
    h.real(value);
  }
}

void hash_law(const io::SolidSpec& law, PartHasher& h) {
  h.text(law.type);
  hash_parameters(law.parameters, h);
  h.integer(static_cast<std::int64_t>(law.constituents.size()));
  for (const io::SolidSpec& c : law.constituents)
    hash_law(c, h);
}

void hash_axes(const material::AxesSpec& axes, PartHasher& h) {
  h.kind(axes.kind);
  h.vec3(axes.a);
  h.vec3(axes.d);
  h.vec3(axes.center);
  h.vec3(axes.axis);
  h.text(axes.view);
  h.text(axes.d_view);
}

void hash_material(const io::MaterialSpec& m, PartHasher& h) {
  h.text(m.type);
  hash_parameters(m.parameters, h);
  h.flag(m.solid.has_value());
  if (m.solid)
    hash_law(*m.solid, h);
  h.flag(m.density.has_value());
  if (m.density)
    h.real(*m.density);
  h.integer(static_cast<std::int64_t>(m.constituents.size()));
  for (const io::SolidSpec& c : m.constituents)
    hash_law(c, h);
  h.kind(m.element);
  h.flag(m.axes.has_value());
  if (m.axes)
    hash_axes(*m.axes, h);
}

/// Every material with all its parameters (those the case gave and the defaults the reader
/// filled in), and the material of each cell block.
std::uint64_t materials_hash(const io::CaseSpec& spec) {
  PartHasher h;
  h.integer(static_cast<std::int64_t>(spec.materials.size()));
  for (const auto& [name, material] : spec.materials) {
    h.text(name);
    hash_material(material, h);
  }
  h.integer(static_cast<std::int64_t>(spec.boxes.size()));
  for (const io::BoxMeshSpec& box : spec.boxes) {
    h.text(box.box.name);
    h.text(box.material);
  }
  h.integer(static_cast<std::int64_t>(spec.gmsh.size()));
  for (const io::GmshMeshSpec& g : spec.gmsh)
    h.names(g.materials);
  h.integer(static_cast<std::int64_t>(spec.meshes.size()));
  for (const io::InlineMeshSpec& m : spec.meshes)
    h.names(m.materials);
  return h.value();
}

void hash_fixed(const std::vector<io::FixedSpec>& fixed, PartHasher& h) {
  h.integer(static_cast<std::int64_t>(fixed.size()));
  for (const io::FixedSpec& f : fixed) {
    h.text(f.set);
    h.indices(f.components);
    h.integer(static_cast<std::int64_t>(f.fields.size()));
    for (const io::FieldKind kind : f.fields)
      h.kind(kind);
  }
}

void hash_prescribed(const std::vector<io::PrescribedSpec>& prescribed, PartHasher& h) {
  h.integer(static_cast<std::int64_t>(prescribed.size()));
  for (const io::PrescribedSpec& p : prescribed) {
    h.text(p.set);
    h.integer(p.component);
    h.real(p.value);
    h.text(p.curve);
    h.kind(p.field);
    h.flag(p.relative);
  }
}

void hash_surface_loads(const std::vector<io::PressureSpec>& pressures,
                        const std::vector<io::TractionSpec>& tractions, PartHasher& h) {
  h.integer(static_cast<std::int64_t>(pressures.size()));
  for (const io::PressureSpec& p : pressures) {
    h.text(p.surface);
    h.real(p.value);
    h.text(p.curve);
    if (!p.follower) // (a follower: the hash is unchanged)
      h.integer(2);
  }
  h.integer(static_cast<std::int64_t>(tractions.size()));
  for (const io::TractionSpec& t : tractions) {
    h.text(t.surface);
    h.vec3(t.value);
    h.text(t.curve);
    if (t.per_current_area) // (per reference area: the hash is unchanged)
      h.integer(1);
    if (t.total_force) // (a traction: the hash is unchanged)
      h.integer(3);
  }
}

/// The case-level conditions and loads, and every load curve (steps and rigid bodies name them
/// too).
std::uint64_t boundary_conditions_hash(const io::CaseSpec& spec) {
  PartHasher h;
  hash_fixed(spec.fixed, h);
  hash_prescribed(spec.prescribed, h);
  h.integer(static_cast<std::int64_t>(spec.impermeable_surfaces.size()));
  for (const io::ImpermeableSurfaceSpec& s : spec.impermeable_surfaces)
    h.text(s.surface);
  hash_surface_loads(spec.pressures, spec.tractions, h);
  h.integer(static_cast<std::int64_t>(spec.baths.size()));
  for (const io::BathSpec& b : spec.baths) {
    h.text(b.surface);
    h.real(b.concentration);
    h.real(b.pressure);
    h.text(b.curve);
  }
  if (!spec.body_forces.empty()) { // (none: the hash is unchanged)
    h.integer(static_cast<std::int64_t>(spec.body_forces.size()));
    for (const io::BodyForceSpec& b : spec.body_forces) {
      h.vec3(b.force);
      h.integer(static_cast<std::int64_t>(b.blocks.size()));
      for (const std::string& block : b.blocks)
        h.text(block);
      h.text(b.curve);
    }
  }
  if (!spec.nodal_forces.empty()) { // (none: the hash is unchanged)
    h.integer(static_cast<std::int64_t>(spec.nodal_forces.size()));
    for (const io::NodalForceSpec& f : spec.nodal_forces) {
      h.text(f.set);
      h.vec3(f.value);
      h.text(f.curve);
    }
  }
  if (!spec.initial_velocities.empty()) { // (none: the hash is unchanged)
    h.integer(static_cast<std::int64_t>(spec.initial_velocities.size()));
    for (const io::InitialVelocitySpec& v : spec.initial_velocities) {
      h.text(v.set);
      h.vec3(v.value);
    }
  }
  h.integer(static_cast<std::int64_t>(spec.curves.size()));
  for (const auto& [name, curve] : spec.curves) {
    h.text(name);
    h.kind(curve.interpolation);
    h.integer(static_cast<std::int64_t>(curve.points.size()));
    for (const auto& [t, v] : curve.points) {
      h.real(t);
      h.real(v);
    }
    if (curve.extension != dofs::Extension::Constant) // constant: older restart files match
      h.kind(curve.extension);
  }
  return h.value();
}

std::uint64_t contact_hash(const io::CaseSpec& spec) {
  PartHasher h;
  h.integer(static_cast<std::int64_t>(spec.contacts.size()));
  for (const io::ContactSpec& c : spec.contacts) {
    h.text(c.master);
    h.text(c.slave);
    h.flag(c.both_surfaces);
    h.real(c.scale);
    h.real(c.search_distance);
    h.real(c.penetration_tolerance);
  }
  return h.value();
}

/// The connectors (nothing without any: the hash of a case without them is unchanged).
void hash_connectors(const io::CaseSpec& spec, PartHasher& h) {
  if (spec.connectors.empty())
    return;
  h.integer(static_cast<std::int64_t>(spec.connectors.size()));
  for (const io::ConnectorSpec& c : spec.connectors) {
    h.text(c.name);
    h.kind(c.kind);
    h.text(c.body_a);
    h.text(c.body_b);
    for (const Vec3& v :
         {c.origin, c.axis, c.transverse.value_or(Vec3::Zero()), c.point_a, c.point_b})
      h.vec3(v);
    for (const io::RigidComponentSpec* d : {&c.rotation, &c.translation}) {
      h.kind(d->drive);
      h.real(d->value);
      h.text(d->curve);
    }
    for (const Real v : {c.torsion_stiffness, c.stiffness, c.free_length.value_or(-1.0), c.force})
      h.real(v);
    h.text(c.curve);
  }
}

/// The constraints (nothing without any: the hash of a case without them is unchanged).
void hash_constraints(const io::CaseSpec& spec, PartHasher& h) {
  if (spec.constraints.empty())
    return;
  h.integer(static_cast<std::int64_t>(spec.constraints.size()));
  for (const io::ConstraintSpec& c : spec.constraints) {
    h.text(c.name);
    h.kind(c.kind);
    h.text(c.surface);
    for (const io::LinearConstraintEntry& e : c.entries) {
      h.integer(e.node);
      h.integer(e.component);
      h.real(e.coefficient);
    }
    h.real(c.value);
    h.text(c.curve);
    h.vec3(c.point);
    h.vec3(c.normal);
  }
}

std::uint64_t rigid_bodies_hash(const io::CaseSpec& spec) {
  PartHasher h;
  h.integer(static_cast<std::int64_t>(spec.rigid_bodies.size()));
  for (const io::RigidBodySpec& b : spec.rigid_bodies) {
    h.text(b.name);
    h.text(b.set);
    h.indices(b.components);
    for (const io::RigidComponentSpec& d : b.drives) {
      h.kind(d.drive);
      h.real(d.value);
      h.text(d.curve);
    }
    if (!b.rotates) // a body that only translates hashes its translation alone
      continue;
    h.integer(static_cast<std::int64_t>(b.blocks.size()));
    for (const std::string& block : b.blocks)
      h.text(block);
    h.flag(b.center.has_value());
    if (b.center)
      h.vec3(*b.center);
    for (const io::RigidComponentSpec& d : b.rotation_drives) {
      h.kind(d.drive);
      h.real(d.value);
      h.text(d.curve);
    }
    if (b.density) // (none: the hash is unchanged)
      h.real(*b.density);
    if (b.euler_angles) // (none: the hash is unchanged)
      for (const io::RigidComponentSpec& a : *b.euler_angles) {
        h.real(a.value);
        h.text(a.curve);
      }
    for (const io::RigidFollowerSpec& f : b.followers) { // (none: the hash is unchanged)
      h.vec3(f.force);
      h.vec3(f.point.value_or(Vec3::Constant(-1e300)));
      h.vec3(f.moment);
      h.text(f.curve);
    }
  }
  hash_connectors(spec, h);
  hash_constraints(spec, h);
  return h.value();
}

/// What each step applies and when it starts; not the end of the last step (the end of the
/// run) nor the steps' time-step settings.
std::uint64_t steps_hash(const io::CaseSpec& spec) {
  PartHasher h;
  h.integer(static_cast<std::int64_t>(spec.steps.size()));
  Real start = 0.0;
  for (const io::StepSpec& s : spec.steps) {
    h.real(start);
    hash_fixed(s.fixed, h);
    hash_prescribed(s.prescribed, h);
    hash_surface_loads(s.pressures, s.tractions, h);
    h.real(s.release_time);
    h.kind(s.analysis);
    h.flag(s.steady);
    start = s.time.end_time;
  }
  return h.value();
}

std::uint64_t analysis_options_hash(const io::CaseSpec& spec) {
  PartHasher h;
  h.kind(spec.analysis.type);
  h.kind(spec.analysis.initial_state);
  h.kind(spec.analysis.flux_mass);
  h.text(spec.analysis.fixed_charge_curve);
  const io::ElectrochemistrySpec& e = spec.electrochemistry;
  for (const Real v : {e.R, e.T, e.faraday, e.bath_concentration, e.bath_activity, e.bath_osmotic})
    h.real(v);
  // the explicit steps' model: the multiplier's constraint and penalty, the damping, the reading
  const io::ExplicitSpec& x = spec.explicit_dynamics;
  h.kind(x.reading);
  h.kind(x.constraint);
  h.flag(x.multiplier);
  h.real(x.penalty);
  h.real(x.damping);
  return h.value();
}

} // namespace

std::string_view case_part_name(CasePart part) {
  switch (part) {
  case CasePart::Mesh:
    return "mesh";
  case CasePart::DegreesOfFreedom:
    return "degrees of freedom";
  case CasePart::Materials:
    return "materials";
  case CasePart::BoundaryConditions:
    return "boundary conditions";
  case CasePart::Contact:
    return "contact pairs";
  case CasePart::RigidBodies:
    return "rigid bodies";
  case CasePart::Steps:
    return "analysis steps";
  case CasePart::AnalysisOptions:
    return "analysis options";
  }
  return "?";
}

CaseFingerprint case_fingerprint(const io::CaseSpec& spec, const model::Model& model) {
  CaseFingerprint f{};
  f[static_cast<std::size_t>(CasePart::Mesh)] = mesh_hash(model.mesh);
  f[static_cast<std::size_t>(CasePart::DegreesOfFreedom)] = dofs_hash(model);
  f[static_cast<std::size_t>(CasePart::Materials)] = materials_hash(spec);
  f[static_cast<std::size_t>(CasePart::BoundaryConditions)] = boundary_conditions_hash(spec);
  f[static_cast<std::size_t>(CasePart::Contact)] = contact_hash(spec);
  f[static_cast<std::size_t>(CasePart::RigidBodies)] = rigid_bodies_hash(spec);
  f[static_cast<std::size_t>(CasePart::Steps)] = steps_hash(spec);
  f[static_cast<std::size_t>(CasePart::AnalysisOptions)] = analysis_options_hash(spec);
  return f;
}

} // namespace trifem::analysis
