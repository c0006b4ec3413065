// SPDX-License-Identifier: MIT
#include "trifem/fe/refine_cells.hpp"

#include "trifem/core/error.hpp"
#include "trifem/fe/reference_element.hpp"
#include "trifem/mesh/refine.hpp"

#include <algorithm>
#include <limits>
#include <map>
#include <unordered_map>

namespace trifem::fe {
namespace {

using mesh::cell_faces;
using mesh::CellFace;
using mesh::CellType;
using mesh::Facet;
using mesh::linear_type;
using mesh::Mesh;
using mesh::num_corners;
using mesh::Surface;

/// Natural coordinates of the corners of the eight children of a cell of linear type `linear`,
/// each child's corners in its type's order.
using ChildCorners = std::vector<std::vector<Vec3>>;

Vec3 reference_corner(CellType linear, int a) {
  return reference_cell(linear).nodes().row(a).transpose();
}

ChildCorners hex_children() {
  ChildCorners children;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        std::vector<Vec3> corners;
        for (int l = 0; l < 8; ++l) {
          const Vec3 r = reference_corner(CellType::Hex8, l); // ±1
          corners.emplace_back(i + 0.5 * (r[0] + 1) - 1, j + 0.5 * (r[1] + 1) - 1,
                               k + 0.5 * (r[2] + 1) - 1);
        }
        children.push_back(corners);
      }
  return children;
}

/// Bey's split: the four corner tets and the octahedron of the edge midpoints cut along the
/// diagonal from the midpoint of (0, 2) to that of (1, 3).
ChildCorners tet_children() {
  const auto P = [](int a) { return reference_corner(CellType::Tet4, a); };
  const auto M = [&](int a, int b) { return Vec3(0.5 * (P(a) + P(b))); };
  return {{P(0), M(0, 1), M(0, 2), M(0, 3)},    {M(0, 1), P(1), M(1, 2), M(1, 3)},
          {M(0, 2), M(1, 2), P(2), M(2, 3)},    {M(0, 3), M(1, 3), M(2, 3), P(3)},
          {M(0, 2), M(1, 3), M(0, 1), M(1, 2)}, {M(0, 2), M(1, 3), M(1, 2), M(2, 3)},
          {M(0, 2), M(1, 3), M(2, 3), M(0, 3)}, {M(0, 2), M(1, 3), M(0, 3), M(0, 1)}};
}

/// The triangle split into four by its edge midpoints, times the two halves in z.
ChildCorners wedge_children() {
  const Vec2 T[3] = {{0, 0}, {1, 0}, {0, 1}};
  const auto m = [&](int a, int b) { return Vec2(0.5 * (T[a] + T[b])); };
  const std::array<std::array<Vec2, 3>, 4> triangles = {{{T[0], m(0, 1), m(2, 0)},
                                                         {m(0, 1), T[1], m(1, 2)},
                                                         {m(2, 0), m(1, 2), T[2]},
                                                         {m(0, 1), m(1, 2), m(2, 0)}}};
  ChildCorners children;
  for (const Real z0 : {-1.0, 0.0})
    for (const auto& t : triangles) {
      std::vector<Vec3> corners;
      for (const Real z : {z0, z0 + 1})
        for (const Vec2& p : t)
          corners.emplace_back(p[0], p[1], z);
      children.push_back(corners);
    }
  return children;
}

/// Determinant of the map of a child's corners at its reference centroid.
Real child_orientation(CellType linear, const std::vector<Vec3>& corners) {
  const ReferenceCell& ref = reference_cell(linear);
  const Vec3 centroid = ref.nodes().colwise().mean().transpose();
  const ShapeGrads G = ref.shape_grad(centroid);
  Mat3 J = Mat3::Zero();
  for (int a = 0; a < ref.num_nodes(); ++a)
    J += corners[static_cast<std::size_t>(a)] * G.row(a);
  return J.determinant();
}

/// The children of `linear`, each oriented as its parent (positive Jacobian).
const ChildCorners& children_of(CellType linear) {
  static const std::map<CellType, ChildCorners> all = [] {
    std::map<CellType, ChildCorners> m = {{CellType::Hex8, hex_children()},
                                          {CellType::Tet4, tet_children()},
                                          {CellType::Penta6, wedge_children()}};
    for (auto& [type, children] : m)
      for (auto& corners : children)
        if (child_orientation(type, corners) < 0)
          std::swap(corners[2], corners[3]); // (a tet: the only family built unoriented)
    return m;
  }();
  return all.at(linear);
}

/// A new node's key: the parent corners (mesh nodes) it is a weighted mean of under the
/// parent's linear map and their weights in 64ths (exact for the points of a refinement),
/// sorted by node: the same point of a shared edge or face from either cell.
using NodeKey = std::vector<std::pair<Index, int>>;
struct NodeKeyHash {
  std::size_t operator()(const NodeKey& k) const {
    std::size_t h = 0;
    for (const auto& [n, w] : k)
      h = (h * 1000003u) ^ static_cast<std::size_t>(n * 131 + w);
    return h;
  }
};

class FamilyRefiner {
public:
  explicit FamilyRefiner(const Mesh& coarse) : coarse_(coarse) {
    for (const Vec3& x : coarse.nodes())
      fine_.add_node(x);
    // the mid-edge nodes of quadratic cells are the midpoints of their edges' corners
    for (Index c = 0; c < coarse.num_cells(); ++c) {
      const auto nodes = coarse.cell_nodes(c);
      const auto edges = mesh::mid_edges(coarse.cell_type(c));
      const auto corners = static_cast<std::size_t>(num_corners(coarse.cell_type(c)));
      for (std::size_t e = 0; e < edges.size(); ++e) {
        NodeKey key = {{nodes[static_cast<std::size_t>(edges[e][0])], 32},
                       {nodes[static_cast<std::size_t>(edges[e][1])], 32}};
        std::ranges::sort(key);
        shared_.try_emplace(key, nodes[corners + e]);
        mid_edge_corners_.try_emplace(nodes[corners + e],
                                      std::array<Index, 2>{key[0].first, key[1].first});
      }
    }
  }

  void split_cells() {
    std::vector<Index> nodes;
    for (Index c = 0; c < coarse_.num_cells(); ++c) {
      const CellType type = coarse_.cell_type(c);
      const ReferenceCell& child_ref = reference_cell(type);
      for (const std::vector<Vec3>& corners : children_of(linear_type(type))) {
        nodes.clear();
        for (int a = 0; a < child_ref.num_nodes(); ++a)
          nodes.push_back(node_at(c, child_point(type, corners, child_ref.nodes().row(a))));
        fine_.add_cell(type, nodes); // index 8c + child
      }
    }
  }

  Mesh& fine() { return fine_; }
  const Mesh& fine() const { return fine_; }
  /// The coarse corners node n of the fine mesh is built from (itself for a coarse corner, its
  /// edge's two for a coarse mid-edge node).
  std::vector<Index> parents(Index n) const {
    if (n < coarse_.num_nodes()) {
      const auto it = mid_edge_corners_.find(n);
      return it == mid_edge_corners_.end() ? std::vector<Index>{n}
                                           : std::vector<Index>{it->second[0], it->second[1]};
    }
    std::vector<Index> p;
    for (const auto& [m, w] : keys_[static_cast<std::size_t>(n - coarse_.num_nodes())])
      p.push_back(m);
    return p;
  }

private:
  /// Natural coordinates in the parent of the child node at reference point r of the child.
  static Vec3 child_point(CellType type, const std::vector<Vec3>& corners,
                          const Eigen::Ref<const Eigen::RowVector3d>& r) {
    const ShapeValues N = reference_cell(linear_type(type)).shape(r.transpose());
    Vec3 x = Vec3::Zero();
    for (Index a = 0; a < N.size(); ++a)
      x += N[a] * corners[static_cast<std::size_t>(a)];
    return x;
  }

  /// The node at natural coordinates xi of coarse cell c: a coarse node, or a new node shared
  /// by its key.
  Index node_at(Index c, const Vec3& xi) {
    const CellType type = coarse_.cell_type(c);
    const std::span<const Index> nodes = coarse_.cell_nodes(c);
    const ShapeValues L = reference_cell(linear_type(type)).shape(xi);
    NodeKey key;
    for (Index a = 0; a < L.size(); ++a) {
      const auto w = static_cast<int>(std::lround(64 * L[a]));
      if (w != 0)
        key.emplace_back(nodes[static_cast<std::size_t>(a)], w);
    }
    if (key.size() == 1 && key.front().second == 64) // a corner of the parent
      return key.front().first;
    std::ranges::sort(key);
    const auto [it, inserted] = shared_.try_emplace(key, -1);
    if (inserted) {
      const ShapeValues N = reference_cell(type).shape(xi);
      Vec3 x = Vec3::Zero();
      for (Index a = 0; a < N.size(); ++a)
        x += N[a] * coarse_.node(nodes[static_cast<std::size_t>(a)]);
      it->second = fine_.add_node(x);
      keys_.push_back(key);
    }
    return it->second;
  }

  const Mesh& coarse_;
  Mesh fine_;
  std::unordered_map<NodeKey, Index, NodeKeyHash> shared_;
  std::vector<NodeKey> keys_;                                        ///< of the new nodes, in order
  std::unordered_map<Index, std::array<Index, 2>> mid_edge_corners_; ///< of the coarse mid nodes
};

/// The faces of the children of facet f's cell that lie on f (their corners built from f's
/// corners only), as quads (a triangle's fourth corner repeating its third).
void add_child_faces(const FamilyRefiner& r, const Facet& f,
                     std::vector<std::array<Index, 4>>& quads) {
  const Mesh& fine = r.fine();
  const auto on_f = [&](Index n) {
    const std::vector<Index> p = r.parents(n);
    return std::ranges::all_of(p, [&](Index m) {
      return std::find(f.nodes.begin(), f.nodes.begin() + f.num_corners(), m) !=
             f.nodes.begin() + f.num_corners();
    });
  };
  for (Index child = 8 * f.cell; child < 8 * f.cell + 8; ++child) {
    const std::span<const Index> nodes = fine.cell_nodes(child);
    for (const CellFace& face : cell_faces(fine.cell_type(child))) {
      const int corners = num_corners(face.type);
      std::array<Index, 4> quad{};
      bool on = true;
      for (int i = 0; i < corners; ++i) {
        quad[static_cast<std::size_t>(i)] = nodes[static_cast<std::size_t>(face.nodes[i])];
        on = on && on_f(quad[static_cast<std::size_t>(i)]);
      }
      if (corners == 3)
        quad[3] = quad[2];
      if (on)
        quads.push_back(quad);
    }
  }
}

} // namespace

Mesh refine_uniformly(const Mesh& mesh) {
  if (mesh.all_hex8())
    return mesh::refine_uniformly(mesh);
  TRIFEM_CHECK(mesh.num_cells() <= std::numeric_limits<Index>::max() / 8 &&
                   mesh.num_nodes() + 8LL * 27 * mesh.num_cells() <=
                       std::numeric_limits<Index>::max(),
               "refining a mesh of {} cells would give more cells or nodes than a mesh can hold",
               mesh.num_cells());
  FamilyRefiner r(mesh);
  r.split_cells();
  Mesh& fine = r.fine();
  for (const auto& [name, surface] : mesh.surfaces()) {
    mesh::check_refinable_surface(name, surface);
    std::vector<std::array<Index, 4>> quads;
    for (const Facet& f : surface.facets)
      add_child_faces(r, f, quads);
    Surface s;
    s.facets = fine.orient_quads(quads);
    fine.add_surface(name, std::move(s)); // also its node set
  }
  const auto parents = [&r](Index n) { return r.parents(n); };
  for (const auto& [name, set] : mesh.node_sets())
    if (!mesh.has_surface(name))
      fine.add_node_set(name,
                        mesh::refined_node_set(set, mesh.num_nodes(), fine.num_nodes(), parents));
  mesh::add_refined_cell_sets(mesh, fine);
  return std::move(fine);
}

Mesh refine_uniformly(const Mesh& mesh, int levels) {
  TRIFEM_CHECK(levels >= 0, "mesh refinement: {} levels (expected 0 or more)", levels);
  Mesh fine = mesh;
  for (int level = 0; level < levels; ++level)
    fine = fe::refine_uniformly(fine);
  return fine;
}

} // namespace trifem::fe
