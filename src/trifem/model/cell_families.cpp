// SPDX-License-Identifier: MIT
#include "trifem/model/cell_families.hpp"

#include "trifem/core/error.hpp"

#include <algorithm>
#include <set>

namespace trifem::model {

std::string describe_cell(const mesh::Mesh& mesh, Index c) {
  for (const auto& [name, cells] : mesh.cell_blocks())
    if (std::find(cells.begin(), cells.end(), c) != cells.end())
      return fmt::format("a {} cell ({}, in block '{}')", mesh::name(mesh.cell_type(c)),
                         mesh.describe(c), name);
  return fmt::format("a {} cell ({})", mesh::name(mesh.cell_type(c)), mesh.describe(c));
}

namespace {

void check_material(const io::CaseSpec& spec, const Model& model, Index c) {
  const CellMaterial& m = model.materials[static_cast<std::size_t>(c)];
  const std::string where = describe_cell(model.mesh, c);
  const mesh::CellType type = model.mesh.cell_type(c);
  TRIFEM_CHECK(!m.mixture || type != mesh::CellType::Tet4,
               "materials.{}: {} has this mixture material, and tet4 cells cannot carry it: "
               "their displacement, fluxes and potentials would all be linear, and that pair "
               "locks or oscillates in the undrained limit (docs/theory/elements.md). Mesh the "
               "tissue with tet10 cells (Gmsh: -order 2), or with penta6, hex8 or hex20 cells",
               m.name, where);
  TRIFEM_CHECK(!m.mixture || !m.mixture->charged || type != mesh::CellType::Tet10,
               "materials.{}: {} has this triphasic material, and tet10 cells carry biphasic "
               "materials only so far: their ion contents, one per cell, change only by the "
               "outflows of the corners' fluxes, too few on a tet to reach a uniform state, and "
               "steady states come out wrong by up to 0.3 % (docs/theory/elements.md). Mesh the "
               "tissue with penta6 (wedge layers), hex8 or hex20 cells",
               m.name, where);
  TRIFEM_CHECK(!m.mixture || spec.solver.linear_solver.schur != SchurApproximation::drained,
               "solver.schur_approximation: the drained Schur complement takes the mixture on hex8 "
               "cells only, and {} has the mixture material '{}'; use \"selfp\" or a direct "
               "solver",
               where, m.name);
}

} // namespace

void check_cell_families(const io::CaseSpec& spec, const Model& model) {
  const Index first = model.mesh.first_non_hex8();
  if (first < 0)
    return;
  // one check per material and cell type, at its first cell (the message names it)
  std::set<std::pair<std::string, mesh::CellType>> checked;
  for (Index c = first; c < model.mesh.num_cells(); ++c) {
    const mesh::CellType type = model.mesh.cell_type(c);
    if (type != mesh::CellType::Hex8 &&
        checked.emplace(model.materials[static_cast<std::size_t>(c)].name, type).second)
      check_material(spec, model, c);
  }
}

physics::SolidElement cell_element(const Model& model, Index c) {
  const physics::SolidElement element = model.materials[static_cast<std::size_t>(c)].element;
  const mesh::CellType type = model.mesh.cell_type(c);
  // one volume per tet, or per triangle of a wedge, locks: theirs is averaged over the nodes
  const bool averaged = type == mesh::CellType::Tet4 || type == mesh::CellType::Penta6;
  return averaged && element == physics::SolidElement::MeanDilatation
             ? physics::SolidElement::NodalDilatation
             : element;
}

} // namespace trifem::model
