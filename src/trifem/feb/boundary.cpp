// SPDX-License-Identifier: MIT
// Boundary and Loads sections: fixed and prescribed displacements, zero fluid pressure
// (drained nodes), pressure and traction loads.
#include "trifem/feb/reader.hpp"

#include <fmt/format.h>
#include <sstream>

namespace trifem::feb::detail {
namespace {

bool is_element(pugi::xml_node n) {
  return n.type() == pugi::node_element;
}

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
  for (pugi::xml_node c : bc.children()) {
    if (!is_element(c))
      continue;
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
  for (pugi::xml_node c : bc.children()) {
    if (!is_element(c))
      continue;
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
  for (pugi::xml_node c : bc.children()) {
    if (!is_element(c))
      continue;
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
  for (pugi::xml_node bc : section.children()) {
    if (!is_element(bc))
      continue;
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
    else if (type == "fix" && r.version == Version::V3)
      fix(r, bc, fixed, step);
    else if (type == "prescribe" && r.version == Version::V3)
      prescribed_displacement(r, bc, prescribed);
    else
      r.doc.fail(bc, "type",
                 fmt::format("boundary condition type '{}' is not supported (supported: {})", type,
                             r.version == Version::V4
                                 ? "zero displacement, prescribed displacement, zero fluid "
                                   "pressure, prescribed fluid pressure, prescribed concentration"
                                 : "fix, prescribe"));
  }
}

namespace {

/// <surface_load type="pressure">: a follower pressure on the deformed surface.
io::PressureSpec pressure_load(const Reader& r, pugi::xml_node load) {
  io::PressureSpec p;
  p.surface = r.surface(load);
  const pugi::xml_node value = r.doc.child(load, "pressure");
  p.value = r.doc.number(value);
  p.curve = r.curve_of(value);
  for (pugi::xml_node c : load.children()) {
    if (!is_element(c))
      continue;
    const std::string_view name = c.name();
    if (name == "linear" && flag(r, c))
      r.doc.fail(c, "a linear (non-follower) pressure is not supported: trifem's pressure "
                    "follows the deformed surface");
    if (name == "shell_bottom" && flag(r, c))
      r.doc.fail(c, "shell_bottom is not supported (trifem has no shells)");
    if (name != "pressure" && name != "linear" && name != "symmetric_stiffness" &&
        name != "shell_bottom")
      r.doc.fail(c, fmt::format("unknown parameter '{}' of a pressure load", name));
  }
  return p;
}

/// <surface_load type="traction">: scale x traction per reference area, a dead load (FEBio
/// integrates it over the reference surface, as trifem's [[loads.traction]]); the load curve
/// is that of <scale>.
io::TractionSpec traction_load(const Reader& r, pugi::xml_node load) {
  io::TractionSpec t;
  t.surface = r.surface(load);
  Real scale = 1.0;
  for (pugi::xml_node c : load.children()) {
    if (!is_element(c))
      continue;
    const std::string_view name = c.name();
    if (name == "scale") {
      scale = r.doc.number(c);
      t.curve = r.curve_of(c);
    } else if (name == "traction") {
      if (c.attribute("lc"))
        r.doc.fail(c, "a load curve on the traction vector is not supported (put it on <scale>)");
      t.value = r.doc.vector(c);
    } else if (name == "shell_bottom") {
      if (flag(r, c))
        r.doc.fail(c, "shell_bottom is not supported (trifem has no shells)");
    } else {
      r.doc.fail(c, fmt::format("unknown parameter '{}' of a traction load (expected one of: "
                                "scale, traction, shell_bottom)",
                                name));
    }
  }
  r.doc.child(load, "traction"); // required: InputError if missing
  t.value *= scale;
  return t;
}

} // namespace

void read_loads(Reader& r, pugi::xml_node section, std::vector<io::PressureSpec>& pressures,
                std::vector<io::TractionSpec>& tractions) {
  for (pugi::xml_node load : section.children()) {
    if (!is_element(load))
      continue;
    const std::string type = load.attribute("type").value();
    const bool surface_load = std::string_view(load.name()) == "surface_load";
    if (surface_load && type == "pressure")
      pressures.push_back(pressure_load(r, load));
    else if (surface_load && type == "traction")
      tractions.push_back(traction_load(r, load));
    else
      r.doc.fail(load, "only <surface_load type=\"pressure\"> and <surface_load "
                       "type=\"traction\"> are supported in <Loads>");
  }
}

} // namespace trifem::feb::detail
