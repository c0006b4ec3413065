// SPDX-License-Identifier: MIT
#include "trifem/io/pvtu_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>

namespace trifem::io {
namespace {

void write_arrays(std::ostream& out, const char* section, const std::vector<DataArray>& arrays) {
  out << "    <" << section << ">\n";
  for (const DataArray& a : arrays)
    out << fmt::format(R"(      <PDataArray type="Float64" Name="{}" NumberOfComponents="{}"/>)",
                       xml_escape(a.name), a.components)
        << '\n';
  out << "    </" << section << ">\n";
}

} // namespace

UnstructuredGrid piece_of(const UnstructuredGrid& grid, std::span<const Index> cells) {
  UnstructuredGrid piece;
  std::vector<Index> new_index(grid.points.size(), -1);
  for (Index c : cells) {
    const Index begin = c == 0 ? 0 : grid.offsets[c - 1];
    for (Index k = begin; k < grid.offsets[c]; ++k)
      new_index[grid.connectivity[k]] = 0;
  }
  std::vector<Index> kept; // original numbers of the piece's points
  for (Index p = 0; p < static_cast<Index>(new_index.size()); ++p)
    if (new_index[p] == 0) {
      new_index[p] = static_cast<Index>(kept.size());
      kept.push_back(p);
    }
  for (Index p : kept)
    piece.points.push_back(grid.points[p]);
  std::vector<Index> nodes;
  for (Index c : cells) {
    const Index begin = c == 0 ? 0 : grid.offsets[c - 1];
    nodes.clear();
    for (Index k = begin; k < grid.offsets[c]; ++k)
      nodes.push_back(new_index[grid.connectivity[k]]);
    piece.add_cell(grid.types[c], nodes);
  }
  const auto subset = [](const DataArray& a, std::span<const Index> items) {
    DataArray out{a.name, a.components, {}};
    out.values.reserve(items.size() * a.components);
    for (Index i : items)
      for (int k = 0; k < a.components; ++k)
        out.values.push_back(a.values[static_cast<std::size_t>(i) * a.components + k]);
    return out;
  };
  for (const DataArray& a : grid.point_data)
    piece.point_data.push_back(subset(a, kept));
  for (const DataArray& a : grid.cell_data)
    piece.cell_data.push_back(subset(a, cells));
  return piece;
}

void write_pvtu(const std::filesystem::path& file, const UnstructuredGrid& like,
                const std::vector<std::string>& pieces) {
  constexpr bool kLittle = std::endian::native == std::endian::little;
  write_file_atomically(file, [&](std::ostream& out) {
    out << "<?xml version=\"1.0\"?>\n"
        << fmt::format(R"(<VTKFile type="PUnstructuredGrid" version="1.0" byte_order="{}")",
                       kLittle ? "LittleEndian" : "BigEndian")
        << " header_type=\"UInt64\">\n  <PUnstructuredGrid GhostLevel=\"0\">\n";
    write_arrays(out, "PPointData", like.point_data);
    write_arrays(out, "PCellData", like.cell_data);
    out << "    <PPoints>\n      <PDataArray type=\"Float64\" NumberOfComponents=\"3\"/>\n"
        << "    </PPoints>\n";
    for (const std::string& piece : pieces)
      out << fmt::format(R"(    <Piece Source="{}"/>)", xml_escape(piece)) << '\n';
    out << "  </PUnstructuredGrid>\n</VTKFile>\n";
  });
}

} // namespace trifem::io
