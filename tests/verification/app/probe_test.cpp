// SPDX-License-Identifier: MIT
// [[output.probe]] of any field on the Terzaghi creep column (examples/biphasic_creep): the
// pressure probe equals the cell's pressure unknown (the VTU cell value) and the series
// solution, the interpolated displacement probe equals the series between nodes, the total
// stress probe equals the applied load (equilibrium of the 1-D column), and probes outside the
// mesh or of a quantity the material lacks are input errors naming the key.
#include "case_runner.hpp"
#include "exact_solutions.hpp"
#include "trifem/analysis/probes.hpp"
#include "trifem/core/error.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

using namespace trifem;

namespace {

const std::filesystem::path kCase =
    std::filesystem::path(TRIFEM_EXAMPLES_DIR) / "biphasic_creep" / "biphasic_creep.toml";
constexpr Real kSigma0 = 1e-4;                        ///< the example's load [MPa]
const exact::ConfinedLayer kLayer{1.0, 0.3, 1.07e-3}; ///< its layer (H_A = E, nu = 0)

std::string example_text() {
  std::ifstream in(kCase);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The example's case with the probes appended, its end time shortened to `end` and its
/// largest step to 10 s.
std::string case_with_probes(const std::string& probes, Real end = 600.0) {
  std::string text = example_text();
  const std::string key = "end_time = 6000.0";
  const auto at = text.find(key);
  EXPECT_NE(at, std::string::npos);
  text.replace(at, key.size(), fmt::format("end_time = {}", end));
  const std::string dt_max = "dt_max = 50.0"; // backward Euler: 10 s keeps its error < 2e-3
  const auto dt = text.find(dt_max);
  EXPECT_NE(dt, std::string::npos);
  text.replace(dt, dt_max.size(), "dt_max = 10.0");
  return text + "\n" + probes;
}

const char* kProbes = R"(
[[output.probe]]
name = "bottom"
quantity = "fluid_pressure"
point = [0.3, 0.6, 0.01]
[[output.probe]]
name = "middle"
point = [0.2, 0.7, 0.5061]
[[output.probe]]
name = "load"
quantity = "stress"
point = [0.5, 0.5, 0.73]
[[output.probe]]
name = "flux"
quantity = "fluid_flux"
point = [0.5, 0.5, 0.98]
)";

const model::Probe& probe(const model::Model& m, const std::string& name) {
  for (const model::Probe& p : m.probes)
    if (p.name == name)
      return p;
  throw std::runtime_error("no probe " + name);
}

std::vector<double> probe_values(const model::Model& m, const std::string& name) {
  std::vector<double> row;
  analysis::append_probe_values(m, analysis::CellEvaluator(m), probe(m, name), m.problem->state(),
                                row);
  return row;
}

TEST(Probes, MeasureEveryFieldOfTheCreepColumn) {
  int checked = 0;
  const auto run = test::run_case_text(
      case_with_probes(kProbes), kCase, [&](const test::CaseRun& r, const solver::StepInfo& info) {
        const model::Model& m = *r.model;
        const Real t = info.time;
        if (t < 50.0) // the early transient is resolved only by the finer steps
          return;
        // pressure: the unknown of the bottom cell (centre z = 0.0125) and the series there
        const std::vector<double> p = probe_values(m, "bottom");
        ASSERT_EQ(p.size(), 1u);
        EXPECT_EQ(p[0], m.problem->state()[m.dofs.dof(m.fields.p, 0, 0)]) << "t = " << t;
        EXPECT_NEAR(p[0], exact::creep_pressure(kLayer, kSigma0, 0.0125, t), 5e-3 * kSigma0)
            << "t = " << t;
        // displacement between two nodes, interpolated linearly along z
        const std::vector<double> u = probe_values(m, "middle");
        ASSERT_EQ(u.size(), 3u);
        const Real u_exact = exact::creep_displacement(kLayer, kSigma0, 0.5061, t);
        EXPECT_NEAR(u[2], u_exact, 5e-3 * kSigma0 * kLayer.h / kLayer.H_A) << "t = " << t;
        EXPECT_NEAR(u[0], 0.0, 1e-14 * kLayer.h);
        // total stress: -sigma0 in every cell of the column (equilibrium), xx yy zz xy yz xz
        const std::vector<double> s = probe_values(m, "load");
        ASSERT_EQ(s.size(), 6u);
        EXPECT_NEAR(s[2], -kSigma0, 1e-8 * kSigma0) << "t = " << t;
        // fluid flux near the top: upward (draining), zero laterally
        const std::vector<double> w = probe_values(m, "flux");
        ASSERT_EQ(w.size(), 3u);
        EXPECT_GT(w[2], 0.0);
        EXPECT_NEAR(w[0], 0.0, 1e-12 * w[2]);
        ++checked;
      });
  ASSERT_TRUE(run.report.success) << run.report.failure;
  EXPECT_GT(checked, 5);
}

TEST(Probes, ColumnsNameTheQuantityComponentsAndUnits) {
  const auto spec = io::parse_case(case_with_probes(kProbes), kCase);
  const auto m = model::build_model(spec);
  EXPECT_EQ(analysis::probe_columns(probe(*m, "bottom")),
            std::vector<std::string>{"bottom.fluid_pressure [MPa]"});
  EXPECT_EQ(analysis::probe_columns(probe(*m, "middle")),
            (std::vector<std::string>{"middle.ux [mm]", "middle.uy [mm]", "middle.uz [mm]"}));
  const auto stress = analysis::probe_columns(probe(*m, "load"));
  ASSERT_EQ(stress.size(), 6u);
  EXPECT_EQ(stress[3], "load.stress_xy [MPa]");
  EXPECT_EQ(analysis::probe_columns(probe(*m, "flux"))[2], "flux.fluid_flux_z [mm/s]");
}

/// The InputError message of building the model with `probes`.
std::string build_error(const std::string& probes) {
  try {
    model::build_model(io::parse_case(case_with_probes(probes), kCase));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Probes, OutsideTheMeshOrMissingQuantityIsAnInputError) {
  const std::string outside = build_error(R"(
[[output.probe]]
name = "out"
quantity = "fluid_pressure"
point = [0.5, 0.5, 1.001]
)");
  EXPECT_NE(outside.find("output.probe[2].point"), std::string::npos) << outside;
  EXPECT_NE(outside.find("outside the mesh"), std::string::npos) << outside;
  const std::string biphasic = build_error(R"(
[[output.probe]]
name = "psi"
quantity = "electric_potential"
point = [0.5, 0.5, 0.5]
)");
  EXPECT_NE(biphasic.find("output.probe[2].quantity = 'electric_potential'"), std::string::npos)
      << biphasic;
  EXPECT_NE(biphasic.find("triphasic"), std::string::npos) << biphasic;
}

} // namespace
