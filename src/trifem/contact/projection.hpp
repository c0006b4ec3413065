// SPDX-License-Identifier: MIT
// Closest-point projection of a point onto the facets (tri3, tri6, quad4, quad8) of a contact
// surface (docs/theory/contact.md §2.2): local Newton per candidate facet, then selection.
#pragma once

#include "trifem/contact/bucket_search.hpp"

#include <limits>
#include <optional>

namespace trifem::contact {

/// Closest-point projection of a point p onto a contact surface.
///
/// Interior projection (on_boundary = false): ξ is a stationary point of ½|p - x(ξ)|² inside
/// the reference facet enlarged by tol, so p - x(ξ) = g n(ξ) and
///   gap = (p - x(ξ)) · n(ξ),   normal = n(ξ) = t_1 × t_2 / |t_1 × t_2|.
/// Boundary projection (on_boundary = true; no facet contains the projection, e.g. p lies
/// beyond a convex kink or beyond the edge of the surface): ξ is the nearest point on the
/// edges/corners of the facet (straight or, on quadratic facets, curved), `edge` names the edge
/// and `corner` the corner if it is one, and
///   gap = s |p - x(ξ)|,   normal = (p - x(ξ)) / gap,   s = sign((p - x(ξ)) · n(ξ)),
/// so gap and normal are continuous where the projection leaves the facet (there p - x ∥ n).
/// If |p - x(ξ)| vanishes (p on an edge) the facet normal n(ξ) is used instead.
struct Projection {
  Index facet = -1;           ///< facet index in the ContactSurface
  Vec2 xi = Vec2::Zero();     ///< reference coordinates on the facet
  Real gap = 0;               ///< signed gap, > 0 outside (separation), < 0 penetration
  Vec3 normal = Vec3::Zero(); ///< unit normal (see above)
  Vec3 point = Vec3::Zero();  ///< x(ξ): the closest point on the surface
  bool on_boundary = false;   ///< clamped to a facet edge or corner
  int edge = -1;              ///< on_boundary: the edge (from corner `edge` to the next) ξ lies on
  int corner = -1;            ///< on_boundary: the corner ξ sits at (-1: inside the edge)
  bool on_free_boundary = false; ///< clamped to an edge with no neighbour facet: p lies
                                 ///< outside the surface's coverage (candidate for inactive)
};

/// Tolerances of the projection.
struct ProjectionOptions {
  /// Accept an interior projection for ξ in the reference facet enlarged by xi_tolerance
  /// (quads: ξ ∈ [-1-xi_tolerance, 1+xi_tolerance]²).
  Real xi_tolerance = 1e-6;
  /// A point whose nearest projection lies on a free edge of the surface (no neighbour facet)
  /// but within free_edge_tolerance of the extended facet (reference units)
  /// gets the interior projection onto the extension instead (0: none).
  Real free_edge_tolerance = 0;
  /// Points whose distance |p - x(ξ)| to the surface exceeds this get no projection.
  Real search_distance = std::numeric_limits<Real>::infinity();
  /// Newton iterations per start (facet centre, nearest corner, nearest coarse sample).
  int max_iterations = 30;
};

/// Projection of p onto one facet with current nodal coordinates X (`facet` is left at -1 and
/// `on_free_boundary` false: the facet knows no neighbours). Newton on r_α(ξ) = (p - x(ξ))·t_α
/// = 0 with the full Hessian a_αβ - (p - x)·x_{,αβ} (Gauss-Newton while it is indefinite,
/// steps ≤ 0.5, backtracking on |p - x|²) from the facet centre, then from the nearest corner
/// if that fails; a second Newton from the nearest of a grid of samples guards strongly twisted
/// or curved facets with several stationary points. The nearest of the accepted interior
/// point(s) and the nearest edge/corner point (Newton along curved edges) is returned (interior
/// on ties within 1e-10 h). Converges to round-off (|Δξ| ≤ 1e-12). Empty only for a degenerate
/// X (all nodes coincident) or a non-finite p.
std::optional<Projection> project_onto_facet(const Vec3& p, const FacetCoords& X,
                                             const ProjectionOptions& options = {});

/// Closest-point projection of p onto `surface` in configuration x, testing every facet
/// (brute force, O(n_facets); for tests and small surfaces). Selection: the smallest |gap|
/// (= distance); on ties (|Δ|gap|| ≤ 1e-10 × facet size) an interior projection beats a
/// boundary one, then the lower facet index wins. Empty if the distance > search_distance.
std::optional<Projection> project(const Vec3& p, const ContactSurface& surface,
                                  const NodePositions& x, const ProjectionOptions& options = {});

/// As above, but testing only the candidates of `search` (built for `surface` in the same x).
/// The effective search distance is min(search_distance, search.radius()); with it the
/// result equals the brute-force one.
std::optional<Projection> project(const Vec3& p, const ContactSurface& surface,
                                  const NodePositions& x, const BucketSearch& search,
                                  const ProjectionOptions& options = {});

/// Projects the points x(node) of the given mesh nodes onto `surface` (e.g. all slave nodes
/// onto the master surface, or all master nodes onto the slave surface, once per Newton
/// iteration). Result i belongs to nodes[i].
std::vector<std::optional<Projection>> project_nodes(const std::vector<Index>& nodes,
                                                     const ContactSurface& surface,
                                                     const NodePositions& x,
                                                     const BucketSearch& search,
                                                     const ProjectionOptions& options = {});

} // namespace trifem::contact
