// SPDX-License-Identifier: MIT
// Programmatic two-body contact models for the contact verification tests (pattern of
// tests/verification/solid_model.hpp): tensor-product hex blocks with given node coordinates,
// a displacement field, a contact-pressure field on the slave nodes and a ContactTerm.
#pragma once

#include "mapped_mesh.hpp"
#include "trifem/assembly/fe_problem.hpp"
#include "trifem/contact/contact_term.hpp"
#include "trifem/linalg/linear_solver.hpp"
#include "trifem/material/registry.hpp"
#include "trifem/mesh/box.hpp"
#include "trifem/physics/solid_term.hpp"
#include "trifem/solver/newton.hpp"

#include <cmath>
#include <memory>

namespace trifem::test {

/// A block of hex8 cells with node (i, j, k) at (xs[i], ys[j], zs[k]) (strictly increasing
/// lists); surfaces "<name>.xmin" ... "<name>.zmax", cell block <name>, node set <name>.all.
inline mesh::Mesh make_block(const std::string& name, const std::vector<Real>& xs,
                             const std::vector<Real>& ys, const std::vector<Real>& zs) {
  mesh::BoxSpec spec;
  spec.name = name;
  spec.divisions = {static_cast<int>(xs.size()) - 1, static_cast<int>(ys.size()) - 1,
                    static_cast<int>(zs.size()) - 1};
  const std::array<const std::vector<Real>*, 3> lists{&xs, &ys, &zs};
  return map_nodes(mesh::make_box(spec), [&](const Vec3& X) {
    Vec3 x;
    for (int d = 0; d < 3; ++d)
      x[d] = (*lists[d])[static_cast<std::size_t>(std::lround(X[d] * spec.divisions[d]))];
    return x;
  });
}

/// n + 1 coordinates of [a, b] in n equal cells, the interior ones shifted by `offset` cells
/// (0 ≤ offset < 1): the mesh "slid" by a fraction of an element, end points kept.
inline std::vector<Real> shifted_coordinates(Real a, Real b, int n, Real offset = 0) {
  std::vector<Real> x(n + 1);
  const Real h = (b - a) / n;
  for (int i = 0; i <= n; ++i)
    x[i] = (i == 0 || i == n) ? a + i * h : a + (i + offset) * h;
  x[n] = b;
  return x;
}

/// Two blocks of one hyperelastic material in contact through master/slave surfaces.
struct ContactModel {
  mesh::Mesh mesh;
  dofs::DofMap dofs;
  dofs::FieldId u, lambda;
  std::shared_ptr<const material::ElasticLaw> law;
  std::string master_name, slave_name;
  std::vector<dofs::DirichletCondition> conditions;
  std::vector<std::unique_ptr<physics::Term>> loads;
  const physics::SolidTerm* solid = nullptr;
  contact::ContactTerm* contact = nullptr;
  std::unique_ptr<assembly::FeProblem> problem;

  ContactModel(mesh::Mesh m, const std::string& law_type, material::ParameterValues params,
               std::string master, std::string slave)
      : mesh(std::move(m)), law(material::create_law(law_type, params, "test")),
        master_name(std::move(master)), slave_name(std::move(slave)) {
    u = dofs.add_field("displacement", FieldRole::displacement, mesh.num_nodes(), 3);
    const Index slave_nodes = static_cast<Index>(mesh.node_set(slave_name).size());
    lambda = dofs.add_field("contact_pressure", FieldRole::multiplier, slave_nodes, 1);
  }

  /// Fixes component k of the nodes to value * curve(t) (ramp 0..1 by default).
  void prescribe(const std::vector<Index>& nodes, int k, Real value = 0,
                 dofs::LoadCurve curve = dofs::LoadCurve({{0, 0}, {1, 1}},
                                                         dofs::Interpolation::Linear)) {
    dofs::DirichletCondition c{{}, value, std::move(curve)};
    for (Index n : nodes)
      c.dofs.push_back(dofs.dof(u, n, k));
    conditions.push_back(std::move(c));
  }

  /// Finalizes DOFs and builds solid + loads + contact (call once, after all conditions).
  void build(contact::ContactSettings settings) {
    dofs::constrain_all(conditions, dofs);
    dofs.finalize();
    std::vector<Index> cells(mesh.num_cells());
    for (Index c = 0; c < mesh.num_cells(); ++c)
      cells[c] = c;
    std::vector<std::unique_ptr<physics::Term>> terms;
    auto s = std::make_unique<physics::SolidTerm>(
        mesh, dofs, u, cells,
        std::vector<std::shared_ptr<const material::ElasticLaw>>(mesh.num_cells(), law));
    solid = s.get();
    terms.push_back(std::move(s));
    for (auto& l : loads)
      terms.push_back(std::move(l));
    auto c = std::make_unique<contact::ContactTerm>(
        mesh, dofs, u, lambda, mesh.surface(master_name), mesh.surface(slave_name),
        std::make_shared<contact::FrictionlessLaw>(u), settings);
    contact = c.get();
    terms.push_back(std::move(c));
    const Real L = 1.0, E = law->p_wave_modulus();
    problem = std::make_unique<assembly::FeProblem>(
        dofs, conditions, std::move(terms),
        std::vector<solver::FieldScale>{{"displacement", E * L * L, L},
                                        {"contact_pressure", L * L * L, E}});
  }

  /// One Newton solve of the step ending at `time`.
  solver::NewtonReport solve_step(Real time, Real dt, solver::NewtonSettings settings = {}) {
    solver::NewtonSolver newton(settings, linalg::make_linear_solver({LinearSolverKind::umfpack}));
    problem->begin_step(time, dt);
    solver::NewtonReport report = newton.solve(*problem);
    if (report.status == solver::SolveStatus::Converged)
      problem->commit_step();
    return report;
  }

  /// Mean x displacement of the nodes of a node set.
  Real mean_displacement(const std::string& set, int i) const {
    const auto& nodes = mesh.node_set(set);
    Real sum = 0;
    for (Index n : nodes)
      sum += problem->state()[dofs.dof(u, n, i)];
    return sum / static_cast<Real>(nodes.size());
  }

  /// Contact pressure t_k of slave node k.
  Real pressure(Index k) const { return problem->state()[contact->multiplier_dof(k, 0)]; }
};

} // namespace trifem::test
