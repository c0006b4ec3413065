// SPDX-License-Identifier: MIT
// Material axes per cell: the solid law of each cell of a material with [<name>.axes], wrapped
// in the cell's local basis.
#pragma once

#include "trifem/io/case_spec.hpp"
#include "trifem/mesh/mesh.hpp"
#include "trifem/model/model.hpp"

#include <map>
#include <string>
#include <vector>

namespace trifem::model {

/// Orients the cells of the materials that have axes: the solid law of such a cell (or its
/// mixture's solid) becomes a material::RotatedLaw in the cell's basis Q (constant, at the
/// reference centroid of the cell, or from the mesh's element data). Cells of one material
/// with the same Q share one law (and one mixture), so memory grows with the number of
/// distinct bases, not of cells. `blocks` maps cell blocks to material names as in
/// build_mesh, `per_cell` holds the unrotated materials. Returns Q per cell (the identity for
/// cells without axes), or nothing if no material has axes (`per_cell` is then unchanged).
std::vector<Mat3> orient_cells(const io::CaseSpec& spec, const mesh::Mesh& mesh,
                               const std::map<std::string, std::string>& blocks,
                               std::vector<CellMaterial>& per_cell);

} // namespace trifem::model
