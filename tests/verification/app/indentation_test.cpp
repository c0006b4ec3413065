// SPDX-License-Identifier: MIT
// The 3-D indentation example (examples/indentation) shortened to its load ramp, on a coarser
// mesh (6 x 6 x 2 cells): its quarter model (symmetry planes x = 0 and y = 0) against the whole
// layer on the mirrored mesh. The two
// are the same problem, so every force of the quarter model is a quarter of the whole model's;
// the layer is in equilibrium (contact force on the layer = bone reaction), and the water and
// ion balances close to round-off.
#include "case_runner.hpp"
#include "trifem/analysis/mass_balance.hpp"
#include "trifem/core/log.hpp"
#include "trifem/model/rigid_bodies.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

using namespace trifem;

namespace {

const std::filesystem::path kCase =
    std::filesystem::path(TRIFEM_EXAMPLES_DIR) / "indentation" / "indentation.toml";

std::string example_text() {
  std::ifstream in(kCase);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// text[begin marker, end marker) replaced by `by`; the markers must exist.
std::string replace_between(std::string text, const std::string& begin, const std::string& end,
                            const std::string& by) {
  const auto a = text.find(begin);
  const auto b = a == std::string::npos ? a : text.find(end, a + begin.size());
  EXPECT_NE(a, std::string::npos) << begin;
  EXPECT_NE(b, std::string::npos) << end;
  if (a == std::string::npos || b == std::string::npos)
    return text;
  return text.replace(a, b - a, by);
}

/// The example up to the end of the ramp (t = 10 s, 4 steps), without output: its text up to
/// the relaxation step.
std::string ramp_case(const std::string& text) {
  const auto relaxation = text.find("[[step]]\nname = \"relaxation\"");
  EXPECT_NE(relaxation, std::string::npos);
  std::string ramp = text.substr(0, relaxation);
  const std::string steps = "end_time = 10.0\ndt = 1.0";
  const auto at = ramp.find(steps);
  EXPECT_NE(at, std::string::npos);
  return at == std::string::npos ? ramp
                                 : ramp.replace(at, steps.size(), "end_time = 10.0\ndt = 2.5");
}

/// `text` on the mesh `file` of the test data (make_mesh.py --cells 6 --layers 2 [--full]).
std::string with_mesh(const std::string& text, const std::string& file) {
  const std::string path = (std::filesystem::path(TRIFEM_INDENTATION_MESHES) / file).string();
  return replace_between(text, "file = \"indentation_8.msh\"", "\n", "file = \"" + path + "\"");
}

/// The whole layer: the mirrored mesh, no symmetry conditions.
std::string whole_layer_case(const std::string& ramp) {
  const std::string whole = with_mesh(ramp, "indentation_6_full.msh");
  return replace_between(whole, "# symmetry planes", "# the indenter:", "");
}

/// The forces at the end of a run and the worst mass-balance error over its steps.
struct Forces {
  Real indenter = 0.0;    ///< z force of the rigid indenter on the layer (master side)
  Real layer = 0.0;       ///< z contact force on the layer (slave side)
  Real bone = 0.0;        ///< z reaction of the bonded bottom
  Real worst_balance = 0; ///< largest relative water/ion balance error of any body and step
};

Forces run(const std::string& text) {
  Forces f;
  std::unique_ptr<analysis::MassBalance> balance;
  const test::CaseRun run =
      test::run_case_text(text, kCase, [&](const test::CaseRun& r, const solver::StepInfo& info) {
        const model::Model& m = *r.model;
        if (!balance)
          balance = std::make_unique<analysis::MassBalance>(m);
        else
          balance->record_step(info.dt);
        const Vector& x = m.problem->state();
        f.indenter = model::rigid_body_force(m, m.rigid_bodies.at(0), info.time).z();
        f.layer = m.contacts.at(0)->slave_force(x).z();
        f.bone = 0.0;
        for (Index n : m.mesh.node_set("layer.bottom"))
          f.bone += m.problem->full_residual()[m.dofs.dof(m.fields.u, n, 2)];
      });
  EXPECT_TRUE(run.report.success) << run.report.failure;
  EXPECT_NEAR(run.report.end_time, 10.0, 1e-9);
  for (const analysis::BalanceRegion& r : balance->regions())
    for (Real worst : r.worst)
      f.worst_balance = std::max(f.worst_balance, worst);
  return f;
}

} // namespace

TEST(IndentationExample, QuarterModelGivesTheWholeModelsForces) {
  const std::string ramp = ramp_case(example_text());
  const Forces quarter = run(with_mesh(ramp, "indentation_6.msh"));
  const Forces whole = run(whole_layer_case(ramp));
  const Real scale = std::abs(whole.layer); // ~0.13 N at 0.15 mm of indentation
  ASSERT_GT(scale, 0.05);
  // the same solution: the slave side and the bone see exactly a quarter of the forces
  EXPECT_NEAR(4.0 * quarter.layer, whole.layer, 1e-8 * scale);
  EXPECT_NEAR(4.0 * quarter.bone, whole.bone, 1e-8 * scale);
  // the master side: master nodes on the symmetry planes keep their multipliers (they were
  // exposed once, and the quarter model's indenter force was 40 % low)
  EXPECT_NEAR(4.0 * quarter.indenter, whole.indenter, 1e-3 * scale);
  // equilibrium of the layer: contact force + bone reaction = 0
  EXPECT_NEAR(whole.layer + whole.bone, 0.0, 1e-8 * scale);
  EXPECT_NEAR(quarter.layer + quarter.bone, 0.0, 1e-8 * scale);
  // the master-side force differs from the slave side by the discretisation error of the
  // both-surface scheme (a curved contact zone of a few facets): 10 % on this coarse mesh
  EXPECT_LT(std::abs(whole.indenter - whole.layer), 0.15 * scale);
  log::info("whole layer: indenter {:.6g} N, layer {:.6g} N; quarter x 4 - whole: indenter "
            "{:.3g}, layer {:.3g} (relative to the layer force)",
            whole.indenter, whole.layer, (4.0 * quarter.indenter - whole.indenter) / scale,
            (4.0 * quarter.layer - whole.layer) / scale);
  EXPECT_LT(quarter.worst_balance, 1e-12);
  EXPECT_LT(whole.worst_balance, 1e-12);
}
