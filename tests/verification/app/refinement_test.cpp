// SPDX-License-Identifier: MIT
// Refinement for convergence studies ([mesh] refine, trifem run --refine-mesh/--refine-time) on
// the Terzaghi creep column (examples/biphasic_creep): a refined mesh is the same model as the
// box built at the finer size (identical histories), halving the steps halves them everywhere,
// and refining both makes the top displacement converge to the series solution.
#include "case_runner.hpp"
#include "exact_solutions.hpp"
#include "trifem/analysis/case_file.hpp"
#include "trifem/analysis/probes.hpp"
#include "trifem/core/error.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>

using namespace trifem;

namespace {

const std::filesystem::path kCase =
    std::filesystem::path(TRIFEM_EXAMPLES_DIR) / "biphasic_creep" / "biphasic_creep.toml";
constexpr Real kSigma0 = 1e-4;                        ///< the example's load [MPa]
const exact::ConfinedLayer kLayer{1.0, 0.3, 1.07e-3}; ///< its layer (H_A = E, nu = 0)

/// `text` with the first `from` replaced by `to` (which must be there).
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos)
    text.replace(at, from.size(), to);
  return text;
}

/// The example with `divisions`, ending at `end` s with steps of at most `dt_max` s.
std::string creep_case(const std::string& divisions, Real end, Real dt_max) {
  std::ifstream in(kCase);
  std::stringstream s;
  s << in.rdbuf();
  std::string text = replaced(s.str(), "divisions = [1, 1, 40]", "divisions = " + divisions);
  text = replaced(text, "end_time = 6000.0", fmt::format("end_time = {}", end));
  return replaced(text, "dt_max = 50.0", fmt::format("dt_max = {}", dt_max));
}

/// The top displacement (probe "top", z component) after every step, with the step times.
std::vector<std::pair<Real, Real>> run_top_history(io::CaseSpec spec) {
  std::vector<std::pair<Real, Real>> history;
  const test::CaseRun run = test::run_case_spec(
      std::move(spec), [&](const test::CaseRun& r, const solver::StepInfo& info) {
        const model::Model& m = *r.model;
        std::vector<double> row;
        analysis::append_probe_values(m, analysis::CellEvaluator(m), m.probes.at(0),
                                      m.problem->state(), row);
        history.emplace_back(info.time, row.at(2));
      });
  EXPECT_TRUE(run.report.success) << run.report.failure;
  return history;
}

io::CaseSpec parse(const std::string& text) {
  return io::parse_case(text, kCase);
}

TEST(Refinement, ARefinedMeshIsTheBoxOfTwiceTheDivisions) {
  const std::string coarse = creep_case("[1, 1, 5]", 200.0, 20.0);
  const std::string refined =
      replaced(coarse, "[[mesh.box]]", "[mesh]\nrefine = 1\n\n[[mesh.box]]");
  const auto a = run_top_history(parse(refined));
  const auto b = run_top_history(parse(creep_case("[2, 2, 10]", 200.0, 20.0)));
  ASSERT_EQ(a.size(), b.size());
  ASSERT_GT(a.size(), 10u);
  const Real scale = kSigma0 * kLayer.h / kLayer.H_A; // the final settlement
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].first, b[i].first);
    EXPECT_NEAR(a[i].second, b[i].second, 1e-10 * scale) << "t = " << a[i].first;
  }
}

TEST(Refinement, RefineTimeHalvesEveryStepLimit) {
  io::CaseSpec spec = parse(creep_case("[1, 1, 5]", 200.0, 20.0));
  io::StepSpec hold;
  hold.name = "hold";
  hold.key = "step[1]";
  hold.time = spec.time;
  spec.steps.push_back(hold);
  analysis::refine_case(spec, {.mesh_levels = 2, .time_levels = 1});
  EXPECT_EQ(spec.mesh_refinement, 2);
  for (const io::TimeSpec* t : {&spec.time, &spec.steps[0].time}) {
    EXPECT_EQ(t->dt, 1.25 / 2);
    EXPECT_EQ(t->dt_max, 20.0 / 2);
    EXPECT_EQ(t->end_time, 200.0); // the step ends and the output times stay
  }
  EXPECT_EQ(model::build_model(spec)->mesh.num_cells(), 5 * 64);
}

TEST(Refinement, BadLevelsAreInputErrors) {
  io::CaseSpec spec = parse(creep_case("[1, 1, 5]", 200.0, 20.0));
  EXPECT_THROW(analysis::refine_case(spec, {.mesh_levels = -1}), InputError);
  EXPECT_THROW(analysis::refine_case(spec, {.mesh_levels = io::kMaxMeshRefinement + 1}),
               InputError);
  EXPECT_THROW(analysis::refine_case(spec, {.time_levels = 40}), InputError); // > 1e8 steps
  try {
    parse(replaced(creep_case("[1, 1, 5]", 200.0, 20.0), "[[mesh.box]]",
                   "[mesh]\nrefine = 9\n\n[[mesh.box]]"));
    ADD_FAILURE() << "refine = 9 was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("mesh.refine"), std::string::npos) << e.what();
  }
}

// Refining mesh and steps together, the top displacement at 100 s converges to the series
// solution: backward Euler is first order in the step, so each level at least halves the error.
TEST(Refinement, MeshAndStepRefinementConvergeToTheTerzaghiSeries) {
  constexpr Real kTime = 100.0;
  const Real exact = exact::creep_surface_displacement(kLayer, kSigma0, kTime);
  std::vector<Real> errors;
  for (int level = 0; level < 3; ++level) {
    io::CaseSpec spec = parse(creep_case("[1, 1, 5]", kTime, 10.0));
    analysis::refine_case(spec, {.mesh_levels = level, .time_levels = level});
    const auto history = run_top_history(spec);
    ASSERT_EQ(history.back().first, kTime);
    errors.push_back(std::abs(history.back().second - exact));
  }
  const Real scale = kSigma0 * kLayer.h / kLayer.H_A;
  std::printf("top displacement at %g s, error / final settlement: %.3e %.3e %.3e\n", kTime,
              errors[0] / scale, errors[1] / scale, errors[2] / scale);
  EXPECT_LT(errors[0], 0.05 * std::abs(exact)) << errors[0] / scale;
  EXPECT_LT(errors[1], 0.6 * errors[0]);
  EXPECT_LT(errors[2], 0.6 * errors[1]);
}

} // namespace
