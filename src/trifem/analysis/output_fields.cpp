// SPDX-License-Identifier: MIT
#include "trifem/analysis/output_fields.hpp"

namespace trifem::analysis {
namespace {

/// mmol/mm^3 -> mM (mmol/L)
constexpr Real kPerLitre = 1e6;

io::DataArray array(std::string name, int components, Index count) {
  return {std::move(name), components, std::vector<double>(std::size_t(components) * count, 0.0)};
}

void set_vector(io::DataArray& a, Index i, const Vec3& v) {
  for (int k = 0; k < 3; ++k)
    a.values[3 * i + k] = v[k];
}

void set_tensor(io::DataArray& a, Index i, const Mat3& m) {
  const Vec6 v = voigt::stress(m);
  for (int k = 0; k < 6; ++k)
    a.values[6 * i + k] = v[k];
}

/// Nodal field values (physical units: ion fluxes are stored divided by c_ref).
io::DataArray nodal_vector(const model::Model& model, dofs::FieldId f, std::string name,
                           Real scale) {
  const Index n = model.mesh.num_nodes();
  io::DataArray a = array(std::move(name), 3, n);
  const Vector& x = model.problem->state();
  for (Index node = 0; node < n; ++node)
    for (int k = 0; k < 3; ++k)
      a.values[3 * node + k] = scale * x[model.dofs.dof(f, node, k)];
  return a;
}

/// Average of a cell array over the cells around each node.
io::DataArray nodal_average(const model::Model& model, const io::DataArray& cells,
                            std::string name) {
  const Index n = model.mesh.num_nodes();
  io::DataArray a = array(std::move(name), 1, n);
  std::vector<int> count(n, 0);
  for (Index c = 0; c < model.mesh.num_cells(); ++c)
    for (Index node : model.mesh.cell(c)) {
      a.values[node] += cells.values[c];
      ++count[node];
    }
  for (Index node = 0; node < n; ++node)
    if (count[node] > 0)
      a.values[node] /= count[node];
  return a;
}

void add_mixture_cells(const model::Model& model, std::vector<io::DataArray>& out) {
  const physics::MixtureTerm& mix = *model.mixture;
  const Index cells = model.mesh.num_cells();
  io::DataArray p = array("fluid_pressure [MPa]", 1, cells);
  io::DataArray mu_w = array("fluid_chemical_potential [MPa]", 1, cells);
  io::DataArray psi = array("electric_potential [mV]", 1, cells);
  io::DataArray cp = array("cation_concentration [mM]", 1, cells);
  io::DataArray cm = array("anion_concentration [mM]", 1, cells);
  io::DataArray cf = array("fixed_charge_density [mEq/L]", 1, cells);
  io::DataArray mup = array("cation_electrochemical_potential [mJ/mmol]", 1, cells);
  io::DataArray mum = array("anion_electrochemical_potential [mJ/mmol]", 1, cells);
  io::DataArray phi = array("water_volume_fraction", 1, cells);
  io::DataArray w = array("fluid_flux [mm/s]", 3, cells);
  io::DataArray current = array("current_density [A/mm^2]", 3, cells);
  const Vector& x = model.problem->state();
  for (Index e = 0; e < mix.num_elements(); ++e) {
    const Index c = mix.cell(e);
    const physics::MixtureCellOutput o = mix.output(e, x);
    p.values[c] = x[model.dofs.dof(model.fields.p, c, 0)];
    mu_w.values[c] = o.chem.mu_w;
    if (mix.has_ions()) {
      psi.values[c] =
          x[model.dofs.dof(model.fields.eta, c, 0)] / model.chem.c_ref / model.chem.faraday;
      cp.values[c] = o.chem.c_plus * kPerLitre;
      cm.values[c] = o.chem.c_minus * kPerLitre;
      cf.values[c] = o.chem.c_fixed * kPerLitre;
      mup.values[c] = o.chem.mu_plus;
      mum.values[c] = o.chem.mu_minus;
      set_vector(current, c, model.chem.faraday * (o.j_plus - o.j_minus));
    }
    phi.values[c] = o.chem.phi_w;
    set_vector(w, c, o.w);
  }
  out.push_back(std::move(p));
  out.push_back(std::move(mu_w));
  out.push_back(std::move(phi));
  out.push_back(std::move(w));
  if (!mix.has_ions())
    return;
  for (io::DataArray* a : {&psi, &cp, &cm, &cf, &mup, &mum, &current})
    out.push_back(std::move(*a));
}

} // namespace

std::vector<io::DataArray> point_fields(const model::Model& model) {
  const Vector& x = model.problem->state();
  const Vector& R = model.problem->full_residual();
  std::vector<io::DataArray> out;
  out.push_back(nodal_vector(model, model.fields.u, "displacement [mm]", 1.0));
  io::DataArray reaction = array("reaction_forces [N]", 3, model.mesh.num_nodes());
  for (Index a = 0; a < model.mesh.num_nodes(); ++a)
    for (int k = 0; k < 3; ++k)
      if (const Index d = model.dofs.dof(model.fields.u, a, k); model.dofs.is_constrained(d))
        reaction.values[3 * a + k] = R[d];
  out.push_back(std::move(reaction));
  if (!model.mixture)
    return out;
  out.push_back(nodal_vector(model, model.fields.w, "fluid_flux [mm/s]", 1.0));
  if (model.fields.j_plus.valid()) {
    out.push_back(
        nodal_vector(model, model.fields.j_plus, "cation_flux [mmol/(mm^2 s)]", model.chem.c_ref));
    out.push_back(
        nodal_vector(model, model.fields.j_minus, "anion_flux [mmol/(mm^2 s)]", model.chem.c_ref));
  }
  // nodal averages of the element-constant pressure and potential (for smooth contours)
  io::DataArray p = array("p", 1, model.mesh.num_cells()), psi = p;
  for (Index e = 0; e < model.mixture->num_elements(); ++e) {
    const Index c = model.mixture->cell(e);
    p.values[c] = x[model.dofs.dof(model.fields.p, c, 0)];
    if (model.fields.eta.valid())
      psi.values[c] =
          x[model.dofs.dof(model.fields.eta, c, 0)] / model.chem.c_ref / model.chem.faraday;
  }
  out.push_back(nodal_average(model, p, "fluid_pressure [MPa]"));
  if (model.fields.eta.valid())
    out.push_back(nodal_average(model, psi, "electric_potential [mV]"));
  return out;
}

std::vector<io::DataArray> cell_fields(const model::Model& model) {
  const Vector& x = model.problem->state();
  const Index cells = model.mesh.num_cells();
  io::DataArray stress = array("stress [MPa]", 6, cells);
  io::DataArray solid_stress = array("solid_stress [MPa]", 6, cells);
  io::DataArray volume = array("relative_volume", 1, cells);
  if (model.solid)
    for (Index e = 0; e < model.solid->num_elements(); ++e) {
      const physics::CellStress s = model.solid->stress(e, x);
      set_tensor(stress, model.solid->cell(e), s.cauchy);
      set_tensor(solid_stress, model.solid->cell(e), s.cauchy);
      volume.values[model.solid->cell(e)] = s.J;
    }
  if (model.mixture)
    for (Index e = 0; e < model.mixture->num_elements(); ++e) {
      const Index c = model.mixture->cell(e);
      const physics::MixtureCellOutput o = model.mixture->output(e, x);
      const Real p = x[model.dofs.dof(model.fields.p, c, 0)];
      set_tensor(solid_stress, c, o.solid_stress);
      set_tensor(stress, c, o.solid_stress - p * Mat3::Identity());
      volume.values[c] = o.J;
    }
  std::vector<io::DataArray> out;
  out.push_back(std::move(stress));
  out.push_back(std::move(solid_stress));
  out.push_back(std::move(volume));
  if (model.mixture)
    add_mixture_cells(model, out);
  return out;
}

} // namespace trifem::analysis
