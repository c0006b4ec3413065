// SPDX-License-Identifier: MIT
// [[output.probe]] columns of history.csv: nodal fields interpolated at the probe's point, cell
// quantities of the cell that contains it.
#pragma once

#include "trifem/analysis/cell_values.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace trifem::analysis {

/// History column names of the quantity `q` under the prefix `name` with their units, e.g.
/// "top.uz [mm]", "centre.fluid_pressure [MPa]", "centre.stress_xy [MPa]": displacements are
/// `<name>.ux`, positions `<name>.x`, other vectors and tensors `<name>.<quantity>_<component>`.
std::vector<std::string> quantity_columns(std::string_view name, const io::ProbeQuantity& q);

/// The nodal quantity `q` (an io::ProbeLocation::Node quantity) at the natural coordinates `xi`
/// of `cell` at the state x, interpolated with the cell's shape functions, in physical units.
Vec3 nodal_quantity(const model::Model& model, const io::ProbeQuantity& q, Index cell,
                    const Vec3& xi, const Vector& x);

/// History column names of a probe with their units, e.g. "top.uz [mm]",
/// "centre.fluid_pressure [MPa]", "centre.stress_xy [MPa]".
std::vector<std::string> probe_columns(const model::Probe& probe);

/// Appends the probe's values at the state x (one per column).
void append_probe_values(const model::Model& model, const CellEvaluator& cells,
                         const model::Probe& probe, const Vector& x, std::vector<double>& row);

} // namespace trifem::analysis
