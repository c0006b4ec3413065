// SPDX-License-Identifier: MIT
// [[step]] tables: time keys per step (end_time or duration), step-level conditions and loads
// with their own key paths, and the errors of bad steps.
#include "bad_input.hpp"
#include "trifem/core/error.hpp"
#include "trifem/io/case_reader.hpp"

#include <gtest/gtest.h>

using trifem::InputError;
using trifem::io::CaseSpec;
using trifem::io::parse_case;

using namespace trifem::test;

namespace {

const std::string kModel = R"(
[[mesh.box]]
name = "block"
size = [1, 1, 1]
divisions = [2, 2, 2]
material = "soft"

[materials.soft]
type = "neo-hookean"
E = 1.0

[curves.ramp]
points = [[0, 0], [1, 1]]
)";

const std::string kTwoSteps = kModel + R"(
[[step]]
name = "settle"
end_time = 10.0
dt = 1.0

[[step]]
duration = 5.0
dt = 0.5
dt_max = 1.0
release_time = 2.0
[[step.boundary.fixed]]
set = "block.zmin"
components = ["z"]
[[step.boundary.prescribed]]
set = "block.zmax"
component = "z"
value = -0.1
curve = "ramp"
relative = true
[[step.loads.pressure]]
surface = "block.xmax"
value = 0.01
)";

TEST(CaseReaderSteps, ReadsTimeConditionsAndLoadsPerStep) {
  const CaseSpec c = parse_case(kTwoSteps, "memory/case.toml");
  ASSERT_EQ(c.steps.size(), 2u);
  EXPECT_EQ(c.steps[0].name, "settle");
  EXPECT_EQ(c.steps[1].name, "step2");
  EXPECT_EQ(c.steps[0].time.end_time, 10.0);
  EXPECT_EQ(c.steps[1].time.end_time, 15.0); // duration after the previous end
  EXPECT_EQ(c.steps[1].time.dt_max, 1.0);
  EXPECT_EQ(c.steps[1].release_time, 2.0);
  EXPECT_TRUE(c.steps[0].fixed.empty());
  ASSERT_EQ(c.steps[1].fixed.size(), 1u);
  EXPECT_EQ(c.steps[1].fixed[0].key, "step[2].boundary.fixed[1]");
  ASSERT_EQ(c.steps[1].prescribed.size(), 1u);
  EXPECT_TRUE(c.steps[1].prescribed[0].relative);
  EXPECT_EQ(c.steps[1].pressures.size(), 1u);
  EXPECT_TRUE(c.fixed.empty()) << "step conditions are not case conditions";
  EXPECT_EQ(c.time.end_time, 15.0) << "the run spans every step";
}

/// kModel with a density: a quasi-static step and a dynamic-explicit one after it.
const std::string kDenseModel = replaced_in(kModel, "E = 1.0\n", "E = 1.0\ndensity = 1e-9\n");
const std::string kStretch = R"(
[[step]]
name = "stretch"
end_time = 1.0
dt = 0.5
[[step.boundary.prescribed]]
set = "block.zmax"
component = "z"
value = 0.01
curve = "ramp"
)";
const std::string kRelease = R"(
[[step]]
name = "release"
analysis = "dynamic-explicit"
duration = 1e-3
[[step.boundary.fixed]]
set = "block.zmin"
)";

TEST(CaseReaderSteps, ReadsADynamicExplicitLastStep) {
  const CaseSpec c = parse_case(
      kDenseModel + "[explicit]\nmultiplier = false\n" + kStretch + kRelease, "memory/case.toml");
  ASSERT_EQ(c.steps.size(), 2u);
  EXPECT_FALSE(c.is_explicit()) << "the case stays quasi-static";
  EXPECT_TRUE(c.has_explicit_step());
  EXPECT_FALSE(c.steps[0].is_explicit()) << "the default is the case's analysis";
  EXPECT_TRUE(c.steps[1].is_explicit());
  EXPECT_EQ(c.steps[1].time.end_time, 1.001);
  EXPECT_EQ(c.steps[1].time.dt, 0.0) << "no dt: the stability estimate";
  EXPECT_EQ(c.steps[1].fixed.size(), 1u);
  EXPECT_FALSE(c.explicit_dynamics.multiplier) << "[explicit] applies to the explicit step";
  EXPECT_EQ(c.time.end_time, 1.001);
}

class BadSteps : public testing::TestWithParam<BadCase> {};

TEST_P(BadSteps, FailNamingTheStepKey) {
  expect_fails_naming(GetParam());
}

const std::vector<BadCase> kBadSteps = {
    {"time_and_steps", kTwoSteps + "[time]\nend_time = 1.0\ndt = 0.1\n", {"time", "in each step"}},
    {"end_before_previous",
     kModel + "[[step]]\nend_time = 10.0\ndt = 1.0\n[[step]]\nend_time = 5.0\ndt = 1.0\n",
     {"step[2].end_time = 5", "after the previous step's end, 10 s"}},
    {"end_time_and_duration",
     kModel + "[[step]]\nend_time = 10.0\nduration = 10.0\ndt = 1.0\n",
     {"step[1].duration", "either end_time or duration"}},
    {"missing_dt", kModel + "[[step]]\nend_time = 10.0\n", {"step[1].dt", "missing required key"}},
    {"unknown_key",
     kModel + "[[step]]\nend_time = 10.0\ndt = 1.0\ndt_maximum = 2.0\n",
     {"step[1].dt_maximum", "unknown key"}},
    {"bath_in_step",
     kModel + "[[step]]\nend_time = 10.0\ndt = 1.0\n[[step.boundary.bath]]\nsurface = "
              "\"block.zmax\"\nconcentration = 1e-4\n",
     {"step[1].boundary.bath", "unknown key"}},
    {"duplicate_name",
     kModel + "[[step]]\nname = \"a\"\nend_time = 1.0\ndt = 1.0\n[[step]]\nname = \"a\"\n"
              "end_time = 2.0\ndt = 1.0\n",
     {"step[2].name = 'a'", "duplicate step name"}},
    {"unknown_analysis",
     kDenseModel + kStretch + replaced_in(kRelease, "dynamic-explicit", "implicit"),
     {"step[2].analysis = 'implicit'", "unknown analysis type", "dynamic-explicit"}},
    {"explicit_first",
     kDenseModel + kRelease,
     {"step[1].analysis = 'dynamic-explicit'", "follows at least one other step"}},
    {"explicit_with_material_axes",
     replaced_in(kDenseModel, "density = 1e-9\n",
                 "density = 1e-9\n[materials.soft.axes]\ntype = \"vector\"\na = [0, 1, 0]\n"
                 "d = [1, 0, 0]\n") +
         kStretch + kRelease,
     {"step[2].analysis = 'dynamic-explicit'", "material 'soft' has material axes"}},
    {"explicit_without_density",
     kModel + kStretch + kRelease,
     {"step[2].analysis = 'dynamic-explicit'", "material 'soft' has no density"}},
    {"explicit_with_biphasic",
     kDenseModel + kStretch + kRelease +
         "[materials.gel]\ntype = \"biphasic\"\nphi_s0 = 0.2\npermeability = 1e-3\n"
         "[materials.gel.solid]\ntype = \"neo-hookean\"\nE = 1.0\n",
     {"step[2].analysis = 'dynamic-explicit'", "material 'gel' is biphasic", "solid models"}},
    {"explicit_step_dt_max",
     kDenseModel + kStretch + replaced_in(kRelease, "duration", "dt_max = 1e-5\nduration"),
     {"step[2].dt_max", "quasi-static steps only"}},
    {"explicit_step_release_time",
     kDenseModel + kStretch + replaced_in(kRelease, "duration", "release_time = 1e-4\nduration"),
     {"step[2].release_time", "released at once"}},
    {"explicit_table_without_explicit_step",
     kDenseModel + "[explicit]\nmultiplier = false\n" + kStretch,
     {"explicit", "only applies to dynamic-explicit analyses"}},
    {"stable_step_none_without_dt",
     kDenseModel + "[explicit]\nstable_step = \"none\"\n" + kStretch + kRelease,
     {"step[2].analysis = 'dynamic-explicit'", "needs the step's dt"}},
};

INSTANTIATE_TEST_SUITE_P(Steps, BadSteps, testing::ValuesIn(kBadSteps), bad_case_name);

} // namespace
