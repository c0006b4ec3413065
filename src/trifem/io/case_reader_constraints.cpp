// SPDX-License-Identifier: MIT
// Case reader, part 6: [[constraint]] (symmetry planes, normal displacement, linear constraints
// between node components, rigid walls), which the model imposes exactly in every step.
#include "trifem/io/toml_table.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace trifem::io::detail {
namespace {

using CK = ConstraintKind;

const Options<ConstraintKind>& constraint_kinds() {
  static const Options<ConstraintKind> kinds = {{"symmetry-plane", CK::SymmetryPlane},
                                                {"normal-displacement", CK::NormalDisplacement},
                                                {"linear", CK::Linear},
                                                {"rigid-wall", CK::RigidWall}};
  return kinds;
}

/// The `type` string of `kind`.
std::string_view constraint_type_name(ConstraintKind kind) {
  for (const auto& [name, k] : constraint_kinds())
    if (k == kind)
      return name;
  return "";
}

/// A key of [[constraint]] besides type and name: the kinds that have it, and what messages say
/// when another kind gives it ("only <owners>").
struct ConstraintKey {
  std::string_view key;
  std::vector<ConstraintKind> kinds;
  std::string_view owners;
};

const std::vector<ConstraintKey>& constraint_keys() {
  static const std::vector<ConstraintKey> keys = {
      {"surface",
       {CK::SymmetryPlane, CK::NormalDisplacement, CK::RigidWall},
       "symmetry-plane, normal-displacement and rigid-wall constraints act on a surface"},
      {"terms", {CK::Linear}, "a linear constraint has terms"},
      {"value", {CK::Linear}, "a linear constraint has a value (a rigid wall moves by its offset)"},
      {"curve", {CK::Linear, CK::RigidWall}, "linear and rigid-wall constraints have a curve"},
      {"point", {CK::RigidWall}, "a rigid-wall has a point"},
      {"normal", {CK::RigidWall}, "a rigid-wall has a normal"},
      {"offset", {CK::RigidWall}, "a rigid-wall has an offset"}};
  return keys;
}

bool has_key(const ConstraintKey& k, ConstraintKind kind) {
  return std::find(k.kinds.begin(), k.kinds.end(), kind) != k.kinds.end();
}

/// Rejects the keys of other kinds (naming the kind) and unknown keys.
void check_constraint_keys(const Table& t, ConstraintKind kind) {
  const auto foreign = [&](std::string_view key) -> const ConstraintKey* {
    for (const ConstraintKey& k : constraint_keys())
      if (k.key == key && !has_key(k, kind))
        return &k;
    return nullptr;
  };
  const auto [key, node] = t.first_key([&](std::string_view k) { return foreign(k) != nullptr; });
  if (node)
    fail(node, t.path(key),
         fmt::format("only {}; this constraint is of type '{}'", foreign(key)->owners,
                     constraint_type_name(kind)));
  std::vector<std::string_view> allowed = {"type", "name"};
  for (const ConstraintKey& k : constraint_keys())
    if (has_key(k, kind))
      allowed.push_back(k.key);
  t.allow(allowed);
}

/// One element of `terms`: { node, component, coefficient }.
LinearConstraintEntry read_term(const Table& term) {
  term.allow({"node", "component", "coefficient"});
  if (!term.find("node"))
    term.missing("node", "an integer >= 0, a mesh node index");
  LinearConstraintEntry e;
  e.node = term.integer("node", 0, 0);
  e.component =
      term.choice("component", component_options(), std::optional<Component>(), "component");
  e.coefficient = term.number("coefficient", {});
  if (e.coefficient == 0.0)
    fail(term.find("coefficient"), fmt::format("{} = 0", term.path("coefficient")),
         "expected a non-zero coefficient (leave the term out)");
  return e;
}

/// `terms`: at least one, no (node, component) twice.
std::vector<LinearConstraintEntry> read_terms(const Table& t) {
  constexpr std::string_view form = "an array of { node = <index>, component = \"x\" | "
                                    "\"y\" | \"z\", coefficient = <number> } tables";
  const toml::node* given = t.find("terms");
  if (!given)
    t.missing("terms", form);
  array_of(*given, t.path("terms"), form);
  const std::vector<Table> terms = t.tables("terms");
  if (terms.empty())
    fail(t.find("terms"), t.path("terms"), "expected at least one term, got an empty array");
  std::vector<LinearConstraintEntry> entries;
  for (std::size_t i = 0; i < terms.size(); ++i) {
    const LinearConstraintEntry e = read_term(terms[i]);
    for (std::size_t j = 0; j < entries.size(); ++j)
      if (entries[j].node == e.node && entries[j].component == e.component)
        fail(terms[i].where(), terms[i].path(),
             fmt::format("node {} component '{}' is already in {} (give each component once, "
                         "with the sum of its coefficients)",
                         e.node, kAxis[e.component], terms[j].path()));
    entries.push_back(e);
  }
  return entries;
}

/// `v` / |v|, or `v` itself if its length is 1 to rounding (a written normal reads back bitwise).
Vec3 unit_vector(const Vec3& v) {
  const Real length = v.stableNorm();
  if (std::abs(length - 1.0) <= 4.0 * std::numeric_limits<Real>::epsilon())
    return v;
  return v / length;
}

/// point, normal (normalised), offset and curve of a rigid wall.
void read_rigid_wall(const Table& t, const CaseSpec& spec, ConstraintSpec& c) {
  c.point = t.vec3("point", {.unit = "mm"}, Vec3(Vec3::Zero()));
  const Vec3 normal = t.vec3("normal", {}, std::nullopt);
  if (normal.stableNorm() == 0.0)
    fail(t.find("normal"), t.path("normal"),
         "expected a direction (the side of the plane the surface keeps to), not the zero vector");
  c.normal = unit_vector(normal);
  c.value = t.number("offset", {.fallback = 0.0, .unit = "mm"});
  c.curve = read_curve_reference(t, spec);
}

/// The unique `name` of the constraint `t` (default "constraint_<i>").
std::string read_constraint_name(const Table& t, const CaseSpec& spec) {
  const std::string name = t.find("name")
                               ? read_identifier(t, "name", false)
                               : fmt::format("constraint_{}", spec.constraints.size() + 1);
  for (const ConstraintSpec& other : spec.constraints)
    if (other.name == name)
      fail(t.find("name") ? t.find("name") : t.where(),
           fmt::format("{} = '{}'", t.path("name"), name),
           fmt::format("duplicate constraint name (already used by {})", other.key));
  return name;
}

} // namespace

void read_constraints(const Table& root, CaseSpec& spec) {
  for (const Table& t : root.tables("constraint")) {
    ConstraintSpec c;
    c.key = t.path();
    c.kind =
        t.choice("type", constraint_kinds(), std::optional<ConstraintKind>(), "constraint type");
    check_constraint_keys(t, c.kind);
    c.name = read_constraint_name(t, spec);
    if (c.kind != CK::Linear)
      c.surface = t.name("surface");
    if (c.kind == CK::RigidWall)
      read_rigid_wall(t, spec, c);
    if (c.kind == CK::Linear) {
      c.entries = read_terms(t);
      c.value = t.number("value", {.fallback = 0.0, .unit = "mm"});
      c.curve = read_curve_reference(t, spec);
    }
    spec.constraints.push_back(std::move(c));
  }
}

} // namespace trifem::io::detail
