// SPDX-License-Identifier: MIT
#include "trifem/contact/projection.hpp"

#include <algorithm>
#include <cmath>

namespace trifem::contact {
namespace {

enum class NewtonStatus { Converged, Outside, Failed };

struct NewtonResult {
  NewtonStatus status = NewtonStatus::Failed;
  Vec2 xi = Vec2::Zero();
};

constexpr Real kMaxStep = 0.5; ///< largest Newton step in ξ (a quarter of the facet)
constexpr Real kOutside = 2.5; ///< |ξ|∞ beyond which the iterate has clearly left the facet
constexpr Real kEps = std::numeric_limits<Real>::epsilon();

/// Full Hessian of ½|p - x(ξ)|²: H_αβ = a_αβ - d·x_{,αβ}, d = p - x (only x_{,12} ≠ 0).
Mat2 distance_hessian(const FacetPoint& fp, const Vec3& d) {
  Mat2 H = fp.metric();
  H(0, 1) -= d.dot(fp.x12);
  H(1, 0) = H(0, 1);
  return H;
}

bool positive_definite(const Mat2& H) {
  return H(0, 0) > 0 && H.determinant() > 0;
}

/// Newton direction for r_α(ξ) = (p - x(ξ))·t_α = 0: H Δξ = r with the full Hessian when it is
/// positive definite, else with the metric a_αβ (Gauss-Newton; always a descent direction).
bool newton_direction(const Vec3& p, const FacetPoint& fp, Vec2& step) {
  const Vec3 d = p - fp.x;
  const Vec2 r(d.dot(fp.t[0]), d.dot(fp.t[1]));
  const Mat2 a = fp.metric();
  if (!(a.determinant() > 1e-14 * a.trace() * a.trace()))
    return false; // degenerate parametrisation at ξ
  const Mat2 H = distance_hessian(fp, d);
  step = positive_definite(H) ? H.inverse() * r : a.inverse() * r;
  return step.allFinite();
}

/// Backtracks a long step until ½|p - x|² does not increase (at most 20 halvings).
Vec2 backtrack(const Vec3& p, const fe::QuadCoords& X, const Vec2& xi, Real f0, Vec2 step) {
  for (int k = 0; k < 20; ++k) {
    const Vec3 x = X.transpose() * fe::quad4_shape(xi + step);
    if (0.5 * (p - x).squaredNorm() <= f0)
      break;
    step *= 0.5;
  }
  return step;
}

/// Stationary point of ½|p - x(ξ)|² on the bilinear extension of the facet, from xi0.
NewtonResult newton_closest_point(const Vec3& p, const fe::QuadCoords& X, Vec2 xi, Real h,
                                  int max_iterations) {
  const Real scale = p.lpNorm<Eigen::Infinity>() + X.lpNorm<Eigen::Infinity>();
  const Real step_tol = std::max(1e-12, 64 * kEps * scale / h);
  for (int it = 0; it < max_iterations; ++it) {
    const FacetPoint fp = evaluate_facet(X, xi);
    Vec2 step;
    if (!newton_direction(p, fp, step))
      return {NewtonStatus::Failed, xi};
    const Real size = step.lpNorm<Eigen::Infinity>();
    if (size > kMaxStep)
      step *= kMaxStep / size;
    if (size > 1e-6)
      step = backtrack(p, X, xi, 0.5 * (p - fp.x).squaredNorm(), step);
    xi += step;
    if (xi.lpNorm<Eigen::Infinity>() > kOutside)
      return {NewtonStatus::Outside, xi};
    if (size <= step_tol) // the last (quadratically convergent) step has been applied
      return {NewtonStatus::Converged, xi};
  }
  return {NewtonStatus::Failed, xi};
}

int nearest_corner(const Vec3& p, const fe::QuadCoords& X) {
  int best = 0;
  for (int a = 1; a < 4; ++a)
    if ((p - X.row(a).transpose()).norm() < (p - X.row(best).transpose()).norm())
      best = a;
  return best;
}

/// Nearest of the 5 x 5 equally spaced samples ξ ∈ {-1, -0.5, 0, 0.5, 1}².
Vec2 coarse_sample(const Vec3& p, const fe::QuadCoords& X) {
  Vec2 best = Vec2::Zero();
  Real best_distance = std::numeric_limits<Real>::infinity();
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) {
      const Vec2 xi(-1 + 0.5 * i, -1 + 0.5 * j);
      const Real d = (p - X.transpose() * fe::quad4_shape(xi)).norm();
      if (d < best_distance) {
        best_distance = d;
        best = xi;
      }
    }
  return best;
}

Projection interior_projection(const Vec3& p, const fe::QuadCoords& X, const Vec2& xi) {
  const FacetPoint fp = evaluate_facet(X, xi);
  Projection pr;
  pr.xi = xi;
  pr.point = fp.x;
  pr.normal = fp.normal;
  pr.gap = (p - fp.x).dot(fp.normal);
  return pr;
}

/// Nearest point on the four (straight) facet edges: edge e runs from corner e to corner e+1.
Projection boundary_projection(const Vec3& p, const fe::QuadCoords& X, Real h) {
  int best_edge = 0;
  Real best_u = 0, best_dist = std::numeric_limits<Real>::infinity();
  for (int e = 0; e < 4; ++e) {
    const Vec3 A = X.row(e).transpose(), B = X.row((e + 1) % 4).transpose();
    const Real len2 = (B - A).squaredNorm();
    const Real u = len2 > 0 ? std::clamp((p - A).dot(B - A) / len2, 0.0, 1.0) : 0.0;
    const Real dist = (p - A - u * (B - A)).norm();
    if (dist < best_dist) {
      best_dist = dist;
      best_edge = e;
      best_u = u;
    }
  }
  const int free_dir = best_edge % 2 == 0 ? 0 : 1; // edges 0, 2 run along ξ^1; 1, 3 along ξ^2
  const Vec2 c0 = facet_corner(best_edge), c1 = facet_corner((best_edge + 1) % 4);
  Projection pr;
  pr.on_boundary = true;
  pr.xi = c0;
  pr.xi[free_dir] = c0[free_dir] + best_u * (c1[free_dir] - c0[free_dir]);
  pr.fixed[1 - free_dir] = true;
  pr.fixed[free_dir] = best_u == 0.0 || best_u == 1.0;
  const FacetPoint fp = evaluate_facet(X, pr.xi);
  const Vec3 d = p - fp.x;
  const Real dist = d.norm();
  pr.point = fp.x;
  if (dist > 1e-10 * h) {
    pr.gap = d.dot(fp.normal) >= 0 ? dist : -dist;
    pr.normal = d / pr.gap;
  } else { // p on the edge: the direction p - x is undefined, use the facet normal
    pr.gap = d.dot(fp.normal);
    pr.normal = fp.normal;
  }
  return pr;
}

} // namespace

std::optional<Projection> project_onto_facet(const Vec3& p, const fe::QuadCoords& X,
                                             const ProjectionOptions& options) {
  const Real h = facet_size(X);
  if (!(h > 0) || !p.allFinite())
    return std::nullopt;
  // Candidates: the nearest edge/corner point, and interior stationary points of ½|p - x|²
  // found by Newton; the nearest wins, an interior point on ties (within 1e-10 h).
  Projection best = boundary_projection(p, X, h);
  const auto consider = [&](const NewtonResult& res) {
    if (res.status != NewtonStatus::Converged ||
        res.xi.lpNorm<Eigen::Infinity>() > 1 + options.xi_tolerance)
      return;
    const Projection pr = interior_projection(p, X, res.xi);
    if (std::abs(pr.gap) <= std::abs(best.gap) + 1e-10 * h)
      best = pr;
  };
  NewtonResult res = newton_closest_point(p, X, Vec2::Zero(), h, options.max_iterations);
  if (res.status == NewtonStatus::Failed)
    res = newton_closest_point(p, X, facet_corner(nearest_corner(p, X)), h, options.max_iterations);
  consider(res);
  // Safeguard for strongly twisted facets (several stationary points): Newton again from the
  // nearest coarse sample unless it lies in the basin of the interior point already found.
  const Vec2 seed = coarse_sample(p, X);
  if (best.on_boundary || (seed - best.xi).lpNorm<Eigen::Infinity>() > 0.5)
    consider(newton_closest_point(p, X, seed, h, options.max_iterations));
  return best;
}

namespace {

/// Lower bound of the distance from p to facet f: the distance to the box of its nodes (the
/// bilinear patch lies in their convex hull).
Real distance_bound(const Vec3& p, const fe::QuadCoords& X) {
  const Vec3 lo = X.colwise().minCoeff().transpose(), hi = X.colwise().maxCoeff().transpose();
  return (p - p.cwiseMax(lo).cwiseMin(hi)).norm();
}

/// True if `pr` should replace `best`: nearer by more than `tie`; on a tie an interior
/// projection beats a boundary one, then the lower facet index wins.
bool better(const Projection& pr, const Projection& best, Real tie) {
  const Real d = std::abs(pr.gap), d_best = std::abs(best.gap);
  if (d < d_best - tie || d > d_best + tie)
    return d < d_best;
  if (pr.on_boundary != best.on_boundary)
    return !pr.on_boundary;
  return pr.facet < best.facet;
}

std::optional<Projection> select(const Vec3& p, const ContactSurface& surface,
                                 const NodePositions& x, std::span<const Index> facets,
                                 const ProjectionOptions& options) {
  // Visit the facets by increasing distance bound and stop when no facet can be nearer.
  std::vector<std::pair<Real, Index>> order;
  order.reserve(facets.size());
  for (Index f : facets)
    order.emplace_back(distance_bound(p, surface.coords(f, x)), f);
  std::sort(order.begin(), order.end());
  std::optional<Projection> best;
  for (const auto& [bound, f] : order) {
    const fe::QuadCoords X = surface.coords(f, x);
    const Real tie = 1e-10 * facet_size(X);
    if (bound > options.search_distance || (best && bound > std::abs(best->gap) + tie))
      break;
    std::optional<Projection> pr = project_onto_facet(p, X, options);
    if (!pr)
      continue;
    pr->facet = f;
    if (pr->on_boundary)
      pr->on_free_boundary = surface.on_free_boundary(f, pr->xi, pr->fixed);
    if (!best || better(*pr, *best, tie))
      best = pr;
  }
  if (best && std::abs(best->gap) > options.search_distance)
    return std::nullopt;
  if (best && best->on_free_boundary && options.free_edge_tolerance > options.xi_tolerance) {
    ProjectionOptions extended = options;
    extended.xi_tolerance = options.free_edge_tolerance;
    std::optional<Projection> pr = project_onto_facet(p, surface.coords(best->facet, x), extended);
    if (pr && !pr->on_boundary && std::abs(pr->gap) <= options.search_distance) {
      pr->facet = best->facet;
      return pr;
    }
  }
  return best;
}

/// The search only sees facets within its radius: never accept farther projections.
ProjectionOptions within_radius(ProjectionOptions options, const BucketSearch& search) {
  options.search_distance = std::min(options.search_distance, search.radius());
  return options;
}

} // namespace

std::optional<Projection> project(const Vec3& p, const ContactSurface& surface,
                                  const NodePositions& x, const ProjectionOptions& options) {
  std::vector<Index> all(surface.num_facets());
  for (Index f = 0; f < surface.num_facets(); ++f)
    all[f] = f;
  return select(p, surface, x, all, options);
}

std::optional<Projection> project(const Vec3& p, const ContactSurface& surface,
                                  const NodePositions& x, const BucketSearch& search,
                                  const ProjectionOptions& options) {
  std::vector<Index> candidates;
  search.candidates(p, candidates);
  return select(p, surface, x, candidates, within_radius(options, search));
}

std::vector<std::optional<Projection>> project_nodes(const std::vector<Index>& nodes,
                                                     const ContactSurface& surface,
                                                     const NodePositions& x,
                                                     const BucketSearch& search,
                                                     const ProjectionOptions& options) {
  std::vector<std::optional<Projection>> out;
  out.reserve(nodes.size());
  std::vector<Index> candidates;
  for (Index node : nodes) {
    const Vec3 p = x(node);
    search.candidates(p, candidates);
    out.push_back(select(p, surface, x, candidates, within_radius(options, search)));
  }
  return out;
}

} // namespace trifem::contact
