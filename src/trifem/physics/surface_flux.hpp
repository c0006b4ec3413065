// SPDX-License-Identifier: MIT
// Flux of a nodal vector field through a surface in the current configuration.
#pragma once

#include "trifem/dofs/dof_map.hpp"
#include "trifem/mesh/mesh.hpp"

#include <vector>

namespace trifem::physics {

/// Outflow  sum_facets int j . n da  of the nodal field `flux` (times `scale`) through the
/// facets, on the surface deformed by the displacement field `u` of state x. Exact for the
/// bilinear interpolation (2x2 Gauss on each quad4 facet); on the other facets the flux is that
/// of their corners (physics::mixture_flux_map), by the facet's rule.
Real surface_outflow(const mesh::Mesh& mesh, const dofs::DofMap& dofs, dofs::FieldId u,
                     dofs::FieldId flux, const std::vector<mesh::Facet>& facets, const Vector& x,
                     Real scale = 1.0);

} // namespace trifem::physics
