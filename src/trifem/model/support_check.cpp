// SPDX-License-Identifier: MIT
#include "trifem/model/support_check.hpp"

#include "trifem/core/error.hpp"

#include <array>
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
  for (const mesh::Hex8& cell : mesh.cells())
    for (Index a : cell)
      parent[root(a)] = root(cell[0]);
  for (Index n = 0; n < mesh.num_nodes(); ++n)
    parent[n] = root(n);
  return parent;
}

/// A name for the body of component `c`: the cell block holding its first cell.
std::string body_name(const mesh::Mesh& mesh, const std::vector<Index>& component, Index c) {
  for (const auto& [name, cells] : mesh.cell_blocks())
    for (Index cell : cells)
      if (component[mesh.cell(cell)[0]] == c)
        return "'" + name + "'";
  return "of the mesh";
}

} // namespace

void check_support(const io::CaseSpec& spec, const Model& model) {
  const mesh::Mesh& mesh = model.mesh;
  const std::vector<Index> component = node_components(mesh);
  // held[c][k]: translation k of component c is held by something
  std::vector<std::array<bool, 3>> held(mesh.num_nodes(), {false, false, false});
  for (const auto& pair : spec.contacts)
    for (const std::string* name : {&pair.master, &pair.slave})
      for (Index n : mesh::surface_nodes(mesh.surface(*name)))
        held[component[n]] = {true, true, true};
  for (Index n = 0; n < mesh.num_nodes(); ++n)
    for (int k = 0; k < 3; ++k) {
      const Index d = model.dofs.dof(model.fields.u, n, k);
      if (model.dofs.is_constrained(d) || model.dofs.leader(d) != d ||
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
