// SPDX-License-Identifier: MIT
#include "trifem/model/support_check.hpp"

#include "trifem/core/error.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace trifem::model {
namespace {

/// Connected components of the mesh (cells sharing a node), as a component index per node.
std::vector<Index> node_components(const mesh::Mesh& mesh) {
  std::vector<Index> parent(mesh.num_nodes());
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](Index n) {
    while (parent[n] != n)
      n = parent[n] = parent[parent[n]];
    return n;
  };
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const std::span<const Index> cell = mesh.cell_nodes(c);
    for (Index a : cell)
      parent[root(a)] = root(cell[0]);
  }
  for (Index n = 0; n < mesh.num_nodes(); ++n)
    parent[n] = root(n);
  return parent;
}

/// A name for the body of component `c`: the cell block holding its first cell.
std::string body_name(const mesh::Mesh& mesh, const std::vector<Index>& component, Index c) {
  for (const auto& [name, cells] : mesh.cell_blocks())
    for (Index cell : cells)
      if (component[mesh.cell_nodes(cell)[0]] == c)
        return "'" + name + "'";
  return "of the mesh";
}

/// Per DOF: held when the analysis starts, by a condition of the case or of its first step.
std::vector<char> held_at_start(const Model& model) {
  std::vector<char> held(static_cast<std::size_t>(model.dofs.num_dofs()), 0);
  for (Index d = 0; d < model.dofs.num_dofs(); ++d)
    held[static_cast<std::size_t>(d)] = model.dofs.is_constrained(d) ? 1 : 0;
  if (!model.steps.empty())
    for (const auto& c : model.steps.front().conditions)
      for (Index d : c.dofs)
        held[static_cast<std::size_t>(d)] = 1;
  return held;
}

/// Throws if a rotating rigid body has an unknown that nothing holds: no prescribed value, and
/// no deformable cell, contact surface or connector on the body.
void check_rigid_bodies(const io::CaseSpec& spec, const Model& model,
                        const std::vector<char>& in_contact, const std::vector<char>& held) {
  if (model.rigid_bodies.empty() || !model.problem)
    return;
  const mesh::Mesh& mesh = model.mesh;
  std::vector<char> deformable(mesh.num_nodes(), 0);
  for (Index c = 0; c < mesh.num_cells(); ++c)
    if (!model.materials[c].rigid())
      for (Index n : mesh.cell_nodes(c))
        deformable[n] = 1;
  const Index u_offset = model.dofs.field(model.fields.u).offset;
  for (std::size_t i = 0; i < model.rigid_bodies.size(); ++i) {
    const RigidBody& body = model.rigid_bodies[i];
    if (body.rotating < 0)
      continue;
    const io::RigidBodySpec& b = spec.rigid_bodies[i];
    const dofs::RigidBodyDofs& r = model.problem->rigid_map().bodies()[body.rotating];
    bool touched = std::any_of(spec.connectors.begin(), spec.connectors.end(), [&](const auto& c) {
      return c.body_a == b.name || c.body_b == b.name;
    });
    for (const auto& follower : r.followers) {
      const Index n = (follower[0] - u_offset) / 3;
      touched = touched || deformable[n] || in_contact[n];
    }
    if (touched)
      continue;
    for (int k = 0; k < 6; ++k) {
      const Index d = k < 3 ? r.translation[k] : r.rotation[k - 3];
      const std::string key = fmt::format("{}{}", k < 3 ? "" : "r", "xyz"[k % 3]);
      TRIFEM_CHECK(held[static_cast<std::size_t>(d)],
                   "{}: the rigid body '{}' is not supported in {}: no prescribed value, and no "
                   "deformable cell, contact pair or [[connector]] on it, so a quasi-static "
                   "analysis cannot determine its motion (singular stiffness). Prescribe it "
                   "({} = {{ {} = 0.0 }}) or join the body to another with a [[connector]]",
                   b.key, b.name, key, key, k < 3 ? "displacement" : "rotation");
    }
  }
}

} // namespace

void check_support(const io::CaseSpec& spec, const Model& model) {
  const mesh::Mesh& mesh = model.mesh;
  const std::vector<Index> component = node_components(mesh);
  // held[c][k]: translation k of component c is held by something
  std::vector<std::array<bool, 3>> held(mesh.num_nodes(), {false, false, false});
  std::vector<char> in_contact(mesh.num_nodes(), 0);
  for (const auto& pair : spec.contacts)
    for (const std::string* name : {&pair.master, &pair.slave})
      for (Index n : mesh::surface_nodes(mesh.surface(*name))) {
        held[component[n]] = {true, true, true};
        in_contact[n] = 1;
      }
  for (const io::ConstraintSpec& c : spec.constraints) { // held along some direction
    if (c.kind == io::ConstraintKind::Linear)
      for (const io::LinearConstraintEntry& e : c.entries)
        held[component[e.node]][e.component] = true;
    else
      for (Index n : mesh::surface_nodes(mesh.surface(c.surface)))
        for (int k = 0; k < 3; ++k)
          held[component[n]][k] = held[component[n]][k] || std::abs(c.normal[k]) > 0.0 ||
                                  c.kind != io::ConstraintKind::RigidWall;
  }
  const std::vector<char> held_dofs = held_at_start(model);
  check_rigid_bodies(spec, model, in_contact, held_dofs);
  for (Index n = 0; n < mesh.num_nodes(); ++n)
    for (int k = 0; k < 3; ++k) {
      const Index d = model.dofs.dof(model.fields.u, n, k);
      if (held_dofs[static_cast<std::size_t>(d)] || model.dofs.leader(d) != d ||
          model.dofs.is_dependent(d)) // fixed, or a rigid body
        held[component[n]][k] = true;
    }
  for (Index n = 0; n < mesh.num_nodes(); ++n) {
    if (component[n] != n)
      continue;
    for (int k = 0; k < 3; ++k)
      TRIFEM_CHECK(held[n][k],
                   "the body {} is not supported in {}: no fixed or prescribed displacement, "
                   "contact pair or rigid body holds its {} translation, so a quasi-static "
                   "analysis cannot determine it (singular stiffness). Fix the {} displacement "
                   "of some of its nodes (e.g. [[boundary.fixed]] on a face or symmetry plane)",
                   body_name(mesh, component, n), "xyz"[k], "xyz"[k], "xyz"[k]);
  }
}

} // namespace trifem::model
