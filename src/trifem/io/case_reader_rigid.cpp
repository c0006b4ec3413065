// SPDX-License-Identifier: MIT
// Case reader, part 4: [[rigid_body]] (a node set moving with one rigid translation, or
// translating and rotating).
#include "trifem/io/toml_table.hpp"
#include "trifem/material/schema.hpp"

#include <algorithm>

namespace trifem::io::detail {
namespace {

/// The keys and units of a translation and of a rotation component.
struct ComponentKeys {
  std::string_view motion, motion_unit, load, load_unit;
};
constexpr ComponentKeys kTranslation{"displacement", "mm", "force", "N"};
constexpr ComponentKeys kRotation{"rotation", "rad", "moment", "N mm"};

/// The table of a component of a rigid body (x, y, z: `keys` kTranslation; rx, ry, rz:
/// kRotation): exactly one of the motion and the load, and an optional curve.
RigidComponentSpec read_component(const Table& t, const CaseSpec& spec, const ComponentKeys& keys) {
  t.allow({keys.motion, keys.load, "curve"});
  const bool motion = t.find(keys.motion) != nullptr;
  const bool load = t.find(keys.load) != nullptr;
  if (motion == load)
    fail(t.where(), t.path(),
         motion ? fmt::format("give either {} or {}, not both", keys.motion, keys.load)
                : fmt::format("expected {} = <{}> or {} = <{}> (omit the component to leave it "
                              "free)",
                              keys.motion, keys.motion_unit, keys.load, keys.load_unit));
  RigidComponentSpec c;
  c.drive = motion ? RigidDrive::Displacement : RigidDrive::Force;
  c.value = motion ? t.number(keys.motion, {.unit = keys.motion_unit})
                   : t.number(keys.load, {.unit = keys.load_unit});
  c.curve = read_curve_reference(t, spec);
  return c;
}

/// blocks = [...]: cell blocks of the mesh with no material (each of one body only).
std::vector<std::string> read_blocks(const Table& t, const CaseSpec& spec) {
  std::vector<std::string> blocks =
      t.get<std::vector<std::string>>("blocks").value_or(std::vector<std::string>{});
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const std::string path = element_path(t.path("blocks"), i);
    const auto where = &(*t.find("blocks")->as_array())[i];
    for (const BoxMeshSpec& box : spec.boxes)
      if (box.box.name == blocks[i] && !box.material.empty())
        fail(where, fmt::format("{} = '{}'", path, blocks[i]),
             fmt::format("the box has the material '{}': the cells of a rigid body have none "
                         "(remove its material)",
                         box.material));
    for (const RigidBodySpec& other : spec.rigid_bodies)
      if (std::find(other.blocks.begin(), other.blocks.end(), blocks[i]) != other.blocks.end())
        fail(where, fmt::format("{} = '{}'", path, blocks[i]),
             fmt::format("the block already belongs to {}", other.key));
  }
  return blocks;
}

/// rotation = "free" | "fixed" (the default unless rx, ry or rz is given), center and the
/// rotation components rx, ry, rz of a rigid body.
void read_rotation(const Table& t, const CaseSpec& spec, RigidBodySpec& b) {
  constexpr const char* kComponents[] = {"rx", "ry", "rz"};
  bool driven = false;
  for (const char* key : kComponents)
    driven = driven || t.find(key) != nullptr;
  static const Options<bool> rotations = {{"fixed", false}, {"free", true}};
  b.rotates =
      t.choice("rotation", rotations,
               std::optional(driven || !b.blocks.empty() || t.find("euler_angles")), "rotation");
  if (!b.rotates && t.find("euler_angles"))
    fail(t.find("rotation"), fmt::format("{} = 'fixed'", t.path("rotation")),
         "the body does not rotate, so euler_angles cannot be given (set rotation = \"free\")");
  if (!b.rotates && !b.blocks.empty())
    fail(t.find("rotation"), fmt::format("{} = 'fixed'", t.path("rotation")),
         "a body made of cells (blocks) rotates; hold its rotation with rx, ry, rz = { rotation "
         "= 0.0 }");
  if (!b.rotates && driven)
    fail(t.find("rotation"), fmt::format("{} = 'fixed'", t.path("rotation")),
         "the body does not rotate, so rx, ry and rz cannot be given (set rotation = \"free\")");
  if (!b.rotates && t.find("center"))
    fail(t.find("center"), t.path("center"),
         "only a rotating body (rotation = \"free\") has a center");
  if (!b.rotates)
    return;
  if (b.components.size() != 3)
    fail(t.find("components"), t.path("components"),
         "a rotating body carries all three components of its nodes (remove components)");
  if (t.find("center"))
    b.center = t.vec3("center", {.unit = "mm"}, std::nullopt);
  for (int k = 0; k < 3; ++k)
    if (const auto c = t.table(kComponents[k]))
      b.rotation_drives[k] = read_component(*c, spec, kRotation);
  if (const auto e = t.table("euler_angles")) {
    if (driven)
      fail(e->where(), e->path(),
           "the rotation is given either by rx, ry, rz or by euler_angles, not both");
    e->allow({"x", "y", "z"});
    std::array<RigidComponentSpec, 3> angles;
    for (int k = 0; k < 3; ++k)
      if (const auto c = e->table(kAxis[k])) {
        c->allow({"rotation", "curve"});
        angles[k] = read_component(*c, spec, kRotation);
      } else {
        angles[k] = {RigidDrive::Displacement, 0.0, ""};
      }
    b.euler_angles = angles;
  }
}

/// [[rigid_body.follower]]: force (at point) and moment turning with a rotating body.
void read_followers(const Table& t, const CaseSpec& spec, RigidBodySpec& b) {
  for (const Table& f : t.tables("follower")) {
    f.allow({"force", "point", "moment", "curve"});
    if (!b.rotates)
      fail(f.where(), f.path(),
           "a follower load turns with its body: the body must rotate (rotation = \"free\")");
    if (!f.find("force") && !f.find("moment"))
      fail(f.where(), f.path(), "expected force = [<N>, <N>, <N>] and/or moment = [<N mm>, ...]");
    RigidFollowerSpec load;
    load.force = f.vec3("force", {.unit = "N"}, Vec3::Zero());
    load.moment = f.vec3("moment", {.unit = "N mm"}, Vec3::Zero());
    if (f.find("point"))
      load.point = f.vec3("point", {.unit = "mm"}, std::nullopt);
    load.curve = read_curve_reference(f, spec);
    b.followers.push_back(load);
  }
}

/// shell_thickness (of a surface body), density (of the body's cells or shells), velocity and
/// angular_velocity (at the start of the dynamic analysis: read_dynamic rejects them in a
/// quasi-static one).
void read_motion(const Table& t, RigidBodySpec& b) {
  if (t.find("shell_thickness")) {
    if (!b.blocks.empty())
      fail(t.find("shell_thickness"), t.path("shell_thickness"),
           "a body made of cells (blocks) has no shells: shell_thickness is for a body whose set "
           "is a surface mesh");
    b.shell_thickness = t.number("shell_thickness", {.range = Range::positive(), .unit = "mm"});
  }
  if (t.find("density")) {
    if (b.blocks.empty() && !b.shell_thickness)
      fail(t.find("density"), t.path("density"),
           "only a body made of cells (blocks) or of shells (shell_thickness) has a density of "
           "its own (the mass of a node set or a surface is that of the tissue cells at its "
           "nodes)");
    b.density = t.number("density", {.range = Range::positive(),
                                     .unit = "t/mm^3",
                                     .plausible = &material::plausible::density()});
  }
  if (b.shell_thickness && !b.density)
    fail(t.find("shell_thickness"), t.path("shell_thickness"),
         "the shells have no mass without a density: give `density` (t/mm^3)");
  b.velocity = t.vec3("velocity", {.unit = "mm/s"}, Vec3::Zero());
  b.angular_velocity = t.vec3("angular_velocity", {.unit = "rad/s"}, Vec3::Zero());
  if (!b.rotates && t.find("angular_velocity"))
    fail(t.find("angular_velocity"), t.path("angular_velocity"),
         "only a rotating body (rotation = \"free\") has an angular velocity");
}

/// Rejects a rigid body on a node set that a boundary condition already constrains.
void check_unconstrained(const Table& t, const RigidBodySpec& b, const CaseSpec& spec) {
  for (const FixedSpec& f : spec.fixed)
    if (f.set == b.set &&
        std::find(f.fields.begin(), f.fields.end(), FieldKind::Displacement) != f.fields.end())
      fail(t.find("set"), fmt::format("{} = '{}'", t.path("set"), b.set),
           fmt::format("the node set's displacement is already constrained by {} (drive the "
                       "rigid body through its x, y, z tables instead)",
                       f.key));
  for (std::size_t i = 0; i < spec.prescribed.size(); ++i)
    if (spec.prescribed[i].set == b.set && spec.prescribed[i].field == FieldKind::Displacement)
      fail(t.find("set"), fmt::format("{} = '{}'", t.path("set"), b.set),
           fmt::format("the node set's displacement is already prescribed by {}",
                       element_path("boundary.prescribed", i)));
}

} // namespace

RigidComponentSpec read_rigid_component(const Table& t, const CaseSpec& spec, bool rotation) {
  return read_component(t, spec, rotation ? kRotation : kTranslation);
}

void read_rigid_bodies(const Table& root, CaseSpec& spec) {
  for (const Table& t : root.tables("rigid_body")) {
    t.allow({"name", "set", "blocks", "components", "x", "y", "z", "rotation", "center", "rx", "ry",
             "rz", "euler_angles", "follower", "density", "shell_thickness", "velocity",
             "angular_velocity"});
    RigidBodySpec b;
    b.key = t.path();
    b.name = read_identifier(t, "name", false);
    if (b.name == "ground")
      fail(t.find("name"), fmt::format("{} = 'ground'", t.path("name")),
           "the name 'ground' is reserved: it stands for space in a [[connector]]");
    for (const RigidBodySpec& other : spec.rigid_bodies)
      if (other.name == b.name)
        fail(t.find("name"), fmt::format("{} = '{}'", t.path("name"), b.name),
             fmt::format("duplicate rigid body name (already used by {})", other.key));
    b.blocks = read_blocks(t, spec);
    b.set = t.name("set", b.blocks.empty());
    b.components = read_components(t);
    for (int k = 0; k < 3; ++k) {
      const auto c = t.table(kAxis[k]);
      if (!c)
        continue;
      if (std::find(b.components.begin(), b.components.end(), k) == b.components.end())
        fail(c->where(), c->path(),
             fmt::format("component {} is not tied to the rigid body (not in {})", kAxis[k],
                         t.path("components")));
      b.drives[k] = read_component(*c, spec, kTranslation);
    }
    read_rotation(t, spec, b);
    read_followers(t, spec, b);
    read_motion(t, b);
    check_unconstrained(t, b, spec);
    spec.rigid_bodies.push_back(std::move(b));
  }
}

} // namespace trifem::io::detail
