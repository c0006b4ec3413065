// SPDX-License-Identifier: MIT
// Rotated nodal frames: the three DOFs of a nodal vector field at a node hold components in a
// local basis (global = Q local), so that normal components on faces that are not aligned with
// the axes can be constrained like any other DOF.
#pragma once

#include "trifem/dofs/dof_map.hpp"
#include "trifem/mesh/mesh.hpp"
#include "trifem/tensor/tensor.hpp"

#include <array>
#include <vector>

namespace trifem::dofs {

/// One rotated triple: columns of Q are the local basis vectors in global components.
struct NodalFrame {
  std::array<Index, 3> dofs{};
  Mat3 Q = Mat3::Identity();
};

/// Rotated frames of a set of fields and the conversions of all-DOF vectors.
class NodalFrames {
public:
  NodalFrames() = default;
  explicit NodalFrames(std::vector<NodalFrame> frames, Index num_dofs);

  bool empty() const { return frames_.empty(); }
  const std::vector<NodalFrame>& frames() const { return frames_; }
  /// Frame of a DOF and its position (0..2) in the frame, or -1.
  int frame_of(Index dof) const { return dof < Index(frame_of_.size()) ? frame_of_[dof] : -1; }

  /// Local -> global components (in place on a copy).
  void to_global(Vector& x) const;
  /// Global -> local components.
  void to_local(Vector& x) const;

private:
  std::vector<NodalFrame> frames_;
  std::vector<int> frame_of_;
};

/// Frames from face normals: every node of the given facet lists gets, for each field in
/// `fields`, a frame whose first local axes are its (area-averaged, reference-configuration)
/// normals to each list it belongs to, orthonormalised; `constrained` receives the DOFs of the
/// normal components (one per independent normal at the node). Merge the frames of several
/// calls (different fields) into one NodalFrames.
std::vector<NodalFrame> normal_frames(const mesh::Mesh& mesh, const DofMap& map,
                                      const std::vector<FieldId>& fields,
                                      const std::vector<std::vector<mesh::Facet>>& faces,
                                      std::vector<Index>& constrained);

} // namespace trifem::dofs
