// SPDX-License-Identifier: MIT
// VTK XML unstructured grid (.vtu) writer: raw binary appended data.
#include "trifem/io/vtu_writer.hpp"

#include "trifem/core/error.hpp"

#include <array>
#include <bit>
#include <cerrno>
#include <cmath>
#include <fmt/format.h>
#include <fstream>
#include <iterator>
#include <set>
#include <system_error>
#include <type_traits>
#include <variant>

namespace trifem::io {

namespace fs = std::filesystem;

void UnstructuredGrid::add_cell(std::uint8_t vtk_type, std::span<const Index> nodes) {
  TRIFEM_VERIFY(!nodes.empty(), "a VTK cell (type {}) needs at least one node", vtk_type);
  connectivity.insert(connectivity.end(), nodes.begin(), nodes.end());
  offsets.push_back(static_cast<Index>(connectivity.size()));
  types.push_back(vtk_type);
}

std::string xml_escape(std::string_view text) {
  std::string escaped;
  escaped.reserve(text.size());
  for (const char c : text) {
    switch (c) {
    case '&':
      escaped += "&amp;";
      break;
    case '<':
      escaped += "&lt;";
      break;
    case '>':
      escaped += "&gt;";
      break;
    case '"':
      escaped += "&quot;";
      break;
    case '\'':
      escaped += "&apos;";
      break;
    default:
      escaped += c;
    }
  }
  return escaped;
}

void write_file_atomically(const fs::path& file, const std::function<void(std::ostream&)>& write) {
  fs::path tmp = file;
  tmp += ".tmp";
  std::error_code ignored;
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    TRIFEM_CHECK_OUTPUT(out.is_open(), "cannot write '{}': cannot create '{}' ({})", file.string(),
                        tmp.string(), std::generic_category().message(errno));
    try {
      write(out);
    } catch (...) {
      out.close();
      fs::remove(tmp, ignored);
      throw;
    }
    out.close();
    if (out.fail()) {
      fs::remove(tmp, ignored);
      throw OutputError(
          fmt::format("cannot write '{}': write error on '{}'", file.string(), tmp.string()));
    }
  }
  std::error_code ec;
  fs::rename(tmp, file, ec);
  if (ec) {
    fs::remove(tmp, ignored);
    throw OutputError(fmt::format("cannot write '{}': cannot rename '{}' onto it ({})",
                                  file.string(), tmp.string(), ec.message()));
  }
}

namespace {

using Values = std::variant<std::span<const double>, std::span<const std::int64_t>,
                            std::span<const std::uint8_t>>;

/// One array as it goes into the file.
struct Array {
  std::string_view type; ///< VTK type name
  std::string name;      ///< unescaped
  int components = 1;
  Values values;
  std::uint64_t offset = 0; ///< byte offset in the appended data block
};

/// The grid converted to the file's types, in the order the arrays are written.
struct Piece {
  std::vector<double> coords;
  std::vector<std::int64_t> connectivity;
  std::vector<std::int64_t> offsets;
  std::vector<Array> point_data, cell_data, points, cells;
};

std::span<const std::byte> bytes_of(const Array& array) {
  return std::visit([](auto values) { return std::as_bytes(values); }, array.values);
}

void verify_data(const std::vector<DataArray>& arrays, std::size_t count, std::string_view where) {
  std::set<std::string_view> names;
  for (const DataArray& a : arrays) {
    TRIFEM_VERIFY(!a.name.empty(), "{} data array without a name", where);
    TRIFEM_VERIFY(names.insert(a.name).second, "{} data array '{}' appears twice", where, a.name);
    TRIFEM_VERIFY(a.components >= 1, "{} data '{}': {} components", where, a.name, a.components);
    TRIFEM_VERIFY(a.values.size() == count * static_cast<std::size_t>(a.components),
                  "{} data '{}' has {} values, expected {} x {}", where, a.name, a.values.size(),
                  count, a.components);
  }
}

void verify_grid(const UnstructuredGrid& grid) {
  TRIFEM_VERIFY(grid.offsets.size() == grid.types.size(), "{} cell offsets but {} cell types",
                grid.offsets.size(), grid.types.size());
  Index previous = 0;
  for (const Index end : grid.offsets) {
    TRIFEM_VERIFY(end > previous, "cell offsets must increase strictly ({} after {})", end,
                  previous);
    previous = end;
  }
  TRIFEM_VERIFY(static_cast<std::size_t>(previous) == grid.connectivity.size(),
                "last cell offset {} != connectivity size {}", previous, grid.connectivity.size());
  const auto n_points = static_cast<Index>(grid.points.size());
  for (const Index node : grid.connectivity)
    TRIFEM_VERIFY(node >= 0 && node < n_points, "cell node {} outside [0, {})", node, n_points);
  verify_data(grid.point_data, grid.points.size(), "point");
  verify_data(grid.cell_data, grid.types.size(), "cell");
}

std::vector<Array> data_arrays(const std::vector<DataArray>& arrays) {
  std::vector<Array> result;
  for (const DataArray& a : arrays)
    result.push_back({"Float64", a.name, a.components, std::span<const double>(a.values)});
  return result;
}

Piece make_piece(const UnstructuredGrid& grid) {
  Piece piece;
  piece.coords.reserve(3 * grid.points.size());
  for (const Vec3& p : grid.points)
    piece.coords.insert(piece.coords.end(), {p[0], p[1], p[2]});
  piece.connectivity.assign(grid.connectivity.begin(), grid.connectivity.end());
  piece.offsets.assign(grid.offsets.begin(), grid.offsets.end());
  piece.point_data = data_arrays(grid.point_data);
  piece.cell_data = data_arrays(grid.cell_data);
  piece.points.push_back({"Float64", "Points", 3, std::span<const double>(piece.coords)});
  piece.cells.push_back(
      {"Int64", "connectivity", 1, std::span<const std::int64_t>(piece.connectivity)});
  piece.cells.push_back({"Int64", "offsets", 1, std::span<const std::int64_t>(piece.offsets)});
  piece.cells.push_back({"UInt8", "types", 1, std::span<const std::uint8_t>(grid.types)});
  return piece;
}

/// Calls `f` on every array of the piece, in file order.
template <class F>
void for_each_array(Piece& piece, F&& f) {
  for (auto* section : {&piece.point_data, &piece.cell_data, &piece.points, &piece.cells})
    for (Array& array : *section)
      f(array);
}

std::size_t count_non_finite(const Piece& piece) {
  std::size_t count = 0;
  for (const double x : piece.coords)
    count += std::isfinite(x) ? 0 : 1;
  for (const auto* section : {&piece.point_data, &piece.cell_data})
    for (const Array& array : *section)
      for (const double x : std::get<std::span<const double>>(array.values))
        count += std::isfinite(x) ? 0 : 1;
  return count;
}

void write_raw(std::ostream& out, std::span<const std::byte> bytes) {
  out.write(reinterpret_cast<const char*>(bytes.data()),
            static_cast<std::streamsize>(bytes.size()));
}

std::span<const std::byte> header_bytes(const std::uint64_t& byte_count) {
  return std::as_bytes(std::span<const std::uint64_t, 1>(&byte_count, 1));
}

void write_data_array(std::ostream& out, const Array& array) {
  out << fmt::format(R"(        <DataArray type="{}" Name="{}" NumberOfComponents="{}")",
                     array.type, xml_escape(array.name), array.components)
      << fmt::format(R"( format="appended" offset="{}"/>)", array.offset) << '\n';
}

void write_section(std::ostream& out, std::string_view tag, const std::vector<Array>& arrays) {
  out << "      <" << tag << ">\n";
  for (const Array& array : arrays)
    write_data_array(out, array);
  out << "      </" << tag << ">\n";
}

void write_appended_data(std::ostream& out, Piece& piece) {
  out << "  <AppendedData encoding=\"raw\">\n   _";
  for_each_array(piece, [&](const Array& array) {
    const std::span<const std::byte> bytes = bytes_of(array);
    const std::uint64_t byte_count = bytes.size();
    write_raw(out, header_bytes(byte_count));
    write_raw(out, bytes);
  });
  out << "\n  </AppendedData>\n";
}

void write_document(std::ostream& out, Piece& piece, std::size_t n_points, std::size_t n_cells) {
  constexpr bool kLittle = std::endian::native == std::endian::little;
  out << "<?xml version=\"1.0\"?>\n"
      << fmt::format(R"(<VTKFile type="UnstructuredGrid" version="1.0" byte_order="{}")",
                     kLittle ? "LittleEndian" : "BigEndian")
      << " header_type=\"UInt64\">\n  <UnstructuredGrid>\n"
      << fmt::format(R"(    <Piece NumberOfPoints="{}" NumberOfCells="{}">)", n_points, n_cells)
      << '\n';
  write_section(out, "PointData", piece.point_data);
  write_section(out, "CellData", piece.cell_data);
  write_section(out, "Points", piece.points);
  write_section(out, "Cells", piece.cells);
  out << "    </Piece>\n  </UnstructuredGrid>\n";
  write_appended_data(out, piece);
  out << "</VTKFile>\n";
}

} // namespace

std::size_t write_vtu(const fs::path& file, const UnstructuredGrid& grid) {
  verify_grid(grid);
  Piece piece = make_piece(grid);
  std::uint64_t offset = 0;
  for_each_array(piece, [&](Array& array) {
    array.offset = offset;
    offset += sizeof(std::uint64_t) + bytes_of(array).size();
  });
  write_file_atomically(file, [&](std::ostream& out) {
    write_document(out, piece, grid.points.size(), grid.types.size());
  });
  return count_non_finite(piece);
}

} // namespace trifem::io
