// SPDX-License-Identifier: MIT
// TOML case writer: meshes, curves, conditions, loads, time, solver and output. The materials
// are written in case_writer_materials.cpp; the TOML text helpers are in case_writer_text.hpp.
#include "trifem/io/case_writer.hpp"

#include "trifem/core/error.hpp"
#include "trifem/io/case_writer_text.hpp"
#include "trifem/mesh/gmsh_writer.hpp"

#include <fstream>

namespace trifem::io {
namespace {

using detail::TomlText;

/// Refuses the members of `spec` that the writer cannot express (or that no TOML case holds).
void check_supported(const CaseSpec& spec) {
  const auto refuse = [](bool unsupported, std::string_view what) {
    TRIFEM_CHECK(!unsupported, "{}: writing this to a TOML case is not supported yet", what);
  };
  refuse(!spec.meshes.empty(), "inline meshes (write them with write_case)");
  refuse(spec.is_explicit() || spec.has_explicit_step(), "dynamic-explicit analyses");
}

std::string_view interpolation_name(dofs::Interpolation i) {
  switch (i) {
  case dofs::Interpolation::Linear:
    return "linear";
  case dofs::Interpolation::Step:
    return "step";
  case dofs::Interpolation::Smooth:
    return "smooth";
  case dofs::Interpolation::Next:
    return "next";
  case dofs::Interpolation::QuadraticBlend:
    return "quadratic-blend";
  }
  return "linear";
}

/// The `extend` value of a curve (as the reader names it).
std::string_view extension_name(dofs::Extension e) {
  switch (e) {
  case dofs::Extension::Constant:
    return "constant";
  case dofs::Extension::Repeat:
    return "repeat";
  case dofs::Extension::RepeatOffset:
    return "repeat-offset";
  }
  return "constant";
}

constexpr std::string_view kAxes[] = {"x", "y", "z"};

void write_meshes(const CaseSpec& spec, TomlText& t) {
  if (spec.mesh_refinement > 0) {
    t.header("[mesh]");
    t.raw("refine", fmt::format("{}", spec.mesh_refinement));
  }
  for (const BoxMeshSpec& b : spec.boxes) {
    t.header("[[mesh.box]]");
    t.string("name", b.box.name);
    t.vector("origin", b.box.origin);
    t.vector("size", b.box.size);
    t.raw("divisions",
          fmt::format("[{}, {}, {}]", b.box.divisions[0], b.box.divisions[1], b.box.divisions[2]));
    t.vector("grading", b.box.grading);
    if (b.box.cell != mesh::CellType::Hex8)
      t.string("cell", std::string(mesh::name(b.box.cell)));
    if (!b.material.empty())
      t.string("material", b.material);
  }
  for (const GmshMeshSpec& g : spec.gmsh) {
    t.header("[[mesh.gmsh]]");
    t.string("file", g.file.generic_string());
    std::vector<std::pair<std::string, std::string>> entries;
    for (const auto& [block, material] : g.materials)
      entries.emplace_back(TomlText::key(block), TomlText::quoted(material));
    t.inline_table("materials", entries);
  }
}

void write_curves(const CaseSpec& spec, TomlText& t) {
  for (const auto& [name, c] : spec.curves) {
    t.header(fmt::format("[curves.{}]", TomlText::key(name)));
    t.string("interpolation", interpolation_name(c.interpolation));
    std::string points = "[";
    for (std::size_t i = 0; i < c.points.size(); ++i)
      points += fmt::format("{}[{}, {}]", i ? ", " : "", TomlText::number(c.points[i].first),
                            TomlText::number(c.points[i].second));
    t.raw("points", points + "]");
    if (c.extension != dofs::Extension::Constant)
      t.string("extend", extension_name(c.extension));
  }
}

std::string components(const std::vector<Component>& c) {
  std::string s = "[";
  for (std::size_t i = 0; i < c.size(); ++i)
    s += fmt::format("{}\"{}\"", i ? ", " : "", kAxes[c[i]]);
  return s + "]";
}

/// [[<prefix>.fixed]]: one table per field, except that all three fluxes together are one
/// table with field = "fluxes" (which, like [[boundary.bonded]] and [[boundary.impermeable]],
/// holds on a biphasic model too: its ion fluxes do not exist, and a table naming them would be
/// an error).
void write_fixed(const FixedSpec& f, std::string_view prefix, TomlText& t) {
  const std::vector<FieldKind> fluxes = {FieldKind::FluidFlux, FieldKind::CationFlux,
                                         FieldKind::AnionFlux};
  const auto table = [&](std::string_view field) {
    t.header(fmt::format("[[{}.fixed]]", prefix));
    t.string("set", f.set);
    if (!field.empty())
      t.string("field", field);
    t.raw("components", components(f.components));
  };
  std::vector<FieldKind> flux_fields;
  for (FieldKind k : f.fields)
    if (k == FieldKind::Displacement)
      table("");
    else
      flux_fields.push_back(k);
  if (flux_fields == fluxes)
    return table("fluxes");
  for (FieldKind k : flux_fields)
    table(field_name(k));
}

void write_prescribed(const PrescribedSpec& p, std::string_view prefix, TomlText& t) {
  t.header(fmt::format("[[{}.prescribed]]", prefix));
  t.string("set", p.set);
  if (p.field != FieldKind::Displacement)
    t.string("field", field_name(p.field));
  t.string("component", kAxes[p.component]);
  t.number("value", p.value);
  t.optional_string("curve", p.curve);
  if (p.relative)
    t.raw("relative", "true");
}

/// Fixed and prescribed conditions, pressures and tractions under `boundary` and `loads`.
void write_conditions(const std::vector<FixedSpec>& fixed,
                      const std::vector<PrescribedSpec>& prescribed,
                      const std::vector<PressureSpec>& pressures,
                      const std::vector<TractionSpec>& tractions, std::string_view boundary,
                      std::string_view loads, TomlText& t) {
  for (const FixedSpec& f : fixed)
    write_fixed(f, boundary, t);
  for (const PrescribedSpec& p : prescribed)
    write_prescribed(p, boundary, t);
  for (const PressureSpec& p : pressures) {
    t.header(fmt::format("[[{}.pressure]]", loads));
    t.string("surface", p.surface);
    t.number("value", p.value);
    t.optional_string("curve", p.curve);
    if (!p.follower)
      t.raw("follower", "false");
  }
  for (const TractionSpec& p : tractions) {
    t.header(fmt::format("[[{}.traction]]", loads));
    t.string("surface", p.surface);
    t.vector(p.total_force ? "force" : "value", p.value);
    t.optional_string("curve", p.curve);
    if (p.per_current_area)
      t.string("area", "current");
  }
}

void write_boundary(const CaseSpec& spec, TomlText& t) {
  write_conditions(spec.fixed, spec.prescribed, {}, {}, "boundary", "loads", t);
  for (const ImpermeableSurfaceSpec& s : spec.impermeable_surfaces) {
    t.header("[[boundary.impermeable]]");
    t.string("surface", s.surface);
  }
  for (const BathSpec& b : spec.baths) {
    t.header("[[boundary.bath]]");
    t.string("surface", b.surface);
    if (b.concentration > 0.0)
      t.number("concentration", b.concentration);
    if (b.pressure != 0.0)
      t.number("pressure", b.pressure);
    t.optional_string("curve", b.curve);
  }
  write_conditions({}, {}, spec.pressures, spec.tractions, "boundary", "loads", t);
  for (const BodyForceSpec& b : spec.body_forces) {
    t.header("[[loads.body_force]]");
    t.vector("force", b.force);
    if (!b.blocks.empty()) {
      std::string blocks;
      for (const std::string& block : b.blocks)
        blocks += (blocks.empty() ? "" : ", ") + TomlText::quoted(block);
      t.raw("blocks", "[" + blocks + "]");
    }
    t.optional_string("curve", b.curve);
  }
  for (const NodalForceSpec& f : spec.nodal_forces) {
    t.header("[[loads.nodal_force]]");
    t.string("set", f.set);
    t.vector("value", f.value);
    t.optional_string("curve", f.curve);
  }
  for (const InitialVelocitySpec& v : spec.initial_velocities) {
    t.header("[[initial_velocity]]");
    t.string("set", v.set);
    t.vector("value", v.value);
  }
}

void write_contacts(const CaseSpec& spec, TomlText& t) {
  for (const ContactSpec& c : spec.contacts) {
    t.header("[[contact]]");
    t.string("master", c.master);
    t.string("slave", c.slave);
    t.string("integration", c.both_surfaces ? "both-surfaces" : "slave-nodes");
    if (c.scale > 0.0)
      t.number("scale", c.scale);
    if (c.search_distance > 0.0)
      t.number("search_distance", c.search_distance);
    if (c.penetration_tolerance >= 0.0)
      t.number("penetration_tolerance", c.penetration_tolerance);
    if (c.friction > 0.0)
      t.number("friction", c.friction);
  }
}

/// The table of a driven component of a rigid body (`motion` and `load`: its keys).
void write_rigid_component(TomlText& t, std::string_view key, const RigidComponentSpec& d,
                           const char* motion, const char* load) {
  if (d.drive == RigidDrive::Free)
    return;
  std::vector<std::pair<std::string, std::string>> entries = {
      {d.drive == RigidDrive::Force ? load : motion, TomlText::number(d.value)}};
  if (!d.curve.empty())
    entries.emplace_back("curve", TomlText::quoted(d.curve));
  t.inline_table(key, entries);
}

/// [[rigid_body]]: the tied components, each driven one with its table (free ones have none),
/// and the rotation of a rotating body.
void write_rigid_bodies(const CaseSpec& spec, TomlText& t) {
  for (const RigidBodySpec& b : spec.rigid_bodies) {
    t.header("[[rigid_body]]");
    t.string("name", b.name);
    if (!b.set.empty())
      t.string("set", b.set);
    t.raw("components", components(b.components));
    if (!b.blocks.empty()) {
      std::string list;
      for (const std::string& block : b.blocks)
        list += (list.empty() ? "" : ", ") + TomlText::quoted(block);
      t.raw("blocks", "[" + list + "]");
    }
    for (Component k : b.components)
      write_rigid_component(t, kAxes[k], b.drives[k], "displacement", "force");
    if (b.velocity != Vec3::Zero())
      t.vector("velocity", b.velocity);
    if (!b.rotates)
      continue;
    t.string("rotation", "free");
    if (b.center)
      t.vector("center", *b.center);
    if (b.density)
      t.number("density", *b.density);
    if (b.shell_thickness)
      t.number("shell_thickness", *b.shell_thickness);
    if (b.angular_velocity != Vec3::Zero())
      t.vector("angular_velocity", b.angular_velocity);
    constexpr std::string_view kRotationKeys[] = {"rx", "ry", "rz"};
    for (int k = 0; k < 3; ++k)
      write_rigid_component(t, kRotationKeys[k], b.rotation_drives[k], "rotation", "moment");
    if (b.euler_angles) {
      std::vector<std::pair<std::string, std::string>> angles;
      for (int k = 0; k < 3; ++k) {
        const RigidComponentSpec& a = (*b.euler_angles)[k];
        angles.emplace_back(std::string(kAxes[k]),
                            "{ rotation = " + TomlText::number(a.value) +
                                (a.curve.empty() ? "" : ", curve = " + TomlText::quoted(a.curve)) +
                                " }");
      }
      t.inline_table("euler_angles", angles);
    }
    for (const RigidFollowerSpec& f : b.followers) {
      t.header("[[rigid_body.follower]]");
      t.vector("force", f.force);
      if (f.point)
        t.vector("point", *f.point);
      t.vector("moment", f.moment);
      t.optional_string("curve", f.curve);
    }
  }
}

/// [[connector]]: the keys of its kind (case_reader_connectors.cpp).
void write_connectors(const CaseSpec& spec, TomlText& t) {
  static const char* const kTypes[] = {"spherical", "revolute",   "prismatic", "cylindrical",
                                       "planar",    "lock",       "spring",    "cable",
                                       "damper",    "contractile"};
  for (const ConnectorSpec& c : spec.connectors) {
    t.header("[[connector]]");
    t.string("type", kTypes[static_cast<int>(c.kind)]);
    t.string("name", c.name);
    t.string("body_a", c.body_a);
    t.string("body_b", c.body_b);
    if (c.kind <= ConnectorKind::Lock) {
      t.vector("origin", c.origin);
      t.vector("axis", c.axis);
      if (c.transverse)
        t.vector("transverse", *c.transverse);
      write_rigid_component(t, "rotation", c.rotation, "rotation", "moment");
      write_rigid_component(t, "translation", c.translation, "displacement", "force");
      if (c.torsion_stiffness > 0.0)
        t.number("torsion_stiffness", c.torsion_stiffness);
      continue;
    }
    t.vector("point_a", c.point_a);
    t.vector("point_b", c.point_b);
    if (c.kind == ConnectorKind::Spring || c.kind == ConnectorKind::Cable) {
      t.number("stiffness", c.stiffness);
      if (c.free_length)
        t.number("free_length", *c.free_length);
    }
    if (c.kind == ConnectorKind::Damper)
      t.number("damping", c.stiffness);
    if (c.kind == ConnectorKind::Contractile) {
      t.number("force", c.force);
      t.optional_string("curve", c.curve);
    }
  }
}

/// The `type` of a [[constraint]] of kind `kind` (case_reader_constraints.cpp).
std::string_view constraint_type(ConstraintKind kind) {
  switch (kind) {
  case ConstraintKind::Linear:
    return "linear";
  case ConstraintKind::SymmetryPlane:
    return "symmetry-plane";
  case ConstraintKind::NormalDisplacement:
    return "normal-displacement";
  case ConstraintKind::RigidWall:
    return "rigid-wall";
  }
  return "linear";
}

/// `terms` of a linear constraint: one inline table per line.
std::string constraint_terms(const ConstraintSpec& c) {
  std::string terms = "[\n";
  for (const LinearConstraintEntry& e : c.entries)
    terms += fmt::format("  {{ node = {}, component = \"{}\", coefficient = {} }},\n", e.node,
                         kAxes[e.component], TomlText::number(e.coefficient));
  return terms + "]";
}

/// [[constraint]]: the keys of its kind (case_reader_constraints.cpp).
void write_constraints(const CaseSpec& spec, TomlText& t) {
  for (const ConstraintSpec& c : spec.constraints) {
    t.header("[[constraint]]");
    t.string("type", constraint_type(c.kind));
    t.string("name", c.name);
    if (c.kind == ConstraintKind::Linear) {
      t.raw("terms", constraint_terms(c));
      t.number("value", c.value);
      t.optional_string("curve", c.curve);
      continue;
    }
    t.string("surface", c.surface);
    if (c.kind == ConstraintKind::RigidWall) {
      t.vector("point", c.point);
      t.vector("normal", c.normal);
      t.number("offset", c.value);
      t.optional_string("curve", c.curve);
    }
  }
}

/// [analysis]: the type of an implicit dynamic analysis and the options of a mixture model, when
/// they differ from the defaults (dynamic-explicit analyses: check_supported refuses them).
void write_analysis(const CaseSpec& spec, TomlText& t) {
  const AnalysisSpec& a = spec.analysis;
  const bool dynamic = a.type == AnalysisType::Dynamic;
  const bool mixture_options = a.initial_state != InitialStateKind::Donnan ||
                               !a.fixed_charge_curve.empty() || a.flux_mass != FluxMass::Consistent;
  if (!dynamic && !mixture_options)
    return;
  t.header("[analysis]");
  if (dynamic)
    t.string("type", "dynamic");
  if (!mixture_options)
    return;
  t.string("initial_state",
           a.initial_state == InitialStateKind::Donnan ? "donnan" : "donnan-prestressed");
  if (a.flux_mass == FluxMass::Lumped)
    t.string("flux_mass", "lumped");
  t.optional_string("fixed_charge_curve", a.fixed_charge_curve);
}

/// [dynamic] of a case with implicit dynamic steps.
void write_dynamic(const CaseSpec& spec, TomlText& t) {
  if (!spec.has_dynamic_step())
    return;
  t.header("[dynamic]");
  t.number("rho_inf", spec.dynamics.rho_inf);
  t.string("mass", spec.dynamics.mass == MassMatrixSpec::Lumped ? "lumped" : "consistent");
}

void write_electrochemistry(const CaseSpec& spec, TomlText& t) {
  const ElectrochemistrySpec d;
  const ElectrochemistrySpec& e = spec.electrochemistry;
  if (e.R == d.R && e.T == d.T && e.faraday == d.faraday &&
      e.bath_concentration == d.bath_concentration && e.bath_activity == d.bath_activity &&
      e.bath_osmotic == d.bath_osmotic)
    return;
  t.header("[electrochemistry]");
  t.number("R", e.R);
  t.number("T", e.T);
  t.number("faraday", e.faraday);
  t.number("bath_concentration", e.bath_concentration);
  t.number("bath_activity", e.bath_activity);
  t.number("bath_osmotic", e.bath_osmotic);
}

/// The time keys of [time] or of a [[step]] (the current table).
void write_time_keys(const TimeSpec& s, TomlText& t) {
  t.number("end_time", s.end_time);
  t.number("dt", s.dt);
  if (s.dt_min > 0.0)
    t.number("dt_min", s.dt_min);
  if (s.dt_max > 0.0)
    t.number("dt_max", s.dt_max);
  t.raw("target_iterations", fmt::format("{}", s.target_iterations));
  t.number("growth", s.growth);
  t.number("cutback", s.cutback);
}

void write_time(const CaseSpec& spec, TomlText& t) {
  if (spec.steps.empty()) {
    t.header("[time]");
    return write_time_keys(spec.time, t);
  }
  for (const StepSpec& s : spec.steps) {
    t.header("[[step]]");
    t.string("name", s.name);
    if (s.analysis != spec.analysis.type)
      t.string("analysis", s.is_dynamic() ? "dynamic" : "quasi-static");
    write_time_keys(s.time, t);
    if (s.release_time > 0.0)
      t.number("release_time", s.release_time);
    if (s.steady)
      t.raw("steady", "true");
    write_conditions(s.fixed, s.prescribed, s.pressures, s.tractions, "step.boundary", "step.loads",
                     t);
  }
}

void write_solver(const SolverSpec& s, TomlText& t) {
  t.header("[solver]");
  t.raw("max_iterations", fmt::format("{}", s.max_iterations));
  t.number("residual_tolerance", s.residual_tolerance);
  t.number("increment_tolerance", s.increment_tolerance);
  t.raw("line_search", s.line_search ? "true" : "false");
  const LinearSolverChoice& c = s.linear_solver;
  t.string("linear_solver", to_string(c.kind));
  t.optional_string("petsc_options", c.petsc_options);
  if (c.reuse_factorization)
    t.raw("reuse_factorization", "true");
  if (c.preconditioner != KrylovPreconditioner::lu)
    t.string("preconditioner", to_string(c.preconditioner));
  if (c.schur != SchurApproximation::selfp)
    t.string("schur_approximation", to_string(c.schur));
  if (c.precision != FactorPrecision::single)
    t.string("factorization_precision", to_string(c.precision));
}

void write_output(const OutputSpec& o, TomlText& t) {
  t.header("[output]");
  if (o.interval_given)
    t.number("interval", o.interval);
  if (!o.times.empty()) {
    std::string times = "[";
    for (std::size_t i = 0; i < o.times.size(); ++i)
      times += fmt::format("{}{}", i ? ", " : "", TomlText::number(o.times[i]));
    t.raw("times", times + "]");
  }
  if (o.history_interval > 0.0)
    t.number("history_interval", o.history_interval);
  t.raw("vtu", o.vtu ? "true" : "false");
  if (o.restart)
    t.raw("restart", "true");
  for (const ReactionSpec& r : o.reactions) {
    t.header("[[output.reaction]]");
    t.string("set", r.set);
  }
  for (const ProbeSpec& p : o.probes) {
    t.header("[[output.probe]]");
    t.string("name", p.name);
    t.string("quantity", p.quantity);
    t.vector("point", p.point);
  }
  for (const AverageSpec& a : o.averages) {
    t.header("[[output.average]]");
    t.string("name", a.name);
    t.string("quantity", a.quantity);
    t.string("block", a.block);
  }
}

void write_preamble(const CaseSpec& spec, TomlText& t) {
  t.comment("trifem case file (docs/input.md)");
  if (!spec.file.empty())
    t.comment(fmt::format("converted from {} by trifem convert", spec.file.filename().string()));
  for (const std::string& w : spec.warnings)
    t.comment(fmt::format("note: {}", w));
  if (!spec.title.empty())
    t.string("title", spec.title);
}

} // namespace

std::string case_toml(const CaseSpec& spec) {
  check_supported(spec);
  TomlText t;
  write_preamble(spec, t);
  write_meshes(spec, t);
  detail::write_materials(spec, t);
  write_curves(spec, t);
  write_boundary(spec, t);
  write_contacts(spec, t);
  write_rigid_bodies(spec, t);
  write_connectors(spec, t);
  write_constraints(spec, t);
  write_analysis(spec, t);
  write_dynamic(spec, t);
  write_electrochemistry(spec, t);
  write_time(spec, t);
  write_solver(spec.solver, t);
  write_output(spec.output, t);
  return t.text();
}

std::vector<std::filesystem::path> write_case(const CaseSpec& spec,
                                              const std::filesystem::path& file) {
  for (const auto& [name, m] : spec.materials) // the Gmsh writer leaves out per-cell data
    for (const InlineMeshSpec& inline_mesh : spec.meshes)
      TRIFEM_CHECK(!m.axes || m.axes->kind != material::AxesKind::Mesh ||
                       !inline_mesh.mesh.cell_data().contains(m.axes->view),
                   "materials.{}: axes from the cell data '{}' of the file's mesh (e.g. FEBio's "
                   "local fibres): writing this to a TOML case is not supported yet",
                   name, m.axes->view);
  CaseSpec out = spec;
  out.meshes.clear();
  for (GmshMeshSpec& g : out.gmsh)
    if (g.file.is_relative())
      g.file = std::filesystem::absolute(spec.file.parent_path() / g.file);
  std::vector<std::filesystem::path> written = {file};
  for (std::size_t i = 0; i < spec.meshes.size(); ++i) {
    const std::string suffix = spec.meshes.size() > 1 ? fmt::format("_{}", i + 1) : "";
    const std::filesystem::path name = file.stem().string() + suffix + ".msh";
    written.push_back(file.parent_path() / name);
    out.gmsh.push_back({name, spec.meshes[i].materials});
  }
  const std::string text = case_toml(out); // refuses what it cannot write, before any file
  for (std::size_t i = 0; i < spec.meshes.size(); ++i)
    mesh::write_gmsh(spec.meshes[i].mesh, written[i + 1]);
  std::ofstream stream(file, std::ios::binary);
  TRIFEM_CHECK(stream.is_open(), "{}: cannot write the case file", file.string());
  stream << text;
  stream.close();
  TRIFEM_CHECK(stream.good(), "{}: error while writing the case file", file.string());
  return written;
}

} // namespace trifem::io
