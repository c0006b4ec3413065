// SPDX-License-Identifier: MIT
// Fill-reducing ordering by nested dissection (METIS) of the symmetrised graph of a sparse
// matrix, with rows of identical structure (the components of a node's fields) merged into
// one weighted vertex first, so METIS sees the mesh rather than the equations.
#pragma once

#include "trifem/core/types.hpp"

#include <vector>

namespace trifem::linalg {

/// A matrix pattern in compressed rows (row i holds column[row_start[i] .. row_start[i+1])).
struct RowPattern {
  Index rows = 0;
  const Index* row_start = nullptr;
  const Index* column = nullptr;
};

/// The nested-dissection order of the rows of the square pattern: order[k] is the row
/// eliminated k-th (a permutation of 0 .. rows-1).
std::vector<Index> nested_dissection_order(const RowPattern& pattern);

/// A partition of the rows of the square pattern into `parts` parts of about equal size with
/// few couplings between them (METIS k-way on the same merged graph): the part of each row.
/// Rows of identical structure stay together. Deterministic for a given pattern.
std::vector<int> partition_rows(const RowPattern& pattern, int parts);

} // namespace trifem::linalg
