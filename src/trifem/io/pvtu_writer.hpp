// SPDX-License-Identifier: MIT
// Parallel VTK unstructured grids (.pvtu): a grid written as pieces, one per process, and the
// small file that lists them for ParaView.
#pragma once

#include "trifem/io/vtu_writer.hpp"

#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace trifem::io {

/// The cells `cells` of `grid` as a grid of their own: the points they use (in ascending order
/// of the original numbering), renumbered, with their point data; the cells' cell data.
UnstructuredGrid piece_of(const UnstructuredGrid& grid, std::span<const Index> cells);

/// Writes the .pvtu file that assembles `pieces` (.vtu files written by write_vtu, paths as
/// seen from the directory of `file`), whose arrays are those of `like` (names and components;
/// Float64 as write_vtu writes them). Atomic like write_vtu; InputError naming the path if the
/// file cannot be written.
void write_pvtu(const std::filesystem::path& file, const UnstructuredGrid& like,
                const std::vector<std::string>& pieces);

} // namespace trifem::io
