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

// Repeating curves: the values are written out by shifting the time by whole periods by hand.
// FEBio's convention at the period ends: after the points t maps into (t_0, t_n], before them
// into [t_0, t_n).

/// Linear through (1, 0), (2, 2), (4, 1): period 3, v_n - v_0 = 1.
const std::vector<std::pair<Real, Real>> kCycle = {{1, 0}, {2, 2}, {4, 1}};

TEST(LoadCurve, RepeatShiftsTimeByWholePeriods) {
  const dofs::LoadCurve c(kCycle, dofs::Interpolation::Linear, "cycle", dofs::Extension::Repeat);
  EXPECT_DOUBLE_EQ(c(1.5), 1.0); // inside: unchanged
  EXPECT_DOUBLE_EQ(c(3.0), 1.5);
  EXPECT_DOUBLE_EQ(c(4.0), 1.0);
  EXPECT_DOUBLE_EQ(c(5.5), 1.75);  // 2.5 = 5.5 - 3: 2 - 0.5 / 2
  EXPECT_DOUBLE_EQ(c(7.0), 1.0);   // 4 = 7 - 3: the end of a period takes v_n
  EXPECT_DOUBLE_EQ(c(7.25), 0.5);  // 1.25 = 7.25 - 6: 2 x 0.25
  EXPECT_DOUBLE_EQ(c(101.0), 2.0); // 2 = 101 - 33 x 3
  EXPECT_DOUBLE_EQ(c(0.0), 1.5);   // before: 3 = 0 + 3
  EXPECT_DOUBLE_EQ(c(-2.0), 0.0);  // 1 = -2 + 3: the start of a period takes v_0
  EXPECT_DOUBLE_EQ(c(-2.5), 1.25); // 3.5 = -2.5 + 6: 2 - 1.5 / 2
  // a curve of one point has no period: constant
  const dofs::LoadCurve one({{1.0, 3.0}}, dofs::Interpolation::Linear, "one",
                            dofs::Extension::Repeat);
  EXPECT_DOUBLE_EQ(one(-5.0), 3.0);
  EXPECT_DOUBLE_EQ(one(50.0), 3.0);
}

TEST(LoadCurve, RepeatOffsetAddsTheRiseOfEachPeriod) {
  const dofs::LoadCurve c(kCycle, dofs::Interpolation::Linear, "cycle",
                          dofs::Extension::RepeatOffset);
  EXPECT_DOUBLE_EQ(c(3.0), 1.5);
  EXPECT_DOUBLE_EQ(c(5.5), 2.75);       // 1.75 + 1 x 1
  EXPECT_DOUBLE_EQ(c(7.0), 2.0);        // 1 + 1
  EXPECT_DOUBLE_EQ(c(7.25), 2.5);       // 0.5 + 2
  EXPECT_DOUBLE_EQ(c(101.0), 35.0);     // 2 + 33
  EXPECT_DOUBLE_EQ(c(0.0), 0.5);        // 1.5 - 1
  EXPECT_DOUBLE_EQ(c(-2.0), -1.0);      // 0 - 1
  EXPECT_DOUBLE_EQ(c(-2.5), -0.75);     // 1.25 - 2
  for (const Real t : {4.0, 7.0, -2.0}) // continuous across the period ends
    EXPECT_NEAR(c(t - 1e-9), c(t + 1e-9), 1e-8) << t;
}

TEST(LoadCurve, RepeatsEveryInterpolation) {
  // step (right-continuous) through (0, 1), (1, 3), (2, 5), period 2
  const dofs::LoadCurve step({{0, 1}, {1, 3}, {2, 5}}, dofs::Interpolation::Step, "step",
                             dofs::Extension::Repeat);
  EXPECT_DOUBLE_EQ(step(2.5), 1.0);        // 0.5
  EXPECT_DOUBLE_EQ(step(3.0), 3.0);        // 1
  EXPECT_DOUBLE_EQ(step(4.0), 5.0);        // 2: the end of the period
  EXPECT_DOUBLE_EQ(step(4.0 + 1e-9), 1.0); // just after it: 0+
  EXPECT_DOUBLE_EQ(step(-0.5), 3.0);       // 1.5
  EXPECT_DOUBLE_EQ(step(-2.0), 1.0);       // 0
  // FEBio's STEP through (0, 0), (1, 2), (3, 5), period 3, rise 5
  const dofs::LoadCurve next({{0, 0}, {1, 2}, {3, 5}}, dofs::Interpolation::Next, "next",
                             dofs::Extension::RepeatOffset);
  EXPECT_DOUBLE_EQ(next(3.5), 7.0);         // 0.5: 2, + 5
  EXPECT_DOUBLE_EQ(next(4.0), 7.0);         // 1: 2, + 5
  EXPECT_DOUBLE_EQ(next(4.0 + 1e-9), 10.0); // 1+: 5, + 5
  EXPECT_DOUBLE_EQ(next(6.0), 10.0);        // 3: 5, + 5
  EXPECT_DOUBLE_EQ(next(6.0 + 1e-9), 12.0); // 0+: 2, + 10
  EXPECT_DOUBLE_EQ(next(-1.0), 0.0);        // 2: 5, - 5
  // smooth from (0, 0) to (1, 1): s^2 (3 - 2s), period 1, rise 1
  const dofs::LoadCurve smooth({{0, 0}, {1, 1}}, dofs::Interpolation::Smooth, "smooth",
                               dofs::Extension::RepeatOffset);
  EXPECT_DOUBLE_EQ(smooth(1.25), 1.15625);   // 0.25: 0.0625 x 2.5, + 1
  EXPECT_DOUBLE_EQ(smooth(2.5), 2.5);        // 0.5: 0.5, + 2
  EXPECT_DOUBLE_EQ(smooth(-0.75), -0.84375); // 0.25: 0.15625, - 1
  // FEBio's SMOOTH through (0, 0), (1, 1), (2, 0), (3, 1): -t^2 + 2t on [0, 1], (t - 2)^2 on
  // [2, 3], 0.5 at 1.5 (TheQuadraticBlendIsFebiosSmoothCurve), period 3
  const dofs::LoadCurve blend({{0, 0}, {1, 1}, {2, 0}, {3, 1}}, dofs::Interpolation::QuadraticBlend,
                              "blend", dofs::Extension::Repeat);
  EXPECT_NEAR(blend(3.3), 0.51, 1e-14);  // 0.3: -0.09 + 0.6
  EXPECT_NEAR(blend(4.5), 0.5, 1e-14);   // 1.5
  EXPECT_NEAR(blend(-0.6), 0.16, 1e-14); // 2.4: 0.4^2
  EXPECT_NEAR(blend(-1.0), 0.0, 1e-14);  // 2
}

TEST(LoadCurve, BreakpointsOfARepeatingCurveCoverTheWindow) {
  const dofs::LoadCurve constant(kCycle, dofs::Interpolation::Linear);
  EXPECT_EQ(constant.breakpoints(1.5, 30.0), (std::vector<Real>{2, 4}));
  for (const auto extension : {dofs::Extension::Repeat, dofs::Extension::RepeatOffset}) {
    const dofs::LoadCurve c(kCycle, dofs::Interpolation::Linear, "cycle", extension);
    EXPECT_EQ(c.breakpoints(), (std::vector<Real>{1, 2, 4})); // one period
    EXPECT_EQ(c.breakpoints(0.0, 11.0), (std::vector<Real>{1, 2, 4, 5, 7, 8, 10, 11}));
    EXPECT_EQ(c.breakpoints(-2.5, 1.5), (std::vector<Real>{-2, -1, 1}));
    EXPECT_EQ(c.breakpoints(4.5, 4.9), std::vector<Real>{});
  }
  // a window of more than 1e8 periods is refused rather than listed
  const dofs::LoadCurve fast({{0, 0}, {1e-3, 1}}, dofs::Interpolation::Linear, "fast",
                             dofs::Extension::Repeat);
  EXPECT_THROW(fast.breakpoints(0.0, 1e6), InputError);
}

TEST(LoadCurve, ARepeatingCurveTakesThePointValuesAtItsBreakpoints) {
  // times that binary fractions do not hold: the shifted breakpoints must still hit the points
  // (a step curve jumps there); FEBio's STEP: 1 on (0, 0.1], 2 on (0.1, 0.3]
  const dofs::LoadCurve c({{0.0, 0.0}, {0.1, 1.0}, {0.3, 2.0}}, dofs::Interpolation::Next, "c",
                          dofs::Extension::Repeat);
  const std::vector<Real> b = c.breakpoints(0.0, 300.0);
  ASSERT_GE(b.size(), 2000u);
  EXPECT_EQ(c(b[0]), 0.0);
  for (std::size_t j = 1; j < b.size(); ++j)
    ASSERT_EQ(c(b[j]), j % 2 ? 1.0 : 2.0) << "t = " << b[j]; // t_1 + kT, else t_n + kT
}

TEST(LoadCurve, RejectsNonIncreasingTimes) {
  EXPECT_THROW(dofs::LoadCurve({{0, 0}, {0, 1}}, dofs::Interpolation::Linear), InputError);
  EXPECT_THROW(dofs::LoadCurve({}, dofs::Interpolation::Linear), InputError);
}
