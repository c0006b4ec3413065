// SPDX-License-Identifier: MIT
// VTK XML unstructured grid (.vtu) writer for ParaView, plus atomic file writing helpers.
#pragma once

#include "trifem/core/types.hpp"
#include "trifem/tensor/tensor.hpp"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace trifem::io {

/// One named data array on points or cells; values.size() == count * components.
struct DataArray {
  std::string name;           ///< shown in ParaView; may contain spaces, units and XML specials
  int components = 1;         ///< 1 scalar, 3 vector, 6 or 9 tensor, ...
  std::vector<double> values; ///< tuple-major: (c0, c1, ..) of item 0, then item 1, ...
};

/// VTK cell type codes used by trifem.
namespace vtk_cell {
inline constexpr std::uint8_t kTriangle = 5;
inline constexpr std::uint8_t kQuad = 9;
inline constexpr std::uint8_t kQuadraticTriangle = 22; ///< corners, then mid-edge nodes (as tri6)
inline constexpr std::uint8_t kQuadraticQuad = 23;     ///< corners, then mid-edge nodes (as quad8)
inline constexpr std::uint8_t kHexahedron = 12;
} // namespace vtk_cell

/// An unstructured grid in VTK conventions (cell types: 12 = VTK_HEXAHEDRON, 9 = VTK_QUAD,
/// 5 = VTK_TRIANGLE, 3 = line, 1 = vertex).
struct UnstructuredGrid {
  std::vector<Vec3> points;
  std::vector<Index> connectivity; ///< concatenated cell node lists
  std::vector<Index> offsets;      ///< end offset of each cell in connectivity (VTK convention)
  std::vector<std::uint8_t> types; ///< one VTK cell type per cell
  std::vector<DataArray> point_data;
  std::vector<DataArray> cell_data;

  /// Appends a cell; returns nothing. Helper to keep offsets consistent.
  void add_cell(std::uint8_t vtk_type, std::span<const Index> nodes);
  /// Number of cells (size of `types`).
  std::size_t cell_count() const { return types.size(); }
};

/// Writes a .vtu XML file (VTK UnstructuredGrid, version 1.0, header_type UInt64, byte order of
/// the host, i.e. LittleEndian on x86-64/arm64; arrays as raw binary appended data). Points and
/// data arrays are Float64, connectivity and offsets Int64, types UInt8.
/// Sizes are checked with TRIFEM_VERIFY (an inconsistent grid is a bug). Non-finite values are
/// written as they are (VTK accepts NaN); the function returns how many point coordinates and
/// data values are non-finite so the caller can report them.
/// Writes to "<file>.tmp" then renames, so a crash never leaves a truncated file. Throws
/// OutputError (naming the path) if the file cannot be written.
std::size_t write_vtu(const std::filesystem::path& file, const UnstructuredGrid& grid);

/// Escapes the XML special characters & < > " ' of `text` for use in attribute values.
std::string xml_escape(std::string_view text);

/// Writes `file` through `write`: the content goes to "<file>.tmp", which is renamed onto `file`
/// only once it is complete. Throws OutputError naming the path if the file cannot be written
/// (the temporary is removed then).
void write_file_atomically(const std::filesystem::path& file,
                           const std::function<void(std::ostream&)>& write);

} // namespace trifem::io
