// SPDX-License-Identifier: MIT
// The arrays written to the volume VTU files (names follow FEBio's vocabulary with units).
#pragma once

#include "trifem/io/vtu_writer.hpp"
#include "trifem/model/model.hpp"

namespace trifem::analysis {

/// Nodal arrays: displacement, reaction forces (`residual` at the constrained DOFs); with
/// mixtures the nodal fluxes and the nodal averages of pressure and electric potential.
std::vector<io::DataArray> point_fields(const model::Model& model, const Vector& residual);

/// Cell arrays: total and solid Cauchy stress, relative volume; with mixtures the element
/// chemistry (pressure, potentials, concentrations, fixed charge, porosity, current density);
/// with material axes their reference and current directions (axis_fields).
std::vector<io::DataArray> cell_fields(const model::Model& model);

} // namespace trifem::analysis
