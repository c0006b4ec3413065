// SPDX-License-Identifier: MIT
// DOF numbering, constraints and load curves.
#include "trifem/core/error.hpp"
#include "trifem/dofs/dirichlet.hpp"

#include <gtest/gtest.h>

using namespace trifem;

TEST(DofMap, NumbersFieldsContiguouslyAndSplitsFreeAndConstrained) {
  dofs::DofMap map;
  const auto u = map.add_field("u", FieldRole::displacement, 4, 3);
  const auto p = map.add_field("p", FieldRole::potential, 2, 1);
  EXPECT_EQ(map.num_dofs(), 14);
  EXPECT_EQ(map.dof(u, 2, 1), 7);
  EXPECT_EQ(map.dof(p, 1, 0), 13);
  EXPECT_EQ(map.field_of(13), p);
  EXPECT_EQ(map.field_of(11), u);
  map.constrain(map.dof(u, 0, 0));
  map.constrain(map.dof(p, 1, 0));
  map.finalize();
  EXPECT_EQ(map.num_equations(), 12);
  EXPECT_EQ(map.num_constrained(), 2);
  EXPECT_EQ(map.equation(0), -1);
  EXPECT_EQ(map.equation(1), 0);
  EXPECT_EQ(map.constrained_index(13), 1);
  for (Index eq = 0; eq < map.num_equations(); ++eq)
    EXPECT_EQ(map.equation(map.dof_of_equation(eq)), eq);
}

TEST(DofMap, TiedDofsShareTheirLeadersEquation) {
  dofs::DofMap map;
  const auto u = map.add_field("u", FieldRole::displacement, 4, 1);
  map.tie(map.dof(u, 0, 0), map.dof(u, 3, 0)); // the follower precedes its leader
  map.tie(map.dof(u, 2, 0), map.dof(u, 3, 0));
  const auto p =
      map.add_field("p", FieldRole::potential, 1, 1); // a field added after a tie is untied
  map.finalize();
  EXPECT_EQ(map.num_equations(), 3);
  EXPECT_EQ(map.num_constrained(), 0);
  EXPECT_EQ(map.equation(0), map.equation(3));
  EXPECT_EQ(map.equation(2), map.equation(3));
  EXPECT_NE(map.equation(1), map.equation(3));
  EXPECT_EQ(map.dof_of_equation(map.equation(0)), 3);
  EXPECT_EQ(map.leader(map.dof(p, 0, 0)), map.dof(p, 0, 0));
}

TEST(DofMap, TieRejectsChainsAndMixedConstraints) {
  dofs::DofMap chain;
  chain.add_field("u", FieldRole::displacement, 3, 1);
  chain.tie(0, 1);
  EXPECT_THROW(chain.tie(2, 0), LogicError); // 0 follows 1: it cannot lead
  dofs::DofMap mixed;
  mixed.add_field("u", FieldRole::displacement, 2, 1);
  mixed.tie(0, 1);
  mixed.constrain(1);
  EXPECT_THROW(mixed.finalize(), LogicError);
}

TEST(DofMap, DependentDofsHaveNeitherAnEquationNorAConstrainedIndex) {
  dofs::DofMap map;
  map.add_field("u", FieldRole::displacement, 4, 1);
  map.make_dependent(1);
  map.constrain(3);
  map.add_field("rigid", FieldRole::rigid_motion, 1, 2); // added after: not dependent
  map.finalize();
  EXPECT_TRUE(map.is_dependent(1));
  EXPECT_FALSE(map.is_dependent(4));
  EXPECT_EQ(map.equation(1), -1);
  EXPECT_EQ(map.constrained_index(1), -1);
  EXPECT_EQ(map.num_equations(), 4); // 0, 2, 4, 5
  EXPECT_EQ(map.num_constrained(), 1);
  map.reset_constraints(); // keeps the dependent DOF
  map.finalize();
  EXPECT_EQ(map.equation(1), -1);
  EXPECT_EQ(map.num_equations(), 5);
  dofs::DofMap both;
  both.add_field("u", FieldRole::displacement, 2, 1);
  both.make_dependent(0);
  both.constrain(0);
  EXPECT_THROW(both.finalize(), LogicError);
  dofs::DofMap tied;
  tied.add_field("u", FieldRole::displacement, 2, 1);
  tied.tie(1, 0);
  tied.make_dependent(0);
  EXPECT_THROW(tied.finalize(), LogicError); // 1 would follow a DOF without an equation
}

TEST(Dirichlet, PrescribedValuesFollowTheCurve) {
  dofs::DirichletCondition c{
      {1, 3}, 2.0, dofs::LoadCurve({{0, 0}, {2, 1}}, dofs::Interpolation::Linear)};
  Vector x = Vector::Zero(4);
  dofs::prescribed_values({c}, 1.0, x);
  EXPECT_DOUBLE_EQ(x[1], 1.0);
  EXPECT_DOUBLE_EQ(x[3], 1.0);
  EXPECT_DOUBLE_EQ(x[0], 0.0);
}

TEST(LoadCurve, InterpolatesAndHoldsOutside) {
  const std::vector<std::pair<Real, Real>> pts = {{0, 0}, {1, 2}, {3, 2}};
  const dofs::LoadCurve lin(pts, dofs::Interpolation::Linear);
  EXPECT_DOUBLE_EQ(lin(0.5), 1.0);
  EXPECT_DOUBLE_EQ(lin(-1.0), 0.0);
  EXPECT_DOUBLE_EQ(lin(10.0), 2.0);
  const dofs::LoadCurve step(pts, dofs::Interpolation::Step);
  EXPECT_DOUBLE_EQ(step(0.99), 0.0);
  EXPECT_DOUBLE_EQ(step(1.0), 2.0);
  const dofs::LoadCurve next({{0, 0}, {1, 2}, {3, 5}}, dofs::Interpolation::Next); // FEBio's STEP
  EXPECT_DOUBLE_EQ(next(0.0), 0.0);
  EXPECT_DOUBLE_EQ(next(1e-9), 2.0);
  EXPECT_DOUBLE_EQ(next(1.0), 2.0);
  EXPECT_DOUBLE_EQ(next(1.0 + 1e-9), 5.0);
  EXPECT_DOUBLE_EQ(next(-1.0), 0.0);
  EXPECT_DOUBLE_EQ(next(10.0), 5.0);
  const dofs::LoadCurve smooth(pts, dofs::Interpolation::Smooth);
  EXPECT_DOUBLE_EQ(smooth(0.5), 1.0);
  EXPECT_NEAR((smooth(1e-4) - smooth(0)) / 1e-4, 0.0, 1e-3); // zero slope at the points
  EXPECT_EQ(lin.breakpoints(), (std::vector<Real>{0, 1, 3}));
}

TEST(LoadCurve, TheQuadraticBlendIsFebiosSmoothCurve) {
  // (0, 0), (1, 1), (2, 0), (3, 1): the parabolas −t² + 2t through the first three points and
  // (t − 2)² through the last three, blended linearly over [1, 2]
  const dofs::LoadCurve c({{0.0, 0.0}, {1.0, 1.0}, {2.0, 0.0}, {3.0, 1.0}},
                          dofs::Interpolation::QuadraticBlend);
  const auto first = [](Real t) { return -t * t + 2.0 * t; };
  const auto last = [](Real t) { return (t - 2.0) * (t - 2.0); };
  for (const Real t : {0.0, 0.3, 0.9, 1.0})
    EXPECT_NEAR(c(t), first(t), 1e-15) << t;
  for (const Real t : {2.0, 2.4, 3.0})
    EXPECT_NEAR(c(t), last(t), 1e-15) << t;
  for (const Real t : {1.25, 1.5, 1.8}) {
    const Real w = t - 1.0;
    EXPECT_NEAR(c(t), (1.0 - w) * first(t) + w * last(t), 1e-15) << t;
  }
  EXPECT_DOUBLE_EQ(c(1.5), 0.5);
  EXPECT_DOUBLE_EQ(c(5.0), 1.0); // constant outside
  // samples of a quadratic are reproduced, uneven times included
  const auto q = [](Real t) { return 0.5 * t * t - 1.5 * t + 2.0; };
  std::vector<std::pair<Real, Real>> points;
  for (const Real t : {0.0, 0.4, 1.5, 1.7, 3.0})
    points.emplace_back(t, q(t));
  const dofs::LoadCurve quadratic(points, dofs::Interpolation::QuadraticBlend);
  for (Real t = 0.0; t <= 3.0; t += 0.05)
    EXPECT_NEAR(quadratic(t), q(t), 1e-14) << t;
  // through two points: linear
  const dofs::LoadCurve two({{0.0, 1.0}, {2.0, 3.0}}, dofs::Interpolation::QuadraticBlend);
  EXPECT_DOUBLE_EQ(two(0.5), 1.5);
}

TEST(LoadCurve, RejectsNonIncreasingTimes) {
  EXPECT_THROW(dofs::LoadCurve({{0, 0}, {0, 1}}, dofs::Interpolation::Linear), InputError);
  EXPECT_THROW(dofs::LoadCurve({}, dofs::Interpolation::Linear), InputError);
}
