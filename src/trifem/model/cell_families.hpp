// SPDX-License-Identifier: MIT
// What the cells that are not hex8 (tet4, tet10, penta6, hex20) take so far, checked when the
// model is built so that a case using anything else stops with an error naming its key.
#pragma once

#include "trifem/io/case_spec.hpp"
#include "trifem/model/model.hpp"

namespace trifem::model {

/// Throws InputError, naming the case key, the cell family and a cell block holding such a
/// cell, if a cell that is not a hex8 has material axes, if a tet4 has a
/// mixture material or a tet10 a triphasic one (singular: docs/theory/elements.md), if a
/// mixture on such cells meets the drained Schur preconditioner (hex8 only).
void check_cell_families(const io::CaseSpec& spec, const Model& model);

/// "a tet4 cell (element 12 of 'plug.msh', in block 'plug')", "a tet4 cell (cell 12, in block
/// 'plug')" for a cell of no file: cell c of `mesh` as error messages name it.
std::string describe_cell(const mesh::Mesh& mesh, Index c);

/// The element of cell c: that of its material, but on tet4 and penta6 cells the locking-free
/// element is the nodally averaged dilatation (physics/nodal_dilatation.hpp) instead of the
/// mean dilatation of one cell (one volume per tet, or per triangle of a wedge, locks).
physics::SolidElement cell_element(const Model& model, Index c);

} // namespace trifem::model
