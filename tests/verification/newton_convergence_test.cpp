// SPDX-License-Identifier: MIT
// Newton converges quadratically on a 3-D bending problem (consistent tangent incl. the
// follower-load stiffness): the observed order of the last iterations is about 2.
#include "solid_model.hpp"
#include "trifem/physics/surface_load_term.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <iostream>

using namespace trifem;

TEST(NewtonConvergence, QuadraticOnCantileverBendingWithFollowerPressure) {
  mesh::BoxSpec spec;
  spec.size = Vec3(10.0, 1.0, 1.0);
  spec.divisions = {20, 2, 2};
  test::SolidModel m(mesh::make_box(spec), "neo-hookean", {{"E", 1.0}, {"nu", 0.3}});
  for (int k = 0; k < 3; ++k)
    m.prescribe(m.mesh.node_set("box.xmin"), k, 0.0);
  m.loads.push_back(std::make_unique<physics::PressureTerm>(
      m.mesh, m.dofs, m.u, m.mesh.surface("box.zmax").facets, 2e-4,
      dofs::LoadCurve({{0, 0}, {1, 1}}, dofs::Interpolation::Linear)));
  m.build();
  solver::NewtonSettings settings;
  settings.residual_tolerance = 1e-12;
  settings.line_search = false; // pure Newton: the rate is the tangent's, not the search's
  solver::NewtonReport report;
  for (int step = 1; step <= 4; ++step) {
    report = m.solve_step(0.25 * step, 0.25, settings);
    ASSERT_EQ(report.status, solver::SolveStatus::Converged) << "step " << step;
  }
  const auto& r = report.residual_history;
  std::string log;
  for (std::size_t k = 0; k < r.size(); ++k)
    log += fmt::format("  iteration {}: scaled residual {:.3e}\n", k, r[k]);
  std::cout << "Newton residuals of the last step (tip deflection "
            << m.displacement(m.mesh.num_nodes() - 1).z() << " mm):\n"
            << log;
  // Observed order p_k = log(r_{k+1}/r_k) / log(r_k/r_{k-1}) where all three residuals are in
  // the asymptotic range (below 5 % of the step's load scale) and above round-off.
  const Real round_off = *std::min_element(r.begin(), r.end());
  int checked = 0;
  for (std::size_t k = 1; k + 1 < r.size(); ++k) {
    if (r[k - 1] > 0.05 || r[k + 1] < 10 * round_off)
      continue; // pre-asymptotic, or at round-off
    const Real order = std::log(r[k + 1] / r[k]) / std::log(r[k] / r[k - 1]);
    EXPECT_GT(order, 1.8) << "iteration " << k << "\n" << log;
    ++checked;
  }
  EXPECT_GE(checked, 1) << log;
  EXPECT_LT(m.displacement(m.mesh.num_nodes() - 1).z(), -1.0); // genuinely large deflection
}
