// SPDX-License-Identifier: MIT
#include "trifem/model/constraints.hpp"

#include "trifem/contact/rigid_wall_term.hpp"
#include "trifem/core/log.hpp"
#include "trifem/fe/reference_element.hpp"
#include "trifem/model/conditions.hpp"
#include "trifem/physics/linear_constraint_term.hpp"

#include <cmath>
#include <map>
#include <set>

namespace trifem::model {
namespace {

using io::ConstraintKind;

/// A facet normal of a flat symmetry plane may differ from the plane's by this much [rad].
constexpr Real kFlatness = 1e-3;
/// A unit normal is a coordinate axis when one component is at least 1 − this.
constexpr Real kAxis = 1e-10;
/// A direction repeats those held at a node when its part outside their span is shorter.
constexpr Real kRepeated = 1e-6;

/// The unit outward normal of a flat surface; InputError if a facet deviates from it.
Vec3 plane_normal(const mesh::Mesh& mesh, const mesh::Surface& surface) {
  Vec3 sum = Vec3::Zero();
  for (const mesh::Facet& f : surface.facets)
    sum += mesh::facet_area_vector(mesh, f);
  TRIFEM_CHECK(sum.norm() > 0.0, "the surface has no area");
  const Vec3 n = sum.normalized();
  for (const mesh::Facet& f : surface.facets) {
    const Vec3 nf = mesh::facet_area_vector(mesh, f).normalized();
    TRIFEM_CHECK(nf.cross(n).norm() <= kFlatness && nf.dot(n) > 0.0,
                 "a symmetry plane must be flat: the facet of nodes {}, {}, {}{} has the normal "
                 "({:.6g}, {:.6g}, {:.6g}), the surface's mean normal is ({:.6g}, {:.6g}, {:.6g}) "
                 "(use type = \"normal-displacement\" on a curved surface)",
                 f.nodes[0], f.nodes[1], f.nodes[2],
                 f.num_corners() == 4 ? fmt::format(", {}", f.nodes[3]) : std::string(), nf.x(),
                 nf.y(), nf.z(), n.x(), n.y(), n.z());
  }
  return n;
}

/// The unit normal at the reference point s of facet f (its own map: curved if quadratic).
Vec3 facet_normal_at(const mesh::Mesh& mesh, const mesh::Facet& f, const Vec2& s) {
  const fe::FacetShapeGrads G = fe::reference_facet(f.type).shape_grad(s);
  Vec3 t1 = Vec3::Zero(), t2 = Vec3::Zero();
  for (int a = 0; a < f.num_nodes(); ++a) {
    t1 += mesh.node(f.node(a)) * G(a, 0);
    t2 += mesh.node(f.node(a)) * G(a, 1);
  }
  return t1.cross(t2).normalized();
}

/// The area-weighted unit normal N_a of each node of a surface (reference configuration): the
/// facets' corner area vectors summed at their corners, and at a mid-edge node the facet's own
/// normal there times the area.
std::map<Index, Vec3> nodal_normals(const mesh::Mesh& mesh, const mesh::Surface& surface) {
  std::map<Index, Vec3> normals;
  for (const mesh::Facet& f : surface.facets) {
    const Vec3 a = mesh::facet_area_vector(mesh, f);
    std::set<Index> nodes(f.nodes.begin(), f.nodes.begin() + f.num_corners());
    for (Index n : nodes) {
      auto [it, added] = normals.try_emplace(n, Vec3::Zero());
      it->second += a;
    }
    const fe::ReferenceFacet& ref = fe::reference_facet(f.type);
    for (int m = f.num_corners(); m < f.num_nodes(); ++m) {
      auto [it, added] = normals.try_emplace(f.node(m), Vec3::Zero());
      it->second += a.norm() * facet_normal_at(mesh, f, ref.nodes().row(m).transpose());
    }
  }
  for (auto& [node, n] : normals) {
    TRIFEM_CHECK(n.norm() > 0.0,
                 "the facets at node {} cancel (a fold or a closed edge): it has no normal", node);
    n.normalize();
  }
  return normals;
}

/// The coordinate axis a unit vector lies along, or −1.
int axis_of(const Vec3& n) {
  for (int k = 0; k < 3; ++k)
    if (std::abs(n[k]) >= 1.0 - kAxis)
      return k;
  return -1;
}

/// The nodes of every rigid body of the case (set and cells).
std::set<Index> rigid_nodes(const io::CaseSpec& spec, const mesh::Mesh& mesh) {
  std::set<Index> nodes;
  for (const io::RigidBodySpec& b : spec.rigid_bodies) {
    if (!b.set.empty() && mesh.has_node_set(b.set))
      nodes.insert(mesh.node_set(b.set).begin(), mesh.node_set(b.set).end());
    for (const std::string& block : b.blocks)
      if (mesh.has_cell_block(block))
        for (Index c : mesh.cell_block(block))
          nodes.insert(mesh.cell_nodes(c).begin(), mesh.cell_nodes(c).end());
  }
  return nodes;
}

/// Orthonormal directions of the displacement already held at each node (fixed components,
/// earlier equations): an equation whose direction lies in their span repeats them.
class HeldDirections {
public:
  HeldDirections(const Model& model, const std::vector<dofs::DirichletCondition>& conditions) {
    std::set<Index> fixed;
    for (const dofs::DirichletCondition& c : conditions)
      fixed.insert(c.dofs.begin(), c.dofs.end());
    const dofs::FieldInfo& u = model.dofs.field(model.fields.u);
    for (Index d : fixed)
      if (d >= u.offset && d < u.offset + 3 * u.num_entities)
        add((d - u.offset) / 3, Vec3::Unit((d - u.offset) % 3));
  }
  /// Adds direction n at `node`; false (nothing added) if it repeats those held there.
  bool add(Index node, const Vec3& n) {
    std::vector<Vec3>& basis = held_[node];
    Vec3 r = n.normalized();
    for (const Vec3& b : basis)
      r -= r.dot(b) * b;
    if (r.norm() < kRepeated)
      return false;
    basis.push_back(r.normalized());
    return true;
  }
  /// Whether every direction is held at `node`.
  bool full(Index node) const {
    const auto it = held_.find(node);
    return it != held_.end() && it->second.size() == 3;
  }

private:
  std::map<Index, std::vector<Vec3>> held_;
};

/// Collects the equations of the constraints before their multipliers are numbered.
struct Equations {
  std::vector<physics::LinearConstraint> equations; ///< multiplier: set once the field exists
  dofs::DirichletCondition fixed;                   ///< components fixed by axis normals
  Index repeated = 0;                               ///< equations dropped as repeated
};

/// n·u_a = 0 at `node`: a fixed component along an axis, an equation otherwise.
void add_normal_equation(const Model& model, Index node, const Vec3& n, HeldDirections& held,
                         Equations& out) {
  if (!held.add(node, n)) {
    ++out.repeated;
    return;
  }
  if (const int k = axis_of(n); k >= 0) {
    out.fixed.dofs.push_back(model.dofs.dof(model.fields.u, node, k));
    return;
  }
  physics::LinearConstraint c;
  for (int k = 0; k < 3; ++k)
    if (n[k] != 0.0)
      c.coefficients.emplace_back(model.dofs.dof(model.fields.u, node, k), n[k]);
  out.equations.push_back(std::move(c));
}

void check_not_rigid(const std::set<Index>& rigid, Index node) {
  TRIFEM_CHECK(!rigid.contains(node),
               "node {} belongs to a rigid body: constrain the body's motion instead", node);
}

void surface_equations(const io::ConstraintSpec& c, const Model& model,
                       const std::set<Index>& rigid, HeldDirections& held, Equations& out) {
  const mesh::Surface& surface = model.mesh.surface(c.surface);
  if (c.kind == ConstraintKind::SymmetryPlane) {
    const Vec3 n = plane_normal(model.mesh, surface);
    for (Index node : mesh::surface_nodes(surface)) {
      check_not_rigid(rigid, node);
      add_normal_equation(model, node, n, held, out);
    }
    return;
  }
  for (const auto& [node, n] : nodal_normals(model.mesh, surface)) {
    check_not_rigid(rigid, node);
    add_normal_equation(model, node, n, held, out);
  }
}

void linear_equation(const io::CaseSpec& spec, const io::ConstraintSpec& c, const Model& model,
                     const std::set<Index>& rigid, const std::set<Index>& fixed, Equations& out) {
  physics::LinearConstraint e;
  bool free = false;
  for (std::size_t i = 0; i < c.entries.size(); ++i) {
    const io::LinearConstraintEntry& t = c.entries[i];
    TRIFEM_CHECK(t.node >= 0 && t.node < model.mesh.num_nodes(),
                 "terms[{}].node = {}: the mesh has nodes 0 to {}", i + 1, t.node,
                 model.mesh.num_nodes() - 1);
    check_not_rigid(rigid, t.node);
    const Index dof = model.dofs.dof(model.fields.u, t.node, t.component);
    free = free || !fixed.contains(dof);
    e.coefficients.emplace_back(dof, t.coefficient);
  }
  TRIFEM_CHECK(free, "every displacement component it names is fixed or prescribed by a "
                     "boundary condition, so its force is undetermined: remove it");
  e.value = c.value;
  e.curve = make_curve(spec, c.curve);
  out.equations.push_back(std::move(e));
}

/// The nodes of a wall's surface that can move along its normal (not all of the components
/// the normal has are fixed).
std::vector<Index> wall_nodes(const Model& model, const mesh::Surface& surface, const Vec3& n,
                              const std::set<Index>& fixed) {
  std::vector<Index> nodes;
  for (Index node : mesh::surface_nodes(surface)) {
    bool moves = false;
    for (int k = 0; k < 3; ++k)
      moves = moves || (n[k] != 0.0 && !fixed.contains(model.dofs.dof(model.fields.u, node, k)));
    if (moves)
      nodes.push_back(node);
  }
  return nodes;
}

std::unique_ptr<physics::Term> rigid_wall(const io::CaseSpec& spec, const io::ConstraintSpec& c,
                                          Model& model, const std::set<Index>& fixed) {
  const mesh::Surface& surface = model.mesh.surface(c.surface);
  std::vector<Index> nodes = wall_nodes(model, surface, c.normal, fixed);
  const auto all = static_cast<Index>(mesh::surface_nodes(surface).size());
  TRIFEM_CHECK(!nodes.empty(),
               "every node of the surface '{}' is fixed along the wall's normal: nothing can "
               "touch the wall",
               c.surface);
  if (static_cast<Index>(nodes.size()) < all)
    log::info("  {}: {} of the {} nodes of '{}' are fixed along the wall's normal and left out",
              c.key, all - static_cast<Index>(nodes.size()), all, c.surface);
  const Real h = mesh::mean_facet_size(model.mesh, surface);
  contact::RigidWallSettings s;
  s.point = c.point;
  s.normal = c.normal.normalized();
  s.offset = c.value;
  s.curve = make_curve(spec, c.curve);
  s.scale = model.modulus_scale * h;
  s.gap_tolerance = 1e-6 * h;
  s.release_threshold = 1e-8 * s.scale * h;
  const dofs::FieldId field =
      model.dofs.add_field(fmt::format("wall_forces_{}", model.walls.size() + 1),
                           FieldRole::multiplier, static_cast<Index>(nodes.size()), 1);
  auto term = std::make_unique<contact::RigidWallTerm>(model.mesh, model.dofs, model.fields.u,
                                                       field, std::move(nodes), s);
  model.walls.push_back({c.name, term.get(), field});
  return term;
}

} // namespace

std::vector<std::unique_ptr<physics::Term>>
constraint_terms(const io::CaseSpec& spec, Model& model,
                 std::vector<dofs::DirichletCondition>& conditions) {
  std::vector<std::unique_ptr<physics::Term>> terms;
  if (spec.constraints.empty())
    return terms;
  const std::set<Index> rigid = rigid_nodes(spec, model.mesh);
  std::set<Index> fixed;
  for (const dofs::DirichletCondition& c : conditions)
    fixed.insert(c.dofs.begin(), c.dofs.end());
  HeldDirections held(model, conditions);
  Equations eq;
  for (const io::ConstraintSpec& c : spec.constraints)
    with_context(c.key, [&] {
      TRIFEM_CHECK(c.kind == ConstraintKind::Linear || model.mesh.has_surface(c.surface),
                   "surface = '{}': the mesh has no such surface", c.surface);
      switch (c.kind) {
      case ConstraintKind::SymmetryPlane:
      case ConstraintKind::NormalDisplacement:
        surface_equations(c, model, rigid, held, eq);
        break;
      case ConstraintKind::Linear:
        linear_equation(spec, c, model, rigid, fixed, eq);
        break;
      case ConstraintKind::RigidWall:
        terms.push_back(rigid_wall(spec, c, model, fixed));
        break;
      }
      return 0;
    });
  if (eq.repeated > 0)
    log::info("  constraints: {} nodal equation(s) repeat directions already held (fixed "
              "components or other constraints) and are left out",
              eq.repeated);
  if (!eq.fixed.dofs.empty())
    conditions.push_back(std::move(eq.fixed));
  if (eq.equations.empty())
    return terms;
  model.constraint_forces = model.dofs.add_field("constraint_forces", FieldRole::multiplier,
                                                 static_cast<Index>(eq.equations.size()), 1);
  for (std::size_t i = 0; i < eq.equations.size(); ++i)
    eq.equations[i].multiplier = model.dofs.dof(model.constraint_forces, static_cast<Index>(i), 0);
  terms.push_back(std::make_unique<physics::LinearConstraintTerm>(std::move(eq.equations)));
  return terms;
}

} // namespace trifem::model
