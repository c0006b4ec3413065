// SPDX-License-Identifier: MIT
#include "trifem/linalg/nested_dissection.hpp"

#include "trifem/core/error.hpp"

#include <fmt/format.h>
#include <metis.h>

#include <algorithm>
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

} // namespace

std::vector<Index> nested_dissection_order(const RowPattern& pattern) {
  const Index n = pattern.rows;
  if (n <= 2) {
    std::vector<Index> identity(n);
    std::iota(identity.begin(), identity.end(), 0);
    return identity;
  }
  std::vector<std::vector<Index>> adjacent = symmetric_adjacency(pattern);
  Index groups = 0;
  const std::vector<Index> group = merge_identical(adjacent, groups);

  // the quotient graph: one vertex per group, weighted by its size, without self-loops
  std::vector<std::vector<idx_t>> quotient(groups);
  std::vector<idx_t> weight(groups, 0);
  std::vector<Index> first(groups, -1);
  for (Index v = 0; v < n; ++v) {
    ++weight[group[v]];
    if (first[group[v]] < 0)
      first[group[v]] = v;
  }
  for (Index g = 0; g < groups; ++g) {
    for (Index w : adjacent[first[g]])
      if (group[w] != g)
        quotient[g].push_back(group[w]);
    std::sort(quotient[g].begin(), quotient[g].end());
    quotient[g].erase(std::unique(quotient[g].begin(), quotient[g].end()), quotient[g].end());
  }
  adjacent = {};
  std::vector<idx_t> xadj(groups + 1, 0), adjncy;
  for (Index g = 0; g < groups; ++g)
    xadj[g + 1] = xadj[g] + static_cast<idx_t>(quotient[g].size());
  adjncy.reserve(xadj[groups]);
  for (auto& list : quotient)
    adjncy.insert(adjncy.end(), list.begin(), list.end());
  quotient = {};

  std::vector<idx_t> perm(groups), iperm(groups);
  idx_t vertices = groups;
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_NUMBERING] = 0;
  options[METIS_OPTION_SEED] = 1; // reproducible orderings, so reproducible round-off
  const int status = groups > 1 ? METIS_NodeND(&vertices, xadj.data(), adjncy.data(), weight.data(),
                                               options, perm.data(), iperm.data())
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

} // namespace trifem::linalg
