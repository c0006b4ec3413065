// SPDX-License-Identifier: MIT
#include "trifem/physics/folded_cells.hpp"

#include "trifem/fe/hex8.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace trifem::physics {
namespace {

/// A corner reversed by more than half its reference measure is turned over, not folded by the
/// discretization: the free cube de-swelling in a concentrated bath
/// (OsmoticLoading.FreeCubeInConcentratedBath) folds a corner of an outer cell by a few percent
/// of its measure and unfolds it again; the everted block of tests/fuzz/reproducers reverses
/// corners by 2 to 63 times their reference measure.
constexpr Real kTurnedOver = 0.5;

/// The name of the cell block holding `cell` ("" if none).
std::string block_of(const mesh::Mesh& mesh, Index cell) {
  for (const auto& [name, cells] : mesh.cell_blocks())
    if (std::find(cells.begin(), cells.end(), cell) != cells.end())
      return name;
  return {};
}

} // namespace

std::string folded_cell_rejection(const mesh::Mesh& mesh, const dofs::DofMap& dofs, dofs::FieldId u,
                                  const std::vector<Index>& cells, const Vector& x) {
  for (Index c : cells) {
    if (mesh.cell_type(c) != mesh::CellType::Hex8)
      continue; // (J <= 0 at a point of another cell fails its evaluation)
    fe::HexCoords X, xc;
    const auto& nodes = mesh.cell(c);
    for (int a = 0; a < 8; ++a)
      for (int k = 0; k < 3; ++k) {
        X(a, k) = mesh.node(nodes[a])[k];
        xc(a, k) = X(a, k) + x[dofs.dof(u, nodes[a], k)];
      }
    const auto reversed = fe::hex8_reversed_corner(X, xc, kTurnedOver);
    if (!reversed)
      continue;
    const Vec3 centre = X.colwise().mean().transpose();
    const std::string block = block_of(mesh, c);
    return fmt::format("{}{} (reference centre {:.4g} {:.4g} {:.4g}) turned inside out at "
                       "its node {} (its volume map there is reversed, det ratio {:.3g}): the "
                       "body would pass through itself or its support, which no deformation "
                       "can (check the prescribed motion and the supports)",
                       mesh.describe(c), block.empty() ? "" : fmt::format(" of block '{}'", block),
                       centre.x(), centre.y(), centre.z(), nodes[reversed->corner],
                       reversed->ratio);
  }
  return {};
}

} // namespace trifem::physics
