// SPDX-License-Identifier: MIT
#include "trifem/analysis/cell_values.hpp"

#include "trifem/core/error.hpp"

namespace trifem::analysis {
namespace {

/// mmol/mm^3 -> mM (mmol/L)
constexpr Real kPerLitre = 1e6;

void add_mixture_values(const model::Model& model, const physics::MixtureCellOutput& o, Index c,
                        const Vector& x, CellValues& v) {
  const auto [pressure, eta] = physics::cell_potentials(model.mesh, model.dofs, model.fields, x, c);
  v.fluid_pressure = pressure;
  v.solid_stress = o.solid_stress;
  v.stress = o.solid_stress - v.fluid_pressure * Mat3::Identity();
  v.relative_volume = o.J;
  v.fluid_chemical_potential = o.chem.mu_w;
  v.water_volume_fraction = o.chem.phi_w;
  v.fluid_flux = o.w;
  if (!model.mixture->has_ions())
    return;
  v.electric_potential = eta / model.chem.c_ref / model.chem.faraday;
  v.cation_concentration = o.chem.c_plus * kPerLitre;
  v.anion_concentration = o.chem.c_minus * kPerLitre;
  v.fixed_charge_density = o.chem.c_fixed * kPerLitre;
  v.cation_electrochemical_potential = o.chem.mu_plus;
  v.anion_electrochemical_potential = o.chem.mu_minus;
  v.current_density = model.chem.faraday * (o.j_plus - o.j_minus);
}

void append_vector(const Vec3& a, std::vector<double>& out) {
  out.insert(out.end(), {a.x(), a.y(), a.z()});
}

void append_tensor(const Mat3& a, std::vector<double>& out) {
  const Vec6 v = voigt::stress(a);
  out.insert(out.end(), v.begin(), v.end());
}

} // namespace

CellEvaluator::CellEvaluator(const model::Model& model)
    : model_(model), element_(model.mesh.num_cells(), -1) {
  if (model.solid)
    for (Index e = 0; e < model.solid->num_elements(); ++e)
      element_[model.solid->cell(e)] = e;
  if (model.mixture)
    for (Index e = 0; e < model.mixture->num_elements(); ++e)
      element_[model.mixture->cell(e)] = e;
}

CellValues CellEvaluator::values(Index c, const Vector& x) const {
  CellValues v;
  const Index e = element_[c];
  if (model_.materials[c].rigid()) // moves rigidly: no strain, no stress
    return v;
  if (model_.materials[c].mixture) {
    add_mixture_values(model_, model_.mixture->output(e, x), c, x, v);
  } else {
    const physics::CellStress s = model_.solid->stress(e, x);
    v.stress = v.solid_stress = s.cauchy;
    v.relative_volume = s.J;
  }
  return v;
}

void append_cell_quantity(const CellValues& v, std::string_view name, std::vector<double>& out) {
  const std::pair<std::string_view, Real> scalars[] = {
      {"relative_volume", v.relative_volume},
      {"fluid_pressure", v.fluid_pressure},
      {"fluid_chemical_potential", v.fluid_chemical_potential},
      {"water_volume_fraction", v.water_volume_fraction},
      {"electric_potential", v.electric_potential},
      {"cation_concentration", v.cation_concentration},
      {"anion_concentration", v.anion_concentration},
      {"fixed_charge_density", v.fixed_charge_density},
      {"cation_electrochemical_potential", v.cation_electrochemical_potential},
      {"anion_electrochemical_potential", v.anion_electrochemical_potential},
  };
  for (const auto& [key, value] : scalars)
    if (key == name) {
      out.push_back(value);
      return;
    }
  if (name == "stress")
    append_tensor(v.stress, out);
  else if (name == "solid_stress")
    append_tensor(v.solid_stress, out);
  else if (name == "fluid_flux")
    append_vector(v.fluid_flux, out);
  else if (name == "current_density")
    append_vector(v.current_density, out);
  else
    TRIFEM_VERIFY(false, "{} is not a cell quantity", name);
}

} // namespace trifem::analysis
