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

/// Key of a face independent of node order: the sorted node indices.
using FaceKey = std::array<Index, 4>;
FaceKey face_key(std::array<Index, 4> nodes) {
  std::sort(nodes.begin(), nodes.end());
  return nodes;
}
struct FaceKeyHash {
  std::size_t operator()(const FaceKey& k) const {
    std::size_t h = 0;
    for (Index v : k)
      h = h * 1000003u ^ static_cast<std::size_t>(v);
    return h;
  }
};

Facet make_facet(const Mesh& mesh, Index cell, int face) {
  Facet f;
  f.cell = cell;
  f.local_face = face;
  for (int i = 0; i < 4; ++i)
    f.nodes[i] = mesh.cell(cell)[kHexFaces[face][i]];
  return f;
}

/// True if `b` lists the nodes of `a` in the same cyclic order (the same oriented quad).
bool same_orientation(const std::array<Index, 4>& a, const std::array<Index, 4>& b) {
  for (int shift = 0; shift < 4; ++shift)
    if (a[0] == b[shift] && a[1] == b[(shift + 1) % 4] && a[2] == b[(shift + 2) % 4] &&
        a[3] == b[(shift + 3) % 4])
      return true;
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
  for (Index n : nodes)
    TRIFEM_CHECK(n >= 0 && n < num_nodes(), "cell {} refers to node {} but the mesh has {} nodes",
                 num_cells(), n, num_nodes());
  cells_.push_back(nodes);
  if (!cell_data_.empty())
    pad_cell_data(cell_data_, num_cells());
  return static_cast<Index>(cells_.size()) - 1;
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
  for (Hex8 c : other.cells_) {
    for (Index& n : c)
      n += node_offset;
    cells_.push_back(c);
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
  for (Index c = 0; c < num_cells(); ++c) {
    for (int f = 0; f < 6; ++f) {
      Facet facet = make_facet(*this, c, f);
      faces.try_emplace(face_key(facet.nodes), facet);
    }
  }
  std::vector<Facet> found;
  found.reserve(quads.size());
  for (const auto& quad : quads) {
    const auto it = faces.find(face_key(quad));
    TRIFEM_CHECK(it != faces.end(), "quad ({}) is not a face of any hex8 cell",
                 fmt::join(quad, ", "));
    found.push_back(it->second);
  }
  return found;
}

std::vector<Facet> Mesh::orient_quads(const std::vector<std::array<Index, 4>>& quads) const {
  std::unordered_map<FaceKey, std::size_t, FaceKeyHash> slot_of;
  std::vector<std::size_t> slot(quads.size());
  for (std::size_t i = 0; i < quads.size(); ++i)
    slot[i] = slot_of.try_emplace(face_key(quads[i]), slot_of.size()).first->second;
  std::vector<std::array<Facet, 2>> found(slot_of.size()); // cell -1: not found yet
  for (Index c = 0; c < num_cells(); ++c)
    for (int f = 0; f < 6; ++f) {
      const Facet facet = make_facet(*this, c, f);
      const auto it = slot_of.find(face_key(facet.nodes));
      if (it == slot_of.end())
        continue;
      std::array<Facet, 2>& sides = found[it->second];
      if (sides[0].cell < 0)
        sides[0] = facet;
      else if (sides[1].cell < 0)
        sides[1] = facet;
    }
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
  std::unordered_map<FaceKey, std::pair<Facet, int>, FaceKeyHash> faces;
  for (Index c = 0; c < num_cells(); ++c) {
    for (int f = 0; f < 6; ++f) {
      Facet facet = make_facet(*this, c, f);
      auto [it, inserted] = faces.try_emplace(face_key(facet.nodes), facet, 0);
      ++it->second.second;
    }
  }
  std::vector<Facet> boundary;
  for (const auto& [key, entry] : faces)
    if (entry.second == 1)
      boundary.push_back(entry.first);
  std::sort(boundary.begin(), boundary.end(), [](const Facet& a, const Facet& b) {
    return a.cell != b.cell ? a.cell < b.cell : a.local_face < b.local_face;
  });
  return boundary;
}

std::vector<Index> surface_nodes(const Surface& surface) {
  std::vector<Index> nodes;
  nodes.reserve(surface.facets.size() * 4);
  for (const Facet& f : surface.facets)
    nodes.insert(nodes.end(), f.nodes.begin(), f.nodes.end());
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
  // hex8 edges in the VTK/Gmsh node order: bottom face, top face, verticals
  constexpr std::array<std::array<int, 2>, 12> kEdges = {{{0, 1},
                                                          {1, 2},
                                                          {2, 3},
                                                          {3, 0},
                                                          {4, 5},
                                                          {5, 6},
                                                          {6, 7},
                                                          {7, 4},
                                                          {0, 4},
                                                          {1, 5},
                                                          {2, 6},
                                                          {3, 7}}};
  EdgeRange range{std::numeric_limits<Real>::infinity(), 0.0};
  for (const Hex8& cell : mesh.cells())
    for (const auto& [a, b] : kEdges) {
      const Real h = (mesh.node(cell[b]) - mesh.node(cell[a])).norm();
      range.min = std::min(range.min, h);
      range.max = std::max(range.max, h);
    }
  if (mesh.num_cells() == 0)
    range.min = 0.0;
  return range;
}

} // namespace trifem::mesh
