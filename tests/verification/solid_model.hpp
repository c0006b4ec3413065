// SPDX-License-Identifier: MIT
// Small programmatic solid models for the verification tests (no case files involved).
#pragma once

#include "trifem/assembly/fe_problem.hpp"
#include "trifem/linalg/linear_solver.hpp"
#include "trifem/material/registry.hpp"
#include "trifem/mesh/box.hpp"
#include "trifem/physics/solid_term.hpp"
#include "trifem/solver/newton.hpp"

#include <memory>

namespace trifem::test {

/// A box of one material with its displacement field; conditions and loads added by the test.
struct SolidModel {
  mesh::Mesh mesh;
  dofs::DofMap dofs;
  dofs::FieldId u;
  std::shared_ptr<const material::ElasticLaw> law;
  std::vector<dofs::DirichletCondition> conditions;
  std::vector<std::unique_ptr<physics::Term>> loads;
  physics::SolidElement element = physics::SolidElement::Displacement; ///< of every cell
  const physics::SolidTerm* solid = nullptr;
  std::unique_ptr<assembly::FeProblem> problem;

  SolidModel(mesh::Mesh m, const std::string& law_type, material::ParameterValues params)
      : mesh(std::move(m)), law(material::create_law(law_type, params, "test")) {
    u = dofs.add_field("displacement", FieldRole::displacement, mesh.num_nodes(), 3);
  }

  /// Fixes component k of the nodes to value * curve(t) (curve = t by default: ramp 0..1).
  void prescribe(const std::vector<Index>& nodes, int k, Real value,
                 dofs::LoadCurve curve = dofs::LoadCurve({{0, 0}, {1, 1}},
                                                         dofs::Interpolation::Linear)) {
    dofs::DirichletCondition c{{}, value, std::move(curve)};
    for (Index n : nodes)
      c.dofs.push_back(dofs.dof(u, n, k));
    conditions.push_back(std::move(c));
  }

  /// Finalizes DOFs and builds the problem (call once, after all conditions).
  void build() {
    dofs::constrain_all(conditions, dofs);
    dofs.finalize();
    std::vector<Index> cells(mesh.num_cells());
    std::vector<std::shared_ptr<const material::ElasticLaw>> laws(mesh.num_cells(), law);
    for (Index c = 0; c < mesh.num_cells(); ++c)
      cells[c] = c;
    std::vector<std::unique_ptr<physics::Term>> terms;
    auto s = std::make_unique<physics::SolidTerm>(
        mesh, dofs, u, cells, laws, std::vector<physics::SolidElement>(cells.size(), element));
    solid = s.get();
    terms.push_back(std::move(s));
    for (auto& l : loads)
      terms.push_back(std::move(l));
    const Real L = 1.0;
    problem = std::make_unique<assembly::FeProblem>(
        dofs, conditions, std::move(terms),
        std::vector<solver::FieldScale>{{"displacement", law->p_wave_modulus() * L * L, L}});
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

  Vec3 displacement(Index node) const {
    const Vector& x = problem->state();
    return {x[dofs.dof(u, node, 0)], x[dofs.dof(u, node, 1)], x[dofs.dof(u, node, 2)]};
  }
};

} // namespace trifem::test
