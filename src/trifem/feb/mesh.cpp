// SPDX-License-Identifier: MIT
// Mesh and MeshDomains sections: nodes, hex8 parts, node sets, surfaces, element sets.
#include "trifem/core/error.hpp"
#include "trifem/feb/reader.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace trifem::feb::detail {
namespace {

void read_nodes(Reader& r, pugi::xml_node section) {
  for (pugi::xml_node n : elements(section)) {
    if (std::string_view(n.name()) != "node")
      r.doc.fail(n, "expected <node> elements");
    const long id = n.attribute("id").as_llong(-1);
    if (id < 0)
      r.doc.fail(n, "id", "expected a non-negative integer node id");
    if (r.node_index.contains(id))
      r.doc.fail(n, "id", fmt::format("node id {} is defined twice", id));
    r.node_index[id] = r.mesh.mesh.add_node(r.doc.vector(n));
  }
}

/// Signed volume of a hex8 (sum over its 8 corner tetrahedra; positive for FEBio's order).
Real corner_volume(const mesh::Mesh& mesh, const mesh::Hex8& h) {
  const auto x = [&](int i) { return mesh.node(h[i]); };
  const Vec3 d = x(6) - x(0);
  return d.dot((x(1) - x(0)).cross(x(3) - x(0))) + d.dot((x(4) - x(0)).cross(x(1) - x(0))) +
         d.dot((x(3) - x(0)).cross(x(4) - x(0)));
}

/// The facet of a quad4 or tri3 (a quad whose last node repeats the third) that bounds no cell.
mesh::Facet free_facet(const Reader& r, pugi::xml_node e, std::string_view type) {
  const std::vector<long> ids = r.doc.ids(e);
  const std::size_t count = type == "tri3" ? 3 : 4;
  if (ids.size() != count)
    r.doc.fail(e, fmt::format("a {} has {} nodes, got {}", type, count, ids.size()));
  const std::vector<Index> nodes = r.nodes_of(e, ids);
  mesh::Facet f;
  for (std::size_t a = 0; a < 4; ++a)
    f.nodes[a] = nodes[std::min(a, count - 1)];
  return f;
}

/// A quad4 or tri3 part: a surface of the same name whose facets bound no cell (node order: the
/// normal), which a <ShellDomain> of a rigid body may carry (read_domains).
void read_shell_part(Reader& r, pugi::xml_node part, const std::string& name,
                     std::string_view type) {
  mesh::Surface surface;
  for (pugi::xml_node e : elements(part)) {
    if (std::string_view(e.name()) != "elem")
      r.doc.fail(e, "expected <elem> elements");
    surface.facets.push_back(free_facet(r, e, type));
  }
  if (surface.facets.empty())
    r.doc.fail(part, "the part has no elements");
  with_mesh_errors(r, part, [&] { r.mesh.mesh.add_surface(name, std::move(surface)); });
  r.shell_parts[name] = part;
}

void read_elements(Reader& r, pugi::xml_node part) {
  const std::string type = r.doc.attribute(part, "type");
  if (type != "hex8" && type != "quad4" && type != "tri3")
    r.doc.fail(part, fmt::format("element type '{}' is not supported (trifem has hex8 solids, "
                                 "and quad4 and tri3 shells as rigid bodies)",
                                 type));
  const std::string name = r.doc.attribute(part, "name");
  if (r.parts.contains(name) || r.shell_parts.contains(name))
    r.doc.fail(part, "name", fmt::format("a second <Elements> part named '{}'", name));
  if (type == "quad4" || type == "tri3")
    return read_shell_part(r, part, name, type);
  r.parts[name] = part;
  std::vector<Index> cells;
  for (pugi::xml_node e : elements(part)) {
    if (std::string_view(e.name()) != "elem")
      r.doc.fail(e, "expected <elem> elements");
    const long id = e.attribute("id").as_llong(-1);
    if (id < 0)
      r.doc.fail(e, "id", "expected a non-negative integer element id");
    if (r.cell_index.contains(id))
      r.doc.fail(e, "id", fmt::format("element id {} is defined twice", id));
    const std::vector<long> ids = r.doc.ids(e);
    if (ids.size() != 8)
      r.doc.fail(e, fmt::format("a hex8 has 8 nodes, got {}", ids.size()));
    const std::vector<Index> nodes = r.nodes_of(e, ids);
    mesh::Hex8 hex;
    std::copy(nodes.begin(), nodes.end(), hex.begin());
    if (corner_volume(r.mesh.mesh, hex) <= 0.0)
      r.doc.fail(e, "the element is inverted (negative volume): its node order is not FEBio's "
                    "hex8 order");
    const Index c = r.mesh.mesh.add_cell(hex);
    r.cell_index[id] = c;
    cells.push_back(c);
  }
  with_mesh_errors(r, part, [&] { r.mesh.mesh.add_cell_block(name, cells); });
  if (auto mat = part.attribute("mat")) { // format 3.0: the material id of the part
    const auto it = r.material_by_id.find(mat.value());
    if (it == r.material_by_id.end())
      r.doc.fail(part, "mat", fmt::format("no material has id '{}'", mat.value()));
    r.mesh.materials[name] = it->second;
  }
}

/// Node ids of a NodeSet: the text (4.0) or <n id=..>/<node id=..> children (3.0).
std::vector<long> set_ids(const Reader& r, pugi::xml_node set) {
  std::vector<long> ids;
  bool children = false;
  for (pugi::xml_node n : elements(set)) {
    children = true;
    if (!n.attribute("id"))
      r.doc.fail(n, "expected an id attribute");
    ids.push_back(n.attribute("id").as_llong());
  }
  return children ? ids : r.doc.ids(set);
}

void read_node_set(Reader& r, pugi::xml_node set) {
  const std::string name = r.doc.attribute(set, "name");
  const std::vector<Index> nodes = r.nodes_of(set, set_ids(r, set));
  with_mesh_errors(r, set, [&] { r.mesh.mesh.add_node_set(name, nodes); });
}

/// Whether every node of `quads` belongs to a quad4 (shell) part.
bool on_shells(const Reader& r, const std::vector<std::array<Index, 4>>& quads) {
  if (r.shell_parts.empty())
    return false;
  std::vector<char> shell(r.mesh.mesh.num_nodes(), 0);
  for (const auto& [name, part] : r.shell_parts)
    for (Index n : r.mesh.mesh.node_set(name))
      shell[n] = 1;
  return std::all_of(quads.begin(), quads.end(), [&](const auto& q) {
    return std::all_of(q.begin(), q.end(), [&](Index n) { return shell[n] != 0; });
  });
}

void read_surface(Reader& r, pugi::xml_node surface) {
  const std::string name = r.doc.attribute(surface, "name");
  std::vector<std::array<Index, 4>> quads;
  std::vector<pugi::xml_node> elements;
  for (pugi::xml_node f : detail::elements(surface)) {
    const std::string_view type = f.name();
    if (type != "quad4" && type != "tri3")
      r.doc.fail(f, fmt::format("surface facet type '{}' is not supported (trifem has quad4 faces "
                                "of hex8 cells, and quad4 and tri3 facets of rigid shells)",
                                type));
    quads.push_back(free_facet(r, f, type).nodes);
    elements.push_back(f);
  }
  if (quads.empty())
    r.doc.fail(surface, "the surface has no facets");
  mesh::Surface s;
  const bool triangles =
      std::any_of(quads.begin(), quads.end(), [](const auto& q) { return q[3] == q[2]; });
  if (triangles && !on_shells(r, quads))
    r.doc.fail(surface, "tri3 facets are supported on rigid shells only (trifem has hex8 cells)");
  if (on_shells(r, quads)) { // a surface of a rigid shell: its quads as given
    for (const auto& q : quads)
      s.facets.push_back({.nodes = q, .cell = -1, .local_face = -1});
    with_mesh_errors(r, surface, [&] { r.mesh.mesh.add_surface(name, std::move(s)); });
    return;
  }
  try {
    s.facets = r.mesh.mesh.find_facets(quads);
  } catch (const InputError&) {
    for (std::size_t i = 0; i < quads.size(); ++i)
      try {
        r.mesh.mesh.find_facets({quads[i]});
      } catch (const InputError&) {
        r.doc.fail(elements[i], "this quad4 is not a face of any hex8 element");
      }
    throw;
  }
  with_mesh_errors(r, surface, [&] { r.mesh.mesh.add_surface(name, std::move(s)); });
}

void read_element_set(Reader& r, pugi::xml_node set) {
  const std::string name = r.doc.attribute(set, "name");
  std::vector<Index> cells;
  for (long id : set_ids(r, set)) {
    const auto it = r.cell_index.find(id);
    if (it == r.cell_index.end())
      r.doc.fail(set, fmt::format("element id {} is not defined", id));
    cells.push_back(it->second);
  }
  if (r.mesh.mesh.has_cell_block(name)) { // FEBio Studio repeats a part as an element set
    std::vector<Index> part = r.mesh.mesh.cell_block(name), sorted = cells;
    std::sort(part.begin(), part.end());
    std::sort(sorted.begin(), sorted.end());
    if (part != sorted)
      r.doc.fail(set, "name",
                 fmt::format("the element set '{}' differs from the part of that name", name));
    return;
  }
  with_mesh_errors(r, set, [&] { r.mesh.mesh.add_cell_block(name, cells); });
}

/// A <ShellDomain>: the quad4 part of a rigid body, which then moves the part's nodes (a surface
/// mesh without a volume, e.g. a bone surface); the shell's thickness does not matter.
void read_rigid_shell_domain(Reader& r, pugi::xml_node d) {
  const std::string name = r.doc.attribute(d, "name");
  const std::string mat = r.doc.attribute(d, "mat");
  if (!r.shell_parts.contains(name))
    r.doc.fail(d, "name", fmt::format("no quad4 <Elements> part is named '{}'", name));
  const auto body = r.rigid_bodies.find(mat);
  if (body == r.rigid_bodies.end())
    r.doc.fail(d, "mat",
               fmt::format("shells are supported as rigid bodies only ('{}' is not a rigid body "
                           "material)",
                           mat));
  if (body->second.shell || !body->second.blocks.empty())
    r.doc.fail(d, "a rigid body made of several parts is not supported: give it one part");
  body->second.set = name; // the surface's node set
  body->second.shell = true;
  body->second.attachment = d;
}

void read_domains(Reader& r, pugi::xml_node domains) {
  for (pugi::xml_node d : elements(domains)) {
    if (std::string_view(d.name()) == "ShellDomain") {
      read_rigid_shell_domain(r, d);
      continue;
    }
    if (std::string_view(d.name()) != "SolidDomain")
      r.doc.fail(
          d, fmt::format("<{}> is not supported (trifem has solid hex8 domains only)", d.name()));
    const std::string name = r.doc.attribute(d, "name");
    const std::string mat = r.doc.attribute(d, "mat");
    if (!r.parts.contains(name))
      r.doc.fail(d, "name", fmt::format("no <Elements> part is named '{}'", name));
    if (const auto body = r.rigid_bodies.find(mat); body != r.rigid_bodies.end()) {
      body->second.blocks.push_back(name); // the part moves with the rigid body
      continue;
    }
    if (!r.spec.materials.contains(mat))
      r.doc.fail(d, "mat", fmt::format("no material is named '{}'", mat));
    r.mesh.materials[name] = mat;
  }
}

} // namespace

void read_mesh(Reader& r, pugi::xml_node mesh, pugi::xml_node domains) {
  for (pugi::xml_node n : mesh.children("Nodes"))
    read_nodes(r, n);
  if (r.node_index.empty())
    r.doc.fail(mesh, "the mesh has no <Nodes>");
  for (pugi::xml_node n : mesh.children("Elements"))
    read_elements(r, n);
  if (r.parts.empty() && r.shell_parts.empty())
    r.doc.fail(mesh, "the mesh has no <Elements>");
  for (pugi::xml_node n : elements(mesh)) {
    const std::string_view kind = n.name();
    if (kind == "NodeSet")
      read_node_set(r, n);
    else if (kind == "Surface")
      read_surface(r, n);
    else if (kind == "ElementSet")
      read_element_set(r, n);
    else if (kind == "Edge")
      r.warn(n, fmt::format("<{}> is not used by the supported features (ignored)", kind));
    else if (kind != "Nodes" && kind != "Elements" && kind != "SurfacePair") // pairs: Contact
      r.doc.fail(n, fmt::format("<{}> is not supported", kind));
  }
  if (domains)
    read_domains(r, domains);
  const auto rigid = [&](const std::string& part) {
    for (const auto& [body, input] : r.rigid_bodies)
      if (std::find(input.blocks.begin(), input.blocks.end(), part) != input.blocks.end())
        return true;
    return false;
  };
  for (const auto& [name, part] : r.parts)
    if (!r.mesh.materials.contains(name) && !rigid(name))
      r.doc.fail(part,
                 fmt::format("the part '{}' has no material (no <SolidDomain> names it)", name));
  for (const auto& [name, part] : r.shell_parts)
    if (std::none_of(r.rigid_bodies.begin(), r.rigid_bodies.end(), [&](const auto& body) {
          return body.second.shell && body.second.set == name;
        }))
      r.doc.fail(part, fmt::format("the quad4 part '{}' is no rigid body's (no <ShellDomain> of a "
                                   "rigid body material names it)",
                                   name));
  for (const auto& [name, cells] : r.mesh.mesh.cell_blocks()) // for @elem_set: references
    if (!r.mesh.mesh.has_node_set(name))
      r.mesh.mesh.add_node_set(name, block_nodes(r.mesh.mesh, name));
  r.drained.assign(r.mesh.mesh.num_nodes(), 0);
}

} // namespace trifem::feb::detail
