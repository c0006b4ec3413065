// SPDX-License-Identifier: MIT
// Rigid bodies whose elements share nodes move as one (FEBio's FERigidSystem merges them): the
// merge of their elements, attached nodes, conditions and connectors.
#include "trifem/feb/reader.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <map>

namespace trifem::feb::detail {

std::string union_node_sets(Reader& r, const std::string& a, const std::string& b) {
  std::vector<Index> nodes = r.mesh.mesh.node_set(a);
  const std::vector<Index>& more = r.mesh.mesh.node_set(b);
  nodes.insert(nodes.end(), more.begin(), more.end());
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  std::string name = a + "_and_" + b;
  while (r.mesh.mesh.has_node_set(name))
    name += "_";
  r.mesh.mesh.add_node_set(name, std::move(nodes));
  return name;
}

namespace {

/// The nodes of a body's elements, ascending.
std::vector<Index> element_nodes(const Reader& r, const RigidBodyInput& body) {
  std::vector<Index> nodes;
  for (const std::string& block : body.blocks)
    for (Index c : r.mesh.mesh.cell_block(block))
      nodes.insert(nodes.end(), r.mesh.mesh.cell_nodes(c).begin(), r.mesh.mesh.cell_nodes(c).end());
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

/// Moves body `from` into body `into` (FEBio's merge of rigid bodies whose elements share
/// nodes): elements, attached nodes, conditions and connectors.
void merge_body(Reader& r, const std::string& into, const std::string& from) {
  RigidBodyInput& a = r.rigid_bodies.at(into);
  const RigidBodyInput& b = r.rigid_bodies.at(from);
  const auto density = [&](const RigidBodyInput& body) {
    const pugi::xml_node d = body.material.child("density");
    return d ? r.doc.number(d) : 1.0;
  };
  if (density(a) != density(b))
    r.doc.fail(b.material, fmt::format("the elements of rigid bodies '{}' and '{}' share nodes, so "
                                       "they move as one body (as in FEBio), but their densities "
                                       "differ ({} and {}): give them the same density",
                                       into, from, density(a), density(b)));
  a.blocks.insert(a.blocks.end(), b.blocks.begin(), b.blocks.end());
  if (!b.set.empty())
    a.set = a.set.empty() ? b.set : union_node_sets(r, a.set, b.set);
  for (int k = 0; k < 6; ++k) // the later condition of the two (FEBio's order)
    if (b.order[k] > a.order[k]) {
      if (a.order[k] > 0 && !(a.fixed[k] && b.fixed[k])) // (both fixing it: the same)
        r.warn(b.material, fmt::format("component {} of the merged body '{}' is {} by a rigid "
                                       "condition of '{}' that replaces an earlier one of '{}' "
                                       "(as in FEBio)",
                                       RigidBodyInput::kComponentNames[k], into,
                                       b.fixed[k] ? "fixed" : "driven", from, into));
      a.fixed[k] = b.fixed[k];
      a.drive(k) = b.drive(k);
      a.order[k] = b.order[k];
    }
  a.connected = a.connected || b.connected;
  if (a.velocity == Vec3::Zero() && a.angular_velocity == Vec3::Zero()) {
    a.velocity = b.velocity;
    a.angular_velocity = b.angular_velocity;
    a.initial = b.initial;
  }
  for (io::ConnectorSpec& c : r.connectors)
    for (std::string* name : {&c.body_a, &c.body_b})
      if (*name == from)
        *name = into;
  for (Reader::JointRotation& j : r.joint_rotations)
    for (std::string* name : {&j.body_a, &j.body_b})
      if (*name == from)
        *name = into;
  r.warn(b.material, fmt::format("the elements of rigid body '{}' share nodes with those of '{}': "
                                 "they move as one body, '{}' (as in FEBio)",
                                 from, into, into));
  r.rigid_bodies.erase(from);
}

} // namespace

void merge_touching_bodies(Reader& r) {
  const auto id = [&](const std::string& name) {
    return r.rigid_bodies.at(name).material.attribute("id").as_llong();
  };
  for (bool merged = true; merged;) {
    merged = false;
    std::map<Index, std::string> owner; // node -> body
    for (const auto& [name, body] : r.rigid_bodies) {
      for (Index n : element_nodes(r, body)) {
        const auto [it, fresh] = owner.emplace(n, name);
        if (fresh || it->second == name)
          continue;
        const bool keep_other = id(it->second) <= id(name);
        const std::string into = keep_other ? it->second : name;
        const std::string from = keep_other ? name : it->second;
        merge_body(r, into, from);
        merged = true;
        break;
      }
      if (merged)
        break;
    }
  }
}

} // namespace trifem::feb::detail
