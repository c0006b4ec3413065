// SPDX-License-Identifier: MIT
#include "trifem/dofs/nodal_frames.hpp"

#include "trifem/core/error.hpp"

#include <map>

namespace trifem::dofs {
namespace {

/// Area-weighted normals (reference configuration) at the nodes of a facet list.
std::map<Index, Vec3> nodal_normals(const mesh::Mesh& mesh, const std::vector<mesh::Facet>& fs) {
  std::map<Index, Vec3> normals;
  for (const mesh::Facet& f : fs) {
    const Vec3 d1 = mesh.node(f.nodes[2]) - mesh.node(f.nodes[0]);
    const Vec3 d2 = mesh.node(f.nodes[3]) - mesh.node(f.nodes[1]);
    const Vec3 area = 0.5 * d1.cross(d2); // exact area vector of a planar quad
    for (Index n : f.nodes) {
      auto [it, inserted] = normals.try_emplace(n, Vec3::Zero());
      it->second += area;
    }
  }
  for (auto& [n, v] : normals)
    v.normalize();
  return normals;
}

/// Orthonormal basis whose first vectors span the given normals (Gram-Schmidt, dependent
/// directions dropped); returns the number of independent normals.
int basis_from(const std::vector<Vec3>& normals, Mat3& Q) {
  int k = 0;
  for (const Vec3& v : normals) {
    Vec3 r = v;
    for (int j = 0; j < k; ++j)
      r -= r.dot(Q.col(j)) * Q.col(j);
    if (r.norm() > 1e-3 && k < 3)
      Q.col(k++) = r.normalized();
  }
  const int independent = k;
  for (int axis = 0; k < 3 && axis < 3; ++axis) {
    Vec3 r = Vec3::Unit(axis);
    for (int j = 0; j < k; ++j)
      r -= r.dot(Q.col(j)) * Q.col(j);
    if (r.norm() > 1e-3)
      Q.col(k++) = r.normalized();
  }
  return independent;
}

} // namespace

NodalFrames::NodalFrames(std::vector<NodalFrame> frames, Index num_dofs)
    : frames_(std::move(frames)), frame_of_(num_dofs, -1) {
  for (std::size_t f = 0; f < frames_.size(); ++f)
    for (Index d : frames_[f].dofs) {
      TRIFEM_VERIFY(frame_of_[d] < 0, "DOF {} is in two frames", d);
      frame_of_[d] = static_cast<int>(f);
    }
}

void NodalFrames::to_global(Vector& x) const {
  for (const NodalFrame& f : frames_) {
    const Vec3 local(x[f.dofs[0]], x[f.dofs[1]], x[f.dofs[2]]);
    const Vec3 global = f.Q * local;
    for (int k = 0; k < 3; ++k)
      x[f.dofs[k]] = global[k];
  }
}

void NodalFrames::to_local(Vector& x) const {
  for (const NodalFrame& f : frames_) {
    const Vec3 global(x[f.dofs[0]], x[f.dofs[1]], x[f.dofs[2]]);
    const Vec3 local = f.Q.transpose() * global;
    for (int k = 0; k < 3; ++k)
      x[f.dofs[k]] = local[k];
  }
}

std::vector<NodalFrame> normal_frames(const mesh::Mesh& mesh, const DofMap& map,
                                      const std::vector<FieldId>& fields,
                                      const std::vector<std::vector<mesh::Facet>>& faces,
                                      std::vector<Index>& constrained) {
  std::map<Index, std::vector<Vec3>> per_node;
  for (const auto& list : faces)
    for (const auto& [node, n] : nodal_normals(mesh, list))
      per_node[node].push_back(n);
  std::vector<NodalFrame> frames;
  for (const auto& [node, normals] : per_node) {
    Mat3 Q;
    const int k = basis_from(normals, Q);
    for (FieldId f : fields) {
      NodalFrame frame{{map.dof(f, node, 0), map.dof(f, node, 1), map.dof(f, node, 2)}, Q};
      for (int j = 0; j < k; ++j)
        constrained.push_back(frame.dofs[j]);
      frames.push_back(frame);
    }
  }
  return frames;
}

} // namespace trifem::dofs
