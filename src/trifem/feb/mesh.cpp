// SPDX-License-Identifier: MIT
// Mesh and MeshDomains sections: nodes, solid parts (hex8, tet4, tet10, penta6, hex20), node
// sets, surfaces, element sets.
#include "trifem/core/error.hpp"
#include "trifem/feb/reader.hpp"
#include "trifem/mesh/cell_checks.hpp"
#include "trifem/mesh/conformity.hpp"

#include <algorithm>
#include <cstdio>
#include <fmt/format.h>
#include <optional>
#include <span>

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

/// The solid element types FEBio writes that trifem reads, as cell types.
std::optional<mesh::CellType> solid_type(std::string_view type) {
  for (const mesh::CellType t : {mesh::CellType::Hex8, mesh::CellType::Tet4, mesh::CellType::Tet10,
                                 mesh::CellType::Penta6, mesh::CellType::Hex20})
    if (mesh::name(t) == type)
      return t;
  return std::nullopt;
}

/// For each node of trifem's order (mesh/cell_type.hpp), the position in FEBio's node list.
/// FEBio's tet10 numbers the mid-edge nodes of the edges (1,3) and (2,3) the other way round;
/// its hex20 lists the mid-edge nodes bottom ring, top ring, then the vertical edges
/// (FESolidElementShape's functions); its tet4, penta6 and hex8 are trifem's.
std::span<const int> febio_order(mesh::CellType type) {
  static constexpr std::array<int, 10> tet10 = {0, 1, 2, 3, 4, 5, 6, 7, 9, 8};
  static constexpr std::array<int, 20> hex20 = {0,  1, 2,  3,  4,  5,  6,  7,  8,  11,
                                                16, 9, 17, 10, 18, 19, 12, 15, 13, 14};
  static constexpr std::array<int, 8> identity = {0, 1, 2, 3, 4, 5, 6, 7};
  if (type == mesh::CellType::Tet10)
    return tet10;
  if (type == mesh::CellType::Hex20)
    return hex20;
  return std::span<const int>(identity).first(static_cast<std::size_t>(mesh::num_nodes(type)));
}

/// The cell of one <elem> of a solid part of `type`, its nodes in trifem's order.
Index read_cell(Reader& r, pugi::xml_node e, mesh::CellType type) {
  const std::vector<long> ids = r.doc.ids(e);
  const auto count = static_cast<std::size_t>(mesh::num_nodes(type));
  if (ids.size() != count)
    r.doc.fail(e, fmt::format("a {} has {} nodes, got {}", mesh::name(type), count, ids.size()));
  const std::vector<Index> given = r.nodes_of(e, ids);
  std::vector<Index> nodes(count);
  const std::span<const int> order = febio_order(type);
  for (std::size_t a = 0; a < count; ++a)
    nodes[a] = given[static_cast<std::size_t>(order[a])];
  if (type == mesh::CellType::Hex8) {
    mesh::Hex8 hex;
    std::copy(nodes.begin(), nodes.end(), hex.begin());
    if (corner_volume(r.mesh.mesh, hex) <= 0.0)
      r.doc.fail(e, "the element is inverted (negative volume): its node order is not FEBio's "
                    "hex8 order");
  } else if (const std::string problem = mesh::cell_shape_problem(r.mesh.mesh, type, nodes);
             !problem.empty()) {
    r.doc.fail(e, fmt::format("the {} element {}", mesh::name(type), problem));
  }
  return r.mesh.mesh.add_cell(type, nodes);
}

void read_elements(Reader& r, pugi::xml_node part) {
  const std::string type = r.doc.attribute(part, "type");
  const std::optional<mesh::CellType> cell_type = solid_type(type);
  if (!cell_type && type != "quad4" && type != "tri3")
    r.doc.fail(part,
               fmt::format("element type '{}' is not supported (trifem has hex8, tet4, tet10, "
                           "penta6 and hex20 solids, and quad4 and tri3 shells as rigid "
                           "bodies)",
                           type));
  const std::string name = r.doc.attribute(part, "name");
  if (r.parts.contains(name) || r.shell_parts.contains(name))
    r.doc.fail(part, "name", fmt::format("a second <Elements> part named '{}'", name));
  if (!cell_type)
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
    const Index c = read_cell(r, e, *cell_type);
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

/// The facet types of <Surface> elements.
std::optional<mesh::FacetType> facet_type(std::string_view type) {
  for (const mesh::FacetType t : {mesh::FacetType::Tri3, mesh::FacetType::Tri6,
                                  mesh::FacetType::Quad4, mesh::FacetType::Quad8})
    if (mesh::name(t) == type)
      return t;
  return std::nullopt;
}

/// The corners of a surface element of `type` as a quad (a triangle's fourth repeats its third);
/// its mid-edge nodes, if any, in `mid_edge_nodes`.
std::array<Index, 4> facet_corners(const Reader& r, pugi::xml_node f, mesh::FacetType type,
                                   std::vector<Index>& mid_edge_nodes) {
  const std::vector<long> ids = r.doc.ids(f);
  const auto count = static_cast<std::size_t>(mesh::num_nodes(type));
  if (ids.size() != count)
    r.doc.fail(f, fmt::format("a {} has {} nodes, got {}", mesh::name(type), count, ids.size()));
  const std::vector<Index> nodes = r.nodes_of(f, ids);
  const auto corners = static_cast<std::size_t>(mesh::num_corners(type));
  std::array<Index, 4> quad{};
  for (std::size_t a = 0; a < 4; ++a)
    quad[a] = nodes[std::min(a, corners - 1)];
  mid_edge_nodes.assign(nodes.begin() + static_cast<std::ptrdiff_t>(corners), nodes.end());
  return quad;
}

/// Fails at `f` unless the cell face `found` is of the given type with the given mid-edge nodes.
void check_face(const Reader& r, pugi::xml_node f, mesh::FacetType type,
                const std::vector<Index>& mid_edge_nodes, const mesh::Facet& found) {
  if (found.type != type)
    r.doc.fail(f, fmt::format("this {} is the face of a {} element, whose faces are {} facets",
                              mesh::name(type), mesh::name(r.mesh.mesh.cell_type(found.cell)),
                              mesh::name(found.type)));
  std::vector<Index> given = mid_edge_nodes,
                     face(found.mid_edge_nodes.begin(),
                          found.mid_edge_nodes.begin() + (found.num_nodes() - found.num_corners()));
  std::sort(given.begin(), given.end());
  std::sort(face.begin(), face.end());
  if (given != face)
    r.doc.fail(f, "its mid-edge nodes are not those of the element face with its corners");
}

void read_surface(Reader& r, pugi::xml_node surface) {
  const std::string name = r.doc.attribute(surface, "name");
  std::vector<std::array<Index, 4>> quads;
  std::vector<pugi::xml_node> elements;
  std::vector<mesh::FacetType> types;
  std::vector<std::vector<Index>> mids;
  for (pugi::xml_node f : detail::elements(surface)) {
    const std::optional<mesh::FacetType> type = facet_type(f.name());
    if (!type)
      r.doc.fail(f, fmt::format("surface facet type '{}' is not supported (trifem has the tri3, "
                                "tri6, quad4 and quad8 faces of its cells, and quad4 and tri3 "
                                "facets of rigid shells)",
                                f.name()));
    mids.emplace_back();
    quads.push_back(facet_corners(r, f, *type, mids.back()));
    types.push_back(*type);
    elements.push_back(f);
  }
  if (quads.empty())
    r.doc.fail(surface, "the surface has no facets");
  mesh::Surface s;
  if (on_shells(r, quads)) { // a surface of a rigid shell: its quads as given
    for (std::size_t i = 0; i < quads.size(); ++i) {
      if (types[i] != mesh::FacetType::Quad4 && types[i] != mesh::FacetType::Tri3)
        r.doc.fail(elements[i], "the facets of rigid shells are quad4 or tri3");
      s.facets.push_back({.nodes = quads[i], .cell = -1, .local_face = -1});
    }
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
        r.doc.fail(elements[i],
                   fmt::format("this {} is not a face of any solid element", mesh::name(types[i])));
      }
    throw;
  }
  for (std::size_t i = 0; i < quads.size(); ++i)
    check_face(r, elements[i], types[i], mids[i], s.facets[i]);
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
      r.doc.fail(d, fmt::format("<{}> is not supported (trifem has solid domains and the shell "
                                "domains of rigid bodies)",
                                d.name()));
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

/// Fails at the first of two elements that meet with hanging nodes, naming both by their ids.
void check_conforming(const Reader& r, pugi::xml_node mesh) {
  const std::optional<mesh::HangingNodes> hanging = mesh::find_hanging_nodes(r.mesh.mesh);
  if (!hanging)
    return;
  std::map<Index, long> id_of;
  for (const auto& [id, c] : r.cell_index)
    id_of[c] = id;
  const long id = id_of[hanging->cell];
  pugi::xml_node at = mesh;
  for (const auto& [name, part] : r.parts)
    for (pugi::xml_node e : elements(part))
      if (e.attribute("id").as_llong(-1) == id)
        at = e;
  r.doc.fail(at, fmt::format("elements {} ({}) and {} ({}) {}; trifem needs a conforming mesh, "
                             "in which elements that touch share whole faces with the same nodes",
                             id, mesh::name(r.mesh.mesh.cell_type(hanging->cell)),
                             id_of[hanging->other],
                             mesh::name(r.mesh.mesh.cell_type(hanging->other)), hanging->how));
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
  check_conforming(r, mesh);
  mesh::CellSource source{r.doc.name(), "element", 0,
                          std::vector<long long>(r.mesh.mesh.num_cells())};
  for (const auto& [id, c] : r.cell_index)
    source.tags[static_cast<std::size_t>(c)] = id;
  r.mesh.mesh.add_cell_source(std::move(source));
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

std::string local_fibre_view(long n1, long n2) {
  return fmt::format("febio local fibre {},{}", n1, n2);
}

void add_local_fibre_views(Reader& r) {
  mesh::Mesh& mesh = r.mesh.mesh;
  for (const auto& [name, m] : r.spec.materials) {
    if (!m.axes || m.axes->kind != material::AxesKind::Mesh ||
        mesh.cell_data().contains(m.axes->view))
      continue;
    long n1 = 0, n2 = 0;
    if (std::sscanf(m.axes->view.c_str(), "febio local fibre %ld,%ld", &n1, &n2) != 2)
      continue;
    mesh::CellData data;
    data.components = 3;
    for (Index c = 0; c < mesh.num_cells(); ++c) {
      const mesh::CellType type = mesh.cell_type(c);
      const std::span<const int> order = febio_order(type); // trifem node a is FEBio's order[a]
      const auto at = [&](long febio) -> Vec3 {
        for (std::size_t a = 0; a < order.size(); ++a)
          if (order[a] == febio - 1)
            return mesh.node(mesh.cell_nodes(c)[a]);
        throw InputError(fmt::format("material '{}': its local fibre names element node {}, and "
                                     "a {} element has {} nodes",
                                     name, febio, mesh::name(type), order.size()));
      };
      const Vec3 a = (at(n2) - at(n1)).normalized();
      data.values.insert(data.values.end(), {a.x(), a.y(), a.z()});
    }
    mesh.add_cell_data(m.axes->view, std::move(data));
  }
}

} // namespace trifem::feb::detail
