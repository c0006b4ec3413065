// SPDX-License-Identifier: MIT
// Case reader, part 5: [[connector]] (joints, springs, cables, dampers and contractile forces
// between rotating rigid bodies).
#include "trifem/io/toml_table.hpp"

namespace trifem::io::detail {
namespace {

using K = ConnectorKind;

const Options<ConnectorKind>& connector_kinds() {
  static const Options<ConnectorKind> kinds = {
      {"spherical", K::Spherical},     {"revolute", K::Revolute}, {"prismatic", K::Prismatic},
      {"cylindrical", K::Cylindrical}, {"planar", K::Planar},     {"lock", K::Lock},
      {"spring", K::Spring},           {"cable", K::Cable},       {"damper", K::Damper},
      {"contractile", K::Contractile}};
  return kinds;
}

bool is_joint(ConnectorKind k) {
  return k <= K::Lock;
}
bool turns(ConnectorKind k) {
  return k == K::Revolute || k == K::Cylindrical || k == K::Planar;
}
bool slides(ConnectorKind k) {
  return k == K::Prismatic || k == K::Cylindrical;
}

/// body_a or body_b: a rotating [[rigid_body]] or "ground".
std::string read_body(const Table& t, std::string_view key, const CaseSpec& spec) {
  const std::string name = t.name(key);
  if (name == "ground")
    return name;
  std::vector<std::string> names = {"ground"};
  for (const RigidBodySpec& b : spec.rigid_bodies) {
    if (b.name != name) {
      names.push_back(b.name);
      continue;
    }
    if (!b.rotates)
      fail(t.find(key), fmt::format("{} = '{}'", t.path(key), name),
           fmt::format("{} does not rotate; a connector joins bodies that do (set rotation = "
                       "\"free\" there, and rx, ry, rz = {{ rotation = 0.0 }} to hold it)",
                       b.key));
    return name;
  }
  fail(t.find(key), fmt::format("{} = '{}'", t.path(key), name),
       fmt::format("no rigid body has this name (expected one of: {}){}", join(names),
                   did_you_mean(name, names)));
}

/// origin, axis, transverse, the drives of the free rotation and translation and the torsion
/// spring of a joint.
void read_joint(const Table& t, const CaseSpec& spec, ConnectorSpec& c) {
  t.allow({"type", "name", "body_a", "body_b", "origin", "axis", "transverse", "rotation",
           "translation", "torsion_stiffness"});
  c.origin = t.vec3("origin", {.unit = "mm"}, std::nullopt);
  const bool needs_axis = c.kind != K::Spherical && c.kind != K::Lock;
  c.axis = t.vec3("axis", {}, needs_axis ? std::nullopt : std::optional(Vec3(Vec3::UnitZ())));
  if (c.axis.norm() == 0.0)
    fail(t.find("axis"), t.path("axis"), "expected a direction, not the zero vector");
  if (t.find("transverse"))
    c.transverse = t.vec3("transverse", {}, std::nullopt);
  for (const auto& [key, allowed, rotation] :
       {std::tuple{"rotation", turns(c.kind), true}, {"translation", slides(c.kind), false}}) {
    const auto drive = t.table(key);
    if (!drive)
      continue;
    if (!allowed)
      fail(drive->where(), drive->path(),
           fmt::format("a {} joint has no free {} to drive (only {})",
                       t.get<std::string>("type").value_or(""), key,
                       rotation ? "revolute, cylindrical and planar joints turn"
                                : "prismatic and cylindrical joints slide"));
    (rotation ? c.rotation : c.translation) = read_rigid_component(*drive, spec, rotation);
  }
  if (t.find("torsion_stiffness") && !turns(c.kind))
    fail(t.find("torsion_stiffness"), t.path("torsion_stiffness"),
         "only revolute, cylindrical and planar joints turn about their axis");
  c.torsion_stiffness = t.number(
      "torsion_stiffness", {.range = Range::non_negative(), .fallback = 0.0, .unit = "N mm/rad"});
}

/// point_a, point_b and the law of a link.
void read_link(const Table& t, const CaseSpec& spec, ConnectorSpec& c) {
  std::vector<std::string_view> keys = {"type", "name", "body_a", "body_b", "point_a", "point_b"};
  if (c.kind == K::Spring || c.kind == K::Cable)
    keys.insert(keys.end(), {"stiffness", "free_length"});
  if (c.kind == K::Damper)
    keys.push_back("damping");
  if (c.kind == K::Contractile)
    keys.insert(keys.end(), {"force", "curve"});
  t.allow(keys);
  c.point_a = t.vec3("point_a", {.unit = "mm"}, std::nullopt);
  c.point_b = t.vec3("point_b", {.unit = "mm"}, std::nullopt);
  if (c.kind == K::Spring || c.kind == K::Cable) {
    c.stiffness = t.number("stiffness", {.range = Range::positive(), .unit = "N/mm"});
    if (t.find("free_length"))
      c.free_length = t.number("free_length", {.range = Range::non_negative(), .unit = "mm"});
  }
  if (c.kind == K::Damper)
    c.stiffness = t.number("damping", {.range = Range::positive(), .unit = "N s/mm"});
  if (c.kind == K::Contractile) {
    c.force = t.number("force", {.unit = "N"});
    c.curve = read_curve_reference(t, spec);
  }
  if ((c.point_b - c.point_a).norm() == 0.0 && c.kind != K::Damper)
    fail(t.find("point_b"), t.path("point_b"),
         "the two points coincide: the link has no direction (give points apart)");
}

} // namespace

void read_connectors(const Table& root, CaseSpec& spec) {
  for (const Table& t : root.tables("connector")) {
    ConnectorSpec c;
    c.key = t.path();
    c.kind = t.choice("type", connector_kinds(), std::optional<ConnectorKind>(), "connector type");
    c.name = t.find("name") ? read_identifier(t, "name", false)
                            : fmt::format("connector{}", spec.connectors.size() + 1);
    for (const ConnectorSpec& other : spec.connectors)
      if (other.name == c.name)
        fail(t.find("name"), fmt::format("{} = '{}'", t.path("name"), c.name),
             fmt::format("duplicate connector name (already used by {})", other.key));
    c.body_a = read_body(t, "body_a", spec);
    c.body_b = read_body(t, "body_b", spec);
    if (c.body_a == c.body_b)
      fail(t.find("body_b"), fmt::format("{} = '{}'", t.path("body_b"), c.body_b),
           fmt::format("the connector joins '{}' to itself (body_a is the same body)", c.body_a));
    if (is_joint(c.kind))
      read_joint(t, spec, c);
    else
      read_link(t, spec, c);
    spec.connectors.push_back(std::move(c));
  }
}

} // namespace trifem::io::detail
