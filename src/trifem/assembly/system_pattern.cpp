// SPDX-License-Identifier: MIT
#include "trifem/assembly/system_pattern.hpp"

#include <algorithm>

namespace trifem::assembly {
namespace {

/// DOF -> elements (CSR) over several stencil sets; element ids are (set, element) packed.
struct DofElements {
  std::vector<Index> offsets;
  std::vector<std::pair<int, Index>> entries;
};

DofElements invert(const std::vector<const Stencils*>& sets, Index num_dofs) {
  DofElements inv;
  inv.offsets.assign(num_dofs + 1, 0);
  for (const Stencils* s : sets)
    for (Index d : s->dofs)
      ++inv.offsets[d + 1];
  for (Index d = 0; d < num_dofs; ++d)
    inv.offsets[d + 1] += inv.offsets[d];
  inv.entries.resize(inv.offsets.back());
  std::vector<Index> fill(inv.offsets.begin(), inv.offsets.end() - 1);
  for (int k = 0; k < static_cast<int>(sets.size()); ++k)
    for (Index e = 0; e < sets[k]->size(); ++e)
      for (Index d : sets[k]->of(e))
        inv.entries[fill[d]++] = {k, e};
  return inv;
}

SparseMatrix make_matrix(Index rows, Index cols, const std::vector<std::vector<Index>>& columns) {
  SparseMatrix A(rows, cols);
  if (rows == 0 || cols == 0) // every DOF prescribed, or none: an empty block
    return A;
  Eigen::VectorXi sizes(cols);
  for (Index c = 0; c < cols; ++c)
    sizes[c] = static_cast<int>(columns[c].size());
  A.reserve(sizes);
  for (Index c = 0; c < cols; ++c)
    for (Index r : columns[c])
      A.insert(r, c) = 0.0;
  A.makeCompressed();
  return A;
}

/// Greedy colouring: elements of one colour share no DOF of the inverted map `inv`.
std::vector<std::vector<Index>> colour_with(const Stencils& stencils, const DofElements& inv) {
  std::vector<int> colour(stencils.size(), -1);
  std::vector<std::vector<Index>> colours;
  std::vector<Index> stamp; // stamp[c] == e + 1: colour c is taken by a neighbour of e
  for (Index e = 0; e < stencils.size(); ++e) {
    for (Index d : stencils.of(e))
      for (Index k = inv.offsets[d]; k < inv.offsets[d + 1]; ++k)
        if (const int c = colour[inv.entries[k].second]; c >= 0)
          stamp[c] = e + 1;
    int c = 0;
    while (c < static_cast<int>(colours.size()) && stamp[c] == e + 1)
      ++c;
    if (c == static_cast<int>(colours.size())) {
      colours.emplace_back();
      stamp.push_back(0);
    }
    colour[e] = c;
    colours[c].push_back(e);
  }
  return colours;
}

} // namespace

Stencils collect_stencils(const physics::Term& term) {
  Stencils s;
  s.offsets.reserve(term.num_elements() + 1);
  s.offsets.push_back(0);
  std::vector<Index> dofs;
  for (Index e = 0; e < term.num_elements(); ++e) {
    term.element_dofs(e, dofs);
    s.dofs.insert(s.dofs.end(), dofs.begin(), dofs.end());
    s.offsets.push_back(static_cast<Index>(s.dofs.size()));
  }
  return s;
}

std::vector<std::vector<Index>> colour_elements(const Stencils& stencils, Index num_dofs) {
  const DofElements inv = invert({&stencils}, num_dofs);
  return colour_with(stencils, inv);
}

std::vector<std::vector<Index>> colour_elements(const Stencils& stencils, const dofs::DofMap& map) {
  if (!map.has_ties())
    return colour_elements(stencils, map.num_dofs());
  Stencils leaders = stencils; // elements sharing an unknown through a tie share a colour slot
  for (Index& d : leaders.dofs)
    d = map.leader(d);
  return colour_with(leaders, invert({&leaders}, map.num_dofs()));
}

SystemPattern build_pattern(const dofs::DofMap& map, const std::vector<const Stencils*>& sets) {
  const DofElements inv = invert(sets, map.num_dofs());
  std::vector<std::vector<Index>> ff(map.num_equations()), fc(map.num_constrained());
  std::vector<Index> rows;
  for (Index col = 0; col < map.num_dofs(); ++col) {
    rows.clear();
    for (Index k = inv.offsets[col]; k < inv.offsets[col + 1]; ++k) {
      const auto [set, e] = inv.entries[k];
      for (Index d : sets[set]->of(e))
        if (const Index eq = map.equation(d); eq >= 0)
          rows.push_back(eq);
    }
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    if (map.is_dependent(col)) // in no stencil of a condensed set
      continue;
    if (const Index eq = map.equation(col); eq < 0)
      fc[map.constrained_index(col)] = rows;
    else if (ff[eq].empty())
      ff[eq] = rows;
    else // a tied DOF: its column joins the leader's
      ff[eq].insert(ff[eq].end(), rows.begin(), rows.end());
  }
  if (map.has_ties())
    for (auto& rows_of_eq : ff) {
      std::sort(rows_of_eq.begin(), rows_of_eq.end());
      rows_of_eq.erase(std::unique(rows_of_eq.begin(), rows_of_eq.end()), rows_of_eq.end());
    }
  return {make_matrix(map.num_equations(), map.num_equations(), ff),
          make_matrix(map.num_equations(), map.num_constrained(), fc)};
}

} // namespace trifem::assembly
