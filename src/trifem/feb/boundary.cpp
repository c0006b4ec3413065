// SPDX-License-Identifier: MIT
// Boundary and Loads sections: fixed and prescribed displacements, zero fluid pressure
// (drained nodes), pressure and traction loads, body forces.
#include "trifem/feb/reader.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <optional>
#include <sstream>

namespace trifem::feb::detail {
namespace {

io::Component component(const Reader& r, pugi::xml_node node) {
  const std::string dof = r.doc.text(node);
  if (dof == "x")
    return 0;
  if (dof == "y")
    return 1;
  if (dof == "z")
    return 2;
  r.doc.fail(node, fmt::format("dof '{}' is not supported (expected x, y or z)", dof));
}

bool flag(const Reader& r, pugi::xml_node node) {
  const long v = r.doc.integer(node);
  if (v != 0 && v != 1)
    r.doc.fail(node, fmt::format("expected 0 or 1, got {}", v));
  return v == 1;
}

std::string key_of(const Reader& r, pugi::xml_node bc) {
  return fmt::format("{} (line {})", r.doc.path(bc), r.doc.line(bc));
}

/// 4.0 "zero displacement": x_dof, y_dof, z_dof flags.
void zero_displacement(const Reader& r, pugi::xml_node bc, std::vector<io::FixedSpec>& fixed) {
  io::FixedSpec f;
  f.key = key_of(r, bc);
  f.set = r.node_set(bc);
  for (pugi::xml_node c : elements(bc)) {
    const std::string_view name = c.name();
    const int k = name == "x_dof" ? 0 : name == "y_dof" ? 1 : name == "z_dof" ? 2 : -1;
    if (k < 0)
      r.doc.fail(c, fmt::format("unknown parameter '{}' (expected x_dof, y_dof, z_dof)", name));
    if (flag(r, c))
      f.components.push_back(k);
  }
  if (!f.components.empty())
    fixed.push_back(std::move(f));
}

/// 4.0 "prescribed displacement" (dof, value with lc, relative) and 3.0 "prescribe" (dof,
/// scale with lc, relative).
void prescribed_displacement(const Reader& r, pugi::xml_node bc,
                             std::vector<io::PrescribedSpec>& prescribed) {
  io::PrescribedSpec p;
  p.set = r.node_set(bc);
  p.component = component(r, r.doc.child(bc, "dof"));
  const char* value_key = r.version == Version::V4 ? "value" : "scale";
  const pugi::xml_node value = r.doc.child(bc, value_key);
  p.value = r.doc.number(value);
  p.curve = r.curve_of(value);
  for (pugi::xml_node c : elements(bc)) {
    const std::string_view name = c.name();
    if (name == "relative")
      p.relative = flag(r, c);
    else if (name != "dof" && name != value_key)
      r.doc.fail(
          c, fmt::format("unknown parameter '{}' (expected dof, {}, relative)", name, value_key));
  }
  prescribed.push_back(std::move(p));
}

/// A prescribed effective fluid pressure (charge 0) or concentration: a face drained to a bath,
/// mapped once every condition is known (map_baths).
void effective_condition(Reader& r, pugi::xml_node bc, bool step, int charge, Real value,
                         const std::string& curve) {
  if (step)
    r.doc.fail(bc, "a fluid pressure or concentration condition inside a <step> is not supported "
                   "(give it in the top-level <Boundary>: trifem's drained faces and their bath "
                   "hold for the whole run)");
  r.effective.push_back({bc, r.node_set(bc), charge, value, curve});
}

void drain(Reader& r, pugi::xml_node bc, bool step) {
  effective_condition(r, bc, step, 0, 0.0, "");
}

/// 4.0 "prescribed fluid pressure" and "prescribed concentration": value (with lc), relative
/// (0 only), and dof c<id> for a concentration.
void prescribed_effective(Reader& r, pugi::xml_node bc, bool step, bool concentration) {
  int charge = 0;
  if (concentration) {
    const pugi::xml_node dof = r.doc.child(bc, "dof");
    const std::string name = r.doc.text(dof);
    if (!name.starts_with("c"))
      r.doc.fail(dof, fmt::format("dof '{}': expected c<solute id>", name));
    charge = r.chem.charge(r.doc, dof, name.substr(1));
  }
  const pugi::xml_node value = r.doc.child(bc, "value");
  for (pugi::xml_node c : elements(bc)) {
    const std::string_view name = c.name();
    if (name == "relative" && flag(r, c))
      r.doc.fail(c, "a relative fluid pressure or concentration is not supported");
    if (name != "relative" && name != "value" && !(concentration && name == "dof"))
      r.doc.fail(c, fmt::format("unknown parameter '{}' (expected {}value, relative)", name,
                                concentration ? "dof, " : ""));
  }
  effective_condition(r, bc, step, charge, r.doc.number(value), r.curve_of(value));
}

/// 3.0 "fix": <dofs>x,y,z,p</dofs>.
void fix(Reader& r, pugi::xml_node bc, std::vector<io::FixedSpec>& fixed, bool step) {
  io::FixedSpec f;
  f.key = key_of(r, bc);
  f.set = r.node_set(bc);
  const pugi::xml_node dofs = r.doc.child(bc, "dofs");
  std::string list = r.doc.text(dofs);
  for (char& c : list)
    if (c == ',')
      c = ' ';
  std::istringstream in(list);
  for (std::string dof; in >> dof;) {
    if (dof == "x" || dof == "y" || dof == "z")
      f.components.push_back(dof[0] - 'x');
    else if (dof == "p")
      drain(r, bc, step);
    else
      r.doc.fail(dofs, fmt::format("dof '{}' is not supported (expected x, y, z or p)", dof));
  }
  if (!f.components.empty())
    fixed.push_back(std::move(f));
}

} // namespace

void read_boundary(Reader& r, pugi::xml_node section, std::vector<io::FixedSpec>& fixed,
                   std::vector<io::PrescribedSpec>& prescribed, bool step) {
  for (pugi::xml_node bc : elements(section)) {
    if (std::string_view(bc.name()) != "bc")
      r.doc.fail(bc, fmt::format("<{}> is not supported in <Boundary> (expected <bc>)", bc.name()));
    const std::string type = r.doc.attribute(bc, "type");
    if (type == "zero displacement" && r.version == Version::V4)
      zero_displacement(r, bc, fixed);
    else if (type == "prescribed displacement" && r.version == Version::V4)
      prescribed_displacement(r, bc, prescribed);
    else if (type == "zero fluid pressure" && r.version == Version::V4)
      drain(r, bc, step);
    else if (type == "prescribed fluid pressure" && r.version == Version::V4)
      prescribed_effective(r, bc, step, false);
    else if (type == "prescribed concentration" && r.version == Version::V4)
      prescribed_effective(r, bc, step, true);
    else if (type == "rigid" && r.version == Version::V4)
      attach_rigid(r, bc, step);
    else if (type == "fix" && r.version == Version::V3)
      fix(r, bc, fixed, step);
    else if (type == "prescribe" && r.version == Version::V3)
      prescribed_displacement(r, bc, prescribed);
    else if (type == "linear constraint")
      read_linear_constraint_bc(r, bc, step);
    else
      r.doc.fail(bc, "type",
                 fmt::format("boundary condition type '{}' is not supported (supported: {})", type,
                             r.version == Version::V4
                                 ? "zero displacement, prescribed displacement, zero fluid "
                                   "pressure, prescribed fluid pressure, prescribed "
                                   "concentration, linear constraint"
                                 : "fix, prescribe, linear constraint"));
  }
}

namespace {

/// <surface_load type="pressure">: a follower pressure on the deformed surface, or with
/// <linear>1</linear> a dead pressure along the reference normal per reference area.
io::PressureSpec pressure_load(const Reader& r, pugi::xml_node load) {
  io::PressureSpec p;
  p.surface = r.surface(load);
  const pugi::xml_node value = r.doc.child(load, "pressure");
  p.value = r.doc.number(value);
  p.curve = r.curve_of(value);
  for (pugi::xml_node c : elements(load)) {
    const std::string_view name = c.name();
    if (name == "linear") // 1: along the reference normal per reference area (a dead load)
      p.follower = !flag(r, c);
    if (name == "shell_bottom" && flag(r, c))
      r.doc.fail(c, "shell_bottom is not supported (trifem has no shells)");
    if (name != "pressure" && name != "linear" && name != "symmetric_stiffness" &&
        name != "shell_bottom")
      r.doc.fail(c, fmt::format("unknown parameter '{}' of a pressure load", name));
  }
  return p;
}

/// <surface_load type="traction">: scale x traction in a fixed direction, integrated as FEBio
/// does over the current surface (per current area) unless <linear> is 1 (over the reference
/// surface: a dead load); type="force": scale x force spread over the surface's reference area
/// (FEBio's uniform surface force, a dead traction force/A0). The load curve is that of <scale>.
io::TractionSpec fixed_direction_load(const Reader& r, pugi::xml_node load, bool force) {
  const char* vector = force ? "force" : "traction";
  io::TractionSpec t;
  t.surface = r.surface(load);
  t.per_current_area = !force; // FEBio's traction: linear = 0 by default
  t.total_force = force;
  Real scale = 1.0;
  for (pugi::xml_node c : elements(load)) {
    const std::string_view name = c.name();
    if (name == "scale") {
      scale = r.doc.number(c);
      t.curve = r.curve_of(c);
    } else if (name == vector) {
      if (c.attribute("lc"))
        r.doc.fail(c, fmt::format("a load curve on the {} vector is not supported (put it on "
                                  "<scale>)",
                                  vector));
      t.value = r.doc.vector(c);
    } else if (name == "shell_bottom") {
      if (flag(r, c))
        r.doc.fail(c, "shell_bottom is not supported (trifem has no shells)");
    } else if (name == "linear" && !force) {
      t.per_current_area = !flag(r, c);
    } else {
      r.doc.fail(c, fmt::format("unknown parameter '{}' of a {} load (expected one of: scale, {}, "
                                "{}shell_bottom)",
                                name, vector, vector, force ? "" : "linear, "));
    }
  }
  r.doc.child(load, vector); // required: InputError if missing
  t.value *= scale;
  return t;
}

/// Checks the flags of a load that trifem supports at 0 only (linear, shell_bottom), and that
/// every other child is one of `known`.
void check_load_children(const Reader& r, pugi::xml_node load,
                         std::initializer_list<std::string_view> known) {
  for (pugi::xml_node c : elements(load)) {
    const std::string_view name = c.name();
    if (name == "linear" && flag(r, c))
      r.doc.fail(c, "a linear (non-follower) load is not supported: trifem's surface loads of "
                    "this kind follow the deformed surface");
    if (name == "shell_bottom" && flag(r, c))
      r.doc.fail(c, "shell_bottom is not supported (trifem has no shells)");
    if (name != "linear" && name != "shell_bottom" &&
        std::find(known.begin(), known.end(), name) == known.end())
      r.doc.fail(c, fmt::format("unknown parameter '{}' of a {} load", name,
                                load.attribute("type").value()));
  }
}

/// <surface_load type="normal_traction">: FEBio's traction normal to a mixture's surface
/// (positive pulls). The mixture traction (effective = 0) is a follower pressure -traction; the
/// traction on the solid alone (effective = 1) is accepted only when it is zero throughout.
std::optional<io::PressureSpec> normal_traction(Reader& r, pugi::xml_node load) {
  check_load_children(r, load, {"traction", "effective"});
  const pugi::xml_node value = r.doc.child(load, "traction");
  io::PressureSpec p;
  p.surface = r.surface(load);
  p.value = -r.doc.number(value);
  p.curve = r.curve_of(value);
  const pugi::xml_node effective = load.child("effective");
  if (effective && flag(r, effective)) {
    if (!r.always_zero(p.value, p.curve))
      r.doc.fail(effective, "an effective normal traction (on the solid alone) is not supported: "
                            "trifem's surface loads act on the mixture (effective = 0)");
    r.warn(load, "an effective normal traction that is zero at every time is ignored");
    return std::nullopt;
  }
  return p;
}

/// <surface_load type="fluidflux">: the normal flux w.n of the water relative to the solid
/// (mixture = 0) on a face normal to an axis, prescribed as the fluid flux component along that
/// axis at the face's nodes; the face is then not one of FEBio's impermeable faces.
io::PrescribedSpec fluid_flux(Reader& r, pugi::xml_node load, bool step) {
  check_load_children(r, load, {"flux", "mixture"});
  if (!r.biphasic_module)
    r.doc.fail(load, "a fluid flux needs the biphasic or multiphasic module");
  if (step)
    r.doc.fail(load, "a fluid flux inside a <step> is not supported (give it in the top-level "
                     "<Loads>: the face it crosses is open for the whole run)");
  if (const pugi::xml_node mixture = load.child("mixture"); mixture && flag(r, mixture))
    r.doc.fail(mixture, "mixture = 1 (the flux of the mixture, w.n + v.n) is not supported: "
                        "trifem prescribes the water's flux relative to the solid (mixture = 0)");
  const pugi::xml_node value = r.doc.child(load, "flux");
  io::PrescribedSpec p;
  p.set = r.surface(load);
  p.field = io::FieldKind::FluidFlux;
  p.curve = r.curve_of(value);
  Vec3 normal = Vec3::Zero();
  for (const mesh::Facet& f : r.mesh.mesh.surface(p.set).facets) {
    const Vec3 n = (r.mesh.mesh.node(f.nodes[2]) - r.mesh.mesh.node(f.nodes[0]))
                       .cross(r.mesh.mesh.node(f.nodes[3]) - r.mesh.mesh.node(f.nodes[1]))
                       .normalized();
    if (normal.isZero())
      normal = n;
    if ((n - normal).norm() > 1e-9)
      r.doc.fail(load, "surface",
                 "the surface is not plane: trifem prescribes a fluid flux on a face normal to "
                 "a coordinate axis");
  }
  int axis = 0;
  normal.cwiseAbs().maxCoeff(&axis);
  if (std::abs(std::abs(normal[axis]) - 1.0) > 1e-9)
    r.doc.fail(load, "surface",
               fmt::format("the surface's normal ({:.3g}, {:.3g}, {:.3g}) is not along a "
                           "coordinate axis: trifem prescribes the fluid flux component along it",
                           normal.x(), normal.y(), normal.z()));
  p.component = axis;
  p.value = r.doc.number(value) * (normal[axis] > 0.0 ? 1.0 : -1.0);
  r.flux_surfaces.push_back(p.set);
  return p;
}

/// <nodal_load type="nodal_force" node_set="...">: the force <value> (x,y,z with an lc) on
/// every node of the set, as trifem's [[loads.nodal_force]]. Top level only.
void nodal_force(Reader& r, pugi::xml_node load, bool step) {
  const std::string type = load.attribute("type").value();
  if (type != "nodal_force")
    r.doc.fail(
        load, "type",
        fmt::format("nodal_load of type '{}' is not supported (supported: nodal_force)", type));
  if (step)
    r.doc.fail(load, "a nodal load inside a <step> is not supported (give it in the top-level "
                     "<Loads>: trifem's nodal forces act in every step; a load controller changes "
                     "it in time)");
  io::NodalForceSpec f;
  f.key = key_of(r, load);
  f.set = r.node_set(load);
  for (pugi::xml_node c : elements(load)) {
    const std::string_view name = c.name();
    if (name == "value") {
      if (c.attribute("type"))
        r.doc.fail(c, "type",
                   "a nodal force that varies in space (math or map) is not supported: give a "
                   "constant value (with a load controller lc for its time history)");
      f.value = r.doc.vector(c);
      f.curve = r.curve_of(c);
    } else if (name == "relative" || name == "shell_bottom") {
      if (flag(r, c))
        r.doc.fail(c, name == "relative"
                          ? "a relative nodal force (added to the force at the step's start) "
                            "is not supported"
                          : "shell_bottom is not supported (trifem has no shells)");
    } else {
      r.doc.fail(c, fmt::format("unknown parameter '{}' of a nodal_force load (expected one of: "
                                "value, relative, shell_bottom)",
                                name));
    }
  }
  r.doc.child(load, "value"); // required: InputError if missing
  r.spec.nodal_forces.push_back(f);
}

/// A component of a body load given by a math expression or a map (type attribute).
void reject_expression(const Reader& r, pugi::xml_node value) {
  if (value.attribute("type"))
    r.doc.fail(value, "type",
               "a body force that varies in space (math or map) is not supported: give a "
               "constant value (with a load controller lc for its time history)");
}

/// <body_load type="const"> (children x, y, z, each a value with its own lc) or type="body
/// force" (<force> x,y,z with an lc): FEBio's body force b per unit mass enters its residual as
/// the external force −ρ b (FEElasticSolidDomain::BodyForce), so b = (0, 0, 9.81) is gravity
/// along −z: trifem's force is −b. One [[loads.body_force]] per curve of a non-zero component,
/// on the cells of the attribute elem_set (every cell without one). Top level only.
void body_load(Reader& r, pugi::xml_node load, bool step) {
  const std::string type = load.attribute("type").value();
  if (type != "const" && type != "body force")
    r.doc.fail(load, "type",
               fmt::format("body_load of type '{}' is not supported (supported: const, body force)",
                           type));
  if (load.attribute("lc"))
    r.doc.fail(load, "lc",
               "a load controller on <body_load> itself is not supported: give it on its "
               "components (x, y, z or force)");
  if (step)
    r.doc.fail(load, "a body load inside a <step> is not supported (give it in the top-level "
                     "<Loads>: trifem's body forces act in every step; a load controller changes "
                     "it in time)");
  std::vector<std::string> blocks;
  if (const pugi::xml_attribute set = load.attribute("elem_set")) {
    const std::string name = set.value();
    if (!r.mesh.mesh.has_cell_block(name)) {
      std::string defined;
      for (const auto& entry : r.mesh.mesh.cell_blocks())
        defined += (defined.empty() ? "" : ", ") + entry.first;
      r.doc.fail(load, "elem_set",
                 fmt::format("element set '{}' is not defined (defined: {})", name,
                             defined.empty() ? "none" : defined));
    }
    blocks.push_back(name);
  }
  std::vector<std::pair<std::string, Vec3>> by_curve; // in the order of the components
  const auto add = [&](const std::string& curve, int k, Real b) {
    if (r.always_zero(b, curve))
      return;
    auto it = std::find_if(by_curve.begin(), by_curve.end(),
                           [&](const auto& entry) { return entry.first == curve; });
    if (it == by_curve.end())
      it = by_curve.insert(by_curve.end(), {curve, Vec3::Zero()});
    it->second[k] = -b;
  };
  if (type == "const") {
    for (pugi::xml_node c : elements(load)) {
      const std::string_view name = c.name();
      const int k = name == "x" ? 0 : name == "y" ? 1 : name == "z" ? 2 : -1;
      if (k < 0)
        r.doc.fail(c, fmt::format("unknown parameter '{}' of a const body load (expected one of: "
                                  "x, y, z)",
                                  name));
      reject_expression(r, c);
      add(r.curve_of(c), k, r.doc.number(c));
    }
  } else {
    for (pugi::xml_node c : elements(load))
      if (std::string_view(c.name()) != "force")
        r.doc.fail(c, fmt::format("unknown parameter '{}' of a body force load (expected: force)",
                                  c.name()));
    const pugi::xml_node force = r.doc.child(load, "force");
    reject_expression(r, force);
    const Vec3 b = r.doc.vector(force);
    const std::string curve = r.curve_of(force);
    for (int k = 0; k < 3; ++k)
      add(curve, k, b[k]);
  }
  if (by_curve.empty())
    r.warn(load, "a body load that is zero at every time is ignored");
  for (const auto& [curve, force] : by_curve)
    r.spec.body_forces.push_back({key_of(r, load), force, blocks, curve});
}

} // namespace

void read_loads(Reader& r, pugi::xml_node section, std::vector<io::PressureSpec>& pressures,
                std::vector<io::TractionSpec>& tractions,
                std::vector<io::PrescribedSpec>& prescribed, bool step) {
  for (pugi::xml_node load : elements(section)) {
    const std::string type = load.attribute("type").value();
    const bool surface_load = std::string_view(load.name()) == "surface_load";
    if (surface_load && type == "pressure") {
      pressures.push_back(pressure_load(r, load));
    } else if (surface_load && type == "traction") {
      tractions.push_back(fixed_direction_load(r, load, false));
    } else if (surface_load && type == "force") {
      tractions.push_back(fixed_direction_load(r, load, true));
    } else if (surface_load && type == "normal_traction") {
      if (auto p = normal_traction(r, load))
        pressures.push_back(*p);
    } else if (surface_load && type == "fluidflux") {
      prescribed.push_back(fluid_flux(r, load, step));
    } else if (std::string_view(load.name()) == "body_load") {
      body_load(r, load, step);
    } else if (std::string_view(load.name()) == "nodal_load") {
      nodal_force(r, load, step);
    } else {
      r.doc.fail(load, "only <surface_load> of type pressure, traction, force, normal_traction "
                       "and fluidflux are supported in <Loads>, <body_load> of type const and "
                       "body force, and <nodal_load> of type nodal_force");
    }
  }
}

} // namespace trifem::feb::detail
