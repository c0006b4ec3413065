// SPDX-License-Identifier: MIT
#include "trifem/mesh/mesh.hpp"

#include "trifem/core/error.hpp"
#include "trifem/mesh/hex_faces.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/ranges.h>
#include <limits>
#include <unordered_map>

namespace trifem::mesh {
namespace {

template <class Map>
std::string available_names(const Map& map) {
  std::vector<std::string> names;
  for (const auto& [name, _] : map)
    names.push_back(name);
  return names.empty() ? std::string("(none)") : fmt::format("{}", fmt::join(names, ", "));
}

template <class Map, class Value>
void insert_unique(Map& map, const std::string& kind, const std::string& name, Value value) {
  TRIFEM_CHECK(!name.empty(), "a {} needs a non-empty name", kind);
  TRIFEM_CHECK(!map.contains(name), "{} '{}' is defined twice", kind, name);
  map.emplace(name, std::move(value));
}

template <class Map>
const auto& find_named(const Map& map, const std::string& kind, const std::string& name) {
  const auto it = map.find(name);
  TRIFEM_CHECK(it != map.end(), "undefined {} '{}' (available: {})", kind, name,
               available_names(map));
  return it->second;
}

/// Key of a face independent of node order: its sorted corners (a triangle's fourth −1).
using FaceKey = std::array<Index, 4>;
FaceKey face_key(std::array<Index, 4> nodes) {
  std::sort(nodes.begin(), nodes.end());
  return nodes;
}

bool is_triangle(FacetType type) {
  return type == FacetType::Tri3 || type == FacetType::Tri6;
}

/// The key of a quad given by its corners (a triangle's fourth repeating its third).
FaceKey quad_key(std::array<Index, 4> corners) {
  if (corners[3] == corners[2])
    corners[3] = -1;
  return face_key(corners);
}
struct FaceKeyHash {
  std::size_t operator()(const FaceKey& k) const {
    std::size_t h = 0;
    for (Index v : k)
      h = h * 1000003u ^ static_cast<std::size_t>(v);
    return h;
  }
};

/// The facet of face `face` (of cell_faces()) of cell `cell`.
Facet make_facet(const Mesh& mesh, Index cell, int face) {
  const CellFace& local = cell_faces(mesh.cell_type(cell))[static_cast<std::size_t>(face)];
  const std::span<const Index> nodes = mesh.cell_nodes(cell);
  Facet f;
  f.cell = cell;
  f.local_face = face;
  f.type = local.type;
  const std::size_t corners = is_triangle(local.type) ? 3 : 4;
  for (std::size_t i = 0; i < local.nodes.size(); ++i) {
    const Index n = nodes[static_cast<std::size_t>(local.nodes[i])];
    (i < corners ? f.nodes[i] : f.mid_edge_nodes[i - corners]) = n;
  }
  if (corners == 3)
    f.nodes[3] = f.nodes[2];
  return f;
}

/// The key of face `face` of cell c: its sorted corners (a triangle's fourth entry −1).
FaceKey cell_face_key(const Mesh& mesh, Index c, const CellFace& face) {
  const std::span<const Index> nodes = mesh.cell_nodes(c);
  std::array<Index, 4> corners{};
  for (int i = 0; i < 4; ++i)
    corners[i] =
        is_triangle(face.type) && i == 3 ? -1 : nodes[static_cast<std::size_t>(face.nodes[i])];
  return face_key(corners);
}

/// Calls visit(cell, local face, key) for every face of every cell.
template <class Visit>
void for_each_face(const Mesh& mesh, Visit&& visit) {
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const std::vector<CellFace>& faces = cell_faces(mesh.cell_type(c));
    for (std::size_t f = 0; f < faces.size(); ++f)
      visit(c, static_cast<int>(f), cell_face_key(mesh, c, faces[f]));
  }
}

/// True if `b` lists the corners of `a` in the same cyclic order (the same oriented quad or
/// triangle; a triangle's fourth corner repeats its third).
bool same_orientation(const std::array<Index, 4>& a, const std::array<Index, 4>& b) {
  const int n = a[3] == a[2] ? 3 : 4;
  for (int shift = 0; shift < n; ++shift) {
    bool same = true;
    for (int i = 0; i < n && same; ++i)
      same = a[static_cast<std::size_t>(i)] == b[static_cast<std::size_t>((shift + i) % n)];
    if (same)
      return true;
  }
  return false;
}

constexpr Real kNoValue = std::numeric_limits<Real>::quiet_NaN();

/// Pads every cell data to `num_cells` cells with NaN (cells without data).
void pad_cell_data(std::map<std::string, CellData>& all, Index num_cells) {
  for (auto& [name, data] : all)
    data.values.resize(
        static_cast<std::size_t>(num_cells) * static_cast<std::size_t>(data.components), kNoValue);
}

} // namespace

bool CellData::covers(Index c) const {
  for (int k = 0; k < components; ++k)
    if (std::isnan(value(c, k)))
      return false;
  return true;
}

Index Mesh::add_node(const Vec3& x) {
  nodes_.push_back(x);
  return static_cast<Index>(nodes_.size()) - 1;
}

Index Mesh::add_cell(const Hex8& nodes) {
  return add_cell(CellType::Hex8, nodes);
}

Index Mesh::add_cell(CellType type, std::span<const Index> nodes) {
  TRIFEM_CHECK(std::ssize(nodes) == mesh::num_nodes(type),
               "cell {} of type {} has {} nodes, expected {}", num_cells(), name(type),
               nodes.size(), mesh::num_nodes(type));
  for (Index n : nodes)
    TRIFEM_CHECK(n >= 0 && n < num_nodes(), "cell {} refers to node {} but the mesh has {} nodes",
                 num_cells(), n, num_nodes());
  cell_types_.push_back(type);
  cell_node_list_.insert(cell_node_list_.end(), nodes.begin(), nodes.end());
  cell_offsets_.push_back(static_cast<Index>(cell_node_list_.size()));
  if (!cell_data_.empty())
    pad_cell_data(cell_data_, num_cells());
  return num_cells() - 1;
}

Hex8 Mesh::cell(Index c) const {
  TRIFEM_VERIFY(cell_type(c) == CellType::Hex8, "cell {} is a {}, not a hex8", c,
                name(cell_type(c)));
  Hex8 nodes;
  std::ranges::copy(cell_nodes(c), nodes.begin());
  return nodes;
}

void Mesh::add_cell_source(CellSource source) {
  TRIFEM_VERIFY(source.first >= 0 &&
                    source.first + static_cast<Index>(source.tags.size()) <= num_cells(),
                "cell source beyond the mesh's cells");
  const auto at = std::ranges::upper_bound(cell_sources_, source.first, {}, &CellSource::first);
  cell_sources_.insert(at, std::move(source));
}

std::string Mesh::cell_origin(Index c) const {
  auto at = std::ranges::upper_bound(cell_sources_, c, {}, &CellSource::first);
  if (at == cell_sources_.begin())
    return {};
  --at;
  const Index i = c - at->first;
  if (i >= static_cast<Index>(at->tags.size()))
    return {};
  return fmt::format("{} {} of '{}'", at->what, at->tags[static_cast<std::size_t>(i)], at->file);
}

std::string Mesh::describe(Index c) const {
  const std::string origin = cell_origin(c);
  return origin.empty() ? fmt::format("cell {}", c) : origin;
}

Index Mesh::first_non_hex8() const {
  const auto it = std::ranges::find_if_not(cell_types_, is_hex8);
  return it == cell_types_.end() ? -1 : static_cast<Index>(it - cell_types_.begin());
}

void Mesh::add_node_set(const std::string& name, std::vector<Index> nodes) {
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  TRIFEM_CHECK(nodes.empty() || (nodes.front() >= 0 && nodes.back() < num_nodes()),
               "node set '{}' refers to a node outside 0..{}", name, num_nodes() - 1);
  insert_unique(node_sets_, "node set", name, std::move(nodes));
}

void Mesh::add_surface(const std::string& name, Surface surface) {
  std::vector<Index> nodes = surface_nodes(surface);
  insert_unique(surfaces_, "surface", name, std::move(surface));
  add_node_set(name, std::move(nodes));
}

void Mesh::add_cell_block(const std::string& name, std::vector<Index> cells) {
  for (Index c : cells)
    TRIFEM_CHECK(c >= 0 && c < num_cells(), "cell block '{}' refers to cell {} outside 0..{}", name,
                 c, num_cells() - 1);
  insert_unique(cell_blocks_, "cell block", name, std::move(cells));
}

void Mesh::add_cell_data(const std::string& name, CellData data) {
  TRIFEM_CHECK(data.components >= 1, "cell data '{}' needs at least one component", name);
  TRIFEM_CHECK(std::ssize(data.values) == num_cells() * data.components,
               "cell data '{}' holds {} numbers, expected {} cells x {} components", name,
               data.values.size(), num_cells(), data.components);
  insert_unique(cell_data_, "cell data", name, std::move(data));
}

const CellData& Mesh::cell_data(const std::string& name) const {
  return find_named(cell_data_, "cell data", name);
}

const std::vector<Index>& Mesh::node_set(const std::string& name) const {
  return find_named(node_sets_, "node set", name);
}
const Surface& Mesh::surface(const std::string& name) const {
  return find_named(surfaces_, "surface", name);
}
const std::vector<Index>& Mesh::cell_block(const std::string& name) const {
  return find_named(cell_blocks_, "cell block", name);
}

void Mesh::transform(const Mat3& A, const Vec3& b) {
  for (Vec3& x : nodes_)
    x = A * x + b;
}

void Mesh::append(const Mesh& other) {
  const Index node_offset = num_nodes();
  const Index cell_offset = num_cells();
  nodes_.insert(nodes_.end(), other.nodes_.begin(), other.nodes_.end());
  for (Index c = 0; c < other.num_cells(); ++c) {
    cell_types_.push_back(other.cell_type(c));
    for (Index n : other.cell_nodes(c))
      cell_node_list_.push_back(n + node_offset);
    cell_offsets_.push_back(static_cast<Index>(cell_node_list_.size()));
  }
  for (const auto& [name, nodes] : other.node_sets_) {
    if (other.surfaces_.contains(name))
      continue; // re-created with the surface below
    std::vector<Index> shifted = nodes;
    for (Index& n : shifted)
      n += node_offset;
    add_node_set(name, std::move(shifted));
  }
  for (const auto& [name, surface] : other.surfaces_) {
    Surface shifted = surface;
    for (Facet& f : shifted.facets) {
      if (f.bounds_cell())
        f.cell += cell_offset;
      for (Index& n : f.nodes)
        n += node_offset;
      for (Index& n : f.mid_edge_nodes)
        if (n >= 0)
          n += node_offset;
    }
    add_surface(name, std::move(shifted));
  }
  for (const auto& [name, cells] : other.cell_blocks_) {
    std::vector<Index> shifted = cells;
    for (Index& c : shifted)
      c += cell_offset;
    add_cell_block(name, std::move(shifted));
  }
  append_cell_data(other, cell_offset);
  for (CellSource source : other.cell_sources_) {
    source.first += cell_offset;
    add_cell_source(std::move(source));
  }
}

void Mesh::append_cell_data(const Mesh& other, Index cell_offset) {
  pad_cell_data(cell_data_, num_cells());
  for (const auto& [name, data] : other.cell_data_) {
    auto [it, inserted] = cell_data_.try_emplace(name);
    CellData& joined = it->second;
    if (inserted) {
      joined.components = data.components;
      joined.values.assign(static_cast<std::size_t>(num_cells()) *
                               static_cast<std::size_t>(data.components),
                           kNoValue);
    }
    TRIFEM_CHECK(joined.components == data.components,
                 "cell data '{}' has {} components here and {} in the appended mesh", name,
                 joined.components, data.components);
    std::copy(data.values.begin(), data.values.end(),
              joined.values.begin() + static_cast<std::ptrdiff_t>(cell_offset) * data.components);
  }
}

std::vector<Facet> Mesh::find_facets(const std::vector<std::array<Index, 4>>& quads) const {
  std::unordered_map<FaceKey, Facet, FaceKeyHash> faces;
  for_each_face(*this, [&](Index c, int f, const FaceKey& key) {
    if (!faces.contains(key))
      faces.emplace(key, make_facet(*this, c, f));
  });
  std::vector<Facet> found;
  found.reserve(quads.size());
  for (const auto& quad : quads) {
    const auto it = faces.find(quad_key(quad));
    TRIFEM_CHECK(it != faces.end(), "quad ({}) is not a face of any cell", fmt::join(quad, ", "));
    found.push_back(it->second);
  }
  return found;
}

std::vector<Facet> Mesh::orient_quads(const std::vector<std::array<Index, 4>>& quads) const {
  std::unordered_map<FaceKey, std::size_t, FaceKeyHash> slot_of;
  std::vector<std::size_t> slot(quads.size());
  for (std::size_t i = 0; i < quads.size(); ++i)
    slot[i] = slot_of.try_emplace(quad_key(quads[i]), slot_of.size()).first->second;
  std::vector<std::array<Facet, 2>> found(slot_of.size()); // cell -1: not found yet
  for_each_face(*this, [&](Index c, int f, const FaceKey& key) {
    const auto it = slot_of.find(key);
    if (it == slot_of.end())
      return;
    std::array<Facet, 2>& sides = found[it->second];
    if (sides[0].cell < 0)
      sides[0] = make_facet(*this, c, f);
    else if (sides[1].cell < 0)
      sides[1] = make_facet(*this, c, f);
  });
  std::vector<Facet> facets;
  facets.reserve(quads.size());
  for (std::size_t i = 0; i < quads.size(); ++i) {
    const std::array<Facet, 2>& sides = found[slot[i]];
    if (sides[0].cell < 0) {
      facets.push_back({.nodes = quads[i], .cell = -1, .local_face = -1});
      continue;
    }
    const bool second = sides[1].cell >= 0 && !same_orientation(quads[i], sides[0].nodes) &&
                        same_orientation(quads[i], sides[1].nodes);
    facets.push_back(sides[second ? 1 : 0]);
  }
  return facets;
}

std::vector<Facet> Mesh::boundary_facets() const {
  return boundary_facets(std::vector<char>(static_cast<std::size_t>(num_cells()), 1));
}

std::vector<Facet> Mesh::boundary_facets(const std::vector<char>& inside) const {
  struct Face {
    Index cell;
    int local_face;
    int count;
  };
  std::unordered_map<FaceKey, Face, FaceKeyHash> faces;
  for_each_face(*this, [&](Index c, int f, const FaceKey& key) {
    if (!inside[static_cast<std::size_t>(c)])
      return;
    auto [it, inserted] = faces.try_emplace(key, Face{c, f, 0});
    ++it->second.count;
  });
  std::vector<Facet> boundary;
  for (const auto& [key, face] : faces) {
    if (face.count != 1)
      continue;
    boundary.push_back(make_facet(*this, face.cell, face.local_face));
  }
  std::sort(boundary.begin(), boundary.end(), [](const Facet& a, const Facet& b) {
    return a.cell != b.cell ? a.cell < b.cell : a.local_face < b.local_face;
  });
  return boundary;
}

std::vector<Index> surface_nodes(const Surface& surface) {
  std::vector<Index> nodes;
  nodes.reserve(surface.facets.size() * 4);
  for (const Facet& f : surface.facets) {
    nodes.insert(nodes.end(), f.nodes.begin(), f.nodes.end());
    for (Index n : f.mid_edge_nodes)
      if (n >= 0)
        nodes.push_back(n);
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

Vec3 facet_area_vector(const Mesh& mesh, const Facet& facet) {
  const auto& n = facet.nodes;
  return 0.5 * (mesh.node(n[2]) - mesh.node(n[0])).cross(mesh.node(n[3]) - mesh.node(n[1]));
}

Real mean_facet_size(const Mesh& mesh, const Surface& surface) {
  Real sum = 0.0;
  for (const Facet& f : surface.facets)
    sum += std::sqrt(facet_area_vector(mesh, f).norm());
  return sum / static_cast<Real>(surface.facets.size());
}

EdgeRange edge_length_range(const Mesh& mesh) {
  EdgeRange range{std::numeric_limits<Real>::infinity(), 0.0};
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const std::span<const Index> nodes = mesh.cell_nodes(c);
    for (const auto& [a, b] : corner_edges(mesh.cell_type(c))) {
      const Real h = (mesh.node(nodes[static_cast<std::size_t>(b)]) -
                      mesh.node(nodes[static_cast<std::size_t>(a)]))
                         .norm();
      range.min = std::min(range.min, h);
      range.max = std::max(range.max, h);
    }
  }
  if (mesh.num_cells() == 0)
    range.min = 0.0;
  return range;
}

} // namespace trifem::mesh
