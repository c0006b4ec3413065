// SPDX-License-Identifier: MIT
// Programmatic biphasic/triphasic box models for the verification tests.
#pragma once

#include "trifem/assembly/fe_problem.hpp"
#include "trifem/linalg/linear_solver.hpp"
#include "trifem/material/registry.hpp"
#include "trifem/mesh/box.hpp"
#include "trifem/mesh/convert_cells.hpp"
#include "trifem/physics/mixture_term.hpp"
#include "trifem/physics/surface_load_term.hpp"
#include "trifem/solver/newton.hpp"
#include "trifem/solver/time_loop.hpp"

#include <memory>

namespace trifem::test {

/// The paper's section 4.1 tissue (docs/theory/reference-solutions.md §R0), optionally uncharged
/// or biphasic, with the solid volume fraction `phi_s0`.
inline material::MixtureProperties paper_tissue(bool charged, Real fixed_charge = 2e-4,
                                                Real nu = 0.0, Real phi_s0 = 0.25) {
  auto solid = material::create_law("saint-venant-kirchhoff", {{"E", 0.3}, {"nu", nu}}, "solid");
  material::ParameterValues v = {{"phi_s0", phi_s0}, {"permeability", 1.07e-3}};
  if (charged) {
    v["fixed_charge"] = fixed_charge;
    v["d_plus"] = 5e-4;
    v["d_minus"] = 8e-4;
  }
  return material::make_mixture(charged, std::move(solid), v, "tissue");
}

/// A box of one mixture with u, w, (j+, j-,) p, (eta) fields.
struct MixtureModel {
  mesh::Mesh mesh;
  dofs::DofMap dofs;
  physics::MixtureFields f;
  material::Electrochemistry chem;
  std::shared_ptr<const material::MixtureProperties> props;
  std::vector<dofs::DirichletCondition> conditions;
  std::vector<std::unique_ptr<physics::Term>> loads;
  physics::MixtureTerm* mixture = nullptr;
  std::unique_ptr<assembly::FeProblem> problem;
  std::optional<dofs::LoadCurve> fixed_charge_curve; ///< free swelling from an uncharged state
  dofs::NodalFrames frames;                          ///< rotated nodal DOFs (optional)

  MixtureModel(mesh::Mesh m, material::MixtureProperties p) : mesh(std::move(m)) {
    props = std::make_shared<material::MixtureProperties>(std::move(p));
    f.u = dofs.add_field("displacement", FieldRole::displacement, mesh.num_nodes(), 3);
    f.w = dofs.add_field("fluid_flux", FieldRole::flux, mesh.num_nodes(), 3);
    if (props->charged) {
      f.j_plus = dofs.add_field("cation_flux", FieldRole::flux, mesh.num_nodes(), 3);
      f.j_minus = dofs.add_field("anion_flux", FieldRole::flux, mesh.num_nodes(), 3);
    }
    f.p = dofs.add_field("pressure", FieldRole::potential, mesh.num_cells(), 1);
    if (props->charged)
      f.eta = dofs.add_field("potential", FieldRole::potential, mesh.num_cells(), 1);
    bool tets = false;
    for (Index c = 0; c < mesh.num_cells(); ++c)
      tets = tets || mesh::linear_type(mesh.cell_type(c)) == mesh::CellType::Tet4;
    if (tets) {
      f.p_corner = dofs.add_field("pressure_corner", FieldRole::potential, mesh.num_nodes(), 1);
      if (props->charged)
        f.eta_corner =
            dofs.add_field("potential_corner", FieldRole::potential, mesh.num_nodes(), 1);
    }
  }

  /// Fixes component k of `field` on a node set to value * curve(t).
  void fix(const std::string& set, dofs::FieldId field, int k, Real value = 0.0,
           dofs::LoadCurve curve = dofs::LoadCurve::constant()) {
    dofs::DirichletCondition c{{}, value, std::move(curve)};
    for (Index n : mesh.node_set(set))
      c.dofs.push_back(dofs.dof(field, n, k));
    conditions.push_back(std::move(c));
  }
  /// No normal flux of water and ions through an axis-aligned face with normal axis k.
  void impermeable(const std::string& set, int k) {
    for (dofs::FieldId fl : {f.w, f.j_plus, f.j_minus})
      if (fl.valid())
        fix(set, fl, k);
  }

  /// Fixes the fluxes of the nodes that are no cell's corner (the mid-edge nodes of tet10 and
  /// hex20 cells): the fluxes are interpolated from the corners (physics::mixture_flux_map), so
  /// no element uses them (the models fix every unused DOF so).
  bool tet_corner(Index n) const {
    for (Index c = 0; c < mesh.num_cells(); ++c)
      if (mesh::linear_type(mesh.cell_type(c)) == mesh::CellType::Tet4)
        for (Index m : mesh.cell_nodes(c).first(4))
          if (m == n)
            return true;
    return false;
  }
  void fix_mid_edge_fluxes() {
    std::vector<char> corner(static_cast<std::size_t>(mesh.num_nodes()), 0);
    for (Index c = 0; c < mesh.num_cells(); ++c)
      for (Index n :
           mesh.cell_nodes(c).first(static_cast<std::size_t>(mesh::num_corners(mesh.cell_type(c)))))
        corner[static_cast<std::size_t>(n)] = 1;
    dofs::DirichletCondition c{{}, 0.0, dofs::LoadCurve::constant()};
    for (Index n = 0; n < mesh.num_nodes(); ++n)
      if (!corner[static_cast<std::size_t>(n)])
        for (dofs::FieldId fl : {f.w, f.j_plus, f.j_minus})
          for (int k = 0; k < 3 && fl.valid(); ++k)
            c.dofs.push_back(dofs.dof(fl, n, k));
    for (Index n = 0; n < mesh.num_nodes(); ++n) // the corner potentials but at tets' corners
      if (!corner[static_cast<std::size_t>(n)] || !tet_corner(n))
        for (dofs::FieldId fl : {f.p_corner, f.eta_corner})
          if (fl.valid())
            c.dofs.push_back(dofs.dof(fl, n, 0));
    for (Index cell = 0; cell < mesh.num_cells(); ++cell) // tets' cell potentials
      if (f.p_corner.valid() && mesh::linear_type(mesh.cell_type(cell)) == mesh::CellType::Tet4)
        for (dofs::FieldId fl : {f.p, f.eta})
          if (fl.valid())
            c.dofs.push_back(dofs.dof(fl, cell, 0));
    if (!c.dofs.empty())
      conditions.push_back(std::move(c));
  }

  /// Finalizes the model; initial state IC-1 (Donnan at the reference) unless told otherwise.
  void build(physics::InitialState initial = physics::InitialState::Donnan) {
    fix_mid_edge_fluxes();
    dofs::constrain_all(conditions, dofs);
    dofs.finalize();
    std::vector<Index> cells(mesh.num_cells());
    for (Index c = 0; c < mesh.num_cells(); ++c)
      cells[c] = c;
    auto term = std::make_unique<physics::MixtureTerm>(
        mesh, dofs, f, cells,
        std::vector<std::shared_ptr<const material::MixtureProperties>>(cells.size(), props), chem,
        fixed_charge_curve);
    mixture = term.get();
    std::vector<std::unique_ptr<physics::Term>> terms;
    terms.push_back(std::move(term));
    for (auto& l : loads)
      terms.push_back(std::move(l));
    problem =
        std::make_unique<assembly::FeProblem>(dofs, conditions, std::move(terms), scales(), frames);
    Vector x = problem->state();
    mixture->initialize(initial, 0.0, x);
    problem->set_state(x);
  }

  /// Characteristic sizes: length L, modulus M, flux M kappa / L; residuals = M L^3 / size.
  std::vector<solver::FieldScale> scales() const {
    const Real L = 1.0, M = props->solid->p_wave_modulus();
    const Real flux = M * props->permeability / L, energy = M * L * L * L;
    std::vector<solver::FieldScale> s(dofs.num_fields());
    auto set = [&](dofs::FieldId id, Real size) {
      if (id.valid())
        s[id.index] = {dofs.field(id).name, energy / size, size};
    };
    set(f.u, L);
    set(f.w, flux);
    set(f.j_plus, flux);
    set(f.j_minus, flux);
    set(f.p, M);
    set(f.eta, M);
    set(f.p_corner, M);
    set(f.eta_corner, M);
    return s;
  }

  /// Runs the time loop to `end` with initial step dt (growth allowed up to dt_max).
  solver::RunReport run(Real end, Real dt, Real dt_max, std::vector<Real> must_points = {},
                        const solver::StepObserver& observer = {}) {
    solver::StepSettings s;
    s.start_time = problem->time();
    s.end_time = end;
    s.dt = dt;
    s.dt_max = dt_max;
    s.dt_min = dt * 1e-4;
    s.target_iterations = 5;
    s.must_points = std::move(must_points);
    solver::StepController controller(s);
    solver::NewtonSolver newton({}, linalg::make_linear_solver({LinearSolverKind::umfpack}));
    return solver::run_time_loop(
        *problem, newton, controller, observer ? observer : [](const solver::StepInfo&) {});
  }

  Real value(dofs::FieldId field, Index entity, int k = 0) const {
    return problem->state()[dofs.dof(field, entity, k)];
  }
};

/// Terzaghi's confined creep: a laterally confined, impermeable column of n box cells along z
/// (1 x 1 x 1 mm) turned into `type` cells, bottom fixed and impermeable, top free-draining under a
/// step compressive traction sigma0 [MPa]. One box cell across: every corner is on a lateral
/// face (a tet10's mid-edge nodes inside the column move freely).
inline MixtureModel creep_column(int n, material::MixtureProperties props, Real sigma0,
                                 mesh::CellType type = mesh::CellType::Hex8) {
  mesh::BoxSpec spec;
  spec.divisions = {1, 1, n};
  mesh::Mesh box = mesh::make_box(spec);
  MixtureModel m(type == mesh::CellType::Hex8 ? std::move(box) : mesh::convert_cells(box, type),
                 std::move(props));
  for (int k = 0; k < 2; ++k) {
    m.fix("box.all", m.f.u, k);
    m.impermeable("box.all", k);
  }
  m.fix("box.zmin", m.f.u, 2);
  m.impermeable("box.zmin", 2);
  m.loads.push_back(std::make_unique<physics::TractionTerm>(
      m.mesh, m.dofs, m.f.u, m.mesh.surface("box.zmax").facets, Vec3(0, 0, -sigma0),
      dofs::LoadCurve({{0.0, 0.0}, {1e-9, 1.0}}, dofs::Interpolation::Linear)));
  m.build();
  return m;
}

} // namespace trifem::test
