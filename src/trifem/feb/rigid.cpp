// SPDX-License-Identifier: MIT
// Rigid bodies: a "rigid body" material attached to nodes (bc type "rigid") and driven by the
// <Rigid> section, as a translating [[rigid_body]] (docs/feb.md).
#include "trifem/feb/reader.hpp"

#include <algorithm>
#include <cctype>
#include <fmt/format.h>

namespace trifem::feb::detail {
namespace {

/// The rigid body named by the <rb> child of `node`.
RigidBodyInput& body_of(Reader& r, pugi::xml_node node) {
  const pugi::xml_node rb = r.doc.child(node, "rb");
  const std::string name = r.doc.text(rb);
  const auto it = r.rigid_bodies.find(name);
  if (it == r.rigid_bodies.end())
    r.doc.fail(rb, fmt::format("'{}' is not a material of type 'rigid body'", name));
  return it->second;
}

/// x, y, z (or Rx, Ry, Rz) -> 0, 1, 2.
int translation(const Reader& r, pugi::xml_node dof) {
  std::string d = r.doc.text(dof);
  if (d.size() == 2 && d[0] == 'R')
    d.erase(0, 1);
  if (d == "x" || d == "y" || d == "z")
    return d[0] - 'x';
  r.doc.fail(dof, fmt::format("dof '{}' is not supported: trifem's rigid bodies translate only "
                              "(x, y, z or Rx, Ry, Rz)",
                              r.doc.text(dof)));
}

/// rigid_fixed: Rx_dof ... Rw_dof flags.
void rigid_fixed(Reader& r, pugi::xml_node bc) {
  RigidBodyInput& body = body_of(r, bc);
  for (pugi::xml_node c : elements(bc)) {
    if (std::string_view(c.name()) == "rb")
      continue;
    static constexpr std::string_view names[] = {"Rx_dof", "Ry_dof", "Rz_dof",
                                                 "Ru_dof", "Rv_dof", "Rw_dof"};
    const auto k = std::find(std::begin(names), std::end(names), c.name()) - std::begin(names);
    if (k == 6)
      r.doc.fail(c, fmt::format("unknown parameter '{}' of rigid_fixed", c.name()));
    body.fixed[k] = body.fixed[k] || r.doc.integer(c) != 0;
  }
}

/// rigid_displacement (rigid_bc) and rigid_force (rigid_load): value x curve on one translation.
void rigid_drive(Reader& r, pugi::xml_node node, io::RigidDrive drive) {
  RigidBodyInput& body = body_of(r, node);
  const int k = translation(r, r.doc.child(node, "dof"));
  const pugi::xml_node value = r.doc.child(node, "value");
  for (pugi::xml_node c : elements(node)) {
    const std::string_view name = c.name();
    if (name == "relative" && r.doc.integer(c) != 0)
      r.doc.fail(c, "a relative rigid displacement or force is not supported");
    if (name == "load_type" && r.doc.text(c) != "LOAD")
      r.doc.fail(c, fmt::format("load_type '{}' is not supported (LOAD: the force is applied as "
                                "given)",
                                r.doc.text(c)));
    if (name != "rb" && name != "dof" && name != "value" && name != "relative" &&
        name != "load_type")
      r.doc.fail(c,
                 fmt::format("unknown parameter '{}' of {}", name, node.attribute("type").value()));
  }
  if (body.drives[k].drive != io::RigidDrive::Free)
    r.doc.fail(node, "a second displacement or force on the same component of the body");
  body.drives[k] = {drive, r.doc.number(value), r.curve_of(value)};
}

/// The components of the body's nodes that zero-displacement conditions fix at every node.
std::array<bool, 3> fixed_at_every_node(const Reader& r, const std::string& set) {
  std::array<bool, 3> fixed{};
  for (int k = 0; k < 3; ++k) {
    std::vector<char> held(r.mesh.mesh.num_nodes(), 0);
    for (const io::FixedSpec& f : r.spec.fixed)
      if (std::find(f.fields.begin(), f.fields.end(), io::FieldKind::Displacement) !=
              f.fields.end() &&
          std::find(f.components.begin(), f.components.end(), k) != f.components.end())
        for (Index n : r.mesh.mesh.node_set(f.set))
          held[n] = 1;
    const auto& nodes = r.mesh.mesh.node_set(set);
    fixed[k] = std::all_of(nodes.begin(), nodes.end(), [&](Index n) { return held[n] != 0; });
  }
  return fixed;
}

/// A body name trifem accepts (letters, digits, _).
std::string body_name(std::string name) {
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)))
      c = '_';
  return name;
}

} // namespace

void add_rigid_material(Reader& r, pugi::xml_node node, const std::string& name) {
  for (pugi::xml_node p : node.children())
    if (is_element(p) && std::string_view(p.name()) != "density" &&
        std::string_view(p.name()) != "E" && std::string_view(p.name()) != "v" &&
        std::string_view(p.name()) != "center_of_mass")
      r.doc.fail(p, fmt::format("unknown parameter '{}' of a rigid body", p.name()));
  r.rigid_bodies[name].material = node;
}

void attach_rigid(Reader& r, pugi::xml_node bc, bool step) {
  if (step)
    r.doc.fail(bc, "a rigid attachment inside a <step> is not supported");
  RigidBodyInput& body = body_of(r, bc);
  if (!body.set.empty())
    r.doc.fail(bc, "the body is attached a second time: give all its nodes in one node set");
  body.set = r.node_set(bc);
  body.attachment = bc;
}

void read_rigid(Reader& r, pugi::xml_node section) {
  for (pugi::xml_node c : elements(section)) {
    const std::string kind = c.name(), type = r.doc.attribute(c, "type");
    if (kind == "rigid_bc" && type == "rigid_fixed")
      rigid_fixed(r, c);
    else if (kind == "rigid_bc" && type == "rigid_displacement")
      rigid_drive(r, c, io::RigidDrive::Displacement);
    else if (kind == "rigid_load" && type == "rigid_force")
      rigid_drive(r, c, io::RigidDrive::Force);
    else
      r.doc.fail(c, "type",
                 fmt::format("<{} type=\"{}\"> is not supported (supported: rigid_bc of type "
                             "rigid_fixed or rigid_displacement, rigid_load of type rigid_force)",
                             kind, type));
  }
}

void map_rigid_bodies(Reader& r) {
  for (const auto& [name, body] : r.rigid_bodies) {
    if (body.set.empty()) {
      r.warn(body.material, "a rigid body attached to no nodes (no bc of type rigid) is ignored");
      continue;
    }
    for (int k = 3; k < 6; ++k)
      if (!body.fixed[k])
        r.doc.fail(body.attachment, "the body may rotate (a rotation is not fixed by "
                                    "rigid_fixed): trifem's rigid bodies translate only");
    io::RigidBodySpec spec;
    spec.key = fmt::format("rigid body '{}'", name);
    spec.name = body_name(name);
    spec.set = body.set;
    spec.components.clear();
    const std::array<bool, 3> held = fixed_at_every_node(r, body.set);
    for (int k = 0; k < 3; ++k) {
      if (body.fixed[k] && body.drives[k].drive != io::RigidDrive::Free)
        r.doc.fail(body.attachment,
                   fmt::format("component {} of the body is both fixed and driven", "xyz"[k]));
      if (body.fixed[k] && held[k])
        continue; // every node is fixed in k already: the same motion
      spec.components.push_back(k);
      spec.drives[k] = body.fixed[k] ? io::RigidComponentSpec{io::RigidDrive::Displacement, 0.0, ""}
                                     : body.drives[k];
    }
    if (!spec.components.empty())
      r.spec.rigid_bodies.push_back(spec);
  }
}

} // namespace trifem::feb::detail
