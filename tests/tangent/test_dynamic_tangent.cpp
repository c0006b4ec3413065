// SPDX-License-Identifier: MIT
// Finite-difference check of the tangent of an implicit dynamic step (generalized-α): the
// Jacobian of (1 − α_f) g(x) + α_f g_n + M a_{n+1-α_m}(x) over the free equations, in motion
// (after a step that left a velocity, an acceleration and a residual history), on a graded
// mesh with a dead nodal load, on a biphasic layer (the mixture's mass on the solid) under a
// traction, built as a case is, and on a cube hanging from a swinging rigid body.
#include "trifem/assembly/fe_problem.hpp"
#include "trifem/io/case_reader.hpp"
#include "trifem/linalg/linear_solver.hpp"
#include "trifem/material/registry.hpp"
#include "trifem/mesh/box.hpp"
#include "trifem/model/model.hpp"
#include "trifem/physics/inertia_term.hpp"
#include "trifem/physics/nodal_force_term.hpp"
#include "trifem/physics/solid_term.hpp"
#include "trifem/solver/newton.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <random>

using namespace trifem;

namespace {

struct DynamicBlock {
  mesh::Mesh mesh;
  dofs::DofMap dofs;
  dofs::FieldId u;
  std::unique_ptr<assembly::FeProblem> problem;

  explicit DynamicBlock(physics::MassMatrix mass) {
    mesh::BoxSpec box;
    box.size = Vec3(2.0, 1.0, 1.0);
    box.divisions = {2, 1, 2};
    box.grading = Vec3(1.7, 1.0, 0.6); // cells of different shapes
    mesh = mesh::make_box(box);
    u = dofs.add_field("displacement", FieldRole::displacement, mesh.num_nodes(), 3);
    dofs::DirichletCondition clamp{{}, 0.0, dofs::LoadCurve::constant(1.0)};
    for (Index n : mesh.node_set("box.xmin"))
      for (int k = 0; k < 3; ++k)
        clamp.dofs.push_back(dofs.dof(u, n, k));
    dofs::constrain_all({clamp}, dofs);
    dofs.finalize();
    std::vector<Index> cells(mesh.num_cells());
    for (Index c = 0; c < mesh.num_cells(); ++c)
      cells[c] = c;
    std::vector<std::unique_ptr<physics::Term>> terms;
    const std::shared_ptr<const material::ElasticLaw> law =
        material::create_law("neo-hookean", {{"E", 1.0}, {"nu", 0.3}}, "law");
    terms.push_back(std::make_unique<physics::SolidTerm>(
        mesh, dofs, u, cells,
        std::vector<std::shared_ptr<const material::ElasticLaw>>(cells.size(), law)));
    std::vector<physics::NodalForce> forces;
    const dofs::LoadCurve ramp({{0.0, 0.0}, {1e-3, 1.0}}, dofs::Interpolation::Linear, "ramp");
    for (Index n : mesh.node_set("box.xmax"))
      forces.push_back({dofs.dof(u, n, 2), -0.01, ramp});
    terms.push_back(std::make_unique<physics::NodalForceTerm>(std::move(forces)));
    problem = std::make_unique<assembly::FeProblem>(
        dofs, std::vector<dofs::DirichletCondition>{clamp}, std::move(terms),
        std::vector<solver::FieldScale>{{"displacement", 1.0, 1.0}});
    problem->add_inertia(std::make_unique<physics::InertiaTerm>(
        mesh, dofs, u, cells, std::vector<Real>(cells.size(), 1e-9), mass,
        physics::GeneralizedAlpha::from_spectral_radius(0.6)));
    problem->set_dynamic(true);
  }
};

/// Central differences of the residual of `p` against its Jacobian at a state inside a step
/// that follows one step in motion (steps `dt1`, `dt2`; increments `h` of the equations'
/// unknowns, perturbed by up to `shift`), each (field, field) block to 1e-6 of its largest entry.
void expect_the_finite_difference_tangent(assembly::FeProblem& p, Real dt1, Real dt2, Real h,
                                          Real shift) {
  solver::NewtonSolver newton({}, linalg::make_linear_solver({LinearSolverKind::umfpack}));
  p.begin_step(dt1, dt1); // one step in motion: v, a and g of step n are not zero
  ASSERT_EQ(newton.solve(p).status, solver::SolveStatus::Converged);
  p.commit_step();
  ASSERT_GT(p.inertia()->velocity().norm(), 0.0);

  p.begin_step(dt1 + dt2, dt2);
  const Index n = p.num_equations();
  std::mt19937 random(11);
  std::uniform_real_distribution<Real> perturbation(-shift, shift);
  Vector dx(n);
  for (Index i = 0; i < n; ++i)
    dx[i] = perturbation(random);
  p.update(dx, 1.0); // a state inside the step
  solver::Linearization lin;
  ASSERT_EQ(p.linearize(lin, true), solver::SolveStatus::Converged);
  const Eigen::MatrixXd K(lin.jacobian);
  p.save_iterate();
  Eigen::MatrixXd fd(n, n);
  for (Index j = 0; j < n; ++j) {
    Vector e = Vector::Zero(n);
    e[j] = h;
    solver::Linearization plus, minus;
    p.update(e, 1.0);
    ASSERT_EQ(p.linearize(plus, false), solver::SolveStatus::Converged);
    p.restore_iterate();
    p.update(-e, 1.0);
    ASSERT_EQ(p.linearize(minus, false), solver::SolveStatus::Converged);
    p.restore_iterate();
    fd.col(j) = (plus.residual - minus.residual) / (2 * h);
  }
  const std::vector<int>& field = p.equation_fields();
  const int fields = *std::max_element(field.begin(), field.end()) + 1;
  Real worst = 0.0;
  for (int fr = 0; fr < fields; ++fr)
    for (int fc = 0; fc < fields; ++fc) {
      Real diff = 0.0, size = 0.0;
      for (Index r = 0; r < n; ++r)
        for (Index c = 0; c < n; ++c)
          if (field[r] == fr && field[c] == fc) {
            diff = std::max(diff, std::abs(fd(r, c) - K(r, c)));
            size = std::max(size, std::abs(K(r, c)));
          }
      EXPECT_LE(diff, 1e-6 * size) << "fields " << fr << ", " << fc << ", largest entry " << size;
      worst = std::max(worst, size > 0.0 ? diff / size : 0.0);
    }
  std::cout << fields << " fields, worst block error " << worst << " of its largest entry\n";
}

void expect_the_finite_difference_tangent(physics::MassMatrix mass) {
  DynamicBlock block(mass);
  expect_the_finite_difference_tangent(*block.problem, 2e-4, 3e-4, 1e-7, 1e-3);
}

/// A biphasic layer (2 x 1 x 2 graded cells) with the mixture's mass, clamped at its bottom,
/// free-draining on top under a suddenly applied oblique traction.
constexpr const char* kBiphasicLayer = R"(
[analysis]
type = "dynamic"

[dynamic]
rho_inf = 0.6

[[mesh.box]]
name = "layer"
size = [2.0, 1.0, 1.0]
divisions = [2, 1, 2]
grading = [1.7, 1.0, 0.6]
material = "tissue"

[materials.tissue]
type = "biphasic"
phi_s0 = 0.25
permeability = 1.07e-3
density = 1e-6                # the inertia (M / (beta dt^2)) about the stiffness
[materials.tissue.solid]
type = "neo-hookean"
E = 0.3
nu = 0.2

[curves.step]
points = [[0.0, 0.0], [1e-3, 1.0]]

[[boundary.fixed]]
set = "layer.zmin"
[[boundary.fixed]]
set = "layer.zmin"
field = "fluid_flux"
components = ["z"]

[[loads.traction]]
surface = "layer.zmax"
value = [0.01, 0.0, -0.02]
curve = "step"

[time]
end_time = 1.0
dt = 1e-3
)";

/// A solid cube hanging from a heavy bone (a rigid body of cells) that swings about a hinge
/// with a torsion spring, started with an angular velocity: the inertia of the bone's nodes is
/// condensed onto its six unknowns, projected at both ends of the step.
constexpr const char* kSwingingBone = R"(
[analysis]
type = "dynamic"

[dynamic]
rho_inf = 0.6

[[mesh.box]]
name = "cube"
size = [1.0, 1.0, 1.0]
divisions = [1, 1, 2]
material = "tissue"
[[mesh.box]]
name = "bone"
origin = [0.0, 0.0, 1.0]
size = [1.0, 1.0, 0.3]
divisions = [1, 1, 1]

[materials.tissue]
type = "neo-hookean"
E = 1.0
nu = 0.3
density = 1e-6

[[rigid_body]]
name = "femur"
set = "cube.zmax"
blocks = ["bone"]
density = 2e-6
velocity = [0.0, 0.0, -15.0]
angular_velocity = [30.0, 0.0, 0.0]

[[connector]]
type = "revolute"
name = "hinge"
body_a = "ground"
body_b = "femur"
origin = [0.5, 1.0, 1.15]
axis = [1.0, 0.0, 0.0]
torsion_stiffness = 0.05

[time]
end_time = 1.0
dt = 1e-3
)";

} // namespace

TEST(DynamicTangent, SwingingRigidBodyStepMatchesFiniteDifferences) {
  const std::unique_ptr<model::Model> model =
      model::build_model(io::parse_case(kSwingingBone, "swing.toml"));
  assembly::FeProblem& p = *model->problem;
  ASSERT_NE(p.inertia(), nullptr);
  ASSERT_FALSE(p.rigid_map().empty());
  ASSERT_GT(model->initial_velocity.norm(), 0.0);
  p.set_dynamic(true, true, model->initial_velocity);
  expect_the_finite_difference_tangent(p, 1e-3, 2e-3, 1e-7, 1e-4);
}

TEST(DynamicTangent, BiphasicStepMatchesFiniteDifferences) {
  const std::unique_ptr<model::Model> model =
      model::build_model(io::parse_case(kBiphasicLayer, "layer.toml"));
  assembly::FeProblem& p = *model->problem;
  ASSERT_NE(p.inertia(), nullptr);
  p.set_dynamic(true);
  expect_the_finite_difference_tangent(p, 1e-3, 2e-3, 1e-7, 1e-4);
}

namespace {

TEST(DynamicTangent, ConsistentMassStepMatchesFiniteDifferences) {
  expect_the_finite_difference_tangent(physics::MassMatrix::Consistent);
}

TEST(DynamicTangent, LumpedMassStepMatchesFiniteDifferences) {
  expect_the_finite_difference_tangent(physics::MassMatrix::Lumped);
}

} // namespace
