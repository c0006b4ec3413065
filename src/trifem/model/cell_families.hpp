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
/// mixture on such cells meets the drained Schur preconditioner (hex8 only), if a tet4 or a
/// penta6 has a nearly incompressible law with `element = "auto"` (they lock there with either
/// element, so the element must be asked for) or a tet4 the mean-dilatation element.
void check_cell_families(const io::CaseSpec& spec, const Model& model);

/// "a tet4 cell (cell 12 of block 'plug')": cell c of `mesh` as error messages name it.
std::string describe_cell(const mesh::Mesh& mesh, Index c);

/// The element of cell c: that of its material, but the displacement element on a tet4.
physics::SolidElement cell_element(const Model& model, Index c);

} // namespace trifem::model
