// SPDX-License-Identifier: MIT
// Case reader: what an implicit dynamic analysis (or step) reads besides a quasi-static one:
// the [dynamic] table, the starting velocities and the mass density of every material.
#include "trifem/io/toml_table.hpp"

namespace trifem::io::detail {
namespace {

/// Every material has a density: the inertia of every cell enters a dynamic step.
void check_densities(const Table& root, const CaseSpec& spec) {
  const auto materials = root.table("materials");
  if (!materials)
    return;
  for (const auto& [name, t] : materials->named_tables())
    if (!spec.materials.at(name).density)
      fail(t.where(), t.path("density"),
           "missing required key (expected a number in (0, inf) t/mm^3: dynamic analyses need "
           "the mass density of every material, of a mixture the density of the saturated "
           "tissue, e.g. 1e-9 for water-like tissue)");
}

/// A rigid body's starting velocity belongs to a dynamic analysis.
void check_rigid_velocities(const Table& root) {
  for (const Table& b : root.tables("rigid_body"))
    for (const char* key : {"velocity", "angular_velocity"})
      if (b.find(key))
        fail(b.find(key), b.path(key),
             "only applies to dynamic analyses (the velocity at the start of the first "
             "dynamic step; set [analysis] type = \"dynamic\" or \"dynamic-explicit\")");
}

/// [[initial_velocity]] tables (of a dynamic analysis).
void read_initial_velocities(const Table& root, CaseSpec& spec) {
  for (const Table& t : root.tables("initial_velocity")) {
    t.allow({"set", "value"});
    spec.initial_velocities.push_back(
        {t.path(), t.name("set"), t.vec3("value", {.unit = "mm/s"}, std::nullopt)});
  }
}

} // namespace

void read_dynamic(const Table& root, CaseSpec& spec) {
  const auto t = root.table("dynamic");
  const bool dynamic = spec.has_dynamic_step() || spec.is_explicit() || spec.has_explicit_step();
  if (!dynamic)
    for (const Table& v : root.tables("initial_velocity"))
      fail(v.where(), v.path(),
           "only applies to dynamic analyses (the velocity at the start of the first dynamic "
           "step; set [analysis] type = \"dynamic\" or \"dynamic-explicit\")");
  read_initial_velocities(root, spec);
  if (!spec.has_dynamic_step()) {
    if (!spec.is_explicit() && !spec.has_explicit_step())
      check_rigid_velocities(root);
    if (t)
      fail(t->where(), t->path(),
           "only applies to dynamic analyses (set [analysis] type = \"dynamic\", or analysis = "
           "\"dynamic\" in a [[step]])");
    return;
  }
  check_densities(root, spec);
  if (!t)
    return;
  t->allow({"rho_inf", "mass"});
  DynamicSpec& d = spec.dynamics;
  d.rho_inf = t->number("rho_inf", {.range = Range::closed(0.0, 1.0),
                                    .fallback = d.rho_inf,
                                    .hint = "1: no numerical dissipation; 0: the most"});
  static const Options<MassMatrixSpec> masses = {{"consistent", MassMatrixSpec::Consistent},
                                                 {"lumped", MassMatrixSpec::Lumped}};
  d.mass = t->choice("mass", masses, std::optional(d.mass), "mass matrix");
}

} // namespace trifem::io::detail
