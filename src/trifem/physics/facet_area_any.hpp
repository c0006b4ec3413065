// SPDX-License-Identifier: MIT
// Nodal area vectors of a facet of any family (tri3, tri6, quad4, quad8) in the current
// configuration and their derivative: a_a = ∫ N_a (x_s1 × x_s2) ds (= ∫ N_a n da), by the
// facet's rule (exact for flat and for quadratic facets). The follower pressure of a facet is
// f_a = −p a_a. The quad4 facets of the models keep facet_area.hpp.
#pragma once

#include "trifem/dofs/dof_map.hpp"
#include "trifem/fe/reference_element.hpp"
#include "trifem/mesh/mesh.hpp"

namespace trifem::physics {

/// The most DOFs of a facet: three per node.
inline constexpr int kMaxFacetDofs = 3 * fe::kMaxFacetNodes;

/// Current coordinates of a facet's nodes, one row per node.
using FacetPositions = Eigen::Matrix<Real, Eigen::Dynamic, 3, 0, fe::kMaxFacetNodes, 3>;
using FacetVectorX = Eigen::Matrix<Real, Eigen::Dynamic, 1, 0, kMaxFacetDofs, 1>;
using FacetMatrixX =
    Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxFacetDofs, kMaxFacetDofs>;

/// The coordinates of a facet's nodes (mesh::Facet::node order): the reference ones plus their
/// displacements (field u) in x, or the reference ones without x.
FacetPositions facet_positions(const mesh::Mesh& mesh, const mesh::Facet& f,
                               const dofs::DofMap* dofs = nullptr, dofs::FieldId u = {},
                               const Vector* x = nullptr);

/// The nodal area vectors (a_0, a_1, ...) of the facet of `reference`'s family with nodal
/// coordinates x and, if `derivative` is given, da_a/dx_b = ∫ N_a [N_b,s2 [x_s1]× − N_b,s1
/// [x_s2]×] ds.
FacetVectorX facet_area_vectors(const fe::ReferenceFacet& reference, const FacetPositions& x,
                                FacetMatrixX* derivative = nullptr);

/// The reference area ∫ |X_s1 × X_s2| ds of `facets`, each by its family's rule [mm²].
Real reference_area(const mesh::Mesh& mesh, const std::vector<mesh::Facet>& facets);

} // namespace trifem::physics
