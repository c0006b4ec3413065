// SPDX-License-Identifier: MIT
// Nodal area vectors of a quad4 facet in the current configuration and their derivative:
// a_a = int N_a (x_xi x x_eta) dxi deta  (= int N_a n da), exact by 2x2 Gauss.
#pragma once

#include "trifem/fe/hex8.hpp"

namespace trifem::physics {

using FacetVector = Eigen::Matrix<Real, 12, 1>; ///< (a_0, a_1, a_2, a_3)
using FacetMatrix = Eigen::Matrix<Real, 12, 12>;

/// Nodal area vectors a_a of the facet with current nodal coordinates x (rows) and, if
/// `derivative` is given, da_a/dx_b = int N_a [N_b,eta skew(x_xi) - N_b,xi skew(x_eta)].
FacetVector facet_area_vectors(const fe::QuadCoords& x, FacetMatrix* derivative = nullptr);

} // namespace trifem::physics
