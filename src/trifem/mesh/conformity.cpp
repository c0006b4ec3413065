// SPDX-License-Identifier: MIT
#include "trifem/mesh/conformity.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/format.h>
#include <functional>
#include <map>
#include <span>
#include <unordered_map>
#include <vector>

namespace trifem::mesh {
namespace {

/// One face of one cell.
struct Face {
  Index cell = -1;
  FacetType type = FacetType::Tri3;
  std::span<const Index> corners; ///< counter-clockwise seen from outside the cell
};

/// The sorted corners of a face (the last -1 for a triangle).
using CornerKey = std::array<Index, 4>;

struct CornerKeyHash {
  std::size_t operator()(const CornerKey& k) const {
    std::size_t h = 0;
    for (const Index n : k)
      h = h * 1000003u ^ std::hash<Index>{}(n);
    return h;
  }
};

/// The corners of every face of every cell, one after another (3 or 4 per face).
struct FaceList {
  std::vector<Index> corners;
  std::vector<std::size_t> begin; ///< of each face in corners, and the end
  std::vector<Face> faces;
};

FaceList all_faces(const Mesh& mesh) {
  FaceList list;
  std::vector<std::pair<Index, FacetType>> owner;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const std::span<const Index> nodes = mesh.cell_nodes(c);
    for (const CellFace& f : cell_faces(mesh.cell_type(c))) {
      list.begin.push_back(list.corners.size());
      owner.emplace_back(c, f.type);
      for (int a = 0; a < num_corners(f.type); ++a)
        list.corners.push_back(
            nodes[static_cast<std::size_t>(f.nodes[static_cast<std::size_t>(a)])]);
    }
  }
  list.begin.push_back(list.corners.size());
  for (std::size_t i = 0; i < owner.size(); ++i)
    list.faces.push_back({owner[i].first, owner[i].second,
                          std::span<const Index>(list.corners)
                              .subspan(list.begin[i], list.begin[i + 1] - list.begin[i])});
  return list;
}

CornerKey key_of(const Face& f) {
  CornerKey k = {-1, -1, -1, -1};
  std::copy(f.corners.begin(), f.corners.end(), k.begin());
  std::sort(k.begin(), k.begin() + static_cast<std::ptrdiff_t>(f.corners.size()));
  return k;
}

Vec3 centroid(const Mesh& mesh, const Face& f) {
  Vec3 sum = Vec3::Zero();
  for (Index n : f.corners)
    sum += mesh.node(n);
  return sum / static_cast<Real>(f.corners.size());
}

/// The outward normal of a flat approximation of f times twice its area.
Vec3 area_normal(const Mesh& mesh, const Face& f) {
  Vec3 n = Vec3::Zero();
  const std::size_t k = f.corners.size();
  for (std::size_t i = 0; i < k; ++i)
    n += mesh.node(f.corners[i]).cross(mesh.node(f.corners[(i + 1) % k]));
  return n;
}

/// Whether point p lies on face f: within 1e-6 of its size of its plane and inside the
/// triangles fanned from its first corner.
bool lies_on(const Mesh& mesh, const Face& f, const Vec3& p) {
  const Vec3 n = area_normal(mesh, f);
  const Real size = std::sqrt(n.norm());
  const Vec3 unit = n.normalized();
  const Vec3& x0 = mesh.node(f.corners[0]);
  if (std::abs(unit.dot(p - x0)) > 1e-6 * size)
    return false;
  for (std::size_t i = 1; i + 1 < f.corners.size(); ++i) {
    const Vec3& x1 = mesh.node(f.corners[i]);
    const Vec3& x2 = mesh.node(f.corners[i + 1]);
    const Real tol = -1e-9 * size * size;
    if ((x1 - x0).cross(p - x0).dot(unit) >= tol && (x2 - x1).cross(p - x1).dot(unit) >= tol &&
        (x0 - x2).cross(p - x2).dot(unit) >= tol)
      return true;
  }
  return false;
}

/// Whether every corner of a lies where a corner of b does (within 1e-9 of the face's size):
/// the two sides of a crack or of an interface whose nodes are doubled, not hanging nodes.
bool congruent(const Mesh& mesh, const Face& a, const Face& b, Real size) {
  if (a.corners.size() != b.corners.size())
    return false;
  return std::all_of(a.corners.begin(), a.corners.end(), [&](Index m) {
    return std::any_of(b.corners.begin(), b.corners.end(), [&](Index n) {
      return (mesh.node(m) - mesh.node(n)).norm() <= 1e-9 * size;
    });
  });
}

/// Two boundary faces with a node in common that fold onto each other: opposite normals and
/// the centroid of the smaller on the larger, without being the two sides of a crack.
bool overlap(const Mesh& mesh, const Face& a, const Face& b) {
  const Vec3 na = area_normal(mesh, a), nb = area_normal(mesh, b);
  if (na.normalized().dot(nb.normalized()) > -0.99 || congruent(mesh, a, b, std::sqrt(na.norm())))
    return false;
  const bool a_larger = na.norm() >= nb.norm();
  const Face& large = a_larger ? a : b;
  const Face& small = a_larger ? b : a;
  return lies_on(mesh, large, centroid(mesh, small));
}

std::string face_name(const Face& f) {
  return std::string(name(f.type));
}

} // namespace

std::optional<HangingNodes> find_hanging_nodes(const Mesh& mesh) {
  const FaceList list = all_faces(mesh);
  std::unordered_map<CornerKey, std::vector<const Face*>, CornerKeyHash> groups;
  groups.reserve(list.faces.size());
  for (const Face& f : list.faces)
    groups[key_of(f)].push_back(&f);
  std::optional<HangingNodes> first;
  const auto note = [&](Index c, Index other, std::string how) {
    if (c > other)
      std::swap(c, other);
    if (!first || std::make_pair(c, other) < std::make_pair(first->cell, first->other))
      first = HangingNodes{c, other, std::move(how)};
  };
  std::vector<const Face*> boundary; // faces of one cell only
  for (const auto& [corners, faces] : groups) {
    if (faces.size() == 1) {
      boundary.push_back(faces.front());
      continue;
    }
    for (std::size_t i = 1; i < faces.size(); ++i)
      if (faces[i]->type != faces[0]->type)
        note(faces[0]->cell, faces[i]->cell,
             fmt::format("meet on a {} face and a {} face with the same corners: the mid-edge "
                         "nodes of the quadratic one hang",
                         face_name(*faces[0]), face_name(*faces[i])));
  }
  // boundary faces that share a node
  std::map<Index, std::vector<const Face*>> at_node; // in node order: the same message each run
  for (const Face* f : boundary)
    for (Index n : f->corners)
      at_node[n].push_back(f);
  for (const auto& [node, faces] : at_node)
    for (std::size_t i = 0; i < faces.size(); ++i)
      for (std::size_t j = i + 1; j < faces.size(); ++j)
        if (faces[i]->cell != faces[j]->cell && overlap(mesh, *faces[i], *faces[j])) {
          const bool in_order = faces[i]->cell < faces[j]->cell; // faces named as their cells
          const Face& a = in_order ? *faces[i] : *faces[j];
          const Face& b = in_order ? *faces[j] : *faces[i];
          note(a.cell, b.cell,
               fmt::format("meet on a {} face and a {} face that overlap without being the same "
                           "face (the node at ({:.6g}, {:.6g}, {:.6g}) is one of both): nodes of "
                           "one hang on the other",
                           face_name(a), face_name(b), mesh.node(node).x(), mesh.node(node).y(),
                           mesh.node(node).z()));
        }
  return first;
}

} // namespace trifem::mesh
