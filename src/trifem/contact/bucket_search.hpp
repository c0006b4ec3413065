// SPDX-License-Identifier: MIT
// Broad phase of the contact search: a hashed uniform grid ("buckets") over the current facet
// bounding boxes inflated by a search radius (docs/theory/contact.md §2.3).
#pragma once

#include "trifem/contact/contact_surface.hpp"

#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

namespace trifem::contact {

/// Spatial hash of the facets of one ContactSurface in one configuration. Rebuild it whenever
/// the configuration changes (once per Newton iteration): build is O(n_facets), a query is O(1)
/// on average. Guarantee: every facet whose closest point to p lies within `radius` of p is a
/// candidate of p (the bilinear patch lies in the convex hull, hence the box, of its nodes).
class BucketSearch {
public:
  /// Builds the buckets of `surface` in configuration x; radius ≥ 0 (length unit of x).
  /// The bucket edge is the mean inflated-box extent, so each box covers O(1) buckets.
  BucketSearch(const ContactSurface& surface, const NodePositions& x, Real radius);

  /// Facets whose bounding box inflated by radius() contains p, ascending, without duplicates.
  /// `out` is cleared first (reuse it across queries to avoid allocations).
  void candidates(const Vec3& p, std::vector<Index>& out) const;
  /// Convenience overload of candidates(p, out).
  std::vector<Index> candidates(const Vec3& p) const;

  Real radius() const { return radius_; }
  Real bucket_size() const { return 1 / inv_bucket_; }
  /// Inflated bounding box of facet f.
  const Eigen::AlignedBox3d& box(Index f) const { return boxes_[f]; }
  /// Total number of (bucket, facet) entries (a measure of memory and build work).
  std::size_t num_entries() const { return entries_.size(); }

private:
  using Cell = Eigen::Matrix<std::int64_t, 3, 1>;
  Cell cell_of(const Vec3& p) const;
  std::size_t bucket_of(const Cell& c) const;
  template <class Visit>
  void for_each_cell(const Eigen::AlignedBox3d& box, Visit&& visit) const;

  Real radius_;
  Real inv_bucket_ = 1;
  Vec3 origin_ = Vec3::Zero();
  std::size_t mask_ = 0;
  std::vector<Eigen::AlignedBox3d> boxes_;
  std::vector<Index> offsets_; ///< CSR over the hash table
  std::vector<Index> entries_;
};

} // namespace trifem::contact
