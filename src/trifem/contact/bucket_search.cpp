// SPDX-License-Identifier: MIT
#include "trifem/contact/bucket_search.hpp"

#include "trifem/core/error.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

namespace trifem::contact {

BucketSearch::BucketSearch(const ContactSurface& surface, const NodePositions& x, Real radius)
    : radius_(radius) {
  TRIFEM_CHECK(radius >= 0, "contact search radius must be >= 0, got {}", radius);
  const Index n = surface.num_facets();
  boxes_.resize(n);
  Real extent = 0;
  Eigen::AlignedBox3d all;
  for (Index f = 0; f < n; ++f) {
    // (a quadratic facet lies within twice its bulge of the box of its nodes)
    const FacetCoords X = surface.coords(f, x);
    Eigen::AlignedBox3d box(X.x.colwise().minCoeff().transpose(),
                            X.x.colwise().maxCoeff().transpose());
    const Real grow = radius + 2 * facet_bulge(X);
    box.min().array() -= grow;
    box.max().array() += grow;
    boxes_[f] = box;
    extent += box.sizes().maxCoeff();
    all.extend(box);
  }
  if (n == 0) {
    offsets_.assign(2, 0);
    return;
  }
  const Real h = extent / n;
  inv_bucket_ = h > 0 ? 1 / h : 1;
  origin_ = all.min();
  // Hash table with at least 2 n buckets (power of two: the hash is masked).
  const std::size_t table = std::bit_ceil(2 * static_cast<std::size_t>(n));
  mask_ = table - 1;
  offsets_.assign(table + 1, 0);
  for (Index f = 0; f < n; ++f)
    for_each_cell(boxes_[f], [&](const Cell& c) { ++offsets_[bucket_of(c) + 1]; });
  for (std::size_t b = 0; b < table; ++b)
    offsets_[b + 1] += offsets_[b];
  entries_.resize(offsets_.back());
  std::vector<Index> fill(offsets_.begin(), offsets_.end() - 1);
  for (Index f = 0; f < n; ++f)
    for_each_cell(boxes_[f], [&](const Cell& c) { entries_[fill[bucket_of(c)]++] = f; });
}

BucketSearch::Cell BucketSearch::cell_of(const Vec3& p) const {
  const Vec3 s = (p - origin_) * inv_bucket_;
  return {static_cast<std::int64_t>(std::floor(s[0])), static_cast<std::int64_t>(std::floor(s[1])),
          static_cast<std::int64_t>(std::floor(s[2]))};
}

std::size_t BucketSearch::bucket_of(const Cell& c) const {
  // Teschner et al. (2003) spatial hash with large primes.
  const auto h = static_cast<std::uint64_t>(c[0]) * 73856093ULL ^
                 static_cast<std::uint64_t>(c[1]) * 19349663ULL ^
                 static_cast<std::uint64_t>(c[2]) * 83492791ULL;
  return static_cast<std::size_t>(h) & mask_;
}

template <class Visit>
void BucketSearch::for_each_cell(const Eigen::AlignedBox3d& box, Visit&& visit) const {
  const Cell lo = cell_of(box.min()), hi = cell_of(box.max());
  for (std::int64_t i = lo[0]; i <= hi[0]; ++i)
    for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
      for (std::int64_t k = lo[2]; k <= hi[2]; ++k)
        visit(Cell(i, j, k));
}

void BucketSearch::candidates(const Vec3& p, std::vector<Index>& out) const {
  out.clear();
  if (boxes_.empty() || !p.allFinite())
    return;
  const std::size_t b = bucket_of(cell_of(p));
  for (Index e = offsets_[b]; e < offsets_[b + 1]; ++e) {
    const Index f = entries_[e];
    if (boxes_[f].contains(p))
      out.push_back(f);
  }
  // Hash collisions may list a facet twice in one bucket.
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

std::vector<Index> BucketSearch::candidates(const Vec3& p) const {
  std::vector<Index> out;
  candidates(p, out);
  return out;
}

} // namespace trifem::contact
