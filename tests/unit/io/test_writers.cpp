// SPDX-License-Identifier: MIT
// Tests of the .vtu, .pvd and .csv result writers, reading the files back with small parsers.
#include "trifem/core/error.hpp"
#include "trifem/io/csv_writer.hpp"
#include "trifem/io/pvd_writer.hpp"
#include "trifem/io/pvtu_writer.hpp"
#include "trifem/io/vtu_writer.hpp"

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>
#include <unistd.h>
#include <vector>

namespace trifem::io {
namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  EXPECT_TRUE(in.is_open()) << file;
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string xml_unescape(std::string_view text) {
  static const std::array<std::pair<std::string_view, char>, 5> kEntities = {
      {{"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}}};
  std::string result;
  for (std::size_t i = 0; i < text.size();) {
    bool replaced = false;
    for (const auto& [entity, c] : kEntities) {
      if (text.substr(i, entity.size()) == entity) {
        result += c;
        i += entity.size();
        replaced = true;
        break;
      }
    }
    if (!replaced)
      result += text[i++];
  }
  return result;
}

/// Value of attribute `name` in the XML start tag `tag` (unescaped); "" if absent.
std::string attribute(std::string_view tag, std::string_view name) {
  const std::string key = " " + std::string(name) + "=\"";
  const std::size_t begin = tag.find(key);
  if (begin == std::string_view::npos)
    return {};
  const std::size_t value = begin + key.size();
  return xml_unescape(tag.substr(value, tag.find('"', value) - value));
}

/// All start tags `<element ...>` of the XML text, in order.
std::vector<std::string_view> tags(std::string_view xml, std::string_view element) {
  std::vector<std::string_view> found;
  const std::string open = "<" + std::string(element) + " ";
  for (std::size_t at = xml.find(open); at != std::string_view::npos; at = xml.find(open, at + 1))
    found.push_back(xml.substr(at, xml.find('>', at) + 1 - at));
  return found;
}

/// A .vtu file read back: XML part and the raw appended block.
class VtuFile {
public:
  explicit VtuFile(const fs::path& file) : text_(read_text(file)) {
    const std::size_t appended = text_.find("<AppendedData");
    xml_ = std::string_view(text_).substr(0, appended);
    if (appended != std::string::npos) {
      EXPECT_NE(text_.find("encoding=\"raw\"", appended), std::string::npos);
      base_ = text_.find('_', appended) + 1;
    }
  }

  std::string_view xml() const { return xml_; }
  std::string_view piece() const { return tags(xml_, "Piece").at(0); }

  /// Decoded bytes of the DataArray called `name`, which must have VTK type `type`.
  std::vector<std::byte> bytes(std::string_view name, std::string_view type) const {
    for (const std::string_view tag : tags(xml_, "DataArray")) {
      if (attribute(tag, "Name") != name)
        continue;
      EXPECT_EQ(attribute(tag, "type"), type) << name;
      return decode(tag);
    }
    ADD_FAILURE() << "no DataArray named " << name;
    return {};
  }

  /// The values of DataArray `name` as T (Float64 = double, Int64, UInt8).
  template <class T>
  std::vector<T> values(std::string_view name) const {
    const std::string_view type = std::is_same_v<T, double>         ? "Float64"
                                  : std::is_same_v<T, std::int64_t> ? "Int64"
                                                                    : "UInt8";
    const std::vector<std::byte> raw = bytes(name, type);
    std::vector<T> result(raw.size() / sizeof(T));
    EXPECT_EQ(raw.size() % sizeof(T), 0u);
    if (!result.empty())
      std::memcpy(result.data(), raw.data(), result.size() * sizeof(T));
    return result;
  }

  std::string components(std::string_view name) const {
    for (const std::string_view tag : tags(xml_, "DataArray"))
      if (attribute(tag, "Name") == name)
        return attribute(tag, "NumberOfComponents");
    return {};
  }

private:
  std::vector<std::byte> decode(std::string_view tag) const {
    EXPECT_EQ(attribute(tag, "format"), "appended");
    return appended(std::stoull(attribute(tag, "offset")));
  }

  std::vector<std::byte> appended(std::uint64_t offset) const {
    EXPECT_NE(base_, std::string::npos);
    std::uint64_t n = 0;
    EXPECT_LE(base_ + offset + 8, text_.size());
    std::memcpy(&n, text_.data() + base_ + offset, 8);
    EXPECT_LE(base_ + offset + 8 + n, text_.size());
    const auto* begin = reinterpret_cast<const std::byte*>(text_.data() + base_ + offset + 8);
    return {begin, begin + n};
  }

  std::string text_;
  std::string_view xml_;
  std::size_t base_ = std::string::npos;
};

template <class T>
std::vector<std::byte> as_bytes(const std::vector<T>& values) {
  const auto bytes = std::as_bytes(std::span<const T>(values));
  return {bytes.begin(), bytes.end()};
}

/// Each test gets its own empty scratch directory, removed afterwards.
class WriterTest : public ::testing::Test {
protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(info->test_suite_name()) + "_" + info->name();
    for (char& c : name)
      c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    dir_ = fs::temp_directory_path() / ("trifem_io_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path dir_;
};

/// Doubles whose decimal forms are awkward: exact round trip is the point of the tests.
double tricky(std::size_t i) {
  static const std::array<double, 8> kValues = {
      0.1, 1.0 / 3.0, 1e-300, 5e-324, -0.0, -2.5e17, std::numeric_limits<double>::max(), 42.0};
  const double value = kValues[i % kValues.size()];
  return (i / kValues.size()) % 2 == 0 ? value : -value / 7.0; // stays finite
}

DataArray make_data(std::string name, int components, std::size_t count, std::size_t seed) {
  DataArray a{std::move(name), components, {}};
  for (std::size_t i = 0; i < count * static_cast<std::size_t>(components); ++i)
    a.values.push_back(tricky(seed + i));
  return a;
}

const std::string kPressure = "pressure & <p> \"kPa\" 'x'";

/// Two hexahedra sharing a face (12 points), with point and cell data.
UnstructuredGrid two_hexes() {
  UnstructuredGrid grid;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i)
        grid.points.push_back(Vec3(0.1 * i, 1.0 / 3.0 * j, 1e-3 * k));
  const std::array<Index, 8> h0 = {0, 1, 4, 3, 6, 7, 10, 9};
  const std::array<Index, 8> h1 = {1, 2, 5, 4, 7, 8, 11, 10};
  grid.add_cell(vtk_cell::kHexahedron, h0);
  grid.add_cell(vtk_cell::kHexahedron, h1);
  grid.point_data.push_back(make_data("displacement [mm]", 3, 12, 0));
  grid.point_data.push_back(make_data(kPressure, 1, 12, 5));
  grid.cell_data.push_back(make_data("stress", 6, 2, 3));
  return grid;
}

/// A 2 x 1 grid of quads in the z = 0 plane, with point and cell data.
UnstructuredGrid two_quads() {
  UnstructuredGrid grid;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i)
      grid.points.push_back(Vec3(i, j, 0.0));
  const std::array<Index, 4> q0 = {0, 1, 4, 3};
  const std::array<Index, 4> q1 = {1, 2, 5, 4};
  grid.add_cell(vtk_cell::kQuad, q0);
  grid.add_cell(vtk_cell::kQuad, q1);
  grid.point_data.push_back(make_data("contact pressure", 1, 6, 1));
  grid.cell_data.push_back(make_data("gap <mm>", 1, 2, 2));
  return grid;
}

std::vector<double> flat_points(const UnstructuredGrid& grid) {
  std::vector<double> coords;
  for (const Vec3& p : grid.points)
    coords.insert(coords.end(), {p[0], p[1], p[2]});
  return coords;
}

/// Reads `file` back and checks every array against `grid`, bitwise.
void expect_round_trip(const fs::path& file, const UnstructuredGrid& grid) {
  const VtuFile vtu(file);
  EXPECT_NE(vtu.xml().find("<VTKFile type=\"UnstructuredGrid\" version=\"1.0\""),
            std::string::npos);
  EXPECT_NE(vtu.xml().find("header_type=\"UInt64\""), std::string::npos);
  EXPECT_NE(vtu.xml().find("byte_order=\"LittleEndian\""), std::string::npos);
  EXPECT_EQ(attribute(vtu.piece(), "NumberOfPoints"), std::to_string(grid.points.size()));
  EXPECT_EQ(attribute(vtu.piece(), "NumberOfCells"), std::to_string(grid.types.size()));
  EXPECT_EQ(vtu.bytes("Points", "Float64"), as_bytes(flat_points(grid)));
  EXPECT_EQ(vtu.components("Points"), "3");
  const std::vector<std::int64_t> connectivity(grid.connectivity.begin(), grid.connectivity.end());
  const std::vector<std::int64_t> offsets(grid.offsets.begin(), grid.offsets.end());
  EXPECT_EQ(vtu.values<std::int64_t>("connectivity"), connectivity);
  EXPECT_EQ(vtu.values<std::int64_t>("offsets"), offsets);
  EXPECT_EQ(vtu.values<std::uint8_t>("types"), grid.types);
  for (const auto* section : {&grid.point_data, &grid.cell_data})
    for (const DataArray& a : *section) {
      EXPECT_EQ(vtu.bytes(a.name, "Float64"), as_bytes(a.values)) << a.name;
      EXPECT_EQ(vtu.components(a.name), std::to_string(a.components)) << a.name;
    }
  EXPECT_FALSE(fs::exists(fs::path(file.string() + ".tmp")));
}

TEST_F(WriterTest, AddCellKeepsOffsetsConsistent) {
  const UnstructuredGrid grid = two_hexes();
  EXPECT_EQ(grid.offsets, (std::vector<Index>{8, 16}));
  EXPECT_EQ(grid.types, (std::vector<std::uint8_t>{12, 12}));
  EXPECT_EQ(grid.connectivity.size(), 16u);
}

TEST_F(WriterTest, VtuRoundTripsHexAndQuadGrids) {
  const UnstructuredGrid hexes = two_hexes();
  const UnstructuredGrid quads = two_quads();
  EXPECT_EQ(write_vtu(dir_ / "hexes.vtu", hexes), 0u);
  EXPECT_EQ(write_vtu(dir_ / "quads.vtu", quads), 0u);
  expect_round_trip(dir_ / "hexes.vtu", hexes);
  expect_round_trip(dir_ / "quads.vtu", quads);
}

TEST_F(WriterTest, PiecesHoldTheirCellsWithTheirPointsAndData) {
  const UnstructuredGrid grid = two_hexes();
  for (const Index cell : {0, 1}) {
    SCOPED_TRACE(cell);
    const std::array<Index, 1> cells = {cell};
    const UnstructuredGrid piece = piece_of(grid, cells);
    ASSERT_EQ(piece.cell_count(), 1u);
    ASSERT_EQ(piece.points.size(), 8u); // the cell's points only
    EXPECT_EQ(piece.types[0], vtk_cell::kHexahedron);
    for (Index k = 0; k < 8; ++k) { // the same corners, in the same order
      const Index original = grid.connectivity[8 * cell + k];
      const Index local = piece.connectivity[k];
      EXPECT_EQ(piece.points[local], grid.points[original]);
      for (std::size_t a = 0; a < grid.point_data.size(); ++a) {
        const int n = grid.point_data[a].components;
        for (int c = 0; c < n; ++c)
          EXPECT_EQ(piece.point_data[a].values[local * n + c],
                    grid.point_data[a].values[original * n + c]);
      }
    }
    const int n = grid.cell_data[0].components;
    EXPECT_EQ(piece.cell_data[0].values,
              std::vector<double>(grid.cell_data[0].values.begin() + cell * n,
                                  grid.cell_data[0].values.begin() + (cell + 1) * n));
    EXPECT_EQ(write_vtu(dir_ / "piece.vtu", piece), 0u); // a valid grid of its own
  }
  const std::array<Index, 2> both = {0, 1}; // all cells: the grid itself
  const UnstructuredGrid whole = piece_of(grid, both);
  EXPECT_EQ(whole.connectivity, grid.connectivity);
  EXPECT_EQ(whole.point_data[1].values, grid.point_data[1].values);
}

TEST_F(WriterTest, PvtuListsThePiecesAndTheArraysOfTheGrid) {
  const UnstructuredGrid grid = two_hexes();
  write_pvtu(dir_ / "volume.pvtu", grid, {"volume_0.vtu", "volume_1.vtu"});
  const std::string text = read_text(dir_ / "volume.pvtu");
  EXPECT_NE(text.find(R"(<VTKFile type="PUnstructuredGrid")"), std::string::npos);
  EXPECT_EQ(tags(text, "Piece").size(), 2u);
  EXPECT_EQ(attribute(tags(text, "Piece").at(1), "Source"), "volume_1.vtu");
  const auto arrays = tags(text, "PDataArray");
  ASSERT_EQ(arrays.size(), 4u); // 2 point arrays, 1 cell array, the points
  EXPECT_EQ(attribute(arrays[0], "Name"), "displacement [mm]");
  EXPECT_EQ(attribute(arrays[0], "NumberOfComponents"), "3");
  EXPECT_EQ(attribute(arrays[2], "Name"), "stress");
  EXPECT_EQ(attribute(arrays[2], "NumberOfComponents"), "6");
  EXPECT_NE(text.find("</VTKFile>"), std::string::npos);
}

TEST_F(WriterTest, VtuEscapesSpecialCharactersInNames) {
  write_vtu(dir_ / "hexes.vtu", two_hexes());
  const std::string xml(VtuFile(dir_ / "hexes.vtu").xml());
  EXPECT_NE(xml.find("Name=\"pressure &amp; &lt;p&gt; &quot;kPa&quot; &apos;x&apos;\""),
            std::string::npos);
  EXPECT_EQ(xml.find("<p>"), std::string::npos);
  EXPECT_NE(xml.find("Name=\"displacement [mm]\""), std::string::npos);
}

TEST_F(WriterTest, VtuOfEmptyGridIsValid) {
  UnstructuredGrid empty;
  empty.point_data.push_back({"u", 3, {}});
  empty.cell_data.push_back({"s", 1, {}});
  EXPECT_EQ(write_vtu(dir_ / "empty.vtu", empty), 0u);
  expect_round_trip(dir_ / "empty.vtu", empty);
  EXPECT_NE(read_text(dir_ / "empty.vtu").find("</VTKFile>"), std::string::npos);
}

TEST_F(WriterTest, VtuOfPointsWithoutCells) {
  UnstructuredGrid cloud;
  cloud.points = {Vec3(1, 2, 3), Vec3(-1, 0.5, 1e-9)};
  cloud.point_data.push_back(make_data("p", 1, 2, 0));
  EXPECT_EQ(write_vtu(dir_ / "cloud.vtu", cloud), 0u);
  expect_round_trip(dir_ / "cloud.vtu", cloud);
}

TEST_F(WriterTest, VtuWritesAndCountsNonFiniteValues) {
  UnstructuredGrid grid = two_quads();
  grid.point_data[0].values[2] = std::numeric_limits<double>::quiet_NaN();
  grid.cell_data[0].values[1] = -std::numeric_limits<double>::infinity();
  EXPECT_EQ(write_vtu(dir_ / "bad.vtu", grid), 2u);
  const VtuFile vtu(dir_ / "bad.vtu");
  const std::vector<double> p = vtu.values<double>("contact pressure");
  ASSERT_EQ(p.size(), 6u);
  EXPECT_TRUE(std::isnan(p[2]));
  EXPECT_EQ(vtu.values<double>("gap <mm>").at(1), -std::numeric_limits<double>::infinity());
}

TEST_F(WriterTest, VtuRejectsInconsistentGrid) {
  UnstructuredGrid grid = two_hexes();
  grid.point_data[0].values.pop_back();
  EXPECT_THROW(write_vtu(dir_ / "x.vtu", grid), LogicError);
  grid = two_hexes();
  grid.connectivity[3] = 12;
  EXPECT_THROW(write_vtu(dir_ / "x.vtu", grid), LogicError);
  grid = two_hexes();
  grid.types.pop_back();
  EXPECT_THROW(write_vtu(dir_ / "x.vtu", grid), LogicError);
  EXPECT_FALSE(fs::exists(dir_ / "x.vtu"));
}

TEST_F(WriterTest, VtuInMissingDirectoryIsInputErrorNamingPath) {
  const fs::path file = dir_ / "no_such_dir" / "out.vtu";
  try {
    write_vtu(file, two_quads());
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
  }
}

TEST_F(WriterTest, VtuReplacesExistingFileAtomically) {
  write_vtu(dir_ / "a.vtu", two_hexes());
  write_vtu(dir_ / "a.vtu", two_quads());
  expect_round_trip(dir_ / "a.vtu", two_quads());
}

struct PvdEntry {
  std::string timestep, file, part, name;
};

std::vector<PvdEntry> read_pvd(const fs::path& file) {
  const std::string text = read_text(file);
  EXPECT_NE(text.find("<VTKFile type=\"Collection\""), std::string::npos);
  EXPECT_NE(text.find("</Collection>\n</VTKFile>\n"), std::string::npos) << "incomplete pvd";
  std::vector<PvdEntry> entries;
  for (const std::string_view tag : tags(text, "DataSet"))
    entries.push_back({attribute(tag, "timestep"), attribute(tag, "file"), attribute(tag, "part"),
                       attribute(tag, "name")});
  return entries;
}

TEST_F(WriterTest, PvdListsDatasetsInOrderAfterEveryAdd) {
  PvdWriter pvd(dir_ / "series.pvd");
  EXPECT_EQ(pvd.file(), dir_ / "series.pvd");
  EXPECT_TRUE(read_pvd(pvd.file()).empty());
  fs::create_directories(dir_ / "steps");
  pvd.add(0.0, dir_ / "steps" / "volume_0.vtu");
  ASSERT_EQ(read_pvd(pvd.file()).size(), 1u);
  pvd.add(0.1, dir_ / "steps" / "contact_0.vtu", 1, "contact & <friction>");
  ASSERT_EQ(read_pvd(pvd.file()).size(), 2u);
  pvd.add(2.5e-7, dir_ / "volume_1.vtu", 0);
  const std::vector<PvdEntry> entries = read_pvd(pvd.file());
  ASSERT_EQ(entries.size(), 3u);
  EXPECT_EQ(std::strtod(entries[0].timestep.c_str(), nullptr), 0.0);
  EXPECT_EQ(std::strtod(entries[1].timestep.c_str(), nullptr), 0.1);
  EXPECT_EQ(std::strtod(entries[2].timestep.c_str(), nullptr), 2.5e-7);
  EXPECT_EQ(entries[0].file, "steps/volume_0.vtu");
  EXPECT_EQ(entries[1].file, "steps/contact_0.vtu");
  EXPECT_EQ(entries[2].file, "volume_1.vtu");
  EXPECT_EQ(entries[0].part, "0");
  EXPECT_EQ(entries[1].part, "1");
  EXPECT_EQ(entries[2].part, "0");
  EXPECT_EQ(entries[0].name, "");
  EXPECT_EQ(entries[1].name, "contact & <friction>");
  EXPECT_FALSE(fs::exists(dir_ / "series.pvd.tmp"));
}

TEST_F(WriterTest, PvdStoresPathsOutsideItsDirectoryRelatively) {
  fs::create_directories(dir_ / "pvd");
  PvdWriter pvd(dir_ / "pvd" / "series.pvd");
  pvd.add(1.0, dir_ / "data" / "a.vtu");
  EXPECT_EQ(read_pvd(pvd.file()).at(0).file, "../data/a.vtu");
}

TEST_F(WriterTest, PvdInMissingDirectoryIsInputError) {
  EXPECT_THROW(PvdWriter(dir_ / "missing" / "s.pvd"), InputError);
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> result;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    result.push_back(line);
  return result;
}

std::vector<double> parse_row(const std::string& line) {
  std::vector<double> values;
  const char* p = line.c_str();
  while (*p != '\0') {
    char* end = nullptr;
    values.push_back(std::strtod(p, &end));
    EXPECT_NE(end, p) << line;
    p = *end == ',' ? end + 1 : end;
    if (end == p && *end != '\0')
      break;
  }
  return values;
}

TEST_F(WriterTest, CsvWritesHeaderAndExactRowsFlushedAtOnce) {
  const fs::path file = dir_ / "history.csv";
  CsvWriter csv(file, {"time", "force [N]", "a,\"b\""});
  EXPECT_EQ(csv.columns().size(), 3u);
  EXPECT_EQ(read_text(file), "time,force [N],\"a,\"\"b\"\"\"\n");
  const std::vector<std::vector<double>> rows = {{0.1, 1e-300, -2.5e17},
                                                 {1.0 / 3.0, 5e-324, -0.0},
                                                 {std::numeric_limits<double>::max(), 0, 7}};
  for (std::size_t r = 0; r < rows.size(); ++r) {
    csv.write_row(rows[r]);
    const std::vector<std::string> text = lines(read_text(file)); // flushed: visible at once
    ASSERT_EQ(text.size(), r + 2);
    const std::vector<double> parsed = parse_row(text.back());
    ASSERT_EQ(parsed.size(), 3u);
    for (std::size_t c = 0; c < 3; ++c)
      EXPECT_EQ(std::bit_cast<std::uint64_t>(parsed[c]), std::bit_cast<std::uint64_t>(rows[r][c]))
          << text.back();
  }
}

TEST_F(WriterTest, CsvInMissingDirectoryIsInputErrorNamingPath) {
  const fs::path file = dir_ / "does" / "not" / "exist.csv";
  try {
    CsvWriter csv(file, {"t"});
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
  }
}

TEST_F(WriterTest, CsvRowOfWrongLengthIsLogicError) {
  CsvWriter csv(dir_ / "t.csv", {"a", "b"});
  const std::array<double, 3> three = {1, 2, 3};
  EXPECT_THROW(csv.write_row(three), LogicError);
  const std::array<double, 1> one = {1};
  EXPECT_THROW(csv.write_row(one), LogicError);
}

} // namespace
} // namespace trifem::io
