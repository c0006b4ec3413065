// SPDX-License-Identifier: MIT
// <rigid_connector>: FEBio's joints, springs, dampers and contractile forces as [[connector]]s
// (docs/feb.md). FEBio enforces joints by penalties or augmented Lagrangians; trifem's are
// exact (multipliers), so the enforcement parameters are read and left aside.
#include "trifem/feb/reader.hpp"

#include <fmt/format.h>

#include <map>
#include <set>

namespace trifem::feb::detail {
namespace {

using K = io::ConnectorKind;

const std::map<std::string, K, std::less<>>& kinds() {
  static const std::map<std::string, K, std::less<>> k = {
      {"rigid spherical joint", K::Spherical},
      {"rigid joint", K::Spherical},
      {"rigid revolute joint", K::Revolute},
      {"rigid prismatic joint", K::Prismatic},
      {"rigid cylindrical joint", K::Cylindrical},
      {"rigid planar joint", K::Planar},
      {"rigid lock joint", K::Lock},
      {"rigid spring", K::Spring},
      {"rigid damper", K::Damper},
      {"rigid contractile force", K::Contractile}};
  return k;
}

/// How FEBio enforces a joint: no meaning with exact multipliers.
const std::set<std::string, std::less<>>& enforcement() {
  static const std::set<std::string, std::less<>> s = {
      "laugon",         "tolerance", "gaptol", "angtol", "force_penalty",
      "moment_penalty", "penalty",   "minaug", "maxaug", "auto_penalty"};
  return s;
}

/// What one connector's parameters say, by name.
struct Parameters {
  std::map<std::string, pugi::xml_node, std::less<>> nodes;
  pugi::xml_node operator[](std::string_view name) const {
    const auto it = nodes.find(name);
    return it == nodes.end() ? pugi::xml_node() : it->second;
  }
};

Vec3 vector_or(const Reader& r, pugi::xml_node n, const Vec3& fallback) {
  return n ? r.doc.vector(n) : fallback;
}

bool switched_on(const Reader& r, pugi::xml_node n) {
  return n && r.doc.integer(n) != 0;
}

/// A drive of a joint's free rotation (translation): prescribed (flag set) or loaded. FEBio
/// applies a joint's moment (force) to body a and its reaction to body b; trifem's drive acts
/// on body b, hence the sign.
io::RigidComponentSpec joint_drive(const Reader& r, pugi::xml_node prescribed,
                                   pugi::xml_node motion, pugi::xml_node load) {
  if (switched_on(r, prescribed))
    return {io::RigidDrive::Displacement, motion ? r.doc.number(motion) : 0.0,
            motion ? r.curve_of(motion) : ""};
  if (load && !r.always_zero(r.doc.number(load), r.curve_of(load)))
    return {io::RigidDrive::Force, -r.doc.number(load), r.curve_of(load)};
  return {};
}

/// Refuses a parameter whose non-zero value would need a feature trifem lacks.
void refuse_if_set(const Reader& r, const Parameters& p, std::string_view name,
                   std::string_view why) {
  const pugi::xml_node n = p[name];
  if (n && !r.always_zero(r.doc.number(n), r.curve_of(n)))
    r.doc.fail(n, fmt::format("{} is not supported: {}", name, why));
}

/// A spherical joint's prescribed rotation (prescribed_rotation, rotation_x, _y, _z: the
/// rotation vector of body b relative to body a, R_b R_aᵀ = exp[a]×) or its moments (moment_x,
/// _y, _z: FEBio applies M to body a and −M to body b), for map_rigid_bodies.
void read_spherical_rotation(Reader& r, pugi::xml_node node, const Parameters& p,
                             const io::ConnectorSpec& c) {
  Reader::JointRotation j{node, c.body_a, c.body_b, {}};
  bool any = false;
  for (int k = 0; k < 3; ++k) {
    const pugi::xml_node motion = p[fmt::format("rotation_{}", "xyz"[k])];
    const pugi::xml_node load = p[fmt::format("moment_{}", "xyz"[k])];
    j.drives[k] = joint_drive(r, p["prescribed_rotation"], motion, load);
    any = any || j.drives[k].drive != io::RigidDrive::Free;
  }
  if (any)
    r.joint_rotations.push_back(std::move(j));
}

void read_joint(Reader& r, pugi::xml_node node, const Parameters& p, io::ConnectorSpec& c) {
  refuse_if_set(r, p, "force_damping", "trifem's joints have no damping");
  refuse_if_set(r, p, "moment_damping", "trifem's joints have no damping");
  c.origin = r.doc.vector(p["joint"] ? p["joint"] : r.doc.child(node, "joint_origin"));
  const char* axis_key = c.kind == K::Prismatic     ? "translation_axis"
                         : c.kind == K::Cylindrical ? "joint_axis"
                         : c.kind == K::Lock        ? "first_axis"
                                                    : "rotation_axis";
  c.axis = vector_or(r, p[axis_key], Vec3::UnitZ());
  const char* transverse_key = c.kind == K::Planar ? "translation_axis_1"
                               : c.kind == K::Lock ? "second_axis"
                                                   : "transverse_axis";
  if (const pugi::xml_node t = p[transverse_key])
    c.transverse = r.doc.vector(t);
  if (c.kind == K::Revolute || c.kind == K::Cylindrical || c.kind == K::Planar)
    c.rotation = joint_drive(r, p["prescribed_rotation"], p["rotation"], p["moment"]);
  if (c.kind == K::Prismatic || c.kind == K::Cylindrical)
    c.translation = joint_drive(r, p["prescribed_translation"], p["translation"], p["force"]);
  if (c.kind == K::Spherical)
    read_spherical_rotation(r, node, p, c);
  for (const char* key : {"prescribed_translation_1", "prescribed_translation_2"})
    if (switched_on(r, p[key]))
      r.doc.fail(p[key], "prescribed translations of a planar joint are not supported");
}

void read_link(const Reader& r, pugi::xml_node node, const Parameters& p, io::ConnectorSpec& c) {
  c.point_a = r.doc.vector(r.doc.child(node, "insertion_a"));
  c.point_b = r.doc.vector(r.doc.child(node, "insertion_b"));
  if (c.kind == K::Spring) {
    c.stiffness = r.doc.number(r.doc.child(node, "k"));
    // FEBio: a free length of 0 is the reference distance
    if (const pugi::xml_node l = p["free_length"]; l && r.doc.number(l) > 0.0)
      c.free_length = r.doc.number(l);
  }
  if (c.kind == K::Damper)
    c.stiffness = r.doc.number(r.doc.child(node, "c"));
  if (c.kind == K::Contractile) {
    const pugi::xml_node f = r.doc.child(node, "f0");
    c.force = r.doc.number(f);
    c.curve = r.curve_of(f);
  }
}

/// The parameters each kind knows besides body_a, body_b and the enforcement ones.
const std::set<std::string, std::less<>>& known(K kind, std::string_view type) {
  static const std::map<K, std::set<std::string, std::less<>>> by_kind = {
      {K::Spherical,
       {"joint_origin", "force_damping", "moment_damping", "prescribed_rotation", "rotation_x",
        "rotation_y", "rotation_z", "moment_x", "moment_y", "moment_z"}},
      {K::Revolute,
       {"joint_origin", "rotation_axis", "transverse_axis", "prescribed_rotation", "rotation",
        "moment", "force_damping", "moment_damping"}},
      {K::Prismatic,
       {"joint_origin", "translation_axis", "transverse_axis", "prescribed_translation",
        "translation", "force", "force_damping", "moment_damping"}},
      {K::Cylindrical,
       {"joint_origin", "joint_axis", "transverse_axis", "prescribed_translation", "translation",
        "force", "prescribed_rotation", "rotation", "moment", "force_damping", "moment_damping"}},
      {K::Planar,
       {"joint_origin", "rotation_axis", "translation_axis_1", "prescribed_rotation", "rotation",
        "prescribed_translation_1", "translation_1", "prescribed_translation_2", "translation_2",
        "force_damping", "moment_damping"}},
      {K::Lock, {"joint_origin", "first_axis", "second_axis", "force_damping", "moment_damping"}},
      {K::Spring, {"k", "insertion_a", "insertion_b", "free_length"}},
      {K::Damper, {"c", "insertion_a", "insertion_b"}},
      {K::Contractile, {"f0", "insertion_a", "insertion_b"}}};
  static const std::set<std::string, std::less<>> old_joint = {"joint"};
  return type == "rigid joint" ? old_joint : by_kind.at(kind);
}

} // namespace

void read_rigid_connector(Reader& r, pugi::xml_node node) {
  const std::string type = r.doc.attribute(node, "type");
  const auto kind = kinds().find(type);
  if (kind == kinds().end())
    r.doc.fail(node, "type",
               fmt::format("<rigid_connector type=\"{}\"> is not supported (supported: {})", type,
                           "rigid spherical joint, rigid joint, rigid revolute joint, rigid "
                           "prismatic joint, rigid cylindrical joint, rigid planar joint, rigid "
                           "lock joint, rigid spring, rigid damper, rigid contractile force"));
  io::ConnectorSpec c;
  c.kind = kind->second;
  c.key = fmt::format("rigid_connector '{}'", node.attribute("name").value());
  Parameters p;
  for (pugi::xml_node e : elements(node)) {
    const std::string_view name = e.name();
    if (name != "body_a" && name != "body_b" && !enforcement().contains(name) &&
        !known(c.kind, type).contains(name))
      r.doc.fail(e, fmt::format("unknown parameter '{}' of a {}", name, type));
    p.nodes.emplace(std::string(name), e);
  }
  for (auto [key, body] : {std::pair{"body_a", &c.body_a}, {"body_b", &c.body_b}}) {
    const pugi::xml_node b = r.doc.child(node, key);
    *body = r.doc.text(b);
    const auto it = r.rigid_bodies.find(*body);
    if (it == r.rigid_bodies.end())
      r.doc.fail(b, fmt::format("'{}' is not a material of type 'rigid body'", *body));
    it->second.connected = true;
  }
  if (c.body_a == c.body_b)
    r.doc.fail(r.doc.child(node, "body_b"), "the connector joins a body to itself");
  c.name = rigid_body_name(node.attribute("name") ? node.attribute("name").value() : "connector");
  for (const io::ConnectorSpec& other : r.connectors)
    if (other.name == c.name)
      c.name += fmt::format("_{}", r.connectors.size() + 1);
  if (c.kind <= K::Lock)
    read_joint(r, node, p, c);
  else
    read_link(r, node, p, c);
  r.connectors.push_back(std::move(c));
}

} // namespace trifem::feb::detail
