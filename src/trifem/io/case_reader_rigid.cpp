// SPDX-License-Identifier: MIT
// Case reader, part 4: [[rigid_body]] (a node set moving with one rigid translation).
#include "trifem/io/toml_table.hpp"

#include <algorithm>

namespace trifem::io::detail {
namespace {

/// The table of component `k` ("x", "y" or "z") of a rigid body: exactly one of
/// `displacement` [mm] and `force` [N], and an optional curve.
RigidComponentSpec read_component(const Table& t, const CaseSpec& spec) {
  t.allow({"displacement", "force", "curve"});
  const bool displacement = t.find("displacement") != nullptr;
  const bool force = t.find("force") != nullptr;
  if (displacement == force)
    fail(t.where(), t.path(),
         displacement ? "give either displacement or force, not both"
                      : "expected displacement = <mm> or force = <N> (omit the component to "
                        "leave it free)");
  RigidComponentSpec c;
  c.drive = displacement ? RigidDrive::Displacement : RigidDrive::Force;
  c.value =
      displacement ? t.number("displacement", {.unit = "mm"}) : t.number("force", {.unit = "N"});
  c.curve = read_curve_reference(t, spec);
  return c;
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

void read_rigid_bodies(const Table& root, CaseSpec& spec) {
  for (const Table& t : root.tables("rigid_body")) {
    t.allow({"name", "set", "components", "x", "y", "z"});
    RigidBodySpec b;
    b.key = t.path();
    b.name = read_identifier(t, "name", false);
    for (const RigidBodySpec& other : spec.rigid_bodies)
      if (other.name == b.name)
        fail(t.find("name"), fmt::format("{} = '{}'", t.path("name"), b.name),
             fmt::format("duplicate rigid body name (already used by {})", other.key));
    b.set = t.name("set");
    b.components = read_components(t);
    for (int k = 0; k < 3; ++k) {
      const auto c = t.table(kAxis[k]);
      if (!c)
        continue;
      if (std::find(b.components.begin(), b.components.end(), k) == b.components.end())
        fail(c->where(), c->path(),
             fmt::format("component {} is not tied to the rigid body (not in {})", kAxis[k],
                         t.path("components")));
      b.drives[k] = read_component(*c, spec);
    }
    check_unconstrained(t, b, spec);
    spec.rigid_bodies.push_back(std::move(b));
  }
}

} // namespace trifem::io::detail
