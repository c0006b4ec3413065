// SPDX-License-Identifier: MIT
// The nested-dissection ordering: a permutation of the rows, rows of identical structure kept
// together, and separators last (the vertices of the first separator of a grid are eliminated
// after both halves).
#include "trifem/linalg/nested_dissection.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <vector>

using namespace trifem;

namespace {

/// The pattern of a 7-point Laplacian on an n³ grid with `components` coupled unknowns per
/// point (numbered component-major, as trifem numbers fields), in compressed rows.
struct GridPattern {
  std::vector<Index> row_start{0}, column;
  Index rows = 0;
};

GridPattern grid(int n, int components) {
  GridPattern g;
  const Index points = n * n * n;
  g.rows = points * components;
  auto point = [n](int i, int j, int k) { return (k * n + j) * n + i; };
  for (int c = 0; c < components; ++c)
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          std::vector<Index> neighbours{point(i, j, k)};
          if (i > 0)
            neighbours.push_back(point(i - 1, j, k));
          if (i + 1 < n)
            neighbours.push_back(point(i + 1, j, k));
          if (j > 0)
            neighbours.push_back(point(i, j - 1, k));
          if (j + 1 < n)
            neighbours.push_back(point(i, j + 1, k));
          if (k > 0)
            neighbours.push_back(point(i, j, k - 1));
          if (k + 1 < n)
            neighbours.push_back(point(i, j, k + 1));
          std::vector<Index> row;
          for (int d = 0; d < components; ++d)
            for (Index p : neighbours)
              row.push_back(d * points + p);
          std::sort(row.begin(), row.end());
          g.column.insert(g.column.end(), row.begin(), row.end());
          g.row_start.push_back(static_cast<Index>(g.column.size()));
        }
  return g;
}

} // namespace

TEST(NestedDissection, OrdersEveryRowOnceAndKeepsAPointsUnknownsTogether) {
  const int n = 9, components = 3;
  const GridPattern g = grid(n, components);
  const std::vector<Index> order =
      linalg::nested_dissection_order({g.rows, g.row_start.data(), g.column.data()});
  ASSERT_EQ(static_cast<Index>(order.size()), g.rows);
  std::vector<Index> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  std::vector<Index> all(g.rows);
  std::iota(all.begin(), all.end(), 0);
  EXPECT_EQ(sorted, all);
  // the unknowns of one point have identical rows: they are merged and eliminated together
  const Index points = n * n * n;
  for (Index k = 0; k < g.rows; k += components)
    for (int c = 1; c < components; ++c)
      EXPECT_EQ(order[k + c] % points, order[k] % points) << "position " << k + c;
}

TEST(NestedDissection, EliminatesTheTopSeparatorLast) {
  // the last point eliminated lies on a plane that splits the grid: removing the last n²
  // points leaves the first half and the second half of the grid unconnected
  const int n = 9;
  const GridPattern g = grid(n, 1);
  const std::vector<Index> order =
      linalg::nested_dissection_order({g.rows, g.row_start.data(), g.column.data()});
  const Index separator = n * n;
  std::vector<int> part(g.rows, -1); // 0 / 1: the component of the first point reached
  std::vector<bool> removed(g.rows, false);
  for (Index k = g.rows - separator; k < g.rows; ++k)
    removed[order[k]] = true;
  int components = 0;
  for (Index start = 0; start < g.rows; ++start) {
    if (removed[start] || part[start] >= 0)
      continue;
    std::vector<Index> stack{start};
    part[start] = components;
    while (!stack.empty()) {
      const Index v = stack.back();
      stack.pop_back();
      for (Index k = g.row_start[v]; k < g.row_start[v + 1]; ++k) {
        const Index w = g.column[k];
        if (!removed[w] && part[w] < 0) {
          part[w] = components;
          stack.push_back(w);
        }
      }
    }
    ++components;
  }
  EXPECT_GE(components, 2);
}

TEST(NestedDissection, TinyPatternsAreOrderedToo) {
  const std::vector<Index> start{0, 1}, column{0};
  EXPECT_EQ(linalg::nested_dissection_order({1, start.data(), column.data()}),
            (std::vector<Index>{0}));
  EXPECT_TRUE(linalg::nested_dissection_order({0, start.data(), column.data()}).empty());
}
