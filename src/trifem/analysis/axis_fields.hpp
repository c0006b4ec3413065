// SPDX-License-Identifier: MIT
// The VTU cell arrays of the material axes: e1 in the reference configuration and the current
// direction of the material fibre along it.
#pragma once

#include "trifem/io/vtu_writer.hpp"
#include "trifem/model/model.hpp"

#include <vector>

namespace trifem::analysis {

/// The deformation gradient F = I + sum_a u_a (x) dN_a/dX at the centre (xi = 0) of `cell` at
/// the state `x` (all DOFs, global components).
Mat3 centre_deformation_gradient(const model::Model& model, Index cell, const Vector& x);

/// With material axes (model.axes not empty): the cell arrays `material_axis` (e1 of each cell
/// in the reference configuration; the global x axis in cells of materials without axes) and
/// `fibre_direction` (F e1 / |F e1| with F at the cell centre: where the material line along
/// e1 points now). Nothing without axes.
std::vector<io::DataArray> axis_fields(const model::Model& model, const Vector& x);

} // namespace trifem::analysis
