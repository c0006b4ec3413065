// SPDX-License-Identifier: MIT
// <Constraints> (rigid walls, symmetry planes, fixed normal displacements, linear constraint
// sets) and the boundary condition "linear constraint" as [[constraint]]s (docs/feb.md). FEBio
// enforces them with penalties or augmented Lagrangians; trifem's are exact (multipliers, an
// active set for the wall), so the enforcement parameters are read and left aside.
#include "trifem/feb/reader.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <fmt/format.h>

#include <map>
#include <set>

namespace trifem::feb::detail {
namespace {

using CK = io::ConstraintKind;

/// FEBio's constraint types that map to a [[constraint]].
const std::map<std::string, CK, std::less<>>& constraint_types() {
  static const std::map<std::string, CK, std::less<>> types = {
      {"rigid_wall", CK::RigidWall},
      {"symmetry plane", CK::SymmetryPlane},
      {"fixed normal displacement", CK::NormalDisplacement},
      {"linear constraint", CK::Linear}};
  return types;
}

constexpr std::string_view kSupportedConstraints =
    "rigid_wall, symmetry plane, fixed normal displacement, linear constraint";

/// The parameters of a constraint type: how FEBio enforces it (no meaning with exact
/// multipliers: read and left aside) and the ones that describe the constraint.
struct ConstraintParameters {
  std::set<std::string, std::less<>> enforcement;
  std::set<std::string, std::less<>> values;
};

const ConstraintParameters& parameters_of(CK kind) {
  static const ConstraintParameters wall = {{"laugon", "tolerance", "penalty"},
                                            {"offset", "plane"}};
  static const ConstraintParameters plane = {{"laugon", "tol", "penalty", "minaug", "maxaug"},
                                             {"rhs"}};
  static const ConstraintParameters normal = {{"laugon", "tol", "penalty", "minaug", "maxaug"},
                                              {"rhs", "shell_bottom"}};
  static const ConstraintParameters linear = {{"laugon", "tol", "penalty", "minaug", "maxaug"},
                                              {"rhs", "linear_constraint"}};
  switch (kind) {
  case CK::RigidWall:
    return wall;
  case CK::SymmetryPlane:
    return plane;
  case CK::NormalDisplacement:
    return normal;
  case CK::Linear:
    return linear;
  }
  return linear;
}

/// Refuses a child of `node` that its type does not know.
void check_constraint_parameters(const Reader& r, pugi::xml_node node, CK kind,
                                 std::string_view type) {
  const ConstraintParameters& known = parameters_of(kind);
  for (pugi::xml_node p : elements(node)) {
    const std::string_view name = p.name();
    if (known.enforcement.contains(name) || known.values.contains(name))
      continue;
    std::string expected;
    for (const auto* list : {&known.values, &known.enforcement})
      for (const std::string& k : *list)
        expected += (expected.empty() ? "" : ", ") + k;
    r.doc.fail(p,
               fmt::format("unknown parameter '{}' of a {} (expected {})", name, type, expected));
  }
}

/// A name trifem accepts (letters, digits and _), made unique among the constraints: an empty
/// name becomes constraint_<n>, a taken one gets _<n> (n: the constraint's number).
std::string constraint_name(const Reader& r, std::string name) {
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)))
      c = '_';
  const std::size_t n = r.spec.constraints.size() + 1;
  if (name.empty())
    name = fmt::format("constraint_{}", n);
  const auto taken = [&](const std::string& s) {
    for (const io::ConstraintSpec& other : r.spec.constraints)
      if (other.name == s)
        return true;
    return false;
  };
  while (taken(name))
    name += fmt::format("_{}", n);
  return name;
}

/// A new constraint of `kind` read from `node` (its key names the element and its line).
io::ConstraintSpec new_constraint(const Reader& r, pugi::xml_node node, CK kind,
                                  const std::string& name) {
  io::ConstraintSpec c;
  c.key = fmt::format("{} (line {})", r.doc.path(node), r.doc.line(node));
  c.name = constraint_name(r, name);
  c.kind = kind;
  return c;
}

/// Refuses a parameter whose value (times its curve) is not zero at every time.
void require_zero(const Reader& r, pugi::xml_node p, std::string_view why) {
  if (p && !r.always_zero(r.doc.number(p), r.curve_of(p)))
    r.doc.fail(p, fmt::format("{} = {} is not supported: {} (it must be 0)", p.name(),
                              r.doc.text(p), why));
}

/// Refuses a load curve on `p` (a coefficient that would change in time).
void refuse_curve(const Reader& r, pugi::xml_node p) {
  if (p.attribute("lc"))
    r.doc.fail(p, "lc", "a coefficient that changes in time is not supported");
}

/// x, y or z of a displacement dof.
io::Component displacement_dof(const Reader& r, pugi::xml_node at, const std::string& dof,
                               const char* attribute = nullptr) {
  if (dof == "x" || dof == "y" || dof == "z")
    return dof[0] - 'x';
  const std::string what = fmt::format("dof '{}' is not supported (trifem's linear constraints "
                                       "act on the displacement: x, y or z)",
                                       dof);
  if (attribute)
    r.doc.fail(at, attribute, what);
  r.doc.fail(at, what);
}

/// Adds coefficient x (component k of the node of FEBio id `id`) to `c`; a zero coefficient adds
/// nothing, a node component given twice is refused.
void add_entry(const Reader& r, pugi::xml_node at, io::ConstraintSpec& c, long id, io::Component k,
               Real coefficient) {
  const Index node = r.nodes_of(at, {id}).front();
  for (const io::LinearConstraintEntry& e : c.entries)
    if (e.node == node && e.component == k)
      r.doc.fail(
          at, fmt::format("node {} dof {} appears twice in the linear constraint", id, "xyz"[k]));
  if (coefficient != 0.0)
    c.entries.push_back({node, k, coefficient});
}

/// The integer of the attribute `name` of `node`.
long integer_attribute(const Reader& r, pugi::xml_node node, const char* name) {
  const std::string text = r.doc.attribute(node, name);
  long v = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (error != std::errc() || end != text.data() + text.size())
    r.doc.fail(node, name, fmt::format("expected an integer node id, got '{}'", text));
  return v;
}

/// A rigid wall: the plane a x + b y + c z = d of <plane>, moved along its unit normal by
/// <offset> (with its load controller).
void read_rigid_wall(Reader& r, pugi::xml_node node, io::ConstraintSpec& c) {
  const pugi::xml_node plane = r.doc.child(node, "plane");
  if (plane.attribute("lc"))
    r.doc.fail(plane, "lc",
               "a load curve on the plane is not supported (move the wall with <offset lc=...>)");
  const std::vector<Real> abcd = r.doc.numbers(plane, 4);
  const Vec3 abc(abcd[0], abcd[1], abcd[2]);
  const Real length = abc.stableNorm();
  if (length == 0.0)
    r.doc.fail(plane, "expected a,b,c,d of the plane a x + b y + c z = d with (a, b, c) not zero");
  c.normal = abc / length;
  c.point = c.normal * (abcd[3] / length);
  if (const pugi::xml_node offset = node.child("offset")) {
    c.value = r.doc.number(offset);
    c.curve = r.curve_of(offset);
    // FEBio projects onto the plane as if (a, b, c) were a unit vector
    if (std::abs(length - 1.0) > 1e-9 && !r.always_zero(c.value, c.curve))
      r.warn(offset, fmt::format("the plane's (a, b, c) has length {}: trifem moves the wall by "
                                 "the offset along the unit normal, FEBio by offset / {} (give a "
                                 "unit (a, b, c) for the same result)",
                                 length, length * length));
  }
}

/// One <linear_constraint> of a linear constraint set: <node id="..." bc="x">coefficient</node>
/// entries, equal to the set's rhs.
io::ConstraintSpec read_linear_equation(const Reader& r, pugi::xml_node node,
                                        const std::string& name, pugi::xml_node rhs) {
  io::ConstraintSpec c = new_constraint(r, node, CK::Linear, name);
  for (pugi::xml_node n : elements(node)) {
    if (std::string_view(n.name()) != "node")
      r.doc.fail(n, fmt::format("<{}> is not supported in <linear_constraint> (expected <node "
                                "id=\"...\" bc=\"x\">coefficient</node>)",
                                n.name()));
    refuse_curve(r, n);
    const long id = integer_attribute(r, n, "id");
    add_entry(r, n, c, id, displacement_dof(r, n, r.doc.attribute(n, "bc"), "bc"), r.doc.number(n));
  }
  if (c.entries.empty())
    r.doc.fail(node, "the linear constraint has no node with a non-zero coefficient");
  if (rhs) {
    c.value = r.doc.number(rhs);
    c.curve = r.curve_of(rhs);
  }
  return c;
}

/// A linear constraint set: one [[constraint]] per <linear_constraint>.
void read_linear_constraint_set(Reader& r, pugi::xml_node node, const std::string& name) {
  const pugi::xml_node rhs = node.child("rhs");
  bool any = false;
  for (pugi::xml_node lc : node.children("linear_constraint")) {
    r.spec.constraints.push_back(read_linear_equation(r, lc, name, rhs));
    any = true;
  }
  if (!any)
    r.doc.fail(node, "a linear constraint needs at least one <linear_constraint>");
}

/// A <child_dof> (node, dof, value; FEBio's default value 1) of the linear constraint bc `c`:
/// FEBio's u_parent = sum_i value_i u_child_i + offset is u_parent - sum_i value_i u_child_i =
/// offset, so the child's coefficient is -value.
void add_child_dof(const Reader& r, pugi::xml_node child, io::ConstraintSpec& c) {
  const pugi::xml_node node = r.doc.child(child, "node");
  const pugi::xml_node dof = r.doc.child(child, "dof");
  const pugi::xml_node value = child.child("value");
  for (pugi::xml_node e : elements(child))
    if (std::string_view n = e.name(); n != "node" && n != "dof" && n != "value")
      r.doc.fail(
          e, fmt::format("unknown parameter '{}' of a child_dof (expected node, dof, value)", n));
  if (value)
    refuse_curve(r, value);
  add_entry(r, node, c, r.doc.integer(node), displacement_dof(r, dof, r.doc.text(dof)),
            value ? -r.doc.number(value) : -1.0);
}

} // namespace

void read_constraints(Reader& r, pugi::xml_node section) {
  for (pugi::xml_node node : elements(section)) {
    if (std::string_view(node.name()) != "constraint")
      r.doc.fail(node, fmt::format("<{}> is not supported in <Constraints> (expected <constraint>)",
                                   node.name()));
    const std::string type = r.doc.attribute(node, "type");
    const auto kind = constraint_types().find(type);
    if (kind == constraint_types().end())
      r.doc.fail(node, "type",
                 fmt::format("constraint type '{}' is not supported (supported: {})", type,
                             kSupportedConstraints));
    check_constraint_parameters(r, node, kind->second, type);
    const std::string name = node.attribute("name").value();
    if (kind->second == CK::Linear) {
      read_linear_constraint_set(r, node, name);
      continue;
    }
    io::ConstraintSpec c = new_constraint(r, node, kind->second, name);
    c.surface = r.surface(node);
    if (c.kind == CK::RigidWall)
      read_rigid_wall(r, node, c);
    else
      require_zero(r, node.child("rhs"),
                   "trifem holds the normal displacement of the surface's nodes at zero");
    require_zero(r, node.child("shell_bottom"), "trifem has no shells");
    r.spec.constraints.push_back(std::move(c));
  }
}

void read_linear_constraint_bc(Reader& r, pugi::xml_node bc, bool step) {
  if (step)
    r.doc.fail(bc, "a linear constraint inside a <step> is not supported (give it in the "
                   "top-level <Boundary>: trifem's constraints act in every step)");
  io::ConstraintSpec c = new_constraint(r, bc, CK::Linear, bc.attribute("name").value());
  const pugi::xml_node parent = r.doc.child(bc, "node");
  const pugi::xml_node parent_dof = r.doc.child(bc, "dof");
  add_entry(r, parent, c, r.doc.integer(parent),
            displacement_dof(r, parent_dof, r.doc.text(parent_dof)), 1.0);
  for (pugi::xml_node p : elements(bc)) {
    const std::string_view name = p.name();
    if (name == "offset") {
      c.value = r.doc.number(p);
      c.curve = r.curve_of(p);
    } else if (name == "child_dof") {
      add_child_dof(r, p, c);
    } else if (name != "node" && name != "dof") {
      r.doc.fail(p, fmt::format("unknown parameter '{}' of a linear constraint (expected dof, "
                                "node, offset, child_dof)",
                                name));
    }
  }
  r.spec.constraints.push_back(std::move(c));
}

} // namespace trifem::feb::detail
