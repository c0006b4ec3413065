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
};

INSTANTIATE_TEST_SUITE_P(Steps, BadSteps, testing::ValuesIn(kBadSteps), bad_case_name);

} // namespace
