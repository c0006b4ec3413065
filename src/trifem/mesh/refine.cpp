// SPDX-License-Identifier: MIT
#include "trifem/mesh/refine.hpp"

#include "trifem/core/error.hpp"
#include "trifem/mesh/hex_faces.hpp"

#include <algorithm>
#include <limits>
#include <unordered_map>

namespace trifem::mesh {
namespace {

/// The corners a new node is built from, sorted, padded with -1 (an edge has two, a face four;
/// cell centres are never shared, so they need no key).
using CornerKey = std::array<Index, 4>;
struct CornerKeyHash {
  std::size_t operator()(const CornerKey& k) const {
    std::size_t h = 0;
    for (Index v : k)
      h = h * 1000003u ^ static_cast<std::size_t>(v + 1);
    return h;
  }
};

/// A point of the 3 x 3 x 3 grid of a refined cell: 0, 1, 2 per direction for natural
/// coordinates -1, 0, +1.
using GridPoint = std::array<int, 3>;

/// The local corners (0..7) a grid point is the centroid of.
std::vector<int> corners_of(const GridPoint& g) {
  std::vector<int> corners;
  for (int i = 0; i < 8; ++i) {
    bool on = true;
    for (int d = 0; d < 3; ++d)
      if (g[d] != 1 && kHexNodeCoords[i][d] != g[d] - 1)
        on = false;
    if (on)
      corners.push_back(i);
  }
  return corners;
}

/// The grid point of local node l of child (i, j, k) (each 0 or 1).
GridPoint child_point(int i, int j, int k, int l) {
  return {i + (kHexNodeCoords[l][0] > 0 ? 1 : 0), j + (kHexNodeCoords[l][1] > 0 ? 1 : 0),
          k + (kHexNodeCoords[l][2] > 0 ? 1 : 0)};
}

/// The child index (0..7) of child (i, j, k).
int child_id(int i, int j, int k) {
  return i + 2 * j + 4 * k;
}

/// Builds the nodes and cells of the refined mesh, and the corners each new node comes from.
class Refiner {
public:
  explicit Refiner(const Mesh& coarse) : coarse_(coarse) {
    for (const Vec3& x : coarse.nodes())
      fine_.add_node(x);
  }

  Mesh take() { return std::move(fine_); }
  /// The corners of new node n (node indices from coarse().num_nodes() on).
  const std::vector<Index>& parents(Index n) const {
    return parents_[static_cast<std::size_t>(n - coarse_.num_nodes())];
  }

  void split_cells() {
    for (Index c = 0; c < coarse_.num_cells(); ++c) {
      std::array<std::array<std::array<Index, 3>, 3>, 3> grid{};
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
          for (int e = 0; e < 3; ++e)
            grid[a][b][e] = grid_node(c, {a, b, e});
      for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 2; ++j)
          for (int i = 0; i < 2; ++i) {
            Hex8 child{};
            for (int l = 0; l < 8; ++l) {
              const GridPoint g = child_point(i, j, k, l);
              child[l] = grid[g[0]][g[1]][g[2]];
            }
            fine_.add_cell(child); // index 8c + child_id(i, j, k): i fastest, then j, then k
          }
    }
  }

  Mesh& fine() { return fine_; }

private:
  /// The node at grid point g of coarse cell c (a corner, or a new node shared by key).
  Index grid_node(Index c, const GridPoint& g) {
    const std::vector<int> local = corners_of(g);
    std::vector<Index> corners;
    for (int i : local)
      corners.push_back(coarse_.cell(c)[i]);
    if (corners.size() == 1)
      return corners.front();
    std::sort(corners.begin(), corners.end());
    if (corners.size() == 8)
      return new_node(corners);
    CornerKey key;
    key.fill(-1);
    std::copy(corners.begin(), corners.end(), key.begin());
    const auto [it, inserted] = shared_.try_emplace(key, -1);
    if (inserted)
      it->second = new_node(corners);
    return it->second;
  }

  Index new_node(const std::vector<Index>& corners) {
    Vec3 x = Vec3::Zero();
    for (Index n : corners)
      x += coarse_.node(n);
    parents_.push_back(corners);
    return fine_.add_node(x / static_cast<Real>(corners.size()));
  }

  const Mesh& coarse_;
  Mesh fine_;
  std::unordered_map<CornerKey, Index, CornerKeyHash> shared_;
  std::vector<std::vector<Index>> parents_;
};

/// The children of a cell that touch its local face f, in any order.
std::array<Index, 4> children_on_face(Index cell, int face) {
  // the natural coordinate fixed on each face (kHexFaces order) and its side (0: -1, 1: +1)
  constexpr std::array<int, 6> axis = {2, 2, 1, 0, 1, 0};
  constexpr std::array<int, 6> side = {0, 1, 0, 1, 1, 0};
  std::array<Index, 4> children{};
  int n = 0;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        const std::array<int, 3> ijk = {i, j, k};
        if (ijk[axis[face]] == side[face])
          children[n++] = 8 * cell + child_id(i, j, k);
      }
  return children;
}

Surface refine_surface(const Mesh& fine, const Surface& coarse) {
  Surface s;
  s.facets.reserve(coarse.facets.size() * 4);
  for (const Facet& f : coarse.facets)
    for (Index child : children_on_face(f.cell, f.local_face)) {
      Facet g{.nodes = {}, .cell = child, .local_face = f.local_face};
      for (int a = 0; a < 4; ++a)
        g.nodes[a] = fine.cell(child)[kHexFaces[f.local_face][a]];
      s.facets.push_back(g);
    }
  return s;
}

void check_size(const Mesh& mesh) {
  constexpr long long kMax = std::numeric_limits<Index>::max();
  const long long cells = 8LL * mesh.num_cells();
  const long long nodes = mesh.num_nodes() + 19LL * mesh.num_cells(); // at most 12 + 6 + 1 each
  TRIFEM_CHECK(cells <= kMax && nodes <= kMax,
               "refining a mesh of {} cells would give {} cells, more than a mesh can hold",
               mesh.num_cells(), cells);
}

} // namespace

Mesh refine_uniformly(const Mesh& mesh) {
  check_size(mesh);
  Refiner r(mesh);
  r.split_cells();
  Mesh& fine = r.fine();
  for (const auto& [name, surface] : mesh.surfaces()) {
    check_refinable_surface(name, surface);
    fine.add_surface(name, refine_surface(fine, surface)); // also its node set
  }
  const auto parents = [&r](Index n) { return r.parents(n); };
  for (const auto& [name, set] : mesh.node_sets())
    if (!mesh.has_surface(name))
      fine.add_node_set(name, refined_node_set(set, mesh.num_nodes(), fine.num_nodes(), parents));
  add_refined_cell_sets(mesh, fine);
  return r.take();
}

void add_refined_cell_sets(const Mesh& coarse, Mesh& fine) {
  for (const auto& [name, cells] : coarse.cell_blocks()) {
    std::vector<Index> children;
    children.reserve(cells.size() * 8);
    for (Index c : cells)
      for (int k = 0; k < 8; ++k)
        children.push_back(8 * c + k);
    fine.add_cell_block(name, std::move(children));
  }
  for (const auto& [name, data] : coarse.cell_data()) {
    CellData children{.components = data.components, .values = {}};
    const auto width = static_cast<std::size_t>(data.components);
    children.values.reserve(data.values.size() * 8);
    for (std::size_t start = 0; start < data.values.size(); start += width)
      for (int k = 0; k < 8; ++k)
        children.values.insert(children.values.end(),
                               data.values.begin() + static_cast<long>(start),
                               data.values.begin() + static_cast<long>(start + width));
    fine.add_cell_data(name, std::move(children));
  }
}

std::vector<Index> refined_node_set(const std::vector<Index>& set, Index coarse_nodes,
                                    Index fine_nodes,
                                    const std::function<std::vector<Index>(Index)>& parents) {
  std::vector<char> in(static_cast<std::size_t>(coarse_nodes), 0);
  for (Index n : set)
    in[static_cast<std::size_t>(n)] = 1;
  std::vector<Index> fine = set;
  for (Index n = coarse_nodes; n < fine_nodes; ++n)
    if (std::ranges::all_of(parents(n), [&](Index m) { return in[static_cast<std::size_t>(m)]; }))
      fine.push_back(n);
  return fine;
}

void check_refinable_surface(const std::string& name, const Surface& surface) {
  TRIFEM_CHECK(std::all_of(surface.facets.begin(), surface.facets.end(),
                           [](const Facet& f) { return f.bounds_cell(); }),
               "the surface '{}' is a surface mesh that bounds no cell: refining the mesh "
               "splits cells and their faces only (refine the surface mesh itself instead)",
               name);
}

Mesh refine_uniformly(const Mesh& mesh, int levels) {
  TRIFEM_CHECK(levels >= 0, "mesh refinement: {} levels (expected 0 or more)", levels);
  if (levels == 0)
    return mesh;
  TRIFEM_CHECK(mesh.all_hex8(),
               "mesh refinement: meshes of hex8 cells only can be refined so far, and this one "
               "has {} cells (refine it in the mesher)",
               name(mesh.cell_type(mesh.first_non_hex8())));
  Mesh fine = refine_uniformly(mesh);
  for (int level = 1; level < levels; ++level)
    fine = refine_uniformly(fine);
  return fine;
}

} // namespace trifem::mesh
