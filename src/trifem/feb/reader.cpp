// SPDX-License-Identifier: MIT
#include "trifem/feb/reader.hpp"

#include "trifem/core/log.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace trifem::feb::detail {
namespace {

/// "a, b, c" of the names of a map (at most 12, then "...").
template <class Map>
std::string names_of(const Map& map) {
  std::string s;
  int n = 0;
  for (const auto& entry : map) {
    if (++n > 12)
      return s + ", ...";
    s += fmt::format("{}{}", s.empty() ? "" : ", ", entry.first);
  }
  return s.empty() ? "none" : s;
}

} // namespace

void Reader::warn(pugi::xml_node node, const std::string& what) {
  spec.warnings.push_back(fmt::format("{}: {}", doc.where(node), what));
}

std::string Reader::curve_of(pugi::xml_node node) const {
  const pugi::xml_attribute lc = node.attribute("lc");
  if (!lc)
    return "";
  const auto it = curve_by_id.find(lc.value());
  if (it == curve_by_id.end())
    doc.fail(node, "lc",
             fmt::format("load controller {} is not defined (defined: {})", lc.value(),
                         names_of(curve_by_id)));
  return it->second;
}

bool Reader::always_zero(Real value, const std::string& curve) const {
  if (value == 0.0 || curve.empty())
    return value == 0.0;
  const auto& points = spec.curves.at(curve).points;
  return std::all_of(points.begin(), points.end(), [](const auto& p) { return p.second == 0.0; });
}

int Electrochemistry::charge(const Document& doc, pugi::xml_node node,
                             const std::string& ref) const {
  const auto it = charge_of.find(ref);
  if (it == charge_of.end())
    doc.fail(node, fmt::format("solute '{}' is not defined in <Globals>/<Solutes> (defined: {})",
                               ref, names_of(charge_of)));
  return it->second;
}

std::vector<Index> block_nodes(const mesh::Mesh& mesh, const std::string& block) {
  std::vector<Index> nodes;
  for (Index c : mesh.cell_block(block))
    nodes.insert(nodes.end(), mesh.cell_nodes(c).begin(), mesh.cell_nodes(c).end());
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

std::string Reader::node_set(pugi::xml_node node, const char* attribute) const {
  std::string name = doc.attribute(node, attribute);
  constexpr std::string_view kSurface = "@surface:";
  if (name.starts_with(kSurface)) {
    name.erase(0, kSurface.size());
    if (!mesh.mesh.has_surface(name))
      doc.fail(node, attribute,
               fmt::format("surface '{}' is not defined (defined: {})", name,
                           names_of(mesh.mesh.surfaces())));
    return name; // the mesh registers a surface's nodes as a node set of the same name
  }
  constexpr std::string_view kElementSet = "@elem_set:";
  if (name.starts_with(kElementSet)) {
    name.erase(0, kElementSet.size());
    if (!mesh.mesh.has_cell_block(name))
      doc.fail(node, attribute,
               fmt::format("element set '{}' is not defined (defined: {})", name,
                           names_of(mesh.mesh.cell_blocks())));
    if (!mesh.mesh.has_node_set(name) || mesh.mesh.node_set(name) != block_nodes(mesh.mesh, name))
      doc.fail(node, attribute,
               fmt::format("a node set named '{}' that is not the nodes of the element set of "
                           "that name hides them: rename one of the two",
                           name));
    return name; // read_mesh registers an element set's nodes as a node set of the same name
  }
  if (name.starts_with("@"))
    doc.fail(node, attribute,
             fmt::format("'{}': only node sets, @surface: and @elem_set: references are supported",
                         name));
  if (!mesh.mesh.has_node_set(name)) {
    std::map<std::string, int> defined; // the file's node sets, not those of its element sets
    for (const auto& [set, nodes] : mesh.mesh.node_sets())
      if (!mesh.mesh.has_cell_block(set))
        defined.emplace(set, 0);
    doc.fail(node, attribute,
             fmt::format("node set '{}' is not defined (defined: {})", name, names_of(defined)));
  }
  return name;
}

std::string Reader::surface(pugi::xml_node node, const char* attribute) const {
  const std::string name = doc.attribute(node, attribute);
  if (!mesh.mesh.has_surface(name))
    doc.fail(node, attribute,
             fmt::format("surface '{}' is not defined (defined: {})", name,
                         names_of(mesh.mesh.surfaces())));
  return name;
}

std::vector<Index> Reader::nodes_of(pugi::xml_node node, const std::vector<long>& ids) const {
  std::vector<Index> nodes;
  nodes.reserve(ids.size());
  for (long id : ids) {
    const auto it = node_index.find(id);
    if (it == node_index.end())
      doc.fail(node, fmt::format("node id {} is not defined", id));
    nodes.push_back(it->second);
  }
  return nodes;
}

std::vector<pugi::xml_node> elements(pugi::xml_node node) {
  std::vector<pugi::xml_node> children;
  for (pugi::xml_node c : node.children())
    if (is_element(c))
      children.push_back(c);
  return children;
}

} // namespace trifem::feb::detail
