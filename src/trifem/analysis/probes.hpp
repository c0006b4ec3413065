// SPDX-License-Identifier: MIT
// [[output.probe]] columns of history.csv: nodal fields interpolated at the probe's point, cell
// quantities of the cell that contains it.
#pragma once

#include "trifem/analysis/cell_values.hpp"

#include <string>
#include <vector>

namespace trifem::analysis {

/// History column names of a probe with their units, e.g. "top.uz [mm]",
/// "centre.fluid_pressure [MPa]", "centre.stress_xy [MPa]".
std::vector<std::string> probe_columns(const model::Probe& probe);

/// Appends the probe's values at the state x (one per column).
void append_probe_values(const model::Model& model, const CellEvaluator& cells,
                         const model::Probe& probe, const Vector& x, std::vector<double>& row);

} // namespace trifem::analysis
