// SPDX-License-Identifier: MIT
// Rejection of states that are not deformations of the body: a cell turned inside out.
#pragma once

#include "trifem/dofs/dof_map.hpp"
#include "trifem/mesh/mesh.hpp"

#include <string>
#include <vector>

namespace trifem::physics {

/// Why the displacements `x` (field `u`) are not a deformation of `cells`: the first cell that has
/// turned a corner inside out (fe::hex8_reversed_corner), named with its block and reference
/// centre; "" if none has. Such a state (the body pushed through itself or its support, everted)
/// can satisfy equilibrium with det F > 0 at every Gauss point, so Newton may converge to it; the
/// time loop must reject the step instead.
std::string folded_cell_rejection(const mesh::Mesh& mesh, const dofs::DofMap& dofs, dofs::FieldId u,
                                  const std::vector<Index>& cells, const Vector& x);

} // namespace trifem::physics
