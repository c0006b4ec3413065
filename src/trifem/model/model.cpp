// SPDX-License-Identifier: MIT
#include "trifem/model/model.hpp"

#include "trifem/core/error.hpp"
#include "trifem/core/log.hpp"
#include "trifem/fe/refine_cells.hpp"
#include "trifem/material/registry.hpp"
#include "trifem/mesh/gmsh_reader.hpp"
#include "trifem/model/averages.hpp"
#include "trifem/model/cell_axes.hpp"
#include "trifem/model/cell_families.hpp"
#include "trifem/model/conditions.hpp"
#include "trifem/model/constraints.hpp"
#include "trifem/model/contact_pairs.hpp"
#include "trifem/model/rigid_bodies.hpp"
#include "trifem/model/steps.hpp"
#include "trifem/model/support_check.hpp"

#include <set>

namespace trifem::model {

physics::SolidElement solid_element(io::SolidElementSpec requested,
                                    const material::ElasticLaw& law) {
  switch (requested) {
  case io::SolidElementSpec::Displacement:
    return physics::SolidElement::Displacement;
  case io::SolidElementSpec::MeanDilatation:
    return physics::SolidElement::MeanDilatation;
  case io::SolidElementSpec::Auto:
    break;
  }
  const Real mu = law.shear_modulus();
  const Real bulk = law.p_wave_modulus() - 4.0 / 3.0 * mu;
  return bulk >= kNearlyIncompressible * mu ? physics::SolidElement::MeanDilatation
                                            : physics::SolidElement::Displacement;
}

namespace {

std::vector<CellMaterial> cell_materials(const io::CaseSpec& spec, const mesh::Mesh& mesh,
                                         const std::map<std::string, std::string>& blocks) {
  std::map<std::string, CellMaterial> by_name;
  for (const auto& [name, m] : spec.materials) {
    const std::string ctx = "materials." + name;
    CellMaterial cm;
    cm.name = name;
    if (!m.is_mixture()) {
      cm.solid = material::create_law(m.solid_law(), ctx);
      cm.element = solid_element(m.element, *cm.solid);
    } else {
      std::shared_ptr<const material::ElasticLaw> solid =
          material::create_law(*m.solid, ctx + ".solid");
      cm.mixture = std::make_shared<material::MixtureProperties>(
          material::make_mixture(m.type == "triphasic", std::move(solid), m.parameters, ctx));
    }
    cm.density = m.density.value_or(0.0);
    by_name[name] = cm;
  }
  std::vector<CellMaterial> per_cell(mesh.num_cells());
  for (const auto& [block, material] : blocks) {
    const std::string& name = block; // a lambda may not capture a structured binding (Clang 14)
    for (Index c : with_context("mesh", [&] { return mesh.cell_block(name); }))
      per_cell[c] = by_name.at(material);
  }
  std::vector<char> rigid(mesh.num_cells(), 0);
  for (const io::RigidBodySpec& b : spec.rigid_bodies)
    for (const std::string& block : b.blocks)
      for (Index c : with_context(b.key + ".blocks", [&] { return mesh.cell_block(block); })) {
        TRIFEM_CHECK(per_cell[c].rigid(),
                     "{}.blocks: {} of block '{}' has the material '{}' (the cells of a "
                     "rigid body have none)",
                     b.key, mesh.describe(c), block, per_cell[c].name);
        per_cell[c].name = b.name;
        per_cell[c].density = b.density.value_or(0.0); // none: massless
        rigid[c] = 1;
      }
  for (Index c = 0; c < mesh.num_cells(); ++c)
    TRIFEM_CHECK(!per_cell[c].rigid() || rigid[c],
                 "mesh: {} has no material (assign one to its cell block, or name the block "
                 "in a [[rigid_body]]'s blocks)",
                 mesh.describe(c));
  return per_cell;
}

void add_fields(const std::vector<CellMaterial>& materials, Model& model) {
  bool mixture = false, ions = false, tets = false;
  for (const auto& m : materials) {
    mixture = mixture || m.mixture;
    ions = ions || (m.mixture && m.mixture->charged);
  }
  for (Index c = 0; c < model.mesh.num_cells(); ++c)
    tets = tets || (materials[static_cast<std::size_t>(c)].mixture &&
                    mesh::linear_type(model.mesh.cell_type(c)) == mesh::CellType::Tet4);
  const Index nodes = model.mesh.num_nodes(), cells = model.mesh.num_cells();
  physics::MixtureFields& f = model.fields;
  f.u = model.dofs.add_field("displacement", FieldRole::displacement, nodes, 3);
  if (mixture)
    f.w = model.dofs.add_field("fluid_flux", FieldRole::flux, nodes, 3);
  if (ions) {
    f.j_plus = model.dofs.add_field("cation_flux", FieldRole::flux, nodes, 3);
    f.j_minus = model.dofs.add_field("anion_flux", FieldRole::flux, nodes, 3);
  }
  if (mixture)
    f.p = model.dofs.add_field("pressure", FieldRole::potential, cells, 1);
  if (ions)
    f.eta = model.dofs.add_field("electric_potential", FieldRole::potential, cells, 1);
  if (tets) // (the potentials of tets are linear from their corners)
    f.p_corner = model.dofs.add_field("corner_pressure", FieldRole::potential, nodes, 1);
  if (tets && ions)
    f.eta_corner =
        model.dofs.add_field("corner_electric_potential", FieldRole::potential, nodes, 1);
}

/// Bulk terms: a solid term for pure-solid cells, a mixture term for mixture cells.
std::vector<std::unique_ptr<physics::Term>>
bulk_terms(const io::CaseSpec& spec, const std::vector<CellMaterial>& materials, Model& model) {
  std::vector<Index> solid_cells, mixture_cells;
  std::vector<std::shared_ptr<const material::ElasticLaw>> laws;
  std::vector<physics::SolidElement> elements;
  std::vector<std::shared_ptr<const material::MixtureProperties>> mixtures;
  for (Index c = 0; c < model.mesh.num_cells(); ++c) {
    if (materials[c].mixture) {
      mixture_cells.push_back(c);
      mixtures.push_back(materials[c].mixture);
    } else if (materials[c].solid) { // not a rigid cell
      solid_cells.push_back(c);
      laws.push_back(materials[c].solid);
      elements.push_back(cell_element(model, c));
    }
  }
  std::vector<std::unique_ptr<physics::Term>> terms;
  if (!solid_cells.empty()) {
    auto t = std::make_unique<physics::SolidTerm>(model.mesh, model.dofs, model.fields.u,
                                                  solid_cells, laws, elements);
    model.solid = t.get();
    terms.push_back(std::move(t));
  }
  if (!mixture_cells.empty()) {
    std::optional<dofs::LoadCurve> ramp;
    if (!spec.analysis.fixed_charge_curve.empty())
      ramp = make_curve(spec, spec.analysis.fixed_charge_curve);
    auto t = std::make_unique<physics::MixtureTerm>(model.mesh, model.dofs, model.fields,
                                                    mixture_cells, mixtures, model.chem, ramp);
    t->set_lumped_flux_mass(spec.analysis.flux_mass == io::FluxMass::Lumped);
    model.mixture = t.get();
    terms.push_back(std::move(t));
  }
  return terms;
}

/// DOFs that no term touches (nodes outside every cell, ion DOFs of biphasic regions, ...)
/// are fixed at zero: they would make the Jacobian singular. So are the fluxes that only a
/// contact pair touches: those of a solid or rigid body facing a mixture, impermeable. Tied DOFs
/// count as one unknown (used if one of them is); the nodes of rotating rigid bodies follow their
/// body and the bodies' unknowns are reached through them: neither is fixed. Nor are DOFs
/// `conditions` constrain already.
dofs::DirichletCondition unused_dofs(const Model& model,
                                     const std::vector<std::unique_ptr<physics::Term>>& terms,
                                     const std::vector<dofs::DirichletCondition>& conditions) {
  const dofs::DofMap& map = model.dofs;
  std::vector<char> used(map.num_dofs(), 0);
  std::vector<Index> dofs;
  for (const auto& t : terms)
    for (Index e = 0; e < t->num_elements(); ++e) {
      t->element_dofs(e, dofs);
      for (Index d : dofs) // (contact alone does not use a flux: a solid or rigid side's is 0)
        if (!t->joins_bodies() || map.field(map.field_of(d)).role != FieldRole::flux)
          used[map.leader(d)] = 1;
    }
  for (const auto& c : conditions)
    for (Index d : c.dofs)
      used[d] = 1;
  dofs::DirichletCondition c;
  for (Index d = 0; d < map.num_dofs(); ++d)
    if (!used[map.leader(d)] && !used[d] && !map.is_dependent(d) &&
        map.field(map.field_of(d)).role != FieldRole::rigid_motion)
      c.dofs.push_back(d);
  return c;
}

/// A rotating body whose nodes carry no mass (no `density`, no tissue cell at its nodes) and
/// that is free to move: its unknowns balance statically in the dynamic steps (a warning).
void warn_of_massless_bodies(const io::CaseSpec& spec, const Model& model,
                             const physics::InertiaTerm& inertia) {
  const Vector lumped = inertia.lumped_mass();
  for (std::size_t i = 0; i < model.rigid_bodies.size(); ++i) {
    if (model.rigid_bodies[i].rotating < 0)
      continue;
    const dofs::RigidBodyDofs& b =
        model.problem->rigid_map().bodies()[model.rigid_bodies[i].rotating];
    Real mass = 0.0;
    for (const auto& follower : b.followers)
      mass += lumped[follower[0]];
    bool free = false;
    for (int k = 0; k < 3; ++k)
      free = free || !model.dofs.is_constrained(b.translation[k]) ||
             !model.dofs.is_constrained(b.rotation[k]);
    if (mass == 0.0 && free)
      log::warn(
          "warning: {}: the body has no mass (no density and no tissue cell at its nodes): in the "
          "dynamic steps its free motions balance statically; give its cells a density "
          "for their inertia",
          spec.rigid_bodies[i].key);
  }
}

/// The inertia of every cell with mass (the reader requires a density of every material; the
/// cells of a rigid body without one are massless) and of the rigid bodies' shells, for the
/// dynamic steps of the case. The unknowns of rotating rigid bodies have no mass of their own:
/// the inertia of the nodes they carry reaches them by condensation.
std::unique_ptr<physics::InertiaTerm> inertia_term(const io::CaseSpec& spec, const Model& model) {
  std::vector<Index> cells;
  std::vector<Real> densities;
  for (Index c = 0; c < model.mesh.num_cells(); ++c)
    if (model.materials[c].density > 0.0) {
      cells.push_back(c);
      densities.push_back(model.materials[c].density);
    }
  std::vector<Index> massless;
  for (const dofs::RigidBodyDofs& b : model.problem->rigid_map().bodies()) {
    massless.insert(massless.end(), b.translation.begin(), b.translation.end());
    massless.insert(massless.end(), b.rotation.begin(), b.rotation.end());
  }
  const physics::MassMatrix mass = spec.dynamics.mass == io::MassMatrixSpec::Lumped
                                       ? physics::MassMatrix::Lumped
                                       : physics::MassMatrix::Consistent;
  std::vector<physics::MassElement> masses =
      physics::cell_mass_elements(model.mesh, cells, densities);
  for (physics::MassElement& shell : rigid_shell_masses(spec, model))
    masses.push_back(std::move(shell));
  auto term = std::make_unique<physics::InertiaTerm>(
      model.dofs, model.fields.u, std::move(masses), mass,
      physics::GeneralizedAlpha::from_spectral_radius(spec.dynamics.rho_inf), std::move(massless));
  warn_of_massless_bodies(spec, model, *term);
  return term;
}

void set_scales(const std::vector<CellMaterial>& materials, Model& model) {
  Vec3 lo = model.mesh.node(0), hi = model.mesh.node(0);
  for (const Vec3& x : model.mesh.nodes()) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  model.length_scale = (hi - lo).norm();
  model.modulus_scale = 0.0;
  for (const auto& m : materials) {
    if (m.rigid())
      continue;
    const auto& solid = m.mixture ? m.mixture->solid : m.solid;
    model.modulus_scale = std::max(model.modulus_scale, solid->p_wave_modulus());
    if (m.mixture)
      model.permeability_scale = std::max(model.permeability_scale, m.mixture->permeability);
  }
  if (model.modulus_scale == 0.0) // rigid cells only: the scales of a unit modulus
    model.modulus_scale = 1.0;
}

/// Characteristic sizes per field: length L, modulus M, flux M kappa / L; residual scales are
/// the energy M L^3 over the size (rows are energy-conjugate to their unknowns).
std::vector<solver::FieldScale> field_scales(const Model& model) {
  const Real L = model.length_scale, M = model.modulus_scale;
  const Real flux = M * model.permeability_scale / L, energy = M * L * L * L;
  std::vector<solver::FieldScale> s(model.dofs.num_fields());
  const physics::MixtureFields& f = model.fields;
  for (auto [id, size] : {std::pair{f.u, L},
                          {f.w, flux},
                          {f.j_plus, flux},
                          {f.j_minus, flux},
                          {f.p, M},
                          {f.eta, M},
                          {f.p_corner, M},
                          {f.eta_corner, M}})
    if (id.valid())
      s[id.index] = {model.dofs.field(id).name, energy / size, size};
  // rotating rigid bodies: their center moves like the tissue, their rotation is of order 1 rad;
  // the multipliers of the connectors: forces and moments
  for (auto [id, size] : {std::pair{model.rigid_translation, L},
                          {model.rigid_rotation, 1.0},
                          {model.joint_forces, M * L * L},
                          {model.joint_moments, M * L * L * L},
                          {model.constraint_forces, M * L * L}})
    if (id.valid())
      s[id.index] = {model.dofs.field(id).name, energy / size, size};
  for (const RigidWall& w : model.walls) // nodal contact forces
    s[w.field.index] = {model.dofs.field(w.field).name, energy / (M * L * L), M * L * L};
  return s;
}

material::Electrochemistry electrochemistry(const io::ElectrochemistrySpec& e) {
  material::Electrochemistry c;
  c.R = e.R;
  c.T = e.T;
  c.faraday = e.faraday;
  c.c_ref = e.bath_concentration;
  c.gamma_bath = e.bath_activity;
  c.osmotic_bath = e.bath_osmotic;
  return c;
}

/// The [[initial_velocity]] entries added to the starting velocity `v` (every DOF, empty: at
/// rest). A node carried by a rigid body moves with it: an error naming the entry. Prescribed
/// components keep their prescribed motion (said once in a warning).
void add_initial_velocities(const io::CaseSpec& spec, const Model& model, Vector& v) {
  if (spec.initial_velocities.empty())
    return;
  if (v.size() == 0)
    v = Vector::Zero(model.dofs.num_dofs());
  Index prescribed = 0;
  for (const io::InitialVelocitySpec& s : spec.initial_velocities) {
    const auto& nodes = with_context(
        s.key + ".set", [&]() -> const std::vector<Index>& { return model.mesh.node_set(s.set); });
    for (const Index node : nodes)
      for (int k = 0; k < 3; ++k) {
        const Index dof = model.dofs.dof(model.fields.u, node, k);
        TRIFEM_CHECK(!model.dofs.is_dependent(dof) && model.dofs.leader(dof) == dof,
                     "{}: node {} of the set '{}' is carried by a rigid body, which moves it: "
                     "give the body its velocity ([[rigid_body]] velocity) instead",
                     s.key, node, s.set);
        if (model.dofs.is_constrained(dof)) {
          prescribed += s.value[k] != 0.0 ? 1 : 0;
          continue;
        }
        v[dof] = s.value[k];
      }
  }
  if (prescribed > 0)
    log::warn("warning: initial_velocity: {} prescribed displacement component(s) of its nodes "
              "keep their prescribed motion",
              prescribed);
}

} // namespace

mesh::Mesh build_mesh(const io::CaseSpec& spec, std::map<std::string, std::string>& materials) {
  mesh::Mesh mesh;
  for (const auto& b : spec.boxes) {
    mesh.append(mesh::make_box(b.box));
    if (!b.material.empty()) // the cells of a rigid body otherwise
      materials[b.box.name] = b.material;
  }
  for (std::size_t i = 0; i < spec.gmsh.size(); ++i) {
    const auto& g = spec.gmsh[i];
    const auto path = g.file.is_absolute() ? g.file : spec.file.parent_path() / g.file;
    mesh::Mesh part = mesh::read_gmsh(path);
    for (const auto& [block, material] : g.materials) {
      TRIFEM_CHECK(part.has_cell_block(block),
                   "mesh.gmsh[{}].materials: '{}' is not a physical volume of {}", i + 1, block,
                   path.string());
      materials[block] = material;
    }
    with_context(fmt::format("mesh.gmsh[{}]", i + 1), [&] {
      mesh.append(part);
      return 0;
    });
  }
  for (std::size_t i = 0; i < spec.meshes.size(); ++i) {
    const auto& m = spec.meshes[i];
    for (const auto& [block, material] : m.materials) {
      TRIFEM_CHECK(m.mesh.has_cell_block(block), "mesh[{}].materials: '{}' is not a cell block",
                   i + 1, block);
      materials[block] = material;
    }
    with_context(fmt::format("mesh[{}]", i + 1), [&] {
      mesh.append(m.mesh);
      return 0;
    });
  }
  TRIFEM_CHECK(mesh.num_cells() > 0 || !spec.rigid_bodies.empty(),
               "mesh: the model has no cells (and no rigid body its surface meshes could make)");
  if (spec.mesh_refinement > 0) // [mesh] refine: the refined mesh replaces the given one
    mesh = fe::refine_uniformly(mesh, spec.mesh_refinement);
  return mesh;
}

std::unique_ptr<Model> build_model(const io::CaseSpec& spec) {
  auto model = std::make_unique<Model>();
  std::map<std::string, std::string> block_materials;
  model->mesh = build_mesh(spec, block_materials);
  model->materials = cell_materials(spec, model->mesh, block_materials);
  check_cell_families(spec, *model);
  model->axes = orient_cells(spec, model->mesh, block_materials, model->materials);
  const std::vector<CellMaterial>& materials = model->materials;
  model->chem = electrochemistry(spec.electrochemistry);
  add_fields(materials, *model);
  add_contact_fields(spec, *model);
  set_scales(materials, *model);

  auto terms = bulk_terms(spec, materials, *model);
  for (auto& t : contact_terms(spec, *model))
    terms.push_back(std::move(t));
  for (auto& t : load_terms(spec, *model)) {
    model->loads.push_back(t.get());
    terms.push_back(std::move(t));
  }
  auto bcs = boundary_conditions(spec, *model);
  for (auto& t : constraint_terms(spec, *model, bcs)) // before the rigid bodies: may fix DOFs
    terms.push_back(std::move(t));
  RigidBodyParts rigid = rigid_bodies(spec, *model, bcs);
  for (auto& t : rigid.loads) {       // before unused_dofs: connectors use their multipliers
    if (t.get() != model->connectors) // the bodies' forces and moments
      model->loads.push_back(t.get());
    terms.push_back(std::move(t));
  }
  bcs.push_back(unused_dofs(*model, terms, bcs));
  dofs::NodalFrames frames = impermeable_surfaces(spec, *model, bcs);
  check_frames_of_rotating_bodies(spec, *model, frames);
  model->case_conditions = bcs;
  for (auto& t : step_terms(spec, *model)) {
    model->loads.push_back(t.get());
    terms.push_back(std::move(t));
  }
  dofs::constrain_all(bcs, model->dofs);
  model->dofs.finalize();

  model->problem = std::make_unique<assembly::FeProblem>(model->dofs, std::move(bcs),
                                                         std::move(terms), field_scales(*model),
                                                         std::move(frames), std::move(rigid.map));
  model->problem->set_node_positions(model->fields.u, model->mesh.nodes());
  if (spec.has_dynamic_step())
    model->problem->add_inertia(inertia_term(spec, *model));
  if (spec.has_motion()) {
    model->initial_velocity = initial_rigid_velocity(spec, *model);
    add_initial_velocities(spec, *model, model->initial_velocity);
  } else if (!spec.initial_velocities.empty()) {
    log::warn("warning: {}: an initial velocity applies to dynamic analyses only; this "
              "quasi-static analysis ignores it",
              spec.initial_velocities.front().key);
  }
  if (model->mixture) {
    Vector x = model->problem->state();
    const auto kind = spec.analysis.initial_state == io::InitialStateKind::DonnanPrestressed
                          ? physics::InitialState::DonnanPrestressed
                          : physics::InitialState::Donnan;
    model->mixture->initialize(kind, 0.0, x);
    model->problem->set_state(x);
  }
  if (spec.has_static_step())
    check_support(spec, *model);
  add_outputs(spec, *model);
  model->averages = make_averages(spec, *model);
  return model;
}

int node_owner(const Model& model, Index node) {
  const std::vector<int>& owner = model.problem->equation_owners();
  if (owner.empty())
    return -1;
  for (int c = 0; c < 3; ++c)
    if (const Index eq = model.problem->dof_map().equation(model.dofs.dof(model.fields.u, node, c));
        eq >= 0)
      return owner[eq];
  return -1;
}

} // namespace trifem::model
