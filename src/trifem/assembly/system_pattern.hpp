// SPDX-License-Identifier: MIT
// Sparsity of the free-free (K_ff) and free-constrained (K_fc) blocks, built once from the
// element DOF stencils of all terms and reused across iterations and steps.
#pragma once

#include "trifem/dofs/dof_map.hpp"
#include "trifem/physics/term.hpp"

#include <memory>
#include <span>
#include <vector>

namespace trifem::assembly {

/// Element stencils of one term, flattened: dofs of element e are dofs[offsets[e]..offsets[e+1]).
struct Stencils {
  std::vector<Index> offsets;
  std::vector<Index> dofs;
  std::span<const Index> of(Index e) const {
    return {dofs.data() + offsets[e], static_cast<std::size_t>(offsets[e + 1] - offsets[e])};
  }
  Index size() const { return static_cast<Index>(offsets.size()) - 1; }
};

/// Collects the stencils of a term.
Stencils collect_stencils(const physics::Term& term);

/// Greedy colouring: elements of one colour share no DOF, so they can be assembled in
/// parallel without races, in an order that does not depend on the thread count.
std::vector<std::vector<Index>> colour_elements(const Stencils& stencils, Index num_dofs);
/// As above, treating DOFs tied to one unknown (DofMap::tie) as one DOF.
std::vector<std::vector<Index>> colour_elements(const Stencils& stencils, const dofs::DofMap& map);

/// Zero-valued K_ff (equations x equations) and K_fc (equations x constrained DOFs) with the
/// union of all stencil couplings; compressed, sorted row indices per column.
struct SystemPattern {
  SparseMatrix Kff;
  SparseMatrix Kfc;
};
SystemPattern build_pattern(const dofs::DofMap& map, const std::vector<const Stencils*>& stencils);

} // namespace trifem::assembly
