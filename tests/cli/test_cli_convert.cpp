// SPDX-License-Identifier: MIT
// `trifem convert MODEL.feb -o CASE.toml`: the TOML case and its Gmsh mesh, run to the same
// history as the .feb file; errors as one line.
#include "cli_harness.hpp"

namespace trifem::cli_test {
namespace {

const fs::path kFebData = TRIFEM_FEB_DATA_DIR;

TEST_F(Cli, ConvertWritesACaseThatRunsLikeTheFebFile) {
  const fs::path feb = kFebData / "uniaxial_mooney_rivlin_pressure.feb";
  const Result c = trifem({"convert", feb.string(), "-o", "case.toml"});
  ASSERT_EQ(c.exit_code, kSuccess) << c;
  EXPECT_TRUE(contains(c.out, "wrote case.toml")) << c;
  EXPECT_TRUE(contains(c.out, "wrote case.msh")) << c;
  EXPECT_TRUE(error_lines(c.err).empty()) << c;
  ASSERT_TRUE(fs::exists(dir_ / "case.msh"));

  const Result from_feb = trifem({"run", feb.string(), "-o", "feb_out"});
  const Result from_toml = trifem({"run", "case.toml", "-o", "toml_out"});
  ASSERT_EQ(from_feb.exit_code, kSuccess) << from_feb;
  ASSERT_EQ(from_toml.exit_code, kSuccess) << from_toml;
  const History a = read_history(dir_ / "feb_out" / "history.csv");
  const History b = read_history(dir_ / "toml_out" / "history.csv");
  ASSERT_FALSE(a.names.empty());
  EXPECT_EQ(a.names, b.names);
  EXPECT_EQ(a.columns, b.columns); // the same numbers, bit for bit
}

TEST_F(Cli, ConvertOfAMissingFileIsOneErrorLine) {
  const fs::path missing = dir_ / "no_such_model.feb";
  const Result r = trifem({"convert", missing.string(), "-o", "case.toml"});
  EXPECT_EQ(r.exit_code, kInvalidInput) << r;
  const std::vector<std::string> lines = lines_of(r.err);
  ASSERT_EQ(lines.size(), 1u) << r;
  EXPECT_TRUE(lines[0].starts_with("error: ")) << r;
  EXPECT_TRUE(contains(lines[0], "no_such_model.feb")) << r;
  EXPECT_FALSE(fs::exists(dir_ / "case.toml"));
  EXPECT_FALSE(fs::exists(dir_ / "case.msh"));
}

TEST_F(Cli, ConvertNeedsAnOutputFile) {
  const Result r = trifem({"convert", (kFebData / "ogden_two_steps.feb").string()});
  EXPECT_EQ(r.exit_code, kUsage) << r;
  EXPECT_EQ(error_lines(r.err).size(), 1u) << r;
}

} // namespace
} // namespace trifem::cli_test
