// SPDX-License-Identifier: MIT
// Large sliding: a short block (slave) pressed by a uniform follower pressure q onto a long
// block (master) and dragged over it through several master elements by a prescribed
// tangential displacement of its top (one hex layer, z DOFs fixed). Checks: global force
// balance of the slave body (Σ slave interface force = applied load), Newton convergence
// (residual histories logged), projections and stencils following the motion.
#include "contact_model.hpp"
#include "trifem/physics/facet_area.hpp"
#include "trifem/physics/surface_load_term.hpp"

#include <gtest/gtest.h>

using namespace trifem;

namespace {

constexpr Real kQ = 0.03;

/// Total applied force -q ∫ n da on the current top surface.
Vec3 applied_force(const test::ContactModel& m, Real q) {
  Vec3 f = Vec3::Zero();
  for (const auto& facet : m.mesh.surface("upper.ymax").facets) {
    fe::QuadCoords x;
    for (int a = 0; a < 4; ++a)
      for (int i = 0; i < 3; ++i)
        x(a, i) =
            m.mesh.node(facet.nodes[a])[i] + m.problem->state()[m.dofs.dof(m.u, facet.nodes[a], i)];
    const physics::FacetVector A = physics::facet_area_vectors(x);
    for (int a = 0; a < 4; ++a)
      f -= q * A.segment<3>(3 * a);
  }
  return f;
}

/// Long block [0, 4] x [0, 1] (8 x 2 cells) and a slider [0.4, 1.6] x [1, 2] (6 x 2 cells)
/// whose bottom is rounded, y = 1 + (x - 1)² / (2 R), R = 2 (the bump fades out towards its
/// flat top), touching the long block at x = 1.
mesh::Mesh sliding_mesh() {
  mesh::Mesh mesh =
      test::make_block("lower", test::shifted_coordinates(0, 4, 32), {0, 0.5, 1}, {0, 0.5});
  const Real R = 3;
  mesh.append(test::map_nodes(
      test::make_block("upper", test::shifted_coordinates(0.4, 1.6, 12), {1, 1.5, 2}, {0, 0.5}),
      [R](const Vec3& X) {
        const Real fade = 2 - X[1]; // 1 at the bottom, 0 at the top
        return Vec3(X[0], X[1] + fade * (X[0] - 1) * (X[0] - 1) / (2 * R), X[2]);
      }));
  return mesh;
}

/// Convergence order log(r_{k+1}) / log(r_k) of the last Newton pair in the asymptotic range
/// (r_k ≤ 1e-2, r_{k+1} ≥ 1e-12: above the round-off floor); 2 if there is none.
Real convergence_order(const std::vector<Real>& r) {
  for (std::size_t k = r.size() - 1; k-- > 1;)
    if (r[k] <= 1e-2 && r[k + 1] >= 1e-12)
      return std::log(r[k + 1]) / std::log(r[k]);
  return 2;
}

const dofs::LoadCurve kLoad({{0, 0}, {1, 0.2}, {2, 1}}, dofs::Interpolation::Linear);

/// The sliding model: lower block bottom fixed, z fixed everywhere (one hex layer), pressure
/// q kLoad(t) on the slider's top, whose x displacement goes 0 → travel over t = 2 → steps.
std::unique_ptr<test::ContactModel> sliding_model(contact::Integration integration, Real travel,
                                                  int steps) {
  auto m = std::make_unique<test::ContactModel>(sliding_mesh(), "neo-hookean",
                                                material::ParameterValues{{"E", 1.0}, {"nu", 0.3}},
                                                "lower.ymax", "upper.ymin");
  m->prescribe(m->mesh.node_set("lower.ymin"), 0);
  m->prescribe(m->mesh.node_set("lower.ymin"), 1);
  m->prescribe(m->mesh.node_set("lower.all"), 2);
  m->prescribe(m->mesh.node_set("upper.all"), 2);
  m->prescribe(
      m->mesh.node_set("upper.ymax"), 0, travel,
      dofs::LoadCurve({{2, 0}, {static_cast<Real>(steps), 1}}, dofs::Interpolation::Linear));
  m->loads.push_back(std::make_unique<physics::PressureTerm>(
      m->mesh, m->dofs, m->u, m->mesh.surface("upper.ymax").facets, kQ, kLoad));
  contact::ContactSettings settings;
  settings.integration = integration;
  settings.scale = 1.0 / 0.1; // E / h_slave
  m->build(settings);
  return m;
}

/// Two load steps, then steps - 2 sliding steps of travel / (steps - 2) (0.4 master and 0.5
/// slave elements each). Asserts per step: convergence, a consistent active set, global force
/// balance of the slave body to 1e-8 and, in sliding steps, quadratic convergence.
void run_sliding(contact::Integration integration, Real travel, int steps) {
  auto m = sliding_model(integration, travel, steps);
  solver::NewtonSettings newton;
  newton.residual_tolerance = 1e-12;
  newton.max_iterations = 30;
  newton.line_search = false;
  Real worst_balance = 0, worst_mismatch = 0;
  for (int step = 1; step <= steps; ++step) {
    const auto report = m->solve_step(step, 1.0, newton);
    std::string history;
    for (Real r : report.residual_history)
      history += fmt::format(" {:.1e}", r);
    ASSERT_EQ(report.status, solver::SolveStatus::Converged)
        << "step " << step << ": " << report.failure_reason << "; residuals" << history;
    const Vector& x = m->problem->state();
    const Vec3 fs = m->contact->slave_force(x), fm = m->contact->master_force(x);
    const Vec3 fa = applied_force(*m, kQ * kLoad(step));
    const Real balance = std::abs(fs[1] + fa[1]) / std::abs(fa[1]);
    const Real mismatch = std::abs(fs[1] + fm[1]) / std::abs(fs[1]);
    worst_balance = std::max(worst_balance, balance);
    worst_mismatch = std::max(worst_mismatch, mismatch);
    const Real order = convergence_order(report.residual_history);
    const auto& set = m->contact->active_set();
    std::printf("[ sliding ] step %2d: slide %.3f, active %2d, flips %2d, balance %.1e, "
                "master/slave %.1e, order %.2f, residuals%s\n",
                step, m->mean_displacement("upper.ymin", 0), static_cast<int>(set.num_active()),
                static_cast<int>(set.flips_in_step()), balance, mismatch, order, history.c_str());
    EXPECT_EQ(set.pending(), 0) << "step " << step << ": the active set did not settle";
    if (step > 2) {
      EXPECT_GE(order, 1.5) << "step " << step;
      EXPECT_LE(report.iterations, 8) << "step " << step;
    }
  }
  std::printf("[ sliding ] worst force balance %.1e, worst master/slave force mismatch %.1e, "
              "%d sparsity patterns\n",
              worst_balance, worst_mismatch, m->problem->pattern_id());
  EXPECT_LE(worst_balance, 1e-8);
  EXPECT_GT(m->problem->pattern_id(), steps) << "the stencils follow the sliding";
}

} // namespace

TEST(ContactSliding, BlockOverLongBlockBothSurfaces) {
  run_sliding(contact::Integration::BothSurfaces, 2.0, 42);
}
TEST(ContactSliding, BlockOverLongBlockSlaveNodes) {
  run_sliding(contact::Integration::SlaveNodes, 2.0, 42);
}

// Dragging the slider off the end of the long block: the step in which the loaded contact
// zone crosses the master's free edge converges, and the term cautions against it (a loaded
// slave node lost its projection: the time loop cuts such a step back while it can) without
// rejecting it; rejecting the step restores the committed active set.
TEST(ContactSliding, LoadedNodeLeavingTheMasterSurfaceCautionsAgainstTheStep) {
  auto m = sliding_model(contact::Integration::BothSurfaces, 4.0, 42); // 0.1 per sliding step
  solver::NewtonSettings newton;
  newton.residual_tolerance = 1e-12;
  newton.max_iterations = 30;
  std::string reason;
  int step = 1;
  for (; step <= 42 && reason.empty(); ++step) {
    m->problem->begin_step(step, 1.0);
    solver::NewtonSolver solver(newton, linalg::make_linear_solver({LinearSolverKind::umfpack}));
    const solver::NewtonReport report = solver.solve(*m->problem);
    ASSERT_EQ(report.status, solver::SolveStatus::Converged) << "step " << step;
    EXPECT_EQ(m->problem->step_rejection(), "") << "step " << step;
    reason = m->problem->step_caution();
    if (!reason.empty()) {
      const std::vector<char> committed = m->contact->active_set().flags();
      m->problem->reject_step();
      EXPECT_NE(m->contact->active_set().flags(), committed) << "the set changed in the step";
      break;
    }
    m->problem->commit_step();
  }
  EXPECT_NE(reason.find("left the master surface"), std::string::npos) << reason;
  EXPECT_GT(step, 3) << "rejected while the slider was still on the long block";
  std::printf("[ sliding ] step %d cautioned: %s\n", step, reason.c_str());
}
