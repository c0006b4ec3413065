// SPDX-License-Identifier: MIT
// The cell quantities of the output (stress, relative volume, mixture chemistry) of one cell,
// in the units of the VTU arrays; shared by the VTU writer and the probes.
#pragma once

#include "trifem/model/model.hpp"

#include <string_view>
#include <vector>

namespace trifem::analysis {

/// Every cell quantity of one cell. Mixture and ion values are zero where the cell's material
/// has none.
struct CellValues {
  Mat3 stress = Mat3::Zero();       ///< total Cauchy stress [MPa]
  Mat3 solid_stress = Mat3::Zero(); ///< Cauchy stress of the solid [MPa]
  Real relative_volume = 1.0;       ///< J
  Real fluid_pressure = 0.0;        ///< p [MPa]
  Real fluid_chemical_potential = 0.0;
  Real water_volume_fraction = 0.0;
  Vec3 fluid_flux = Vec3::Zero();              ///< cell average of w [mm/s]
  Real electric_potential = 0.0;               ///< psi [mV]
  Real cation_concentration = 0.0;             ///< [mM]
  Real anion_concentration = 0.0;              ///< [mM]
  Real fixed_charge_density = 0.0;             ///< [mEq/L]
  Real cation_electrochemical_potential = 0.0; ///< [mJ/mmol]
  Real anion_electrochemical_potential = 0.0;  ///< [mJ/mmol]
  Vec3 current_density = Vec3::Zero();         ///< [A/mm^2]
};

/// Evaluates the cell quantities of a model's cells.
class CellEvaluator {
public:
  explicit CellEvaluator(const model::Model& model);
  /// The quantities of cell c at the state x (all DOFs, global components).
  CellValues values(Index c, const Vector& x) const;

private:
  const model::Model& model_;
  std::vector<Index> element_; ///< per cell: its element in the solid or the mixture term
};

/// Appends the components of the cell quantity `name` (an io::ProbeLocation::Cell quantity)
/// of `v` to `out`: scalars one value, vectors x y z, tensors xx yy zz xy yz xz.
void append_cell_quantity(const CellValues& v, std::string_view name, std::vector<double>& out);

} // namespace trifem::analysis
