// SPDX-License-Identifier: MIT
// Finds the cell that contains a point of the reference configuration and the point's natural
// coordinates in it (inverse of the isoparametric map of its family).
#pragma once

#include "trifem/fe/reference_element.hpp"
#include "trifem/mesh/mesh.hpp"

#include <optional>

namespace trifem::fe {

/// A point inside a cell: the cell and the natural coordinates xi in its reference domain
/// ([-1, 1]^3 for a hex).
struct CellPoint {
  Index cell = -1;
  Vec3 xi = Vec3::Zero();
};

/// The cell of `mesh` containing the reference point X, or nothing if no cell does. Points on
/// a face shared by several cells (up to 1e-8 of the cell size) belong to the first of them.
/// Natural coordinates within 1e-10 of -1, 0 or 1 (and 1/2 in the cells other than hex8, whose
/// mid-edge nodes are there) are snapped to them, so that a point on a node interpolates exactly
/// the nodal value.
std::optional<CellPoint> locate_point(const mesh::Mesh& mesh, const Vec3& X);

/// Natural coordinates of X in the cell with nodal coordinates `nodes` (Newton on the
/// trilinear map from the cell centre), or nothing if Newton does not converge (degenerate
/// cell or X far outside).
std::optional<Vec3> natural_coordinates(const Eigen::Matrix<Real, 8, 3>& nodes, const Vec3& X);

/// Natural coordinates of X in the cell of `reference`'s family with nodal coordinates `nodes`
/// (Newton on its map from the centroid of its reference domain), or nothing as above.
std::optional<Vec3> natural_coordinates(const ReferenceCell& reference, const CellNodeCoords& nodes,
                                        const Vec3& X);

} // namespace trifem::fe
