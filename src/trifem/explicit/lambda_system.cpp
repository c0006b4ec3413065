// SPDX-License-Identifier: MIT
#include "trifem/explicit/lambda_system.hpp"

#include "trifem/core/error.hpp"
#include "trifem/core/timer.hpp"
#include "trifem/explicit/parallel.hpp"

#include "trifem/linalg/cholmod_solver.hpp"
#include "trifem/linalg/linear_solver.hpp"

#include <algorithm>

namespace trifem::explicit_dynamics {
LambdaSystem::LambdaSystem(const ExplicitView& model)
    : model_(model),
      solver_(model.distributed() ? linalg::make_linear_solver({LinearSolverKind::mumps})
                                  : linalg::make_cholmod_solver()) {
  if (model.distributed()) {
    build_part_pattern();
    solver_->set_hints({{}, {}, {}, model.cell_owners()});
  } else {
    build_pattern();
  }
  solver_->analyze_pattern(A_);
  TRIFEM_VERIFY(solver_->failure().reason.empty(),
                "symbolic analysis of the multiplier system failed: {}", solver_->failure().reason);
}

void LambdaSystem::build_part_pattern() {
  const Index n = model_.num_cells();
  const NodeIncidence& inc = model_.incidence();
  std::vector<Eigen::Triplet<Real>> entries;
  for (Index f = 0; f < n; ++f)
    if (model_.owns_cell(f))
      entries.emplace_back(f, f, 0.0);
  for (Index a = 0; a < model_.mesh().num_nodes(); ++a)
    if (model_.owns_node(a))
      for (Index i = inc.offsets[a]; i < inc.offsets[a + 1]; ++i)
        for (Index j = inc.offsets[a]; j < inc.offsets[a + 1]; ++j)
          entries.emplace_back(inc.entries[i].first, inc.entries[j].first, 0.0);
  A_ = SparseMatrix(n, n);
  A_.setFromTriplets(entries.begin(), entries.end());
  slots_.clear(); // the value index of each entry, in the order assemble_part() visits them
  for (const Eigen::Triplet<Real>& t : entries) {
    const Index* begin = A_.innerIndexPtr() + A_.outerIndexPtr()[t.col()];
    const Index* end = A_.innerIndexPtr() + A_.outerIndexPtr()[t.col() + 1];
    slots_.push_back(
        static_cast<Index>(std::lower_bound(begin, end, t.row()) - A_.innerIndexPtr()));
  }
}

void LambdaSystem::assemble_part(const CellVectors& h, const Vector& inverse_mass, Real h2,
                                 const Vector& diagonal) {
  const NodeIncidence& inc = model_.incidence();
  const std::vector<Index>& offsets = model_.cell_offsets();
  Real* values = A_.valuePtr();
  std::fill(values, values + A_.nonZeros(), 0.0);
  std::size_t s = 0;
  for (Index f = 0; f < model_.num_cells(); ++f)
    if (model_.owns_cell(f))
      values[slots_[s++]] += diagonal[f];
  for (Index a = 0; a < model_.mesh().num_nodes(); ++a) {
    if (!model_.owns_node(a))
      continue;
    for (Index i = inc.offsets[a]; i < inc.offsets[a + 1]; ++i) {
      const auto [e, le] = inc.entries[i];
      const Vec3 w =
          h2 * inverse_mass.segment<3>(3 * a).cwiseProduct(h.segment<3>(offsets[e] + 3 * le));
      for (Index j = inc.offsets[a]; j < inc.offsets[a + 1]; ++j) {
        const auto [f, lf] = inc.entries[j];
        values[slots_[s++]] += w.dot(h.segment<3>(offsets[f] + 3 * lf));
      }
    }
  }
}

void LambdaSystem::build_pattern() {
  const Index n = model_.num_cells();
  const NodeIncidence& inc = model_.incidence();
  std::vector<Index> col_ptr(n + 1, 0), rows;
  std::vector<Index> column;
  for (Index f = 0; f < n; ++f) { // rows e >= f of column f, sorted: (f, f) comes first
    column.clear();
    for (Index a : model_.mesh().cell_nodes(f))
      for (Index i = inc.offsets[a]; i < inc.offsets[a + 1]; ++i)
        if (inc.entries[i].first >= f)
          column.push_back(inc.entries[i].first);
    std::sort(column.begin(), column.end());
    column.erase(std::unique(column.begin(), column.end()), column.end());
    rows.insert(rows.end(), column.begin(), column.end());
    col_ptr[f + 1] = static_cast<Index>(rows.size());
  }
  A_ = SparseMatrix(n, n);
  A_.resizeNonZeros(static_cast<Index>(rows.size()));
  std::copy(col_ptr.begin(), col_ptr.end(), A_.outerIndexPtr());
  std::copy(rows.begin(), rows.end(), A_.innerIndexPtr());
  std::fill(A_.valuePtr(), A_.valuePtr() + rows.size(), 0.0);
  // Traversal slots, in the order assemble() visits (column, local node, incident cell).
  slot_offsets_.assign(n + 1, 0);
  slots_.clear();
  for (Index f = 0; f < n; ++f) {
    const Index* begin = A_.innerIndexPtr() + col_ptr[f];
    const Index* end = A_.innerIndexPtr() + col_ptr[f + 1];
    for (Index a : model_.mesh().cell_nodes(f))
      for (Index i = inc.offsets[a]; i < inc.offsets[a + 1]; ++i)
        if (inc.entries[i].first >= f)
          slots_.push_back(static_cast<Index>(std::lower_bound(begin, end, inc.entries[i].first) -
                                              A_.innerIndexPtr()));
    slot_offsets_[f + 1] = static_cast<Index>(slots_.size());
  }
}

void LambdaSystem::assemble(const CellVectors& h, const Vector& inverse_mass, Real h2,
                            const Vector& diagonal) {
  const Index n = model_.num_cells();
  const NodeIncidence& inc = model_.incidence();
  const std::vector<Index>& offsets = model_.cell_offsets();
  Real* values = A_.valuePtr();
#pragma omp parallel for schedule(static) if (n >= kMinParallelLoop)
  for (Index f = 0; f < n; ++f) {
    for (Index k = A_.outerIndexPtr()[f]; k < A_.outerIndexPtr()[f + 1]; ++k)
      values[k] = 0.0;
    values[A_.outerIndexPtr()[f]] = diagonal[f];
    Index s = slot_offsets_[f];
    const std::span<const Index> nodes = model_.mesh().cell_nodes(f);
    for (std::size_t lf = 0; lf < nodes.size(); ++lf) {
      const Index a = nodes[lf];
      const Vec3 w = h2 * inverse_mass.segment<3>(3 * a).cwiseProduct(
                              h.segment<3>(offsets[f] + 3 * static_cast<Index>(lf)));
      for (Index i = inc.offsets[a]; i < inc.offsets[a + 1]; ++i) {
        const auto [e, le] = inc.entries[i];
        if (e >= f)
          values[slots_[s++]] += w.dot(h.segment<3>(offsets[e] + 3 * le));
      }
    }
  }
}

bool LambdaSystem::factorize(const CellVectors& h, const Vector& inverse_mass, Real h2,
                             const Vector& diagonal) {
  {
    ScopedTimer timer(timings_.assemble);
    if (model_.distributed())
      assemble_part(h, inverse_mass, h2, diagonal);
    else
      assemble(h, inverse_mass, h2, diagonal);
  }
  ScopedTimer timer(timings_.factorize);
  ++timings_.factorizations;
  return solver_->factorize(A_);
}

void LambdaSystem::solve(const Vector& b, Vector& x) {
  ScopedTimer timer(timings_.solve);
  solver_->solve(b, x);
}

} // namespace trifem::explicit_dynamics
