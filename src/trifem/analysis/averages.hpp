// SPDX-License-Identifier: MIT
// [[output.average]] columns of history.csv: a quantity averaged over the cells of a cell block,
// weighted by the volume its io::AverageWeight names (reference, current or water volume).
#pragma once

#include "trifem/analysis/cell_values.hpp"

#include <string>
#include <vector>

namespace trifem::analysis {

/// History column names of an average with their units, named like those of a probe of the
/// same quantity: "block.stress_zz [MPa]", "block.uz [mm]", "block.relative_volume".
std::vector<std::string> average_columns(const model::Average& average);

/// Appends the average's values at the state x (one per column): Σ_c ∫ f w / Σ_c ∫ w over the
/// block's cells c, integrated with the 2x2x2 Gauss rule of the element. A nodal field f is
/// interpolated at the Gauss points; a cell quantity is the cell's value of the VTU output,
/// constant over the cell. The weight w is dV (reference), dv = J dV (current) or φʷ dv (water).
void append_average_values(const model::Model& model, const CellEvaluator& cells,
                           const model::Average& average, const Vector& x,
                           std::vector<double>& row);

} // namespace trifem::analysis
