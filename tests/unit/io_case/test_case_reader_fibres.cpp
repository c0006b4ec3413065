// SPDX-License-Identifier: MIT
// Solid mixtures, fibre families and fibre distributions in case files: [materials.<name>.solid]
// and top-level "solid-mixture" materials with [[...constituent]] tables, and the errors of bad
// ones.
#include "bad_input.hpp"
#include "trifem/core/error.hpp"
#include "trifem/io/case_reader.hpp"
#include "trifem/material/fibre_distribution.hpp"
#include "trifem/material/fibre_exp_pow.hpp"
#include "trifem/material/registry.hpp"
#include "trifem/material/solid_mixture.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using trifem::InputError;
using trifem::Mat3;
using trifem::Real;
using trifem::Vec3;
using trifem::io::CaseSpec;
using trifem::io::MaterialSpec;
using trifem::io::parse_case;
namespace material = trifem::material;

using namespace trifem::test;

namespace {

const std::string kModel = R"(
[[mesh.box]]
name = "block"
size = [1, 1, 1]
divisions = [2, 2, 2]
material = "cart"

[time]
end_time = 1.0
dt = 0.1
)";

/// The biphasic material of docs/input.md: a neo-Hookean matrix and one fibre family.
const std::string kCartilage = R"(
[materials.cart]
type = "biphasic"
phi_s0 = 0.2
permeability = 1e-3
[materials.cart.solid]
type = "solid-mixture"
[[materials.cart.solid.constituent]]
type = "neo-hookean"
E = 0.5
nu = 0.1
[[materials.cart.solid.constituent]]
type = "fibre-exp-pow"
ksi = 5.0
alpha = 0.0
beta = 2.0
fibre = [1, 0, 0]
)";

/// kModel + kCartilage with `from` replaced by `to` in the material.
std::string cartilage_with(const std::string& from, const std::string& to) {
  return kModel + replaced_in(kCartilage, from, to);
}

/// A biphasic material whose solid is a neo-Hookean matrix and an ellipsoidal fibre
/// distribution (the docs/input.md example): kCartilage with the fibre family replaced (the
/// same number of lines, so the line numbers in messages are those of kCartilage).
const std::string kDistributionCartilage = replaced_in(
    kCartilage, "type = \"fibre-exp-pow\"\nksi = 5.0\nalpha = 0.0\nbeta = 2.0\nfibre = [1, 0, 0]\n",
    "type = \"fibre-distribution\"\nksi = 2.0\nalpha = 0.0\nbeta = 2.5\nsemi_axes = [1, 1, 3]\n");

/// kModel + kDistributionCartilage with `from` replaced by `to` in the material.
std::string distribution_with(const std::string& from, const std::string& to) {
  return kModel + replaced_in(kDistributionCartilage, from, to);
}

} // namespace

TEST(CaseReaderFibres, BiphasicSolidMixture) {
  const CaseSpec c = parse_case(kModel + kCartilage, "memory/case.toml");
  const MaterialSpec& cart = c.materials.at("cart");
  EXPECT_EQ(cart.type, "biphasic");
  EXPECT_TRUE(cart.constituents.empty());
  ASSERT_TRUE(cart.solid.has_value());
  EXPECT_EQ(cart.solid->type, "solid-mixture");
  EXPECT_TRUE(cart.solid->parameters.empty());
  ASSERT_EQ(cart.solid->constituents.size(), 2u);
  const material::LawSpec& matrix = cart.solid->constituents[0];
  EXPECT_EQ(matrix.type, "neo-hookean");
  EXPECT_DOUBLE_EQ(matrix.parameters.at("E"), 0.5);
  EXPECT_DOUBLE_EQ(matrix.parameters.at("nu"), 0.1);
  const material::LawSpec& fibre = cart.solid->constituents[1];
  EXPECT_EQ(fibre.type, "fibre-exp-pow");
  EXPECT_EQ(fibre.parameters.size(), 6u); // ksi, alpha, beta and fibre.x, .y, .z
  EXPECT_DOUBLE_EQ(fibre.parameters.at("ksi"), 5.0);
  EXPECT_DOUBLE_EQ(fibre.parameters.at("alpha"), 0.0);
  EXPECT_DOUBLE_EQ(fibre.parameters.at("beta"), 2.0);
  EXPECT_EQ(material::vector_value(fibre.parameters, "fibre"), Vec3(1, 0, 0));
  EXPECT_TRUE(fibre.constituents.empty());

  // the law of the spec: the sum, with the small-strain moduli of the matrix
  const auto law = material::create_law(*cart.solid, "materials.cart.solid");
  const auto nh = material::create_law("neo-hookean", matrix.parameters, "m");
  EXPECT_EQ(law->type(), "solid-mixture");
  EXPECT_EQ(law->p_wave_modulus(), nh->p_wave_modulus());
  const trifem::Mat3 C = Vec3(1.44, 0.9, 0.9).asDiagonal(); // fibre stretch 1.2
  EXPECT_NEAR(law->energy(C) - nh->energy(C), 5.0 / 2.0 * 0.44 * 0.44, 1e-14);
}

TEST(CaseReaderFibres, TopLevelSolidMixtureWithInlineConstituents) {
  const std::string text = kModel + R"(
[materials.cart]
type = "solid-mixture"
density = 1e-9
constituent = [
  { type = "holmes-mow", E = 0.6, nu = 0.1, beta = 0.3 },
  { type = "fibre-exp-pow", ksi = 2, alpha = 1.5, beta = 2.5, fibre = [0, 3, 4] },
  { type = "fibre-exp-pow", ksi = 2, alpha = 1.5, beta = 2.5, fibre = [0, 3, -4] },
]
)";
  const CaseSpec c = parse_case(text, "memory/case.toml");
  const MaterialSpec& m = c.materials.at("cart");
  EXPECT_EQ(m.type, "solid-mixture");
  EXPECT_FALSE(m.is_mixture()); // a solid law, not a biphasic/triphasic mixture
  EXPECT_FALSE(m.solid.has_value());
  ASSERT_TRUE(m.density.has_value());
  EXPECT_DOUBLE_EQ(*m.density, 1e-9);
  ASSERT_EQ(m.constituents.size(), 3u);
  EXPECT_EQ(m.constituents[0].type, "holmes-mow");
  // stored as given; the law normalises it
  EXPECT_EQ(material::vector_value(m.constituents[2].parameters, "fibre"), Vec3(0, 3, -4));
  const material::LawSpec spec = m.solid_law();
  EXPECT_EQ(spec.type, "solid-mixture");
  EXPECT_EQ(spec.constituents.size(), 3u);
  const auto law = material::create_law(spec, "materials.cart");
  const auto& mixture = dynamic_cast<const material::SolidMixture&>(*law);
  const auto& fibre = dynamic_cast<const material::FibreExpPow&>(*mixture.constituents()[2]);
  EXPECT_LE((fibre.direction() - Vec3(0, 0.6, -0.8)).norm(), 1e-15);
}

TEST(CaseReaderFibres, TopLevelSolidMixtureWithTables) {
  const std::string text = kModel + R"(
[materials.cart]
type = "solid-mixture"
[[materials.cart.constituent]]
type = "neo-hookean"
E = 0.5
[[materials.cart.constituent]]
type = "fibre-exp-pow"
ksi = 1
alpha = 0
beta = 3
fibre = [0.0, 0.0, 1.0]
)";
  const MaterialSpec m =
      parse_case(text, "memory/case.toml").materials.at("cart"); // a copy: the case is a temporary
  ASSERT_EQ(m.constituents.size(), 2u);
  EXPECT_DOUBLE_EQ(m.constituents[0].parameters.at("nu"), 0.0); // schema default
  EXPECT_DOUBLE_EQ(m.constituents[1].parameters.at("beta"), 3.0);
  EXPECT_FALSE(m.density.has_value());
}

class BadFibreInput : public testing::TestWithParam<BadCase> {};

TEST_P(BadFibreInput, FailsNamingTheKeyPath) {
  expect_fails_naming(GetParam());
}

const std::string kConstituent2 = "materials.cart.solid.constituent[2]";

const std::vector<BadCase> kBadFibreCases = {
    {"missing_constituent",
     kModel + kCartilage.substr(0, kCartilage.find("[[materials.cart.solid.constituent]]")),
     {"materials.cart.solid.constituent: missing required array of tables (a solid mixture "
      "needs at least one constituent",
      "one [[materials.cart.solid.constituent]] table each", "(line 16)"}},
    {"empty_constituent_array",
     kModel + kCartilage.substr(0, kCartilage.find("[[materials.cart.solid.constituent]]")) +
         "constituent = []\n",
     {"materials.cart.solid.constituent: no constituent given"}},
    {"constituent_not_an_array",
     cartilage_with("[[materials.cart.solid.constituent]]\ntype = \"neo-hookean\"\nE = 0.5\nnu = "
                    "0.1\n[[materials.cart.solid.constituent]]",
                    "[materials.cart.solid.constituent]"),
     {"materials.cart.solid.constituent: expected an array of tables (one "
      "[[materials.cart.solid.constituent]] per entry), got a table"}},
    {"unknown_constituent_type",
     cartilage_with("\"fibre-exp-pow\"", "\"fiber-exp-pow\""),
     {kConstituent2 + ".type = 'fiber-exp-pow': unknown constituent law (expected one of:",
      "fibre-exp-pow", "did you mean 'fibre-exp-pow'?", "(line 23)"}},
    {"missing_constituent_type",
     cartilage_with("type = \"fibre-exp-pow\"\n", ""),
     {kConstituent2 + ".type: missing required key"}},
    {"zero_fibre_vector",
     cartilage_with("fibre = [1, 0, 0]", "fibre = [0, 0, 0]"),
     {kConstituent2 + ".fibre = [0, 0, 0]: the fibre direction must be a nonzero vector"}},
    {"fibre_of_two_numbers",
     cartilage_with("fibre = [1, 0, 0]", "fibre = [1, 0]"),
     {kConstituent2 + ".fibre: expected an array of 3 numbers, got an array of 2 element(s)",
      "(line 27)"}},
    {"fibre_of_four_numbers",
     cartilage_with("fibre = [1, 0, 0]", "fibre = [1, 0, 0, 0]"),
     {kConstituent2 + ".fibre: expected an array of 3 numbers, got an array of 4 element(s)"}},
    {"fibre_as_a_number",
     cartilage_with("fibre = [1, 0, 0]", "fibre = 1.0"),
     {kConstituent2 + ".fibre: expected an array of 3 numbers, got a floating-point number"}},
    {"fibre_with_a_string",
     cartilage_with("fibre = [1, 0, 0]", "fibre = [1, \"y\", 0]"),
     {kConstituent2 + ".fibre[2]: expected a number, got a string"}},
    {"missing_fibre",
     cartilage_with("fibre = [1, 0, 0]\n", ""),
     {kConstituent2 + ".fibre: missing required parameter (fibre direction"}},
    {"fibre_components_as_keys",
     cartilage_with("fibre = [1, 0, 0]", "fibre_x = 1"),
     {kConstituent2 + ".fibre_x: unknown key (expected one of: type, ksi, alpha, beta, fibre)"}},
    {"beta_below_2",
     cartilage_with("beta = 2.0", "beta = 1.5"),
     {kConstituent2 + ".beta = 1.5: out of range, expected a value in [2, inf)", "(line 26)"}},
    {"negative_ksi",
     cartilage_with("ksi = 5.0", "ksi = -5.0"),
     {kConstituent2 + ".ksi = -5: out of range, expected a value in [0, inf) MPa"}},
    {"missing_ksi",
     cartilage_with("ksi = 5.0\n", ""),
     {kConstituent2 + ".ksi: missing required parameter"}},
    {"misspelt_fibre_key",
     cartilage_with("ksi = 5.0", "ksi = 5.0\nkzi = 1.0"),
     {kConstituent2 + ".kzi: unknown key", "did you mean 'ksi'?"}},
    {"fibre_key_in_the_matrix",
     cartilage_with("nu = 0.1", "nu = 0.1\nksi = 5.0"),
     {"materials.cart.solid.constituent[1].ksi: unknown key (expected one of: type, E, nu)"}},
    {"density_in_a_constituent",
     cartilage_with("nu = 0.1", "nu = 0.1\ndensity = 1e-9"),
     {"materials.cart.solid.constituent[1].density: unknown key"}},
    {"parameter_of_the_mixture",
     cartilage_with("type = \"solid-mixture\"", "type = \"solid-mixture\"\nE = 1.0"),
     {"materials.cart.solid.E: unknown key (expected one of: type, constituent)"}},
    {"nested_solid_mixture",
     cartilage_with("type = \"fibre-exp-pow\"", "type = \"solid-mixture\""),
     {kConstituent2 + ".type = 'solid-mixture': nested solid mixtures are not supported"}},
    {"fibres_only",
     cartilage_with("type = \"neo-hookean\"\nE = 0.5\nnu = 0.1",
                    "type = \"fibre-exp-pow\"\nksi = 1\nalpha = 0\nbeta = 2\nfibre = [0, 1, 0]"),
     {"materials.cart.solid: the solid mixture (fibre-exp-pow, fibre-exp-pow) has no stiffness "
      "at zero strain"}},
    {"fibre_as_the_biphasic_solid",
     kModel + R"(
[materials.cart]
type = "biphasic"
phi_s0 = 0.2
permeability = 1e-3
[materials.cart.solid]
type = "fibre-exp-pow"
ksi = 5.0
alpha = 0.0
beta = 2.0
fibre = [1, 0, 0]
)",
     {"materials.cart.solid.type = 'fibre-exp-pow': a fibre family is valid only as a "
      "constituent of a solid mixture",
      "[[materials.cart.solid.constituent]]"}},
    {"fibre_as_a_material",
     kModel + R"(
[materials.cart]
type = "fibre-exp-pow"
ksi = 5.0
alpha = 0.0
beta = 2.0
fibre = [1, 0, 0]
)",
     {"materials.cart.type = 'fibre-exp-pow': a fibre family is valid only as a constituent of "
      "a solid mixture"}},
    {"constituent_of_a_plain_law",
     kModel + R"(
[materials.cart]
type = "neo-hookean"
E = 1.0
[[materials.cart.constituent]]
type = "neo-hookean"
E = 1.0
)",
     {"materials.cart.constituent: unknown key (expected one of: type, E, nu)"}},
    {"top_level_mixture_without_constituents",
     kModel + "[materials.cart]\ntype = \"solid-mixture\"\ndensity = 1e-9\n",
     {"materials.cart.constituent: missing required array of tables",
      "one [[materials.cart.constituent]] table each", "(line 11)"}},
};

INSTANTIATE_TEST_SUITE_P(SolidMixtures, BadFibreInput, testing::ValuesIn(kBadFibreCases),
                         bad_case_name);

TEST(CaseReaderFibreDistribution, ConstituentOfABiphasicSolid) {
  const CaseSpec c = parse_case(kModel + kDistributionCartilage, kMemoryFile);
  const MaterialSpec& cart = c.materials.at("cart");
  ASSERT_TRUE(cart.solid.has_value());
  ASSERT_EQ(cart.solid->constituents.size(), 2u);
  const material::LawSpec& fibres = cart.solid->constituents[1];
  EXPECT_EQ(fibres.type, "fibre-distribution");
  // ksi, alpha, beta, semi_axes.x, .y, .z and the default resolution
  EXPECT_EQ(fibres.parameters.size(), 7u);
  EXPECT_DOUBLE_EQ(fibres.parameters.at("ksi"), 2.0);
  EXPECT_DOUBLE_EQ(fibres.parameters.at("beta"), 2.5);
  EXPECT_EQ(material::vector_value(fibres.parameters, "semi_axes"), Vec3(1, 1, 3));
  EXPECT_DOUBLE_EQ(fibres.parameters.at("resolution"), 12.0);

  const auto law = material::create_law(*cart.solid, "materials.cart.solid");
  const auto& mixture = dynamic_cast<const material::SolidMixture&>(*law);
  const auto& distribution =
      dynamic_cast<const material::FibreDistribution&>(*mixture.constituents()[1]);
  EXPECT_EQ(distribution.directions().size(), 3u * 12u * 12u);
  // denser along z: the same stretch along z loads the fibres more than along x
  const Real l2 = 1.21;
  EXPECT_GT(distribution.stress(Mat3(Vec3(1, 1, l2).asDiagonal()))(2, 2),
            1.5 * distribution.stress(Mat3(Vec3(l2, 1, 1).asDiagonal()))(0, 0));
}

TEST(CaseReaderFibreDistribution, TopLevelSolidMixtureWithAResolution) {
  const std::string text = kModel + R"(
[materials.cart]
type = "solid-mixture"
constituent = [
  { type = "neo-hookean", E = 0.5, nu = 0.1 },
  { type = "fibre-distribution", ksi = 1, alpha = 0.5, beta = 2, semi_axes = [1, 1, 1], resolution = 20 },
]
)";
  const CaseSpec c = parse_case(text, kMemoryFile);
  const MaterialSpec& m = c.materials.at("cart");
  ASSERT_EQ(m.constituents.size(), 2u);
  EXPECT_DOUBLE_EQ(m.constituents[1].parameters.at("resolution"), 20.0);
  const auto law = material::create_law(m.solid_law(), "materials.cart");
  const auto& mixture = dynamic_cast<const material::SolidMixture&>(*law);
  EXPECT_EQ(dynamic_cast<const material::FibreDistribution&>(*mixture.constituents()[1])
                .directions()
                .size(),
            3u * 20u * 20u);
}

class BadFibreDistributionInput : public testing::TestWithParam<BadCase> {};

TEST_P(BadFibreDistributionInput, FailsNamingTheKeyPath) {
  expect_fails_naming(GetParam());
}

const std::vector<BadCase> kBadDistributionCases = {
    {"fractional_resolution",
     distribution_with("semi_axes = [1, 1, 3]", "semi_axes = [1, 1, 3]\nresolution = 12.5"),
     {kConstituent2 + ".resolution = 12.5: must be an integer"}},
    {"resolution_too_small",
     distribution_with("semi_axes = [1, 1, 3]", "semi_axes = [1, 1, 3]\nresolution = 2"),
     {kConstituent2 + ".resolution = 2: out of range, expected a value in [3, 64]"}},
    {"zero_semi_axis",
     distribution_with("semi_axes = [1, 1, 3]", "semi_axes = [1, 0, 3]"),
     {kConstituent2 + ".semi_axes[2] = 0: out of range, expected a value in (0, inf)",
      "(line 27)"}},
    {"semi_axes_of_two_numbers",
     distribution_with("semi_axes = [1, 1, 3]", "semi_axes = [1, 3]"),
     {kConstituent2 + ".semi_axes: expected an array of 3 numbers, got an array of 2 element(s)"}},
    {"missing_semi_axes",
     distribution_with("semi_axes = [1, 1, 3]\n", ""),
     {kConstituent2 + ".semi_axes: missing required parameter"}},
    {"fibre_direction_given",
     distribution_with("semi_axes = [1, 1, 3]", "semi_axes = [1, 1, 3]\nfibre = [1, 0, 0]"),
     {kConstituent2 + ".fibre: unknown key (expected one of: type, ksi, alpha, beta, semi_axes, "
                      "resolution)"}},
    {"beta_below_2",
     distribution_with("beta = 2.5", "beta = 1.5"),
     {kConstituent2 + ".beta = 1.5: out of range, expected a value in [2, inf)"}},
    {"misspelt_type",
     distribution_with("\"fibre-distribution\"", "\"fiber-distribution\""),
     {kConstituent2 + ".type = 'fiber-distribution': unknown constituent law",
      "did you mean 'fibre-distribution'?"}},
    {"distribution_alone_in_a_mixture",
     distribution_with("type = \"neo-hookean\"\nE = 0.5\nnu = 0.1",
                       "type = \"fibre-distribution\"\nksi = 1\nalpha = 0\nbeta = 2\nsemi_axes = "
                       "[1, 1, 1]"),
     {"materials.cart.solid: the solid mixture (fibre-distribution, fibre-distribution) has no "
      "stiffness at zero strain"}},
    {"distribution_as_the_biphasic_solid",
     kModel + R"(
[materials.cart]
type = "biphasic"
phi_s0 = 0.2
permeability = 1e-3
[materials.cart.solid]
type = "fibre-distribution"
ksi = 1.0
alpha = 0.0
beta = 2.0
semi_axes = [1, 1, 1]
)",
     {"materials.cart.solid.type = 'fibre-distribution': a fibre family is valid only as a "
      "constituent of a solid mixture"}},
    {"distribution_as_a_material",
     kModel + R"(
[materials.cart]
type = "fibre-distribution"
ksi = 1.0
alpha = 0.0
beta = 2.0
semi_axes = [1, 1, 1]
)",
     {"materials.cart.type = 'fibre-distribution': a fibre family is valid only as a constituent "
      "of a solid mixture"}},
};

INSTANTIATE_TEST_SUITE_P(FibreDistribution, BadFibreDistributionInput,
                         testing::ValuesIn(kBadDistributionCases), bad_case_name);

// --- material axes ---------------------------------------------------------------------------

TEST(CaseReaderMaterialAxes, EachTypeOnASolidAndOnAMixture) {
  const CaseSpec none = parse_case(kModel + kCartilage, kMemoryFile);
  EXPECT_FALSE(none.materials.at("cart").axes.has_value());

  const CaseSpec v =
      parse_case(kModel + kCartilage +
                     "[materials.cart.axes]\ntype = \"vector\"\na = [0, 1, 0]\nd = [-1, 0, 0]\n",
                 kMemoryFile);
  const auto& axes = v.materials.at("cart").axes;
  ASSERT_TRUE(axes.has_value());
  EXPECT_EQ(axes->kind, material::AxesKind::Vector);
  EXPECT_EQ(axes->a, Vec3(0, 1, 0));
  EXPECT_EQ(axes->d, Vec3(-1, 0, 0));

  const std::string solid = kModel + R"(
[materials.cart]
type = "neo-hookean"
E = 1.0
nu = 0.3
[materials.cart.axes]
)";
  const CaseSpec c = parse_case(
      solid + "type = \"cylindrical\"\ncenter = [1, 2, 3]\naxis = [0, 0, 2]\n", kMemoryFile);
  EXPECT_EQ(c.materials.at("cart").axes->kind, material::AxesKind::Cylindrical);
  EXPECT_EQ(c.materials.at("cart").axes->center, Vec3(1, 2, 3));
  EXPECT_EQ(c.materials.at("cart").axes->axis, Vec3(0, 0, 2));

  const CaseSpec s = parse_case(solid + "type = \"spherical\"\ncenter = [0, 0, -1]\n", kMemoryFile);
  EXPECT_EQ(s.materials.at("cart").axes->kind, material::AxesKind::Spherical);
  EXPECT_EQ(s.materials.at("cart").axes->axis, Vec3(0, 0, 1)); // the default pole axis

  const CaseSpec m = parse_case(solid + "type = \"mesh\"\nview = \"fibre\"\n", kMemoryFile);
  EXPECT_EQ(m.materials.at("cart").axes->kind, material::AxesKind::Mesh);
  EXPECT_EQ(m.materials.at("cart").axes->view, "fibre");
  EXPECT_EQ(m.materials.at("cart").axes->d_view, ""); // none: the completed basis
  const CaseSpec md =
      parse_case(solid + "type = \"mesh\"\nview = \"fibre\"\nd_view = \"sheet\"\n", kMemoryFile);
  EXPECT_EQ(md.materials.at("cart").axes->view, "fibre");
  EXPECT_EQ(md.materials.at("cart").axes->d_view, "sheet");
}

class BadAxesInput : public testing::TestWithParam<BadCase> {};

TEST_P(BadAxesInput, FailsNamingTheKeyPath) {
  expect_fails_naming(GetParam());
}

/// kModel + kCartilage with the axes table `axes` (its keys).
std::string cartilage_axes(const std::string& axes) {
  return kModel + kCartilage + "[materials.cart.axes]\n" + axes;
}

const std::vector<BadCase> kBadAxesCases = {
    {"missing_type",
     cartilage_axes("a = [1, 0, 0]\n"),
     {"materials.cart.axes.type: missing required key"}},
    {"unknown_type",
     cartilage_axes("type = \"polar\"\n"),
     {"materials.cart.axes.type = 'polar': unknown axes type (expected one of: vector, "
      "cylindrical, spherical, mesh)"}},
    {"parallel_vectors",
     cartilage_axes("type = \"vector\"\na = [1, 2, 3]\nd = [2, 4, 6]\n"),
     {"materials.cart.axes.d: must not be parallel to a", "(line 31)"}},
    {"zero_a",
     cartilage_axes("type = \"vector\"\na = [0, 0, 0]\nd = [0, 1, 0]\n"),
     {"materials.cart.axes.a: must be a nonzero vector"}},
    {"missing_d",
     cartilage_axes("type = \"vector\"\na = [1, 0, 0]\n"),
     {"materials.cart.axes.d: missing required key"}},
    {"key_of_another_type",
     cartilage_axes("type = \"vector\"\na = [1, 0, 0]\ncenter = [0, 0, 0]\n"),
     {"materials.cart.axes.center: unknown key (expected one of: type, a, d)"}},
    {"zero_cylinder_axis",
     cartilage_axes("type = \"cylindrical\"\ncenter = [0, 0, 0]\naxis = [0, 0, 0]\n"),
     {"materials.cart.axes.axis: must be a nonzero vector"}},
    {"missing_center",
     cartilage_axes("type = \"spherical\"\n"),
     {"materials.cart.axes.center: missing required key"}},
    {"mesh_missing_view",
     cartilage_axes("type = \"mesh\"\n"),
     {"materials.cart.axes.view: missing required key"}},
    {"mesh_empty_view",
     cartilage_axes("type = \"mesh\"\nview = \"\"\n"),
     {"materials.cart.axes.view", "expected a non-empty string"}},
    {"mesh_view_not_a_string",
     cartilage_axes("type = \"mesh\"\nview = [1, 0, 0]\n"),
     {"materials.cart.axes.view"}},
    {"mesh_d_view_is_view",
     cartilage_axes("type = \"mesh\"\nview = \"fibre\"\nd_view = \"fibre\"\n"),
     {"materials.cart.axes.d_view: must name another view than view", "(line 31)"}},
    {"mesh_key_of_another_type",
     cartilage_axes("type = \"mesh\"\nview = \"fibre\"\na = [1, 0, 0]\n"),
     {"materials.cart.axes.a: unknown key (expected one of: type, view, d_view)"}},
    {"vector_with_a_view",
     cartilage_axes("type = \"vector\"\na = [1, 0, 0]\nd = [0, 1, 0]\nview = \"fibre\"\n"),
     {"materials.cart.axes.view: unknown key (expected one of: type, a, d)"}},

    {"axes_not_a_table",
     kModel + replaced_in(kCartilage, "phi_s0 = 0.2", "phi_s0 = 0.2\naxes = 1"),
     {"materials.cart.axes: expected a table"}},
    {"axes_in_an_explicit_analysis",
     R"(
[analysis]
type = "dynamic-explicit"
[[mesh.box]]
name = "beam"
size = [4, 1, 1]
divisions = [4, 1, 1]
material = "rubber"
[materials.rubber]
type = "neo-hookean"
E = 0.8
density = 1.1e-9
[materials.rubber.axes]
type = "vector"
a = [0, 1, 0]
d = [1, 0, 0]
[time]
end_time = 0.01
)",
     {"materials.rubber.axes: not supported in dynamic-explicit analyses yet"}},
    {"axes_in_the_mixture_solid",
     kModel + replaced_in(kCartilage, "type = \"solid-mixture\"",
                          "type = \"solid-mixture\"\naxes = { type = \"vector\" }"),
     {"materials.cart.solid.axes: give the material axes of a mixture as [materials.cart.axes]"}},
};

INSTANTIATE_TEST_SUITE_P(MaterialAxes, BadAxesInput, testing::ValuesIn(kBadAxesCases),
                         bad_case_name);
