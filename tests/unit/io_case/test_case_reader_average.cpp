// SPDX-License-Identifier: MIT
// [[output.average]] tables: name, quantity and cell block, and the errors of bad ones (unknown
// block or quantity, duplicate name, a quantity the block's material lacks, explicit analyses).
#include "bad_input.hpp"
#include "trifem/core/error.hpp"
#include "trifem/io/case_reader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

using trifem::io::CaseSpec;
using trifem::io::parse_case;

using namespace trifem::test;

namespace {

/// A solid box on a biphasic box.
const std::string kModel = R"(
[[mesh.box]]
name = "bone"
size = [1, 1, 1]
divisions = [1, 1, 1]
material = "hard"

[[mesh.box]]
name = "layer"
origin = [0, 0, 1]
size = [1, 1, 1]
divisions = [1, 1, 2]
material = "tissue"

[materials.hard]
type = "neo-hookean"
E = 10.0

[materials.tissue]
type = "biphasic"
phi_s0 = 0.2
permeability = 1e-3
[materials.tissue.solid]
type = "neo-hookean"
E = 1.0

[time]
end_time = 1.0
dt = 0.1
)";

/// kModel with one [[output.average]] of `quantity` over `block` named `name`.
std::string with_average(const std::string& name, const std::string& quantity,
                         const std::string& block, const std::string& base = kModel) {
  return base + "\n[[output.average]]\nname = \"" + name + "\"\nquantity = \"" + quantity +
         "\"\nblock = \"" + block + "\"\n";
}

/// "(line N)" for the line of `text` on which `fragment` first appears.
std::string line_of(const std::string& text, const std::string& fragment) {
  const auto at = text.find(fragment);
  EXPECT_NE(at, std::string::npos) << fragment;
  const auto line = std::count(text.begin(), text.begin() + static_cast<long>(at), '\n') + 1;
  return "(line " + std::to_string(line) + ")";
}

TEST(CaseReaderAverage, ReadsNameQuantityAndBlock) {
  const CaseSpec c = parse_case(with_average("pressure", "fluid_pressure", "layer",
                                             with_average("bone_stress", "stress", "bone")),
                                kMemoryFile);
  ASSERT_EQ(c.output.averages.size(), 2u);
  EXPECT_EQ(c.output.averages[0].name, "bone_stress");
  EXPECT_EQ(c.output.averages[0].quantity, "stress");
  EXPECT_EQ(c.output.averages[0].block, "bone");
  EXPECT_EQ(c.output.averages[1].name, "pressure");
  EXPECT_EQ(c.output.averages[1].quantity, "fluid_pressure");
  EXPECT_EQ(c.output.averages[1].block, "layer");
  EXPECT_TRUE(c.output.probes.empty());
}

TEST(CaseReaderAverage, AnyQuantityOfEveryMaterialOverAnyBlock) {
  for (const char* q : {"displacement", "position", "stress", "solid_stress", "relative_volume"})
    for (const char* block : {"bone", "layer"})
      EXPECT_EQ(parse_case(with_average("a", q, block), kMemoryFile).output.averages.size(), 1u)
          << q << " over " << block;
}

TEST(CaseReaderAverage, OtherPhysicalVolumesOfAGmshFileAreLeftToTheModel) {
  // the reader does not read the mesh file: a physical volume without a material may exist
  const std::string gmsh = R"(
[[mesh.gmsh]]
file = "part.msh"
materials = { cartilage_volume = "hard" }
)";
  const auto file = std::filesystem::path(TRIFEM_TEST_DATA_DIR) / "case.toml";
  const CaseSpec c = parse_case(with_average("a", "stress", "core", kModel + gmsh), file);
  ASSERT_EQ(c.output.averages.size(), 1u);
  EXPECT_EQ(c.output.averages[0].block, "core");
  // a volume with a material is checked against it
  const std::string text = with_average("p", "fluid_pressure", "cartilage_volume", kModel + gmsh);
  try {
    parse_case(text, file);
    ADD_FAILURE() << "no InputError";
  } catch (const trifem::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("output.average[1].quantity = 'fluid_pressure': cell "
                                         "block 'cartilage_volume' has the material 'hard'"),
              std::string::npos)
        << e.what();
  }
}

/// The TOML block that follows the heading `## <heading>` in docs/input.md.
std::string documented_example(const std::string& heading) {
  std::ifstream in(std::filesystem::path(TRIFEM_SOURCE_DIR) / "docs" / "input.md");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto begin = text.find("## " + heading + "\n\n");
  const auto body = text.find("```toml\n", begin);
  const auto end = text.find("```", body + 8);
  EXPECT_NE(begin, std::string::npos) << heading;
  if (begin == std::string::npos || body == std::string::npos || end == std::string::npos)
    return "";
  return text.substr(body + 8, end - body - 8);
}

TEST(CaseReaderAverage, DocumentedExamplesAverageTheirBlocks) {
  const CaseSpec solid = parse_case(documented_example("Complete annotated example"), kMemoryFile);
  ASSERT_EQ(solid.output.averages.size(), 1u);
  EXPECT_EQ(solid.output.averages[0].quantity, "stress");
  EXPECT_EQ(solid.output.averages[0].block, "block");
  const CaseSpec charged =
      parse_case(documented_example("Complete triphasic example"), kMemoryFile);
  ASSERT_EQ(charged.output.averages.size(), 1u);
  EXPECT_EQ(charged.output.averages[0].quantity, "cation_concentration");
  EXPECT_EQ(charged.output.averages[0].block, "layer");
}

class BadAverages : public testing::TestWithParam<BadCase> {};

TEST_P(BadAverages, FailNamingTheAverageKey) {
  expect_fails_naming(GetParam());
}

const std::string kProbe = "\n[[output.probe]]\nname = \"tip\"\npoint = [1, 1, 2]\n";

const std::string kExplicit = R"(
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

[time]
end_time = 0.01
)";

const std::vector<BadCase> kBadAverages = {
    {"unknown_block",
     with_average("a", "stress", "layr"),
     {"output.average[1].block = 'layr': unknown cell block (expected the name of a "
      "[[mesh.box]]: bone, layer); did you mean 'layer'?",
      line_of(with_average("a", "stress", "layr"), "block = \"layr\"")}},
    {"missing_block",
     kModel + "[[output.average]]\nname = \"a\"\nquantity = \"stress\"\n",
     {"output.average[1].block: missing required key"}},
    {"unknown_quantity",
     with_average("a", "pressure", "layer"),
     {"output.average[1].quantity = 'pressure': unknown quantity (expected one of: "
      "displacement, position,",
      line_of(with_average("a", "pressure", "layer"), "quantity = \"pressure\"")}},
    {"missing_quantity",
     kModel + "[[output.average]]\nname = \"a\"\nblock = \"layer\"\n",
     {"output.average[1].quantity: missing required key (expected one of: displacement,"}},
    {"unknown_key",
     with_average("a", "stress", "layer") + "point = [0, 0, 0]\n",
     {"output.average[1].point: unknown key (expected one of: name, quantity, block)"}},
    {"invalid_name",
     with_average("a b", "stress", "layer"),
     {"output.average[1].name = 'a b': invalid name"}},
    {"name_of_a_probe",
     with_average("tip", "stress", "layer", kModel + kProbe),
     {"output.average[1].name = 'tip': duplicate name (already used by output.probe[1]; probes "
      "and averages share the column prefixes of history.csv)"}},
    {"name_of_an_average",
     with_average("a", "stress", "layer", with_average("a", "stress", "bone")),
     {"output.average[2].name = 'a': duplicate name (already used by output.average[1]"}},
    {"pressure_of_a_solid",
     with_average("p", "fluid_pressure", "bone"),
     {"output.average[1].quantity = 'fluid_pressure': cell block 'bone' has the material 'hard' "
      "(neo-hookean), which has no fluid_pressure (it needs a biphasic or triphasic material)",
      line_of(with_average("p", "fluid_pressure", "bone"), "quantity = \"fluid_pressure\"")}},
    {"ions_of_a_biphasic_material",
     with_average("c", "cation_concentration", "layer"),
     {"output.average[1].quantity = 'cation_concentration': cell block 'layer' has the material "
      "'tissue' (biphasic), which has no cation_concentration (it needs a triphasic material)"}},
    {"explicit_analysis",
     with_average("u", "displacement", "beam", kExplicit),
     {"output.average[1]: [[output.average]] is not supported in dynamic-explicit analyses",
      "use [[output.probe]]",
      line_of(with_average("u", "displacement", "beam", kExplicit), "[[output.average]]")}},
};

INSTANTIATE_TEST_SUITE_P(Averages, BadAverages, testing::ValuesIn(kBadAverages), bad_case_name);

} // namespace
