// SPDX-License-Identifier: MIT
#include "trifem/io/probe_quantities.hpp"

#include <array>

namespace trifem::io {
namespace {

using enum ProbeLocation;
using enum ProbeRequirement;

constexpr std::array kQuantities = {
    ProbeQuantity{"displacement", "mm", 3, Node, None},
    ProbeQuantity{"position", "mm", 3, Node, None},
    ProbeQuantity{"fluid_flux", "mm/s", 3, Node, Mixture},
    ProbeQuantity{"cation_flux", "mmol/(mm^2 s)", 3, Node, Ions},
    ProbeQuantity{"anion_flux", "mmol/(mm^2 s)", 3, Node, Ions},
    ProbeQuantity{"stress", "MPa", 6, Cell, None},
    ProbeQuantity{"solid_stress", "MPa", 6, Cell, None},
    ProbeQuantity{"relative_volume", "", 1, Cell, None},
    ProbeQuantity{"fluid_pressure", "MPa", 1, Cell, Mixture},
    ProbeQuantity{"fluid_chemical_potential", "MPa", 1, Cell, Mixture},
    ProbeQuantity{"water_volume_fraction", "", 1, Cell, Mixture},
    ProbeQuantity{"electric_potential", "mV", 1, Cell, Ions},
    ProbeQuantity{"cation_concentration", "mM", 1, Cell, Ions},
    ProbeQuantity{"anion_concentration", "mM", 1, Cell, Ions},
    ProbeQuantity{"fixed_charge_density", "mEq/L", 1, Cell, Ions},
    ProbeQuantity{"cation_electrochemical_potential", "mJ/mmol", 1, Cell, Ions},
    ProbeQuantity{"anion_electrochemical_potential", "mJ/mmol", 1, Cell, Ions},
    ProbeQuantity{"current_density", "A/mm^2", 3, Cell, Ions},
};

} // namespace

std::span<const ProbeQuantity> probe_quantities() {
  return kQuantities;
}

const ProbeQuantity* find_probe_quantity(std::string_view name) {
  for (const ProbeQuantity& q : kQuantities)
    if (q.name == name)
      return &q;
  return nullptr;
}

std::string_view component_suffix(int components, int k) {
  static constexpr std::array<std::string_view, 3> vector = {"x", "y", "z"};
  static constexpr std::array<std::string_view, 6> tensor = {"xx", "yy", "zz", "xy", "yz", "xz"};
  if (components == 3)
    return vector[k];
  if (components == 6)
    return tensor[k];
  return "";
}

} // namespace trifem::io
