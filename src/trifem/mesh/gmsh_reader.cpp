// SPDX-License-Identifier: MIT
// Gmsh MSH reader: line-based manual parsing of the ASCII 4.1 and 2.2 formats.
#include "trifem/mesh/gmsh_reader.hpp"

#include "trifem/core/error.hpp"
#include "trifem/mesh/cell_checks.hpp"
#include "trifem/mesh/conformity.hpp"
#include "trifem/mesh/gmsh_element_types.hpp"
#include "trifem/mesh/gmsh_line_reader.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

namespace trifem::mesh {
namespace {

using detail::LineReader;

/// Gmsh node and element tags (size_t in Gmsh; signed here to detect bad input).
using Tag = std::int64_t;
/// (dimension, tag) of a physical group or of a geometric entity.
using DimTag = std::pair<int, int>;

/// A Gmsh element type: number, name and dimension.
struct ElementType {
  int type;
  const char* name;
  int dim;
};

constexpr ElementType kElementTypes[] = {
    {1, "line2", 1},         {2, "triangle3", 2},     {3, "quad4", 2},      {4, "tetra4", 3},
    {5, "hexahedron8", 3},   {6, "prism6", 3},        {7, "pyramid5", 3},   {8, "line3", 1},
    {9, "triangle6", 2},     {10, "quad9", 2},        {11, "tetra10", 3},   {12, "hexahedron27", 3},
    {13, "prism18", 3},      {14, "pyramid14", 3},    {15, "point", 0},     {16, "quad8", 2},
    {17, "hexahedron20", 3}, {18, "prism15", 3},      {19, "pyramid13", 3}, {20, "triangle9", 2},
    {21, "triangle10", 2},   {26, "line4", 1},        {27, "line5", 1},     {28, "line6", 1},
    {29, "tetra20", 3},      {92, "hexahedron64", 3},
};

const ElementType* find_element_type(int type) {
  for (const ElementType& t : kElementTypes)
    if (t.type == type)
      return &t;
  return nullptr;
}

/// Maps Gmsh node tags to dense indices: a vector for tags up to about twice the number of nodes
/// stored so far, a hash map for larger ones. The vector grows with the nodes actually read, not
/// with the count a file declares, so a wrong count or a huge tag cannot exhaust the memory.
class NodeMap {
public:
  /// Clears the map.
  void reset() {
    dense_.clear();
    sparse_.clear();
    size_ = 0;
  }

  /// Stores tag -> index; false if the tag is already present. Requires tag > 0.
  bool insert(Tag tag, Index index) {
    if (find(tag) >= 0)
      return false;
    ++size_;
    const Tag limit = 2 * size_ + 1024;
    if (tag >= limit)
      return sparse_.emplace(tag, index).second;
    if (tag >= std::ssize(dense_))
      dense_.resize(
          static_cast<std::size_t>(std::min(limit, std::max(tag + 1, 2 * std::ssize(dense_)))), -1);
    dense_[static_cast<std::size_t>(tag)] = index;
    return true;
  }

  /// Index of a tag, -1 if absent.
  Index find(Tag tag) const {
    if (tag >= 0 && tag < std::ssize(dense_) && dense_[static_cast<std::size_t>(tag)] >= 0)
      return dense_[static_cast<std::size_t>(tag)];
    const auto it = sparse_.find(tag);
    return it == sparse_.end() ? -1 : it->second;
  }

private:
  Tag size_ = 0; ///< tags stored
  std::vector<Index> dense_;
  std::unordered_map<Tag, Index> sparse_;
};

/// Name of a physical group and the line that named it.
struct GroupName {
  std::string name;
  long line = 0;
};

/// A surface element of a physical surface, kept until all cells are known: its corners (a
/// triangle's fourth repeats its third) and the mid-edge nodes of a quadratic one.
struct PendingQuad {
  std::array<Index, 4> nodes{};
  Tag element = 0;
  long line = 0;
  int physical = 0;
  std::vector<Index> mid_edge_nodes = {};

  bool triangle() const { return nodes[3] == nodes[2]; }
};

/// One element line: its tag, type, the dimension of its entity (-1 if unknown) and its
/// physical groups.
struct ElementHeader {
  Tag tag = 0;
  int type = 0;
  int entity_dim = -1;
  std::span<const int> physicals;
};

/// The $ElementData sections of one view name, kept until all elements are known.
struct PendingView {
  int components = 0;
  long line = 0;             ///< the line of its (first) view name
  std::vector<Tag> elements; ///< element tags in file order
  std::vector<long> lines;   ///< the line of each element's values
  std::vector<Real> values;  ///< `components` values per element
};

/// Everything gathered from the sections.
struct GmshData {
  int major_version = 0;
  bool seen_nodes = false;
  bool seen_elements = false;
  long elements_line = 0;
  std::map<DimTag, GroupName> names;                   ///< (dim, physical tag) -> name
  std::map<DimTag, std::vector<int>> entity_physicals; ///< (dim, entity tag) -> physical tags
  std::map<DimTag, long> first_use; ///< (dim, physical tag) -> first element line
  NodeMap node_map;
  Mesh mesh;
  std::map<int, std::vector<Index>> volume_cells; ///< physical volume tag -> cells
  std::vector<Index> unassigned_cells;
  std::vector<PendingQuad> quads;
  std::map<DimTag, std::vector<Index>> point_sets; ///< physical points/curves -> nodes
  std::unordered_map<Tag, Index> element_cells;    ///< element tag -> cell (-1: not a hex)
  std::map<std::string, PendingView> views;        ///< $ElementData by view name
};

Tag read_count(LineReader& in, std::string_view what) {
  const Tag n = in.number<Tag>(what);
  TRIFEM_CHECK(n >= 0 && n <= std::numeric_limits<Index>::max(), "{}: invalid {} {}", in.location(),
               what, n);
  return n;
}

void expect_section_end(LineReader& in) {
  in.require_line();
  const std::string_view text = in.rest();
  TRIFEM_CHECK(text.starts_with("$End") && text.substr(4) == in.section(),
               "{}: expected $End{}, found '{}' (section ${} holds more entries than declared)",
               in.location(), in.section(), text, in.section());
}

void skip_section(LineReader& in) {
  const std::string end = "$End" + in.section();
  do
    in.require_line();
  while (in.rest() != end);
}

void read_mesh_format(LineReader& in, GmshData& d) {
  TRIFEM_CHECK(in.next_line(), "{}: empty file", in.location());
  const std::string_view header = in.rest();
  TRIFEM_CHECK(header == "$MeshFormat", "{}: not a Gmsh MSH file: expected $MeshFormat, found '{}'",
               in.location(), header);
  in.require_line();
  const std::string version(in.field());
  const int file_type = in.number<int>("file type");
  in.number<int>("data size");
  if (version == "4.1")
    d.major_version = 4;
  else if (version == "2.2" || version == "2.1" || version == "2.0" || version == "2")
    d.major_version = 2;
  TRIFEM_CHECK(d.major_version != 0,
               "{}: unsupported MSH format version '{}' (supported: 4.1 and 2.2 ASCII)",
               in.location(), version);
  TRIFEM_CHECK(file_type == 0,
               "{}: binary MSH files are not supported (file type {}); save the mesh as ASCII",
               in.location(), file_type);
  expect_section_end(in);
}

void read_physical_names(LineReader& in, GmshData& d) {
  in.require_line();
  const Tag count = read_count(in, "number of physical names");
  for (Tag i = 0; i < count; ++i) {
    in.require_line();
    const int dim = in.number<int>("physical group dimension");
    const int tag = in.number<int>("physical tag");
    TRIFEM_CHECK(dim >= 0 && dim <= 3, "{}: invalid physical group dimension {}", in.location(),
                 dim);
    std::string_view name = in.rest();
    if (name.size() >= 2 && name.front() == '"' && name.back() == '"')
      name = name.substr(1, name.size() - 2);
    d.names[{dim, tag}] = GroupName{std::string(name), in.line()};
  }
  expect_section_end(in);
}

/// One line of $Entities (4.1): tag, point or bounding box, physical tags, bounding entities.
void read_entity(LineReader& in, GmshData& d, int dim) {
  in.require_line();
  const int tag = in.number<int>("entity tag");
  for (int k = 0; k < (dim == 0 ? 3 : 6); ++k)
    in.number<double>("entity coordinate");
  const Tag num_physicals = read_count(in, "number of physical tags");
  std::vector<int> physicals;
  for (Tag k = 0; k < num_physicals; ++k)
    physicals.push_back(in.number<int>("physical tag"));
  if (!physicals.empty())
    d.entity_physicals[{dim, tag}] = std::move(physicals);
}

void read_entities(LineReader& in, GmshData& d) {
  in.require_line();
  std::array<Tag, 4> counts{};
  for (Tag& n : counts)
    n = read_count(in, "number of entities");
  for (int dim = 0; dim < 4; ++dim)
    for (Tag i = 0; i < counts[dim]; ++i)
      read_entity(in, d, dim);
  expect_section_end(in);
}

Vec3 read_point(LineReader& in) {
  Vec3 x;
  for (int k = 0; k < 3; ++k)
    x[k] = in.number<double>("node coordinate");
  TRIFEM_CHECK(x.allFinite(), "{}: non-finite node coordinate", in.location());
  return x;
}

void add_node_tag(LineReader& in, GmshData& d, Tag tag, Index index) {
  TRIFEM_CHECK(tag > 0, "{}: node tag {} must be positive", in.location(), tag);
  TRIFEM_CHECK(d.node_map.insert(tag, index), "{}: node tag {} is defined twice", in.location(),
               tag);
}

/// One entity block of $Nodes (4.1): header, node tags, coordinates. Returns its node count.
Tag read_node_block_v4(LineReader& in, GmshData& d, Tag remaining) {
  in.require_line();
  in.number<int>("entity dimension");
  in.number<int>("entity tag");
  in.number<int>("parametric flag");
  const Tag count = read_count(in, "number of nodes in the block");
  TRIFEM_CHECK(count <= remaining, "{}: the node block holds more nodes than $Nodes declares",
               in.location());
  const Index first = d.mesh.num_nodes();
  for (Tag i = 0; i < count; ++i)
    add_node_tag(in, d, in.number_any_line<Tag>("node tag"), first + static_cast<Index>(i));
  for (Tag i = 0; i < count; ++i) {
    in.require_line();
    d.mesh.add_node(read_point(in)); // parametric coordinates, if any, are ignored
  }
  return count;
}

void read_nodes_v4(LineReader& in, GmshData& d) {
  in.require_line();
  const Tag num_blocks = read_count(in, "number of node blocks");
  const Tag num_nodes = read_count(in, "number of nodes");
  in.number<Tag>("minimum node tag");
  in.number<Tag>("maximum node tag");
  d.node_map.reset();
  Tag total = 0;
  for (Tag b = 0; b < num_blocks; ++b)
    total += read_node_block_v4(in, d, num_nodes - total);
  TRIFEM_CHECK(total == num_nodes, "{}: $Nodes declares {} nodes but its blocks hold {}",
               in.location(), num_nodes, total);
  expect_section_end(in);
}

void read_nodes_v2(LineReader& in, GmshData& d) {
  in.require_line();
  const Tag num_nodes = read_count(in, "number of nodes");
  d.node_map.reset();
  for (Tag i = 0; i < num_nodes; ++i) {
    in.require_line();
    add_node_tag(in, d, in.number<Tag>("node tag"), d.mesh.num_nodes());
    d.mesh.add_node(read_point(in));
  }
  expect_section_end(in);
}

Index read_node_ref(LineReader& in, const GmshData& d, const ElementHeader& e) {
  const Tag tag = in.number<Tag>("node tag");
  const Index index = d.node_map.find(tag);
  TRIFEM_CHECK(index >= 0, "{}: element {} refers to node tag {}, which is not defined in $Nodes",
               in.location(), e.tag, tag);
  return index;
}

/// Reads exactly nodes.size() node tags, which must end the line.
void read_element_nodes(LineReader& in, const GmshData& d, const ElementHeader& e,
                        std::span<Index> nodes) {
  for (Index& n : nodes)
    n = read_node_ref(in, d, e);
  TRIFEM_CHECK(in.at_line_end(), "{}: element {} of type {} has more than {} node tags",
               in.location(), e.tag, e.type, nodes.size());
}

void note_use(GmshData& d, DimTag group, long line) {
  d.first_use.try_emplace(group, line);
}

void read_cell(LineReader& in, GmshData& d, const ElementHeader& e, CellType type) {
  std::array<Index, kMaxCellNodes> nodes{};
  const std::span<Index> cell(nodes.data(), static_cast<std::size_t>(num_nodes(type)));
  read_element_nodes(in, d, e, cell);
  const std::string problem = cell_shape_problem(d.mesh, type, cell);
  TRIFEM_CHECK(problem.empty(), "{}: {} element {} {}", in.location(), name(type), e.tag, problem);
  const Index c = d.mesh.add_cell(type, cell);
  d.element_cells[e.tag] = c;
  for (int p : e.physicals) {
    d.volume_cells[p].push_back(c);
    note_use(d, {3, p}, in.line());
  }
  if (e.physicals.empty())
    d.unassigned_cells.push_back(c);
}

void read_quad(LineReader& in, GmshData& d, const ElementHeader& e, int mid_edge_nodes = 0) {
  if (e.physicals.empty())
    return; // a quad in no physical surface is not needed
  PendingQuad quad{.nodes = {}, .element = e.tag, .line = in.line(), .physical = 0};
  std::array<Index, 8> nodes{};
  read_element_nodes(in, d, e, std::span<Index>(nodes.data(), 4 + mid_edge_nodes));
  std::copy_n(nodes.begin(), 4, quad.nodes.begin());
  quad.mid_edge_nodes.assign(nodes.begin() + 4, nodes.begin() + 4 + mid_edge_nodes);
  for (int p : e.physicals) {
    quad.physical = p;
    d.quads.push_back(quad);
    note_use(d, {2, p}, in.line());
  }
}

/// A triangle of a physical surface: a quad whose last node repeats the third, with the
/// mid-edge nodes of a tri6. Its surface is a surface mesh if it bounds no cell, or the node
/// set of a face of a tet or a wedge (add_surfaces).
void read_triangle(LineReader& in, GmshData& d, const ElementHeader& e, int mid_edge_nodes = 0) {
  if (e.physicals.empty())
    return;
  PendingQuad quad{.nodes = {}, .element = e.tag, .line = in.line(), .physical = 0};
  std::array<Index, 6> nodes{};
  read_element_nodes(in, d, e, std::span<Index>(nodes.data(), 3 + mid_edge_nodes));
  std::copy_n(nodes.begin(), 3, quad.nodes.begin());
  quad.nodes[3] = quad.nodes[2];
  quad.mid_edge_nodes.assign(nodes.begin() + 3, nodes.begin() + 3 + mid_edge_nodes);
  for (int p : e.physicals) {
    quad.physical = p;
    d.quads.push_back(quad);
    note_use(d, {2, p}, in.line());
  }
}

/// A point or curve element: its nodes join the node sets of its physical groups.
void read_low_dim_element(LineReader& in, GmshData& d, const ElementHeader& e, int dim) {
  if (e.physicals.empty())
    return;
  std::vector<Index> nodes;
  while (!in.at_line_end())
    nodes.push_back(read_node_ref(in, d, e));
  TRIFEM_CHECK(!nodes.empty(), "{}: element {} has no nodes", in.location(), e.tag);
  for (int p : e.physicals) {
    std::vector<Index>& set = d.point_sets[{dim, p}];
    set.insert(set.end(), nodes.begin(), nodes.end());
    note_use(d, {dim, p}, in.line());
  }
}

/// The rest of an element line after its tag (4.1) or its tag list (2.2).
void read_element(LineReader& in, GmshData& d, const ElementHeader& e) {
  const ElementType* type = find_element_type(e.type);
  TRIFEM_CHECK(!type || e.entity_dim < 0 || type->dim == e.entity_dim,
               "{}: element {} of type {} ({}, dimension {}) is in a block of dimension {}",
               in.location(), e.tag, e.type, type->name, type->dim, e.entity_dim);
  const int dim = type ? type->dim : e.entity_dim;
  d.element_cells[e.tag] = -1; // a hex sets its cell below
  if (dim == 0 || dim == 1)
    return read_low_dim_element(in, d, e, dim);
  switch (e.type) {
  case kGmshHex8:
    return read_cell(in, d, e, CellType::Hex8);
  case kGmshTet4:
    return read_cell(in, d, e, CellType::Tet4);
  case kGmshTet10:
    return read_cell(in, d, e, CellType::Tet10);
  case kGmshPrism6:
    return read_cell(in, d, e, CellType::Penta6);
  case kGmshHex20:
    return read_cell(in, d, e, CellType::Hex20);
  case kGmshQuad4:
    return read_quad(in, d, e);
  case kGmshQuad8:
    return read_quad(in, d, e, 4);
  case kGmshTri3:
    return read_triangle(in, d, e);
  case kGmshTri6:
    return read_triangle(in, d, e, 3);
  default:
    throw InputError(fmt::format(
        "{}: element {} has unsupported element type {} ({}); trifem reads the volume elements "
        "hexahedron8 (type 5), tetra4 (4), tetra10 (11), prism6 (6) and hexahedron20 (17) and "
        "the surface elements quad4 (3), quad8 (16), triangle3 (2) and triangle6 (9)",
        in.location(), e.tag, e.type, type ? type->name : "unknown"));
  }
}

/// One entity block of $Elements (4.1). Returns its element count.
Tag read_element_block_v4(LineReader& in, GmshData& d) {
  in.require_line();
  const int entity_dim = in.number<int>("entity dimension");
  const int entity_tag = in.number<int>("entity tag");
  const int type = in.number<int>("element type");
  const Tag count = read_count(in, "number of elements in the block");
  TRIFEM_CHECK(entity_dim >= 0 && entity_dim <= 3, "{}: invalid entity dimension {}", in.location(),
               entity_dim);
  const auto it = d.entity_physicals.find({entity_dim, entity_tag});
  ElementHeader e{.type = type, .entity_dim = entity_dim, .physicals = {}};
  if (it != d.entity_physicals.end())
    e.physicals = it->second;
  for (Tag i = 0; i < count; ++i) {
    in.require_line();
    e.tag = in.number<Tag>("element tag");
    read_element(in, d, e);
  }
  return count;
}

void read_elements_v4(LineReader& in, GmshData& d) {
  in.require_line();
  const Tag num_blocks = read_count(in, "number of element blocks");
  const Tag num_elements = read_count(in, "number of elements");
  Tag total = 0;
  for (Tag b = 0; b < num_blocks; ++b)
    total += read_element_block_v4(in, d);
  TRIFEM_CHECK(total == num_elements, "{}: $Elements declares {} elements but its blocks hold {}",
               in.location(), num_elements, total);
  expect_section_end(in);
}

void read_elements_v2(LineReader& in, GmshData& d) {
  in.require_line();
  const Tag count = read_count(in, "number of elements");
  for (Tag i = 0; i < count; ++i) {
    in.require_line();
    ElementHeader e{.tag = in.number<Tag>("element tag"),
                    .type = in.number<int>("element type"),
                    .entity_dim = -1,
                    .physicals = {}};
    const Tag num_tags = read_count(in, "number of element tags");
    int physical = 0; // the first tag is the physical group, 0 for none
    for (Tag k = 0; k < num_tags; ++k) {
      const int value = in.number<int>("element tag list entry");
      if (k == 0)
        physical = value;
    }
    if (physical != 0)
      e.physicals = std::span<const int>(&physical, 1);
    read_element(in, d, e);
  }
  expect_section_end(in);
}

/// The view name: the first string tag of an $ElementData section, without its quotes.
std::string read_view_name(LineReader& in) {
  in.require_line();
  const Tag num_strings = read_count(in, "number of string tags");
  TRIFEM_CHECK(num_strings >= 1, "{}: $ElementData needs a string tag (the view name)",
               in.location());
  std::string name;
  for (Tag i = 0; i < num_strings; ++i) {
    in.require_line();
    std::string_view text = in.rest();
    if (text.size() >= 2 && text.front() == '"' && text.back() == '"')
      text = text.substr(1, text.size() - 2);
    if (i == 0)
      name = text;
  }
  TRIFEM_CHECK(!name.empty(), "{}: empty view name in $ElementData", in.location());
  return name;
}

/// The integer tags of an $ElementData section: returns {number of components, number of
/// elements}; the time step and a partition index are ignored.
std::pair<int, Tag> read_view_counts(LineReader& in) {
  in.require_line();
  const Tag num_reals = read_count(in, "number of real tags");
  for (Tag i = 0; i < num_reals; ++i) {
    in.require_line();
    in.number<double>("real tag (time)");
  }
  in.require_line();
  const Tag num_ints = read_count(in, "number of integer tags");
  TRIFEM_CHECK(num_ints >= 3,
               "{}: $ElementData needs 3 integer tags (time step, number of components, number "
               "of elements), found {}",
               in.location(), num_ints);
  std::array<Tag, 3> ints{};
  for (Tag i = 0; i < num_ints; ++i) {
    in.require_line();
    const Tag value = in.number<Tag>("integer tag");
    if (i < 3)
      ints[static_cast<std::size_t>(i)] = value;
    TRIFEM_CHECK(i != 1 || (value >= 1 && value <= 9),
                 "{}: invalid number of components {} (1 to 9)", in.location(), value);
    TRIFEM_CHECK(i != 2 || value >= 0, "{}: invalid number of elements {}", in.location(), value);
  }
  return {static_cast<int>(ints[1]), ints[2]};
}

/// One $ElementData section (a view at one time step): its values, per element tag, join the
/// view of its name (sections of one name, e.g. partitions, must have the same components).
void read_element_data(LineReader& in, GmshData& d) {
  const std::string name = read_view_name(in);
  const long name_line = in.line();
  const auto [components, count] = read_view_counts(in);
  auto [it, inserted] = d.views.try_emplace(name);
  PendingView& view = it->second;
  if (inserted) {
    view.components = components;
    view.line = name_line;
  }
  TRIFEM_CHECK(view.components == components,
               "{}: view '{}' has {} components here but {} in its section at line {}",
               in.location(), name, components, view.components, view.line);
  for (Tag i = 0; i < count; ++i) {
    in.require_line();
    view.elements.push_back(in.number<Tag>("element tag"));
    view.lines.push_back(in.line());
    for (int k = 0; k < components; ++k) {
      const Real value = in.number<double>(fmt::format(
          "value {} of {} of view '{}' (its number of components)", k + 1, components, name));
      TRIFEM_CHECK(std::isfinite(value), "{}: non-finite value in view '{}'", in.location(), name);
      view.values.push_back(value);
    }
    TRIFEM_CHECK(in.at_line_end(),
                 "{}: element {} has more than {} values in view '{}' (its number of components)",
                 in.location(), view.elements.back(), components, name);
  }
  expect_section_end(in);
}

void read_section(LineReader& in, GmshData& d) {
  const std::string_view header = in.rest();
  TRIFEM_CHECK(header.size() > 1 && header.front() == '$' && !header.starts_with("$End"),
               "{}: expected a section header such as $Nodes, found '{}'", in.location(), header);
  in.set_section(header.substr(1));
  const std::string& name = in.section();
  if (name == "PhysicalNames") {
    read_physical_names(in, d);
  } else if (name == "Entities" && d.major_version == 4) {
    read_entities(in, d);
  } else if (name == "Nodes") {
    TRIFEM_CHECK(!d.seen_nodes, "{}: second $Nodes section", in.location());
    d.seen_nodes = true;
    if (d.major_version == 4)
      read_nodes_v4(in, d);
    else
      read_nodes_v2(in, d);
  } else if (name == "Elements") {
    TRIFEM_CHECK(!d.seen_elements, "{}: second $Elements section", in.location());
    d.seen_elements = true;
    d.elements_line = in.line();
    if (d.major_version == 4)
      read_elements_v4(in, d);
    else
      read_elements_v2(in, d);
  } else if (name == "ElementData") {
    read_element_data(in, d);
  } else {
    TRIFEM_CHECK(name != "MeshFormat", "{}: second $MeshFormat section", in.location());
    skip_section(in);
  }
}

std::string group_name(const GmshData& d, DimTag group) {
  static constexpr const char* kPrefix[] = {"point", "curve", "surface", "volume"};
  const auto it = d.names.find(group);
  if (it != d.names.end() && !it->second.name.empty())
    return it->second.name;
  return fmt::format("{}_{}", kPrefix[group.first], group.second);
}

/// The line that defines a group: its $PhysicalNames entry, else its first element.
long group_line(const GmshData& d, DimTag group) {
  const auto it = d.names.find(group);
  return it != d.names.end() ? it->second.line : d.first_use.at(group);
}

/// Runs a Mesh registration and prefixes its errors (name clashes) with file and line.
template <class F>
void register_named(const LineReader& in, long line, F&& add) {
  try {
    add();
  } catch (const InputError& err) {
    throw InputError(fmt::format("{}: {}", in.at(line), err.what()));
  }
}

void add_cell_blocks(const LineReader& in, GmshData& d) {
  if (d.names.empty() && d.first_use.empty()) { // no physical groups at all
    std::vector<Index> all(static_cast<std::size_t>(d.mesh.num_cells()));
    for (Index c = 0; c < d.mesh.num_cells(); ++c)
      all[c] = c;
    d.mesh.add_cell_block("volume", std::move(all));
    return;
  }
  for (auto& entry : d.volume_cells) {
    const DimTag group{3, entry.first};
    register_named(in, group_line(d, group),
                   [&] { d.mesh.add_cell_block(group_name(d, group), std::move(entry.second)); });
  }
  if (!d.unassigned_cells.empty())
    register_named(in, d.elements_line,
                   [&] { d.mesh.add_cell_block("unassigned", std::move(d.unassigned_cells)); });
}

/// A physical surface is made of hex faces, or it is a surface mesh whose quads bound no cell
/// (e.g. a bone surface carried by a rigid body), oriented by their node order: not a mix,
/// which is most likely a quad misplaced on a face.
void check_surface_kinds(const LineReader& in, const GmshData& d,
                         const std::vector<Facet>& facets) {
  std::map<int, std::array<std::size_t, 2>> first; // physical -> first free, first bound quad
  for (std::size_t i = 0; i < facets.size(); ++i) {
    auto [it, added] = first.try_emplace(d.quads[i].physical,
                                         std::array<std::size_t, 2>{facets.size(), facets.size()});
    std::size_t& slot = it->second[facets[i].cell < 0 ? 0 : 1];
    slot = std::min(slot, i);
  }
  for (const auto& [physical, quads] : first) {
    if (quads[0] == facets.size() || quads[1] == facets.size())
      continue;
    const PendingQuad& q = d.quads[quads[0]];
    throw InputError(fmt::format(
        "{}: element {} of physical surface '{}' is not a face of any cell, while "
        "its other quads are (a surface mesh that bounds no cell, such as a rigid bone surface, "
        "must be a physical surface of its own)",
        in.at(q.line), q.element, group_name(d, {2, physical})));
  }
}

/// A quadratic element of a physical surface must be a cell's face (surface meshes that bound
/// no cell are linear).
void check_quadratic_faces(const LineReader& in, const GmshData& d,
                           const std::vector<Facet>& facets) {
  for (std::size_t i = 0; i < facets.size(); ++i)
    TRIFEM_CHECK(facets[i].bounds_cell() || d.quads[i].mid_edge_nodes.empty(),
                 "{}: element {} of physical surface '{}' is quadratic but no face of a cell (a "
                 "surface mesh that bounds no cell is made of quad4 or triangle3 elements)",
                 in.at(d.quads[i].line), d.quads[i].element,
                 group_name(d, {2, d.quads[i].physical}));
}

void add_surfaces(const LineReader& in, GmshData& d) {
  std::vector<std::array<Index, 4>> quads;
  quads.reserve(d.quads.size());
  for (const PendingQuad& q : d.quads)
    quads.push_back(q.nodes);
  const std::vector<Facet> facets = d.mesh.orient_quads(quads);
  check_quadratic_faces(in, d, facets);
  check_surface_kinds(in, d, facets);
  std::map<int, Surface> surfaces;
  for (std::size_t i = 0; i < facets.size(); ++i)
    surfaces[d.quads[i].physical].facets.push_back(facets[i]);
  for (auto& entry : surfaces) {
    const DimTag group{2, entry.first};
    register_named(in, group_line(d, group),
                   [&] { d.mesh.add_surface(group_name(d, group), std::move(entry.second)); });
  }
}

void add_point_sets(const LineReader& in, GmshData& d) {
  for (auto& entry : d.point_sets)
    register_named(in, group_line(d, entry.first), [&] {
      d.mesh.add_node_set(group_name(d, entry.first), std::move(entry.second));
    });
}

/// Each physical volume also gives the node set of its cells' nodes, under its name (unless a
/// physical surface, curve or point of that name gave one).
void add_volume_node_sets(Mesh& mesh) {
  for (const auto& [name, cells] : mesh.cell_blocks()) {
    if (mesh.has_node_set(name))
      continue;
    std::vector<Index> nodes;
    for (Index c : cells)
      nodes.insert(nodes.end(), mesh.cell_nodes(c).begin(), mesh.cell_nodes(c).end());
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    mesh.add_node_set(name, std::move(nodes));
  }
}

/// The values of a view on the cells; values on other elements (surface quads, lines, points)
/// are ignored.
CellData view_cell_data(const LineReader& in, const GmshData& d, const std::string& name,
                        const PendingView& view) {
  const auto n = static_cast<std::size_t>(view.components);
  CellData data{.components = view.components,
                .values = std::vector<Real>(static_cast<std::size_t>(d.mesh.num_cells()) * n,
                                            std::numeric_limits<Real>::quiet_NaN())};
  std::vector<long> given_at(static_cast<std::size_t>(d.mesh.num_cells()), 0);
  for (std::size_t i = 0; i < view.elements.size(); ++i) {
    const auto it = d.element_cells.find(view.elements[i]);
    TRIFEM_CHECK(it != d.element_cells.end(),
                 "{}: view '{}' gives a value to element {}, which is not in $Elements",
                 in.at(view.lines[i]), name, view.elements[i]);
    if (it->second < 0)
      continue;
    const auto c = static_cast<std::size_t>(it->second);
    TRIFEM_CHECK(given_at[c] == 0,
                 "{}: view '{}' gives element {} a second value (first at line {}); one value "
                 "per element (views with several time steps are not supported)",
                 in.at(view.lines[i]), name, view.elements[i], given_at[c]);
    given_at[c] = view.lines[i];
    std::copy_n(view.values.begin() + static_cast<std::ptrdiff_t>(i * n), n,
                data.values.begin() + static_cast<std::ptrdiff_t>(c * n));
  }
  return data;
}

void add_cell_data(const LineReader& in, GmshData& d) {
  for (const auto& [key, view] : d.views) {
    const std::string& name = key; // a lambda may not capture a structured binding (Clang 14)
    CellData data = view_cell_data(in, d, name, view);
    register_named(in, view.line, [&] { d.mesh.add_cell_data(name, std::move(data)); });
  }
}

/// InputError naming two elements by their tags if cells meet with hanging nodes.
void check_conforming(const LineReader& in, const GmshData& d) {
  const std::optional<HangingNodes> hanging = find_hanging_nodes(d.mesh);
  if (!hanging)
    return;
  std::unordered_map<Index, Tag> tag_of;
  for (const auto& [tag, c] : d.element_cells)
    if (c >= 0)
      tag_of[c] = tag;
  throw InputError(fmt::format(
      "{}: elements {} ({}) and {} ({}) {}; trifem needs a conforming mesh, in which cells that "
      "touch share whole faces with the same nodes (mesh all volumes together, with one element "
      "order)",
      in.at(d.elements_line), tag_of[hanging->cell], name(d.mesh.cell_type(hanging->cell)),
      tag_of[hanging->other], name(d.mesh.cell_type(hanging->other)), hanging->how));
}

Mesh finish(const LineReader& in, GmshData& d) {
  TRIFEM_CHECK(d.seen_nodes, "{}: the file has no $Nodes section", in.location());
  TRIFEM_CHECK(d.seen_elements, "{}: the file has no $Elements section", in.location());
  TRIFEM_CHECK(d.mesh.num_cells() > 0 || !d.quads.empty(),
               "{}: the file has no volume elements (hexahedron8, tetra4, tetra10, prism6 or "
               "hexahedron20) and no surface mesh (quad4, type 3, or triangle3, type 2, elements)",
               in.at(d.elements_line));
  check_conforming(in, d);
  CellSource source{in.file(), "element", 0, std::vector<long long>(d.mesh.num_cells())};
  for (const auto& [tag, c] : d.element_cells)
    if (c >= 0)
      source.tags[static_cast<std::size_t>(c)] = tag;
  d.mesh.add_cell_source(std::move(source));
  add_cell_blocks(in, d);
  add_surfaces(in, d);
  add_point_sets(in, d);
  add_volume_node_sets(d.mesh);
  add_cell_data(in, d);
  return std::move(d.mesh);
}

} // namespace

Mesh read_gmsh(const std::filesystem::path& file) {
  LineReader in(file);
  GmshData data;
  read_mesh_format(in, data);
  while (in.next_line())
    read_section(in, data);
  return finish(in, data);
}

} // namespace trifem::mesh
