// SPDX-License-Identifier: MIT
// Rigid bodies: a "rigid body" material on solid elements or attached to nodes (bc type
// "rigid"), driven by the <Rigid> section, as a [[rigid_body]] that translates (its rotation
// held) or rotates (docs/feb.md).
#include "trifem/feb/reader.hpp"

#include <algorithm>
#include <cctype>
#include <fmt/format.h>
#include <numbers>
#include <set>

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
  r.doc.fail(dof,
             fmt::format("dof '{}' is not a translation (x, y, z or Rx, Ry, Rz)", r.doc.text(dof)));
}

/// Ru, Rv, Rw -> 0, 1, 2 (components of the rotation vector).
int rotation(const Reader& r, pugi::xml_node dof) {
  const std::string d = r.doc.text(dof);
  if (d == "Ru" || d == "Rv" || d == "Rw")
    return d[1] - 'u';
  r.doc.fail(dof, fmt::format("dof '{}' is not a rotation (Ru, Rv, Rw)", d));
}

/// A rigid condition fixing (`drive` null) or driving component k of `body`, in the file's
/// order: as in FEBio, it replaces a fixed or driven state an earlier condition gave (with a
/// warning); two drives of one component are an error.
void set_component(Reader& r, pugi::xml_node node, RigidBodyInput& body, int k,
                   const io::RigidComponentSpec* drive) {
  io::RigidComponentSpec& current = body.drive(k);
  if (drive && current.drive != io::RigidDrive::Free)
    r.doc.fail(node, "a second motion or load on the same component of the body");
  if (body.fixed[k] != (drive == nullptr) &&
      (body.fixed[k] || current.drive != io::RigidDrive::Free))
    r.warn(node,
           fmt::format("component {} of the body was {} by an earlier rigid condition; "
                       "this one replaces it (as in FEBio)",
                       RigidBodyInput::kComponentNames[k], body.fixed[k] ? "fixed" : "driven"));
  body.fixed[k] = drive == nullptr;
  current = drive ? *drive : io::RigidComponentSpec{};
  body.order[k] = r.rigid_conditions;
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
    if (r.doc.integer(c) != 0 && !body.fixed[k])
      set_component(r, bc, body, static_cast<int>(k), nullptr);
  }
}

/// rigid_displacement and rigid_rotation (rigid_bc), rigid_force and rigid_moment (rigid_load):
/// value x curve on one translation or rotation component.
void rigid_drive(Reader& r, pugi::xml_node node, io::RigidDrive drive, bool rotating) {
  RigidBodyInput& body = body_of(r, node);
  const pugi::xml_node dof = r.doc.child(node, "dof");
  const int k = rotating ? rotation(r, dof) : translation(r, dof);
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
  const io::RigidComponentSpec given{drive, r.doc.number(value), r.curve_of(value)};
  set_component(r, node, body, rotating ? 3 + k : k, &given);
}

/// rigid_rotation_vector: the three components vx, vy, vz of the rotation vector prescribed
/// (each value x curve; 0 if absent).
void rigid_rotation_vector(Reader& r, pugi::xml_node node) {
  RigidBodyInput& body = body_of(r, node);
  for (pugi::xml_node c : elements(node)) {
    const std::string_view name = c.name();
    if (name != "rb" && name != "vx" && name != "vy" && name != "vz" && name != "relative")
      r.doc.fail(c, fmt::format("unknown parameter '{}' of rigid_rotation_vector", name));
    if (name == "relative" && r.doc.integer(c) != 0)
      r.doc.fail(c, "a relative rigid rotation is not supported");
  }
  for (int k = 0; k < 3; ++k) {
    const pugi::xml_node v = node.child(fmt::format("v{}", "xyz"[k]).c_str());
    const io::RigidComponentSpec given{io::RigidDrive::Displacement, v ? r.doc.number(v) : 0.0,
                                       v ? r.curve_of(v) : ""};
    set_component(r, node, body, 3 + k, &given);
  }
}

/// rigid_euler_angles: the rotation R_z(Ez) R_y(Ey) R_x(Ex) prescribed by three angles in
/// degrees, each with its curve (FEBio's quatd::SetEuler; its only convention).
void rigid_euler_angles(Reader& r, pugi::xml_node node) {
  RigidBodyInput& body = body_of(r, node);
  for (pugi::xml_node c : elements(node)) {
    const std::string_view name = c.name();
    if (name == "convention" && r.doc.text(c) != "ZXY" && r.doc.text(c) != "0")
      r.doc.fail(c, fmt::format("convention '{}' is not supported (FEBio's only one: ZXY, the "
                                "rotation R_z R_y R_x)",
                                r.doc.text(c)));
    if (name != "rb" && name != "Ex" && name != "Ey" && name != "Ez" && name != "convention")
      r.doc.fail(c, fmt::format("unknown parameter '{}' of rigid_euler_angles", name));
  }
  if (body.euler_angles)
    r.doc.fail(node, "a second rigid_euler_angles on the same body");
  std::array<io::RigidComponentSpec, 3> angles;
  for (int k = 0; k < 3; ++k) {
    const pugi::xml_node e = node.child(fmt::format("E{}", "xyz"[k]).c_str());
    angles[k] = {io::RigidDrive::Displacement, e ? r.doc.number(e) * std::numbers::pi / 180.0 : 0.0,
                 e ? r.curve_of(e) : ""};
  }
  body.euler_angles = angles;
  body.euler_node = node;
}

/// initial_rigid_velocity and initial_rigid_angular_velocity (rigid_ic): the body's velocity at
/// the start of a dynamic analysis.
void rigid_initial_velocity(Reader& r, pugi::xml_node node, bool angular) {
  RigidBodyInput& body = body_of(r, node);
  for (pugi::xml_node c : elements(node))
    if (std::string_view name = c.name(); name != "rb" && name != "value")
      r.doc.fail(c,
                 fmt::format("unknown parameter '{}' of {}", name, node.attribute("type").value()));
  (angular ? body.angular_velocity : body.velocity) = r.doc.vector(r.doc.child(node, "value"));
  body.initial = node;
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

/// A body of elements, or one whose rotation is not held, has six unknowns.
bool rotates(const RigidBodyInput& body) {
  if (!body.blocks.empty() || body.shell || body.connected ||
      body.angular_velocity != Vec3::Zero() || body.euler_angles)
    return true;
  for (int k = 0; k < 3; ++k)
    if (!body.fixed[3 + k] || body.rotation_drives[k].drive != io::RigidDrive::Free)
      return true;
  return false;
}

/// A fixed component is held at 0; a driven one keeps its drive; the others are free.
io::RigidComponentSpec component(const Reader& r, const RigidBodyInput& body, bool fixed,
                                 const io::RigidComponentSpec& drive, std::string_view what) {
  if (fixed && drive.drive != io::RigidDrive::Free)
    r.doc.fail(body.material, fmt::format("{} of the body is both fixed and driven", what));
  return fixed ? io::RigidComponentSpec{io::RigidDrive::Displacement, 0.0, ""} : drive;
}

/// A rotating [[rigid_body]]: its elements and attached nodes; center_of_mass, if given, is
/// its center.
io::RigidBodySpec rotating_body(const Reader& r, const std::string& name,
                                const RigidBodyInput& body) {
  io::RigidBodySpec spec;
  spec.key = fmt::format("rigid body '{}'", name);
  spec.name = rigid_body_name(name);
  spec.set = body.set;
  spec.blocks = body.blocks;
  spec.rotates = true;
  spec.velocity = body.velocity;
  spec.angular_velocity = body.angular_velocity;
  if (const pugi::xml_node c = body.material.child("center_of_mass"))
    spec.center = r.doc.vector(c);
  if (body.shell) // a surface mesh has mass if its shells have a thickness
    if (const pugi::xml_node t = body.attachment.child("shell_thickness")) {
      const Real thickness = r.doc.number(t);
      if (thickness < 0.0)
        r.doc.fail(t, "a shell thickness must not be negative");
      if (thickness > 0.0)
        spec.shell_thickness = thickness;
    }
  if (body.mesh_data_thickness.value_or(0.0) > 0.0)
    spec.shell_thickness = body.mesh_data_thickness;
  if (!spec.blocks.empty() || spec.shell_thickness) { // FEBio's default density 1
    const pugi::xml_node d = body.material.child("density");
    spec.density = d ? r.doc.number(d) : 1.0;
    if (!(*spec.density > 0.0))
      r.doc.fail(d, "a rigid body's density must be positive");
  }
  for (int k = 0; k < 3; ++k) {
    spec.drives[k] =
        component(r, body, body.fixed[k], body.drives[k], fmt::format("translation {}", "xyz"[k]));
    spec.rotation_drives[k] = component(r, body, body.fixed[3 + k], body.rotation_drives[k],
                                        fmt::format("rotation R{}", "uvw"[k]));
    if (body.euler_angles && spec.rotation_drives[k].drive != io::RigidDrive::Free)
      r.doc.fail(body.euler_node, fmt::format("the rotation R{} of the body is also fixed or "
                                              "driven by another rigid condition",
                                              "uvw"[k]));
  }
  spec.euler_angles = body.euler_angles;
  return spec;
}

/// A rigid body of no elements and no nodes that connectors join to others: held in all six
/// components, it is the ground (space).
void check_ground(const Reader& r, const RigidBodyInput& body) {
  const bool held =
      std::all_of(body.fixed.begin(), body.fixed.end(), [](bool f) { return f; }) &&
      std::all_of(
          body.drives.begin(), body.drives.end(),
          [](const io::RigidComponentSpec& d) { return d.drive == io::RigidDrive::Free; }) &&
      std::all_of(body.rotation_drives.begin(), body.rotation_drives.end(),
                  [](const io::RigidComponentSpec& d) { return d.drive == io::RigidDrive::Free; });
  if (!held)
    r.doc.fail(body.material, "a rigid body of no elements and no nodes joined by a connector is "
                              "supported as the ground only: fix all six of its degrees of "
                              "freedom (rigid_fixed), or give it elements");
}

} // namespace

std::string rigid_body_name(std::string name) {
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)))
      c = '_';
  return name == "ground" ? "ground_body" : name; // "ground": space in a [[connector]]
}

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
  if (body.shell)
    r.doc.fail(bc, "nodes attached to a rigid body made of a shell part are not supported");
  const std::string set = r.node_set(bc);
  if (!body.set.empty()) { // attached again: the union of the node sets
    body.set = union_node_sets(r, body.set, set);
    return;
  }
  body.set = set;
  body.attachment = bc;
}

void read_rigid(Reader& r, pugi::xml_node section) {
  for (pugi::xml_node c : elements(section)) {
    const std::string kind = c.name(), type = r.doc.attribute(c, "type");
    ++r.rigid_conditions;
    if (kind == "rigid_bc" && type == "rigid_fixed")
      rigid_fixed(r, c);
    else if (kind == "rigid_bc" && (type == "rigid_displacement" || type == "rigid_rotation"))
      rigid_drive(r, c, io::RigidDrive::Displacement, type == "rigid_rotation");
    else if (kind == "rigid_bc" && type == "rigid_rotation_vector")
      rigid_rotation_vector(r, c);
    else if (kind == "rigid_bc" && type == "rigid_euler_angles")
      rigid_euler_angles(r, c);
    else if (kind == "rigid_load" && (type == "rigid_force" || type == "rigid_moment"))
      rigid_drive(r, c, io::RigidDrive::Force, type == "rigid_moment");
    else if (kind == "rigid_connector")
      read_rigid_connector(r, c);
    else if (kind == "rigid_ic" &&
             (type == "initial_rigid_velocity" || type == "initial_rigid_angular_velocity"))
      rigid_initial_velocity(r, c, type == "initial_rigid_angular_velocity");
    else
      r.doc.fail(c, "type",
                 fmt::format("<{} type=\"{}\"> is not supported (supported: rigid_bc of type "
                             "rigid_fixed, rigid_displacement, rigid_rotation, "
                             "rigid_rotation_vector or rigid_euler_angles, rigid_load of type "
                             "rigid_force or "
                             "rigid_moment, rigid_ic of type initial_rigid_velocity or "
                             "initial_rigid_angular_velocity, rigid_connector)",
                             kind, type));
  }
}

namespace {

/// Per mesh node: the displacement components a [[rigid_body]] of the file carries.
std::vector<std::array<bool, 3>> carried_components(const Reader& r) {
  const mesh::Mesh& mesh = r.mesh.mesh;
  std::vector<std::array<bool, 3>> carried(mesh.num_nodes(), {false, false, false});
  for (const io::RigidBodySpec& b : r.spec.rigid_bodies) {
    std::vector<Index> nodes;
    if (!b.set.empty())
      nodes = mesh.node_set(b.set);
    for (const std::string& block : b.blocks)
      for (Index c : mesh.cell_block(block))
        nodes.insert(nodes.end(), mesh.cell_nodes(c).begin(), mesh.cell_nodes(c).end());
    for (Index n : nodes)
      for (int k = 0; k < 3; ++k)
        carried[n][k] =
            carried[n][k] || b.rotates ||
            std::find(b.components.begin(), b.components.end(), k) != b.components.end();
  }
  return carried;
}

/// The nodes of `set` whose component k no rigid body carries, as a node set (its name; "" if
/// there are none), and how many were left out.
std::string uncarried_set(Reader& r, const std::string& set, int k,
                          const std::vector<std::array<bool, 3>>& carried, Index& left_out) {
  std::vector<Index> kept;
  for (Index n : r.mesh.mesh.node_set(set))
    if (carried[n][k])
      ++left_out;
    else
      kept.push_back(n);
  if (kept.size() == r.mesh.mesh.node_set(set).size())
    return set;
  if (kept.empty())
    return "";
  std::string name = fmt::format("{}_not_rigid_{}", set, "xyz"[k]);
  while (r.mesh.mesh.has_node_set(name))
    name += "_";
  r.mesh.mesh.add_node_set(name, std::move(kept));
  return name;
}

/// Whether a displacement condition on `set` and components `components` touches a carried
/// node.
bool touches_carried(const Reader& r, const std::string& set,
                     const std::vector<io::Component>& components,
                     const std::vector<std::array<bool, 3>>& carried) {
  for (Index n : r.mesh.mesh.node_set(set))
    for (io::Component k : components)
      if (carried[n][k])
        return true;
  return false;
}

/// FEBio ignores the fixed and prescribed displacements of the nodes a rigid body carries (its
/// rigid solver numbers their components as the body's, "make sure that the nodes are NOT
/// constrained"): those components leave the conditions, with a warning. (A case file written
/// by hand gets an error instead: the two conditions contradict each other.)
void release_carried_nodes(Reader& r, pugi::xml_node where) {
  const std::vector<std::array<bool, 3>> carried = carried_components(r);
  Index left_out = 0;
  std::vector<io::FixedSpec> fixed;
  for (io::FixedSpec& f : r.spec.fixed) {
    const bool displacement =
        std::find(f.fields.begin(), f.fields.end(), io::FieldKind::Displacement) != f.fields.end();
    if (!displacement || !touches_carried(r, f.set, f.components, carried)) {
      fixed.push_back(std::move(f));
      continue;
    }
    io::FixedSpec others = f; // the flux fields stay as they are
    std::erase(others.fields, io::FieldKind::Displacement);
    if (!others.fields.empty())
      fixed.push_back(others);
    for (io::Component k : f.components)
      if (std::string set = uncarried_set(r, f.set, k, carried, left_out); !set.empty())
        fixed.push_back({f.key, set, {k}, {io::FieldKind::Displacement}});
  }
  r.spec.fixed = std::move(fixed);
  std::vector<io::PrescribedSpec> prescribed;
  for (io::PrescribedSpec& p : r.spec.prescribed) {
    if (p.field == io::FieldKind::Displacement)
      p.set = uncarried_set(r, p.set, p.component, carried, left_out);
    if (!p.set.empty())
      prescribed.push_back(std::move(p));
  }
  r.spec.prescribed = std::move(prescribed);
  if (left_out > 0)
    r.warn(where, fmt::format("{} fixed or prescribed displacement component(s) of nodes that a "
                              "rigid body carries are ignored, as FEBio does (the body moves them)",
                              left_out));
}

} // namespace

namespace {

/// A spherical joint's prescribed rotation or moment between the ground and a body: the
/// body's rotation drives (b: the rotation vector a, the moment; a: R_a = exp[−a]×, and the
/// reaction of the moment).
void drive_by_joint(Reader& r, const Reader::JointRotation& j,
                    const std::set<std::string>& grounds) {
  const bool a_moves = !grounds.contains(j.body_a), b_moves = !grounds.contains(j.body_b);
  if (a_moves && b_moves)
    r.doc.fail(j.where, "a prescribed rotation or a moment of a spherical joint between two "
                        "moving bodies is not supported (one of them must be the ground: a "
                        "body of no elements with all six degrees of freedom fixed)");
  const std::string name = rigid_body_name(b_moves ? j.body_b : j.body_a);
  const auto body = std::find_if(r.spec.rigid_bodies.begin(), r.spec.rigid_bodies.end(),
                                 [&](const io::RigidBodySpec& b) { return b.name == name; });
  if (body == r.spec.rigid_bodies.end() || !body->rotates)
    r.doc.fail(j.where, "the joint's moving body does not rotate");
  for (int k = 0; k < 3; ++k) {
    if (j.drives[k].drive == io::RigidDrive::Free)
      continue;
    io::RigidComponentSpec& drive = body->rotation_drives[k];
    if (drive.drive != io::RigidDrive::Free)
      r.doc.fail(j.where, fmt::format("the rotation {} of body '{}' is driven twice (by the "
                                      "joint and by a rigid condition)",
                                      "xyz"[k], name));
    drive = j.drives[k];
    if (!b_moves)
      drive.value = -drive.value;
  }
}

} // namespace

void map_rigid_bodies(Reader& r) {
  merge_touching_bodies(r);
  std::set<std::string> grounds; // bodies of nothing that connectors hold to: space
  for (const auto& [name, body] : r.rigid_bodies) {
    if (body.set.empty() && body.blocks.empty() && body.connected) {
      check_ground(r, body);
      grounds.insert(name);
      continue;
    }
    if (body.set.empty() && body.blocks.empty()) {
      r.warn(body.material, "a rigid body of no elements attached to no nodes (no bc of type "
                            "rigid) is ignored");
      continue;
    }
    if (rotates(body)) {
      r.spec.rigid_bodies.push_back(rotating_body(r, name, body));
      continue;
    }
    io::RigidBodySpec spec;
    spec.key = fmt::format("rigid body '{}'", name);
    spec.name = rigid_body_name(name);
    spec.set = body.set;
    spec.velocity = body.velocity;
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
  for (const Reader::JointRotation& j : r.joint_rotations)
    drive_by_joint(r, j, grounds);
  if (!r.spec.rigid_bodies.empty())
    release_carried_nodes(r, r.rigid_bodies.begin()->second.material);
  for (io::ConnectorSpec& c : r.connectors) {
    c.body_a = grounds.contains(c.body_a) ? "ground" : rigid_body_name(c.body_a);
    c.body_b = grounds.contains(c.body_b) ? "ground" : rigid_body_name(c.body_b);
    r.spec.connectors.push_back(std::move(c));
  }
}

void drop_static_rigid_velocities(Reader& r) {
  if (r.spec.has_dynamic_step()) // a velocity has no effect in a static analysis (FEBio's too)
    return;
  for (const auto& [name, body] : r.rigid_bodies)
    if (body.velocity != Vec3::Zero() || body.angular_velocity != Vec3::Zero())
      r.warn(body.initial, "the initial velocity of a rigid body is ignored: the analysis is "
                           "static");
  for (io::RigidBodySpec& b : r.spec.rigid_bodies)
    b.velocity = b.angular_velocity = Vec3::Zero();
}

} // namespace trifem::feb::detail
