// SPDX-License-Identifier: MIT
// [[loads.body_force]] and [[loads.nodal_force]]: their keys, the TOML writer's round trip, the
// restart fingerprint, and the errors of bad input, by the reader (keys, with their line) and by
// the model (cell blocks and their materials, node sets, naming the key).
#include "bad_input.hpp"
#include "trifem/analysis/restart_fingerprint.hpp"
#include "trifem/core/error.hpp"
#include "trifem/io/case_reader.hpp"
#include "trifem/io/case_writer.hpp"
#include "trifem/model/model.hpp"

#include <gtest/gtest.h>

using trifem::InputError;
using trifem::Vec3;
using trifem::io::CaseSpec;
using trifem::io::parse_case;

using namespace trifem::test;

namespace {

/// A block of solid with a density, a bone of rigid cells and a ramp; `rest` appended.
std::string body_case(const std::string& rest, const std::string& density = "density = 1e-9\n") {
  return R"(
[[mesh.box]]
name = "block"
size = [1, 1, 1]
divisions = [2, 2, 2]
material = "soft"

[[mesh.box]]
name = "bone"
origin = [0, 0, 1]
size = [1, 1, 0.5]
divisions = [1, 1, 1]

[materials.soft]
type = "neo-hookean"
E = 1.0
)" + density +
         R"(
[curves.ramp]
points = [[0, 0], [1, 1]]

[time]
end_time = 1.0
dt = 0.1

[[boundary.fixed]]
set = "block.zmin"

[[rigid_body]]
name = "femur"
blocks = ["bone"]
set = "block.zmax"
)" + rest;
}

const std::string kGravity = R"(
[[loads.body_force]]
force = [0, 0, -9810]
blocks = ["block"]
curve = "ramp"
)";

/// The message of the InputError that building the model of `text` throws ("" if none).
std::string model_error_of(const std::string& text) {
  const CaseSpec spec = parse_case(text, kMemoryFile);
  try {
    trifem::model::build_model(spec);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

void expect_contains(const std::string& message, const std::vector<std::string>& fragments) {
  ASSERT_FALSE(message.empty()) << "no error";
  for (const auto& f : fragments)
    EXPECT_NE(message.find(f), std::string::npos) << "'" << f << "' not in: " << message;
}

} // namespace

TEST(CaseReaderBodyForce, ReadsForceBlocksAndCurve) {
  const CaseSpec c = parse_case(body_case(kGravity + R"(
[[loads.body_force]]
force = [1.5, 0, 0]
)"),
                                kMemoryFile);
  ASSERT_EQ(c.body_forces.size(), 2u);
  EXPECT_EQ(c.body_forces[0].key, "loads.body_force[1]");
  EXPECT_EQ(c.body_forces[0].force, Vec3(0, 0, -9810));
  EXPECT_EQ(c.body_forces[0].blocks, std::vector<std::string>{"block"});
  EXPECT_EQ(c.body_forces[0].curve, "ramp");
  EXPECT_EQ(c.body_forces[1].key, "loads.body_force[2]");
  EXPECT_TRUE(c.body_forces[1].blocks.empty()); // every cell
  EXPECT_TRUE(c.body_forces[1].curve.empty());
}

TEST(CaseReaderBodyForce, TheWriterRoundTripsIt) {
  const CaseSpec c = parse_case(body_case(R"(
[[loads.body_force]]
force = [0.1, -0.2, -9810.5]
blocks = ["block", "bone"]
curve = "ramp"
[[loads.body_force]]
force = [3, 0, 0]
)"),
                                kMemoryFile);
  const CaseSpec back = parse_case(trifem::io::case_toml(c), kMemoryFile);
  ASSERT_EQ(back.body_forces.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(back.body_forces[i].key, c.body_forces[i].key);
    EXPECT_EQ(back.body_forces[i].force, c.body_forces[i].force);
    EXPECT_EQ(back.body_forces[i].blocks, c.body_forces[i].blocks);
    EXPECT_EQ(back.body_forces[i].curve, c.body_forces[i].curve);
  }
}

TEST(CaseReaderBodyForce, ARestartOfACaseWithAnotherBodyForceIsRefused) {
  const auto fingerprint = [](const std::string& text) {
    const CaseSpec spec = parse_case(text, kMemoryFile);
    const auto model = trifem::model::build_model(spec);
    return trifem::analysis::case_fingerprint(
        spec, *model)[static_cast<std::size_t>(trifem::analysis::CasePart::BoundaryConditions)];
  };
  const auto without = fingerprint(body_case(""));
  const auto with = fingerprint(body_case(kGravity));
  EXPECT_NE(without, with);
  EXPECT_NE(with, fingerprint(body_case(replaced_in(kGravity, "-9810", "-9811"))));
  EXPECT_NE(with,
            fingerprint(body_case(replaced_in(kGravity, "\"block\"", "\"block\", \"bone\""))));
  EXPECT_EQ(with, fingerprint(body_case(kGravity)));
}

const std::vector<BadCase> kBadBodyForces = {
    {"missing_force",
     body_case("[[loads.body_force]]\nblocks = [\"block\"]\n"),
     {"loads.body_force[1].force: missing required key (expected an array of 3 numbers)"}},
    {"unknown_key",
     body_case("[[loads.body_force]]\nforce = [0, 0, -1]\nvalue = 2\n"),
     {"loads.body_force[1].value: unknown key (expected one of: force, blocks, curve)"}},
    {"force_not_a_vector",
     body_case("[[loads.body_force]]\nforce = -9810\n"),
     {"loads.body_force[1].force"}},
    {"undefined_curve",
     body_case("[[loads.body_force]]\nforce = [0, 0, -1]\ncurve = \"rampe\"\n"),
     {"loads.body_force[1].curve = 'rampe': undefined curve", "did you mean 'ramp'?"}},
    {"no_blocks",
     body_case("[[loads.body_force]]\nforce = [0, 0, -1]\nblocks = []\n"),
     {"loads.body_force[1].blocks: no cell block given"}},
    {"a_block_twice",
     body_case("[[loads.body_force]]\nforce = [0, 0, -1]\nblocks = [\"block\", \"block\"]\n"),
     {"loads.body_force[1].blocks[2] = 'block': the block is named twice"}},
    {"in_a_step",
     replaced_in(body_case(R"(
[[step]]
end_time = 1.0
dt = 0.1
[[step.loads.body_force]]
force = [0, 0, -1]
)"),
                 "[time]\nend_time = 1.0\ndt = 0.1\n", ""),
     {"step[1].loads.body_force: a body force acts in every step", "[[loads.body_force]]"}},
};

class BadBodyForce : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadBodyForce, FailsNamingTheKey) {
  expect_fails_naming(GetParam());
}

INSTANTIATE_TEST_SUITE_P(CaseReaderBodyForce, BadBodyForce, ::testing::ValuesIn(kBadBodyForces),
                         [](const auto& info) { return info.param.name; });

TEST(CaseReaderBodyForce, AnUndefinedBlockIsAModelErrorNamingTheKey) {
  expect_contains(
      model_error_of(body_case(replaced_in(kGravity, "\"block\"", "\"block\", \"blok\""))),
      {"loads.body_force[1].blocks[2]", "undefined cell block 'blok'", "block"});
}

TEST(CaseReaderBodyForce, AMixtureUnderABodyForceIsAModelErrorNamingTheKey) {
  const std::string mixture = replaced_in(body_case(R"(
[[loads.body_force]]
force = [0, 0, -9810]
)",
                                                    ""),
                                          "type = \"neo-hookean\"\nE = 1.0\n",
                                          R"(type = "biphasic"
phi_s0 = 0.2
permeability = 1e-3
density = 1e-9
[materials.soft.solid]
type = "neo-hookean"
E = 1.0
)");
  expect_contains(model_error_of(mixture),
                  {"loads.body_force[1]: cell 0 has the mixture material 'soft'",
                   "body forces act on solid and rigid cells only (in a mixture the force also "
                   "drives the fluid through Darcy's law, which trifem does not model)",
                   "'blocks'"});
}

TEST(CaseReaderBodyForce, ASolidWithoutDensityIsAModelErrorNamingTheMaterial) {
  expect_contains(model_error_of(body_case(kGravity, "")),
                  {"loads.body_force[1]: the material 'soft' of cell 0 has no density",
                   "give `density` (t/mm^3) in [materials.soft]"});
}

TEST(CaseReaderBodyForce, NoMassIsAModelError) {
  // the bone's cells have no density: massless, skipped; nothing else is loaded
  expect_contains(model_error_of(body_case(replaced_in(kGravity, "\"block\"", "\"bone\""))),
                  {"loads.body_force[1]: the body force acts on no mass",
                   "give `density` in their [[rigid_body]]"});
  // with a density the bone carries the load
  EXPECT_EQ(model_error_of(replaced_in(body_case(replaced_in(kGravity, "\"block\"", "\"bone\"")),
                                       "set = \"block.zmax\"\n",
                                       "set = \"block.zmax\"\ndensity = 2e-9\n")),
            "");
}

TEST(CaseReaderBodyForce, ShellsOnFacesOfCellsAreAModelErrorNamingTheBodyAndTheSurface) {
  // the body's set is the block's top face: facets of hex cells, no surface mesh
  const std::string shells =
      replaced_in(replaced_in(body_case(kGravity), "blocks = [\"bone\"]\n",
                              "rotation = \"free\"\ndensity = 2e-9\nshell_thickness = 0.1\n"),
                  "name = \"bone\"\n", "name = \"bone\"\nmaterial = \"soft\"\n");
  expect_contains(model_error_of(shells),
                  {"rigid_body[1].shell_thickness", "facet 1 of the surface 'block.zmax'",
                   "is a face of cell", "bound no cell"});
}

// ---------------------------------------------------------------------------------------------
// [[loads.nodal_force]]

namespace {

const std::string kNodalForce = R"(
[[loads.nodal_force]]
set = "block.xmax"
value = [0.5, 0, -1.5]
curve = "ramp"
)";

} // namespace

TEST(CaseReaderNodalForce, ReadsSetValueAndCurveAndTheWriterRoundTripsThem) {
  const CaseSpec c = parse_case(body_case(kNodalForce + R"(
[[loads.nodal_force]]
set = "block.ymin"
value = [0, 2, 0]
)"),
                                kMemoryFile);
  ASSERT_EQ(c.nodal_forces.size(), 2u);
  EXPECT_EQ(c.nodal_forces[0].key, "loads.nodal_force[1]");
  EXPECT_EQ(c.nodal_forces[0].set, "block.xmax");
  EXPECT_EQ(c.nodal_forces[0].value, Vec3(0.5, 0, -1.5));
  EXPECT_EQ(c.nodal_forces[0].curve, "ramp");
  EXPECT_TRUE(c.nodal_forces[1].curve.empty());
  const CaseSpec back = parse_case(trifem::io::case_toml(c), kMemoryFile);
  ASSERT_EQ(back.nodal_forces.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(back.nodal_forces[i].set, c.nodal_forces[i].set);
    EXPECT_EQ(back.nodal_forces[i].value, c.nodal_forces[i].value);
    EXPECT_EQ(back.nodal_forces[i].curve, c.nodal_forces[i].curve);
  }
}

TEST(CaseReaderNodalForce, ARestartOfACaseWithAnotherNodalForceIsRefused) {
  const auto fingerprint = [](const std::string& text) {
    const CaseSpec spec = parse_case(text, kMemoryFile);
    const auto model = trifem::model::build_model(spec);
    return trifem::analysis::case_fingerprint(
        spec, *model)[static_cast<std::size_t>(trifem::analysis::CasePart::BoundaryConditions)];
  };
  const auto with = fingerprint(body_case(kNodalForce));
  EXPECT_NE(fingerprint(body_case("")), with);
  EXPECT_NE(with, fingerprint(body_case(replaced_in(kNodalForce, "-1.5", "-1.6"))));
  EXPECT_NE(with, fingerprint(body_case(replaced_in(kNodalForce, "xmax", "xmin"))));
  EXPECT_EQ(with, fingerprint(body_case(kNodalForce)));
}

const std::vector<BadCase> kBadNodalForces = {
    {"missing_value",
     body_case("[[loads.nodal_force]]\nset = \"block.xmax\"\n"),
     {"loads.nodal_force[1].value: missing required key"}},
    {"missing_set",
     body_case("[[loads.nodal_force]]\nvalue = [0, 0, 1]\n"),
     {"loads.nodal_force[1].set: missing required key"}},
    {"unknown_key",
     body_case("[[loads.nodal_force]]\nset = \"block.xmax\"\nvalue = [0, 0, 1]\nforce = 2\n"),
     {"loads.nodal_force[1].force: unknown key (expected one of: set, value, curve)"}},
    {"undefined_curve",
     body_case("[[loads.nodal_force]]\nset = \"block.xmax\"\nvalue = [0, 0, 1]\ncurve = "
               "\"rampe\"\n"),
     {"loads.nodal_force[1].curve = 'rampe': undefined curve", "did you mean 'ramp'?"}},
    {"in_a_step",
     replaced_in(body_case(R"(
[[step]]
end_time = 1.0
dt = 0.1
[[step.loads.nodal_force]]
set = "block.xmax"
value = [0, 0, -1]
)"),
                 "[time]\nend_time = 1.0\ndt = 0.1\n", ""),
     {"step[1].loads.nodal_force: a nodal force acts in every step", "[[loads.nodal_force]]"}},
};

class BadNodalForce : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadNodalForce, FailsNamingTheKey) {
  expect_fails_naming(GetParam());
}

INSTANTIATE_TEST_SUITE_P(CaseReaderNodalForce, BadNodalForce, ::testing::ValuesIn(kBadNodalForces),
                         [](const auto& info) { return info.param.name; });

TEST(CaseReaderNodalForce, AnUndefinedNodeSetIsAModelErrorNamingTheKey) {
  expect_contains(model_error_of(body_case(replaced_in(kNodalForce, "block.xmax", "block.xmx"))),
                  {"loads.nodal_force[1].set", "block.xmx"});
}

// ---------------------------------------------------------------------------------------------
// [[loads.traction]] area

TEST(CaseReaderTraction, AreaIsPerReferenceByDefaultOrPerCurrentAreaAndRoundTrips) {
  const CaseSpec c = parse_case(body_case(R"(
[[loads.traction]]
surface = "block.xmax"
value = [0.1, 0, 0]
[[loads.traction]]
surface = "block.xmax"
value = [0.2, 0, 0]
area = "current"
)"),
                                kMemoryFile);
  ASSERT_EQ(c.tractions.size(), 2u);
  EXPECT_FALSE(c.tractions[0].per_current_area);
  EXPECT_TRUE(c.tractions[1].per_current_area);
  const CaseSpec back = parse_case(trifem::io::case_toml(c), kMemoryFile);
  ASSERT_EQ(back.tractions.size(), 2u);
  EXPECT_FALSE(back.tractions[0].per_current_area);
  EXPECT_TRUE(back.tractions[1].per_current_area);
  const auto fingerprint = [](const std::string& text) {
    const CaseSpec spec = parse_case(text, kMemoryFile);
    const auto model = trifem::model::build_model(spec);
    return trifem::analysis::case_fingerprint(
        spec, *model)[static_cast<std::size_t>(trifem::analysis::CasePart::BoundaryConditions)];
  };
  const std::string load = "[[loads.traction]]\nsurface = \"block.xmax\"\nvalue = [0.1, 0, 0]\n";
  EXPECT_NE(fingerprint(body_case(load)), fingerprint(body_case(load + "area = \"current\"\n")));
  EXPECT_EQ(fingerprint(body_case(load)), fingerprint(body_case(load + "area = \"reference\"\n")));
  expect_fails_naming({"bad_area",
                       body_case(load + "area = \"deformed\"\n"),
                       {"loads.traction[1].area = 'deformed'", "reference", "current"}});
}

TEST(CaseReaderTraction, AForceIsATotalOverTheReferenceAreaAndRoundTrips) {
  const std::string load = "[[loads.traction]]\nsurface = \"block.xmax\"\n";
  const CaseSpec c = parse_case(body_case(load + "force = [0.3, 0, 0]\n"), kMemoryFile);
  ASSERT_EQ(c.tractions.size(), 1u);
  EXPECT_TRUE(c.tractions[0].total_force);
  EXPECT_EQ(c.tractions[0].value, Vec3(0.3, 0, 0));
  const CaseSpec back = parse_case(trifem::io::case_toml(c), kMemoryFile);
  ASSERT_EQ(back.tractions.size(), 1u);
  EXPECT_TRUE(back.tractions[0].total_force);
  const auto fingerprint = [](const std::string& text) {
    const CaseSpec spec = parse_case(text, kMemoryFile);
    const auto model = trifem::model::build_model(spec);
    return trifem::analysis::case_fingerprint(
        spec, *model)[static_cast<std::size_t>(trifem::analysis::CasePart::BoundaryConditions)];
  };
  EXPECT_NE(fingerprint(body_case(load + "force = [0.3, 0, 0]\n")),
            fingerprint(body_case(load + "value = [0.3, 0, 0]\n")));
  expect_fails_naming({"both",
                       body_case(load + "force = [1, 0, 0]\nvalue = [1, 0, 0]\n"),
                       {"loads.traction[1]", "either value", "force", "not both"}});
  expect_fails_naming({"neither", body_case(load), {"loads.traction[1]", "not neither"}});
  expect_fails_naming({"current",
                       body_case(load + "force = [1, 0, 0]\narea = \"current\"\n"),
                       {"loads.traction[1].area = \"current\"", "reference area"}});
}

TEST(CaseReaderPressure, AFollowerByDefaultOrADeadLoadAndRoundTrips) {
  const std::string load = "[[loads.pressure]]\nsurface = \"block.xmax\"\nvalue = 0.1\n";
  const CaseSpec c = parse_case(body_case(load + load + "follower = false\n"), kMemoryFile);
  ASSERT_EQ(c.pressures.size(), 2u);
  EXPECT_TRUE(c.pressures[0].follower);
  EXPECT_FALSE(c.pressures[1].follower);
  const CaseSpec back = parse_case(trifem::io::case_toml(c), kMemoryFile);
  ASSERT_EQ(back.pressures.size(), 2u);
  EXPECT_TRUE(back.pressures[0].follower);
  EXPECT_FALSE(back.pressures[1].follower);
  const auto fingerprint = [](const std::string& text) {
    const CaseSpec spec = parse_case(text, kMemoryFile);
    const auto model = trifem::model::build_model(spec);
    return trifem::analysis::case_fingerprint(
        spec, *model)[static_cast<std::size_t>(trifem::analysis::CasePart::BoundaryConditions)];
  };
  EXPECT_NE(fingerprint(body_case(load)), fingerprint(body_case(load + "follower = false\n")));
  EXPECT_EQ(fingerprint(body_case(load)), fingerprint(body_case(load + "follower = true\n")));
  expect_fails_naming(
      {"bad_follower", body_case(load + "follower = \"no\"\n"), {"loads.pressure[1].follower"}});
}
