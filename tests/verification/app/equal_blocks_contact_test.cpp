// SPDX-License-Identifier: MIT
// Two blocks of the same section stacked and pressed between clamped platens, their interface
// frictionless contact. The problem is the mirror image of itself about the interface, so both
// sides move alike and the interface carries no shear:
//   * where the interface stays closed, the answer is that of one block of twice the height
//     (the same problem solved two ways);
//   * nearly incompressible thin blocks pressed hard bulge until the interface's corners open
//     (the single block pulls there); the slave surface's edge nodes, which stay on the master
//     surface's edges to round-off, keep their contact on the extended edge facets instead of
//     being released (which made Newton cycle before), and the answer is its own mirror image
//     and balanced to the accuracy of the node-to-segment scheme.
#include "case_runner.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

using namespace trifem;

namespace {

/// A stack of two blocks (or one block of their height) of section `side` x `side` mm, each
/// 1 mm high with `cells` x `cells` x 2 cells, of Poisson's ratio `nu`, the top pressed down
/// by `press` mm; the interface at z = 0.
std::string stack_case(bool contact, Real side, int cells, Real nu, Real press) {
  const auto box = [&](const char* name, Real z0, Real height, int layers) {
    return fmt::format(R"(
[[mesh.box]]
name = "{}"
origin = [{}, {}, {}]
size = [{}, {}, {}]
divisions = [{}, {}, {}]
material = "rubber"
)",
                       name, -side / 2, -side / 2, z0, side, side, height, cells, cells, layers);
  };
  const std::string mesh = contact ? box("lower", -1.0, 1.0, 2) + box("upper", 0.0, 1.0, 2) + R"(
[[contact]]
master = "lower.zmax"
slave = "upper.zmin"
)"
                                   : box("lower", -1.0, 2.0, 4);
  const std::string top = contact ? "upper.zmax" : "lower.zmax";
  return mesh + fmt::format(R"(
[materials.rubber]
type = "neo-hookean"
E = 1.0
nu = {2}
[curves.ramp]
points = [[0, 0], [1, 1]]
[time]
end_time = 1.0
dt = 0.1
dt_min = 0.01
[solver]
residual_tolerance = 1e-11
increment_tolerance = 1e-11
[[boundary.fixed]]
set = "lower.zmin"
[[boundary.fixed]]
set = "{0}"
components = ["x", "y"]
[[boundary.prescribed]]
set = "{0}"
component = "z"
value = {1}
curve = "ramp"
)",
                            top, -press, nu);
}

/// The displacements of the nodes of `m` at X (within 1e-9 mm): two on the stack's interface,
/// the lower block's first.
std::vector<Vec3> displacements_at(const model::Model& m, const Vec3& X) {
  std::vector<Vec3> out;
  const Vector& x = m.problem->state();
  for (Index n = 0; n < m.mesh.num_nodes(); ++n)
    if ((m.mesh.node(n) - X).norm() < 1e-9)
      out.emplace_back(x[m.dofs.dof(m.fields.u, n, 0)], x[m.dofs.dof(m.fields.u, n, 1)],
                       x[m.dofs.dof(m.fields.u, n, 2)]);
  return out;
}

/// The sum of the z reactions at the nodes of node set `set`.
Real z_reaction(const model::Model& m, const std::string& set) {
  const Vector& r = m.problem->full_residual();
  Real sum = 0.0;
  for (Index n : m.mesh.node_set(set))
    sum += r[m.dofs.dof(m.fields.u, n, 2)];
  return sum;
}

} // namespace

TEST(EqualBlocksContact, TwoPressedBlocksOfOneSectionGiveTheAnswerOfOneBlockOfTheirHeight) {
  constexpr Real kPress = 0.4;
  const test::CaseRun stack =
      test::run_case_text(stack_case(true, 2.0, 4, 0.49, kPress), "stack.toml");
  ASSERT_TRUE(stack.report.success) << stack.report.failure;
  const test::CaseRun single =
      test::run_case_text(stack_case(false, 2.0, 4, 0.49, kPress), "single.toml");
  ASSERT_TRUE(single.report.success) << single.report.failure;
  Real worst = 0.0, bulge = 0.0;
  const model::Model& s = *single.model;
  for (Index n = 0; n < s.mesh.num_nodes(); ++n) {
    const Vec3 X = s.mesh.node(n);
    const Vec3 u = displacements_at(s, X).at(0);
    bulge = std::max(bulge, std::hypot(u.x(), u.y()));
    const std::vector<Vec3> in_stack = displacements_at(*stack.model, X);
    ASSERT_EQ(in_stack.size(), std::abs(X.z()) < 1e-12 ? 2u : 1u) << X.transpose();
    for (const Vec3& v : in_stack) // both sides of the interface
      worst = std::max(worst, (u - v).norm());
  }
  std::printf("closed interface: bulge %.4f mm; largest difference from one block %.2e mm "
              "(%.1e of the press)\n",
              bulge, worst, worst / kPress);
  EXPECT_GT(bulge, 0.2 * kPress); // the interface's edges move outwards with the press
  EXPECT_LT(worst, 1e-8 * kPress);
}

TEST(EqualBlocksContact, AStackWhoseCornersOpenIsItsOwnMirrorImageAndKeepsItsEdgesInContact) {
  constexpr Real kPress = 0.5, kSide = 5.0;
  const test::CaseRun stack =
      test::run_case_text(stack_case(true, kSide, 5, 0.499, kPress), "stack.toml");
  ASSERT_TRUE(stack.report.success) << stack.report.failure;
  EXPECT_EQ(stack.report.cutbacks, 0);
  const model::Model& m = *stack.model;
  // mirror image about the deformed interface plane z = −press/2: the node at (X, Y, −Z) of
  // one block moves as the node at (X, Y, Z) of the other with u_z → −press − u_z
  Real asymmetry = 0.0;
  for (Index n = 0; n < m.mesh.num_nodes(); ++n) {
    const Vec3 X = m.mesh.node(n);
    if (X.z() < -1e-12)
      continue; // the upper block's nodes, and the interface
    const std::vector<Vec3> here = displacements_at(m, X);
    const std::vector<Vec3> mirror = displacements_at(m, Vec3(X.x(), X.y(), -X.z()));
    const Vec3 u = here.back(), v = mirror.front(); // upper node at Z, lower node at −Z
    asymmetry = std::max(asymmetry, (Vec3(v.x(), v.y(), -kPress - v.z()) - u).norm());
  }
  const Real top = z_reaction(m, "upper.zmax"), bottom = z_reaction(m, "lower.zmin");
  // the slave edge nodes: in contact, except the corners, which open
  Real corner_gap = 0.0;
  int edge_nodes = 0;
  for (const contact::SlaveNodeState& q : m.contacts.at(0)->slave_states(m.problem->state())) {
    const Vec3 X = m.mesh.node(q.node);
    const bool x_edge = std::abs(std::abs(X.x()) - kSide / 2) < 1e-9,
               y_edge = std::abs(std::abs(X.y()) - kSide / 2) < 1e-9;
    if (x_edge && y_edge) {
      corner_gap = std::max(corner_gap, q.gap);
      EXPECT_TRUE(q.projected && !q.active && q.gap > 0) << "corner " << X.transpose();
    } else if (x_edge || y_edge) {
      ++edge_nodes;
      EXPECT_TRUE(q.projected && q.active) << "edge node " << X.transpose();
      EXPECT_LT(std::abs(q.gap), 1e-10 * kPress) << "edge node " << X.transpose();
    }
  }
  std::printf("opening corners: %d iterations, asymmetry %.2e mm, reactions top %.6g N bottom "
              "%.6g N, corner gap %.4f mm\n",
              stack.report.iterations, asymmetry, top, bottom, corner_gap);
  EXPECT_EQ(edge_nodes, 16);
  // Where the corners open, the master's edge facets are partly uncovered by the slave
  // surface, and the one-pass node-to-segment scheme, which treats the sides differently and
  // conserves momentum only where the surfaces cover each other, is neither exactly symmetric
  // nor exactly balanced: measured 1.7e-3 mm (3.5e-3 of the press) and 1.2e-4 of the load.
  EXPECT_LT(asymmetry, 1e-2 * kPress);
  EXPECT_LT(std::abs(top + bottom), 1e-3 * std::abs(top));
}
