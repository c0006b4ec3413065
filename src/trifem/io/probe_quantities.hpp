// SPDX-License-Identifier: MIT
// The quantities an [[output.probe]] can record: nodal fields interpolated at the point, and
// the cell quantities of the VTU output in the cell that contains it. An [[output.average]]
// records the same quantities averaged over a cell block.
#pragma once

#include <span>
#include <string>
#include <string_view>

namespace trifem::io {

/// Where a probed quantity lives.
enum class ProbeLocation {
  Node, ///< a nodal field, interpolated with the cell's shape functions
  Cell, ///< a cell quantity (constant per cell), the value of the containing cell
};

/// Which models have the quantity.
enum class ProbeRequirement {
  None,    ///< every model
  Mixture, ///< a biphasic or triphasic material at the point
  Ions,    ///< a triphasic material at the point
};

/// The volume over which an [[output.average]] averages the quantity.
enum class AverageWeight {
  Reference, ///< the reference volume: material quantities (displacement, position, J)
  Current,   ///< the current volume: spatial quantities (stresses, pressure, fluxes, ...)
  Water,     ///< the current water volume: concentrations per water volume
};

/// One probe quantity: its case-file name (also its history column prefix), unit (empty:
/// dimensionless), number of components (1 scalar, 3 vector x y z, 6 symmetric tensor
/// xx yy zz xy yz xz), location, requirement and the volume its block averages weight by.
struct ProbeQuantity {
  std::string_view name;
  std::string_view unit;
  int components;
  ProbeLocation location;
  ProbeRequirement requirement;
  AverageWeight weight;
};

/// Every probe quantity, in the order of docs/input.md.
std::span<const ProbeQuantity> probe_quantities();

/// The quantity called `name`, or null.
const ProbeQuantity* find_probe_quantity(std::string_view name);

/// True if a material has the quantity: a mixture (biphasic or triphasic) if `mixture`, with
/// ions (triphasic) if also `charged`.
bool material_has(const ProbeQuantity& q, bool mixture, bool charged);

/// The materials that have the quantity, for messages: "biphasic or triphasic", "triphasic" or
/// "any".
std::string_view required_material(const ProbeQuantity& q);

/// Suffixes of the history columns of one component: "x" "y" "z" for vectors, "xx" "yy" "zz"
/// "xy" "yz" "xz" for tensors, "" for scalars.
std::string_view component_suffix(int components, int k);

} // namespace trifem::io
