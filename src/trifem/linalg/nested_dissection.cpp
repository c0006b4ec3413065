// SPDX-License-Identifier: MIT
#include "trifem/linalg/nested_dissection.hpp"

#include "trifem/core/error.hpp"

#include <fmt/format.h>
#include <metis.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <unordered_map>

namespace trifem::linalg {
namespace {

/// Adjacency of the symmetrised pattern, each list sorted, with the vertex itself included.
std::vector<std::vector<Index>> symmetric_adjacency(const RowPattern& p) {
  std::vector<std::vector<Index>> adjacent(p.rows);
  for (Index i = 0; i < p.rows; ++i) {
    adjacent[i].push_back(i);
    for (Index k = p.row_start[i]; k < p.row_start[i + 1]; ++k) {
      const Index j = p.column[k];
      if (j == i)
        continue;
      adjacent[i].push_back(j);
      adjacent[j].push_back(i);
    }
  }
  for (auto& list : adjacent) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return adjacent;
}

std::size_t hash_of(const std::vector<Index>& list) {
  std::size_t h = list.size();
  for (Index v : list)
    h = h * 1000003u ^ static_cast<std::size_t>(v);
  return h;
}

/// Groups of vertices with identical adjacency; group[v] is v's group.
std::vector<Index> merge_identical(const std::vector<std::vector<Index>>& adjacent, Index& groups) {
  std::vector<Index> group(adjacent.size(), -1);
  std::unordered_map<std::size_t, std::vector<Index>> leaders; // hash -> first members
  groups = 0;
  for (Index v = 0; v < static_cast<Index>(adjacent.size()); ++v) {
    std::vector<Index>& candidates = leaders[hash_of(adjacent[v])];
    for (Index leader : candidates)
      if (adjacent[leader] == adjacent[v]) {
        group[v] = group[leader];
        break;
      }
    if (group[v] < 0) {
      group[v] = groups++;
      candidates.push_back(v);
    }
  }
  return group;
}

/// The quotient graph of the symmetrised pattern: one vertex per group of rows of identical
/// structure, weighted by its size, in METIS's compressed form without self-loops.
struct QuotientGraph {
  Index groups = 0;
  std::vector<Index> group; ///< group of each row
  std::vector<idx_t> xadj, adjncy, weight;
};

QuotientGraph quotient_graph(const RowPattern& pattern) {
  const Index n = pattern.rows;
  QuotientGraph q;
  std::vector<std::vector<Index>> adjacent = symmetric_adjacency(pattern);
  q.group = merge_identical(adjacent, q.groups);
  std::vector<std::vector<idx_t>> lists(q.groups);
  q.weight.assign(q.groups, 0);
  std::vector<Index> first(q.groups, -1);
  for (Index v = 0; v < n; ++v) {
    ++q.weight[q.group[v]];
    if (first[q.group[v]] < 0)
      first[q.group[v]] = v;
  }
  for (Index g = 0; g < q.groups; ++g) {
    for (Index w : adjacent[first[g]])
      if (q.group[w] != g)
        lists[g].push_back(q.group[w]);
    std::sort(lists[g].begin(), lists[g].end());
    lists[g].erase(std::unique(lists[g].begin(), lists[g].end()), lists[g].end());
  }
  adjacent = {};
  q.xadj.assign(q.groups + 1, 0);
  for (Index g = 0; g < q.groups; ++g)
    q.xadj[g + 1] = q.xadj[g] + static_cast<idx_t>(lists[g].size());
  q.adjncy.reserve(q.xadj[q.groups]);
  for (auto& list : lists)
    q.adjncy.insert(q.adjncy.end(), list.begin(), list.end());
  return q;
}

} // namespace

std::vector<Index> nested_dissection_order(const RowPattern& pattern) {
  const Index n = pattern.rows;
  if (n <= 2) {
    std::vector<Index> identity(n);
    std::iota(identity.begin(), identity.end(), 0);
    return identity;
  }
  QuotientGraph q = quotient_graph(pattern);
  const Index groups = q.groups;
  const std::vector<Index>& group = q.group;

  std::vector<idx_t> perm(groups), iperm(groups);
  idx_t vertices = groups;
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_NUMBERING] = 0;
  options[METIS_OPTION_SEED] = 1; // reproducible orderings, so reproducible round-off
  const int status = groups > 1 ? METIS_NodeND(&vertices, q.xadj.data(), q.adjncy.data(),
                                               q.weight.data(), options, perm.data(), iperm.data())
                                : METIS_OK;
  if (groups <= 1)
    perm.assign(groups, 0);
  if (status != METIS_OK)
    throw std::runtime_error(fmt::format("METIS nested dissection failed (status {})", status));

  // expand: the members of each group in the group's order, consecutively
  std::vector<Index> start(groups + 1, 0);
  for (Index v = 0; v < n; ++v)
    ++start[group[v] + 1];
  for (Index g = 0; g < groups; ++g)
    start[g + 1] += start[g];
  std::vector<Index> members(n);
  std::vector<Index> next(start.begin(), start.end() - 1);
  for (Index v = 0; v < n; ++v)
    members[next[group[v]]++] = v;
  std::vector<Index> order;
  order.reserve(n);
  for (Index k = 0; k < groups; ++k) {
    const Index g = static_cast<Index>(perm[k]);
    order.insert(order.end(), members.begin() + start[g], members.begin() + start[g + 1]);
  }
  return order;
}

std::vector<int> partition_rows(const RowPattern& pattern, int parts) {
  const Index n = pattern.rows;
  std::vector<int> owner(n, 0);
  if (parts <= 1 || n == 0)
    return owner;
  QuotientGraph q = quotient_graph(pattern);
  std::vector<idx_t> part(q.groups, 0);
  if (q.groups >= 2 * parts) {
    idx_t vertices = q.groups, constraints = 1, count = parts, cut = 0;
    idx_t options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    options[METIS_OPTION_NUMBERING] = 0;
    options[METIS_OPTION_SEED] = 1;
    const int status = METIS_PartGraphKway(&vertices, &constraints, q.xadj.data(), q.adjncy.data(),
                                           q.weight.data(), nullptr, nullptr, &count, nullptr,
                                           nullptr, options, &cut, part.data());
    if (status != METIS_OK)
      throw std::runtime_error(fmt::format("METIS partitioning failed (status {})", status));
  } else { // too few vertices to cut: consecutive blocks
    for (Index g = 0; g < q.groups; ++g)
      part[g] = static_cast<idx_t>(static_cast<std::int64_t>(g) * parts / q.groups);
  }
  for (Index i = 0; i < n; ++i)
    owner[i] = static_cast<int>(part[q.group[i]]);
  return owner;
}

} // namespace trifem::linalg
