// SPDX-License-Identifier: MIT
#include "trifem/io/probe_quantities.hpp"

#include <array>

namespace trifem::io {
namespace {

using enum ProbeLocation;
using enum ProbeRequirement;
using enum AverageWeight;

constexpr std::array kQuantities = {
    ProbeQuantity{"displacement", "mm", 3, Node, None, Reference},
    ProbeQuantity{"position", "mm", 3, Node, None, Reference},
    ProbeQuantity{"fluid_flux", "mm/s", 3, Node, Mixture, Current},
    ProbeQuantity{"cation_flux", "mmol/(mm^2 s)", 3, Node, Ions, Current},
    ProbeQuantity{"anion_flux", "mmol/(mm^2 s)", 3, Node, Ions, Current},
    ProbeQuantity{"stress", "MPa", 6, Cell, None, Current},
    ProbeQuantity{"solid_stress", "MPa", 6, Cell, None, Current},
    ProbeQuantity{"relative_volume", "", 1, Cell, None, Reference},
    ProbeQuantity{"fluid_pressure", "MPa", 1, Cell, Mixture, Current},
    ProbeQuantity{"fluid_chemical_potential", "MPa", 1, Cell, Mixture, Current},
    ProbeQuantity{"water_volume_fraction", "", 1, Cell, Mixture, Current},
    ProbeQuantity{"electric_potential", "mV", 1, Cell, Ions, Current},
    ProbeQuantity{"cation_concentration", "mM", 1, Cell, Ions, Water},
    ProbeQuantity{"anion_concentration", "mM", 1, Cell, Ions, Water},
    ProbeQuantity{"fixed_charge_density", "mEq/L", 1, Cell, Ions, Water},
    ProbeQuantity{"cation_electrochemical_potential", "mJ/mmol", 1, Cell, Ions, Current},
    ProbeQuantity{"anion_electrochemical_potential", "mJ/mmol", 1, Cell, Ions, Current},
    ProbeQuantity{"current_density", "A/mm^2", 3, Cell, Ions, Current},
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

bool material_has(const ProbeQuantity& q, bool mixture, bool charged) {
  switch (q.requirement) {
  case None:
    return true;
  case Mixture:
    return mixture;
  case Ions:
    return mixture && charged;
  }
  return false;
}

std::string_view required_material(const ProbeQuantity& q) {
  switch (q.requirement) {
  case None:
    return "any";
  case Mixture:
    return "biphasic or triphasic";
  case Ions:
    return "triphasic";
  }
  return "any";
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
