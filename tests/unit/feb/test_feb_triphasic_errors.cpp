// SPDX-License-Identifier: MIT
// Triphasic .feb models (multiphasic module): what the reader maps (units, fixed charge, bath)
// and what it refuses, each with one error line naming the file, line and XML path.
#include "feb_errors.hpp"
#include "trifem/core/error.hpp"
#include "trifem/feb/feb_reader.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

using namespace trifem;

namespace {

const std::filesystem::path kFile =
    std::filesystem::path(TRIFEM_FEB_DATA_DIR) / "triphasic_swelling_column.feb";

std::string column_text() {
  std::ifstream in(kFile);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The column file with the first `from` replaced by `to` (which must occur).
std::string column_with(const std::string& from, const std::string& to) {
  std::string text = column_text();
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos)
    text.replace(at, from.size(), to);
  return text;
}

std::string column_error(const std::string& text) {
  try {
    feb::parse_feb(text, "tri.feb");
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.find('\n'), std::string::npos) << "one line: " << what;
    return what;
  }
  ADD_FAILURE() << "no error";
  return "";
}

using test::expect_contains;

} // namespace

TEST(FebTriphasic, UnitsFixedChargeAndBathAreMapped) {
  const io::CaseSpec spec = feb::parse_feb(column_text(), kFile);
  const io::MaterialSpec& m = spec.materials.at("Cartilage");
  EXPECT_EQ(m.type, "triphasic");
  EXPECT_DOUBLE_EQ(m.parameters.at("phi_s0"), 0.2);
  EXPECT_DOUBLE_EQ(m.parameters.at("permeability"), 0.000914);
  EXPECT_DOUBLE_EQ(m.parameters.at("d_plus"), 0.0005);
  EXPECT_DOUBLE_EQ(m.parameters.at("d_minus"), 0.0008);
  EXPECT_DOUBLE_EQ(m.parameters.at("gamma_plus"), 1.0);
  // amounts in nmol (R = 8.314e-6 mJ/(nmol K)): 1 nmol/mm^3 = 1e-6 mmol/mm^3
  EXPECT_NEAR(m.parameters.at("fixed_charge"), 1e-6, 1e-21);
  EXPECT_NEAR(spec.electrochemistry.bath_concentration, 1.5e-4, 1e-19);
  EXPECT_NEAR(spec.electrochemistry.faraday, 96.485, 1e-12);
  EXPECT_DOUBLE_EQ(spec.electrochemistry.T, 293.0);
  // the charge curve 0 -> -200 (FEBio's negative charge) scales trifem's magnitude 0 -> 200
  ASSERT_EQ(spec.analysis.fixed_charge_curve, "Charge_fixed_charge");
  const auto& points = spec.curves.at("Charge_fixed_charge").points;
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(points[1].second, 200.0);
  // FEBio's STEP (the value of the next point) is trifem's "next"; the top is drained, the
  // other faces closed
  EXPECT_EQ(spec.curves.at("BathPressure").interpolation, dofs::Interpolation::Next);
  ASSERT_EQ(spec.fixed.size(), 7u); // bottom z, sides x y, then the bottom and four sides closed
  EXPECT_EQ(spec.fixed.back().fields.size(), 3u); // water and both ions
}

TEST(FebTriphasic, SolubilityIsTheInverseActivityCoefficient) {
  const std::string text =
      column_with("<solub>1</solub>", "<solub>0.5</solub>"); // the first solute: Na
  const io::CaseSpec spec = feb::parse_feb(text, kFile);
  EXPECT_DOUBLE_EQ(spec.materials.at("Cartilage").parameters.at("gamma_plus"), 2.0);
  EXPECT_DOUBLE_EQ(spec.materials.at("Cartilage").parameters.at("gamma_minus"), 1.0);
}

// diff below free_diff: the solute's friction with the solid (free_d_plus); above it refused
TEST(FebTriphasic, AFreeDiffusivityAboveTheTissuesIsTheFrictionWithTheSolid) {
  const io::CaseSpec spec =
      feb::parse_feb(column_with("<diff>0.0005</diff>", "<diff>0.0004</diff>"), kFile);
  const auto& p = spec.materials.at("Cartilage").parameters;
  EXPECT_DOUBLE_EQ(p.at("d_plus"), 0.0004);
  EXPECT_DOUBLE_EQ(p.at("free_d_plus"), 0.0005);
}

TEST(FebTriphasic, RefusesWhatItCannotMap) {
  expect_contains(column_error(column_with("<diff>0.0005</diff>", "<diff>0.0006</diff>")),
                  {"tri.feb:", "/solute[@sol='Na']/diffusivity[@type='diff-const-iso']: ",
                   "diff = 0.0006 exceeds free_diff = 0.0005"});
  expect_contains(column_error(column_with("<charge_number>-1</charge_number>",
                                           "<charge_number>2</charge_number>")),
                  {"/Solutes/solute[@name='Cl']/charge_number: ", "charge number 2"});
  expect_contains(column_error(column_with("<pt>1000,-200</pt>", "<pt>1000,200</pt>")),
                  {"fixed_charge_density: ", "is positive", "trifem's fixed charge is negative"});
  expect_contains(column_error(column_with("<R>8.314e-06</R>", "")),
                  {"febio_spec/Globals/Constants: ", "needs the constants R and T"});
  // a bath of water only: the ions of the top are not prescribed
  std::string water_only = column_text();
  for (const char* name : {"BathSodium", "BathChloride"}) {
    const auto at = water_only.find(fmt::format("<bc name=\"{}\"", name));
    water_only.erase(at, water_only.find("</bc>", at) + 5 - at);
  }
  expect_contains(column_error(water_only),
                  {"[@name='BathPressure']: ", "has no prescribed cation concentration"});
  // a bath whose gauge pressure p~ + RT (c+ + c-) is not 0
  expect_contains(column_error(column_with("<pt>1,-0.73084</pt>", "<pt>1,-0.5</pt>")),
                  {"[@name='BathPressure']: ", "trifem's bath is at gauge pressure 0"});
  expect_contains(column_error(column_with("<pt>1,150</pt>", "<pt>1,150</pt><pt>5000,100</pt>")),
                  {"[@name='BathSodium']: ", "the value changes in time"});
  expect_contains(column_error(column_with("<value>150</value>", "<value>100</value>")),
                  {"febio_spec/Initial/ic[@type='initial concentration'][@name='Sodium']: ",
                   "initial cation concentration 100", "Donnan equilibrium with its bath"});
  expect_contains(
      column_error(column_with("<Module type=\"multiphasic\"/>", "<Module type=\"biphasic\"/>")),
      {"febio_spec/Globals/Solutes: ", "<Solutes> needs the multiphasic module"});
  expect_contains(
      column_error(column_with("type=\"prescribed concentration\">\n      <dof>c1</dof>",
                               "type=\"prescribed concentration\">\n      <dof>c3</dof>")),
      {"/dof: ", "solute '3' is not defined"});
}
