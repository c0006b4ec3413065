// SPDX-License-Identifier: MIT
// A quadrature rule on the unit half sphere for the fibre distributions: the cubed sphere with
// a Gauss-Legendre rule on each face.
#pragma once

#include "trifem/core/types.hpp"
#include "trifem/material/schema.hpp"

#include <string>

#include <vector>

namespace trifem::material {

/// The resolutions a fibre distribution may ask for.
inline constexpr Real kMinSphereResolution = 3.0, kMaxSphereResolution = 64.0;

/// The `resolution` parameter of the fibre distributions (default 12).
ParameterSchema resolution_schema();
/// InputError naming `context.resolution` unless it is an integer.
void check_resolution(const ParameterValues& params, const std::string& context);

/// The directions n of the half sphere (n and -n give the same terms) and their weights w of
/// `resolution` x `resolution` Gauss-Legendre points in equiangular coordinates on each of the
/// three cube faces x = 1, y = 1, z = 1 (3 resolution^2 directions). The weights have the
/// symmetries of the cube and are corrected once so that the rule integrates every polynomial
/// of degree <= 5 in n exactly (n (x) n and n (x) n (x) n (x) n included); they are not
/// normalised (the caller divides by their sum).
struct SphereRule {
  std::vector<Vec3> directions;
  std::vector<Real> weights;
};
SphereRule sphere_rule(int resolution);

} // namespace trifem::material
