// SPDX-License-Identifier: MIT
// The explicit multiplier scheme on tet10 and hex20 cells (docs/theory/explicit.md §2): their
// lumped mass (diagonal scaling, Hinton-Rock-Zienkiewicz), the homogeneous patch test on a
// distorted cube to round-off, the multiplier stiffness against central differences, the element
// bound above the power iteration, and the thick sphere of hex20 cells against the radial ODE.
#include "exact_sphere.hpp"
#include "exact_uniaxial.hpp"
#include "fixtures.hpp"

#include "generated_meshes.hpp"
#include "solver_history.hpp"
#include "trifem/explicit/cell_kernel.hpp"
#include "trifem/explicit/multiplier_stiffness.hpp"
#include "trifem/explicit/stable_step.hpp"
#include "trifem/mesh/box.hpp"
#include "trifem/mesh/convert_cells.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

using namespace trifem;
using namespace trifem::explicit_dynamics;

namespace {

constexpr mesh::CellType kFamilies[] = {mesh::CellType::Tet10, mesh::CellType::Hex20};

std::string family_name(mesh::CellType type) {
  return std::string(mesh::name(type));
}

/// The hex8 box `box` converted to `type` cells, `corner_map` applied to the corner nodes and
/// every mid-edge node at the middle of its edge (straight edges: the family's rule integrates
/// the homogeneous state exactly).
mesh::Mesh converted_box(const mesh::BoxSpec& box, mesh::CellType type,
                         const std::function<Vec3(const Vec3&)>& corner_map) {
  const mesh::Mesh cells = mesh::convert_cells(mesh::make_box(box), type);
  std::vector<Vec3> X(cells.nodes().begin(), cells.nodes().end());
  for (Vec3& x : X)
    x = corner_map(x);
  const int corners = mesh::num_corners(type);
  const std::span<const mesh::Edge> edges = mesh::mid_edges(type);
  for (Index c = 0; c < cells.num_cells(); ++c) {
    const std::span<const Index> nodes = cells.cell_nodes(c);
    for (std::size_t e = 0; e < edges.size(); ++e)
      X[nodes[corners + e]] = 0.5 * (X[nodes[edges[e][0]]] + X[nodes[edges[e][1]]]);
  }
  Index next = 0;
  return test::transform_nodes(cells, [&](const Vec3&) { return X[next++]; });
}

/// The unit cube of 2 x 2 x 2 hexes as `type` cells with the centre node and two face-centre
/// nodes moved (in plane), as the hex8 patch test's cube.
mesh::Mesh distorted_family_cube(mesh::CellType type) {
  mesh::BoxSpec box;
  box.name = "cube";
  box.divisions = {2, 2, 2};
  return converted_box(box, type, [](const Vec3& X) {
    if ((X - Vec3(0.5, 0.5, 0.5)).norm() < 1e-12)
      return Vec3(0.62, 0.43, 0.56);
    if ((X - Vec3(1.0, 0.5, 0.5)).norm() < 1e-12)
      return Vec3(1.0, 0.57, 0.44);
    if ((X - Vec3(0.5, 0.0, 0.5)).norm() < 1e-12)
      return Vec3(0.45, 0.0, 0.58);
    return X;
  });
}

/// A 4 x 1 x 1 beam of 4 x 2 x 2 hexes as `type` cells, clamped at x = 0, follower pressure on
/// its top, of shear modulus and density 1.
test::TestModel family_beam(mesh::CellType type) {
  mesh::BoxSpec box;
  box.name = "beam";
  box.size = Vec3(4.0, 1.0, 1.0);
  box.divisions = {4, 2, 2};
  test::ExplicitTestCase c(mesh::convert_cells(mesh::make_box(box), type),
                           test::deviatoric_material(1.0, 1.0));
  c.fix("beam.xmin", {0, 1, 2}).pressure("beam.zmax", 0.05, test::step_curve());
  return test::TestModel(c);
}

/// Deterministic displacement of amplitude `amplitude` (zero on fixed DOFs).
Vector family_wobble(const ExplicitView& model, Real amplitude) {
  Vector U(model.num_dofs());
  for (Index i = 0; i < U.size(); ++i)
    U[i] = model.fixed()[i] ? 0.0 : amplitude * std::sin(3.7 * i + 0.3 * (i % 5));
  return U;
}

} // namespace

TEST(ExplicitFamilies, LumpedMassIsPositiveAndHoldsTheTotalMass) {
  for (const mesh::CellType type : kFamilies) {
    SCOPED_TRACE(family_name(type));
    const test::TestModel model = family_beam(type);
    const Real mass = 1.0 * 4.0; // ρ V
    EXPECT_NEAR(model.mass().sum() / 3.0, mass, 1e-13 * mass);
    EXPECT_NEAR(model.volumes().sum(), 4.0, 1e-13 * 4.0);
    EXPECT_GT(model.mass().minCoeff(), 0.0) << "a node without mass (row sums at the corners)";
  }
}

TEST(ExplicitFamilies, PrescribedStretchIsHomogeneousWithTheClosedFormReaction) {
  // the distorted cube's xmax face moved to the axial stretch 1.3 (smoothly over 5 s), damped to
  // rest: the displacement, the multiplier and the face's force are the closed form's, and the
  // constraint holds to round-off in every step
  constexpr Real kMu = 1.0, kAlpha = 1e3;
  const test::Uniaxial exact = test::uniaxial_state(kMu, kAlpha, 1.3);
  for (const mesh::CellType type : kFamilies) {
    SCOPED_TRACE(family_name(type));
    test::ExplicitTestCase c(distorted_family_cube(type), test::deviatoric_material(kMu, 1.0));
    c.fix("cube.xmin", {0}).fix("cube.ymin", {1}).fix("cube.zmin", {2});
    c.prescribe("cube.xmax", 0, exact.a - 1.0, test::smooth_ramp(5.0));
    const test::TestModel model(c);
    ExplicitSettings s;
    s.penalty = kAlpha;
    s.damping = 2.0;
    ExplicitSolver solver(model, s);
    Real worst_residual = 0.0;
    const StepReport last = solver.run(60.0, [&](const ExplicitSolver&, const StepReport& r) {
      worst_residual = std::max(worst_residual, r.constraint_residual);
    });
    ASSERT_TRUE(last.ok()) << last.message;
    EXPECT_LT(worst_residual, 1e-12) << "constraint not at round-off in some step";
    const Vec3 stretch(exact.a, exact.b, exact.b);
    Real error = 0.0;
    for (Index n = 0; n < model.mesh().num_nodes(); ++n) {
      const Vec3 X = model.mesh().node(n);
      const Vec3 u = (stretch.array() - 1.0).matrix().cwiseProduct(X);
      error =
          std::max(error, (solver.displacement().segment<3>(3 * n) - u).lpNorm<Eigen::Infinity>());
    }
    std::printf("%s patch: %ld cells, max |u - u_exact| = %.2e\n", family_name(type).c_str(),
                static_cast<long>(model.num_cells()), error);
    EXPECT_LT(error, 1e-8) << "displacement not the homogeneous field";
    for (Index e = 0; e < model.num_cells(); ++e)
      EXPECT_NEAR(solver.multiplier()[e], exact.lambda, 1e-7 * std::abs(exact.lambda));
    Real force = 0.0;
    for (const Index n : model.mesh().node_set("cube.xmax"))
      force += solver.reaction_force()[3 * n];
    EXPECT_NEAR(force, exact.P, 1e-7 * exact.P) << "force on the unit face = P";
  }
}

TEST(ExplicitFamilies, MultiplierStiffnessIsTheDerivativeOfTheConstraintGradient) {
  constexpr Real kLambda = 0.7, kStep = 1e-6;
  for (const mesh::CellType type : kFamilies) {
    SCOPED_TRACE(family_name(type));
    const test::TestModel model = family_beam(type);
    const Vector U = family_wobble(model, 0.01);
    const auto& geo = std::get<physics::CellGeometry>(model.geometry()[0]);
    const Index size = model.cell_offsets()[1];
    for (const Constraint constraint : {Constraint::JMinusOne, Constraint::LogJ}) {
      physics::CellMatrixX K;
      ASSERT_TRUE(multiplier_stiffness(geo, model.node_values(0, U), constraint, kLambda, K));
      ASSERT_EQ(K.rows(), size);
      EXPECT_LT((K - K.transpose()).norm(), 1e-14 * K.norm());
      Eigen::MatrixXd fd(size, size);
      CellFields plus, minus;
      const std::span<const Index> nodes = model.mesh().cell_nodes(0);
      for (std::size_t a = 0; a < nodes.size(); ++a)
        for (int k = 0; k < 3; ++k) {
          Vector Up = U, Um = U;
          Up[3 * nodes[a] + k] += kStep;
          Um[3 * nodes[a] + k] -= kStep;
          ASSERT_TRUE(evaluate_cells(model, constraint, Up, {false, true, false}, plus).ok());
          ASSERT_TRUE(evaluate_cells(model, constraint, Um, {false, true, false}, minus).ok());
          fd.col(3 * static_cast<Index>(a) + k) =
              kLambda * (plus.gradient.head(size) - minus.gradient.head(size)) / (2.0 * kStep);
        }
      const Real error = (K - fd).norm() / K.norm();
      std::printf("%s multiplier stiffness vs differences: %.2e\n", family_name(type).c_str(),
                  error);
      EXPECT_LT(error, 1e-8);
    }
  }
}

TEST(ExplicitFamilies, ElementBoundStaysAboveThePowerIteration) {
  for (const mesh::CellType type : kFamilies) {
    SCOPED_TRACE(family_name(type));
    const test::TestModel model = family_beam(type);
    const Vector U = family_wobble(model, 0.02);
    Vector lambda(model.num_cells());
    for (Index c = 0; c < lambda.size(); ++c)
      lambda[c] = 0.8 * std::cos(1.3 * c);
    const FrequencyEstimate power =
        power_iteration_omega(model, Constraint::JMinusOne, U, lambda, false, 500, 1e-7);
    const FrequencyEstimate bound = element_bound_omega(model, Constraint::JMinusOne, U, lambda);
    std::printf("%s: omega %.5f (power iteration), %.5f (element bound)\n",
                family_name(type).c_str(), power.omega, bound.omega);
    EXPECT_GT(power.omega, 0.0);
    EXPECT_LE(power.omega, bound.omega * (1.0 + 1e-9));
  }
}

namespace {

/// The thick sphere's octant (A = 1, B = 2) of n x n x n hexes per patch as hex20 cells, their
/// mid-edge nodes on the spheres and rays of their edges' ends (curved cells), with the follower
/// pressure μ curve(t) inside.
test::TestModel hex20_sphere(int n, const io::CurveSpec& curve) {
  test::ShellOctantSpec shell;
  shell.divisions = n;
  shell.layers = n;
  const mesh::Mesh cells =
      mesh::convert_cells(test::make_shell_octant(shell), mesh::CellType::Hex20);
  std::vector<Vec3> X(cells.nodes().begin(), cells.nodes().end());
  const std::span<const mesh::Edge> edges = mesh::mid_edges(mesh::CellType::Hex20);
  for (Index c = 0; c < cells.num_cells(); ++c) {
    const std::span<const Index> nodes = cells.cell_nodes(c);
    for (std::size_t e = 0; e < edges.size(); ++e) {
      const Vec3& a = X[nodes[edges[e][0]]];
      const Vec3& b = X[nodes[edges[e][1]]];
      X[nodes[8 + e]] = 0.5 * (a.norm() + b.norm()) * (a + b).normalized();
    }
  }
  Index next = 0;
  const test::sphere::Sphere sphere{};
  test::ExplicitTestCase c(test::transform_nodes(cells, [&](const Vec3&) { return X[next++]; }),
                           test::deviatoric_material(sphere.mu, sphere.rho));
  c.fix("shell.x0", {0}).fix("shell.y0", {1}).fix("shell.z0", {2});
  c.pressure("shell.inner", sphere.mu, curve);
  return test::TestModel(c);
}

} // namespace

TEST(ExplicitFamilies, Hex20SphereFollowsTheRadialOdeAndConservesEnergy) {
  // the step pressure 0.3 μ from rest, undamped (reading B), over the radial ODE's first period
  const test::sphere::Sphere sphere{};
  const auto ode = test::sphere::integrate_radial(
      sphere, [](Real) { return 0.3; }, 20.0, 1e-4);
  const Real period = test::sphere::first_period(ode);
  ASSERT_GT(period, 0.0);
  const test::TestModel model = hex20_sphere(3, {dofs::Interpolation::Step, {{0.0, 0.3}}});
  ExplicitSettings settings;
  settings.reading = Reading::B;
  ExplicitSolver solver(model, settings);
  const Real energy0 = solver.energies().total();
  Real worst = 0.0, amplitude = 0.0, drift = 0.0, work = 0.0;
  int steps = 0;
  const StepReport r = solver.run(period, [&](const ExplicitSolver& sv, const StepReport&) {
    const Real a = mean_radius(sv, "shell.inner");
    const Real a_ode = test::sphere::radius_at(ode, sv.time());
    worst = std::max(worst, std::abs(a - a_ode) / a_ode);
    amplitude = std::max(amplitude, a_ode - sphere.A);
    const Energies e = sv.energies();
    drift = std::max(drift, std::abs(e.total() - energy0));
    work = std::max(work, std::abs(e.external_work));
    ++steps;
  });
  ASSERT_TRUE(r.ok()) << r.message;
  std::printf("hex20 sphere (%ld cells): period %.4f, %d steps, max |a - a_ode| / a_ode = %.3e "
              "(%.3e of the amplitude), max |E - E0| / W_ext = %.3e\n",
              static_cast<long>(model.num_cells()), period, steps, worst,
              worst * (1.0 + amplitude) / amplitude, drift / work);
  EXPECT_LT(worst, 0.02);
  EXPECT_LT(drift / work, 0.005);
}
