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
/// Distance outside the reference facet (reference units) beyond which the iterate has left it.
constexpr Real kOutside = 1.5;
constexpr Real kEps = std::numeric_limits<Real>::epsilon();

/// Full Hessian of ½|p - x(ξ)|²: H_αβ = a_αβ - d·x_{,αβ}, d = p - x.
Mat2 distance_hessian(const FacetPoint& fp, const Vec3& d) {
  Mat2 H = fp.metric();
  for (int alpha = 0; alpha < 2; ++alpha)
    for (int beta = 0; beta < 2; ++beta)
      H(alpha, beta) -= d.dot(fp.second(alpha, beta));
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

Vec3 position_at(const FacetCoords& X, const Vec2& xi) {
  return X.x.transpose() * X.reference->shape(xi);
}

/// Backtracks a long step until ½|p - x|² does not increase (at most 20 halvings).
Vec2 backtrack(const Vec3& p, const FacetCoords& X, const Vec2& xi, Real f0, Vec2 step) {
  for (int k = 0; k < 20; ++k) {
    if (0.5 * (p - position_at(X, xi + step)).squaredNorm() <= f0)
      break;
    step *= 0.5;
  }
  return step;
}

/// Stationary point of ½|p - x(ξ)|² on the polynomial extension of the facet, from xi0.
NewtonResult newton_closest_point(const Vec3& p, const FacetCoords& X, Vec2 xi, Real h,
                                  int max_iterations) {
  const Real scale = p.lpNorm<Eigen::Infinity>() + X.x.lpNorm<Eigen::Infinity>();
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
    if (outside_distance(X.type(), xi) > kOutside)
      return {NewtonStatus::Outside, xi};
    if (size <= step_tol) // the last (quadratically convergent) step has been applied
      return {NewtonStatus::Converged, xi};
  }
  return {NewtonStatus::Failed, xi};
}

int nearest_corner(const Vec3& p, const FacetCoords& X) {
  int best = 0;
  for (int a = 1; a < X.num_corners(); ++a)
    if ((p - X.node(a)).norm() < (p - X.node(best)).norm())
      best = a;
  return best;
}

/// Nearest of equally spaced samples of the reference facet: ξ ∈ {-1, -0.5, 0, 0.5, 1}² on
/// quads, ξ ∈ {0, ¼, ½, ¾, 1}² with ξ^1 + ξ^2 ≤ 1 on triangles.
Vec2 coarse_sample(const Vec3& p, const FacetCoords& X) {
  const bool triangle = is_triangle(X.type());
  Vec2 best = facet_centre(X.type());
  Real best_distance = std::numeric_limits<Real>::infinity();
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) {
      if (triangle && i + j > 4)
        continue;
      const Vec2 xi = triangle ? Vec2(0.25 * i, 0.25 * j) : Vec2(-1 + 0.5 * i, -1 + 0.5 * j);
      const Real d = (p - position_at(X, xi)).norm();
      if (d < best_distance) {
        best_distance = d;
        best = xi;
      }
    }
  return best;
}

Projection interior_projection(const Vec3& p, const FacetCoords& X, const Vec2& xi) {
  const FacetPoint fp = evaluate_facet(X, xi);
  Projection pr;
  pr.xi = xi;
  pr.point = fp.x;
  pr.normal = fp.normal;
  pr.gap = (p - fp.x).dot(fp.normal);
  return pr;
}

/// The edge curve x(u), u ∈ [0, 1], of edge e: straight between its corners A and B, or the
/// parabola through A, its mid-edge node M (u = ½) and B.
struct EdgeCurve {
  Vec3 A, B, M;
  bool curved = false;

  Vec3 at(Real u) const {
    return curved ? Vec3(A * (1 - u) * (1 - 2 * u) + 4 * u * (1 - u) * M + u * (2 * u - 1) * B)
                  : Vec3(A + u * (B - A));
  }
  Vec3 tangent(Real u) const {
    return curved ? Vec3(A * (4 * u - 3) + M * (4 - 8 * u) + B * (4 * u - 1)) : Vec3(B - A);
  }
  Vec3 second() const { return curved ? Vec3(4 * A - 8 * M + 4 * B) : Vec3::Zero(); }
};

EdgeCurve edge_curve(const FacetCoords& X, int e) {
  const int corners = X.num_corners();
  EdgeCurve c{X.node(e), X.node((e + 1) % corners), Vec3::Zero(), X.num_nodes() > corners};
  if (c.curved)
    c.M = X.node(corners + e);
  return c;
}

/// Parameter u ∈ [0, 1] of the point of the edge curve nearest to p: closed form on a straight
/// edge; on a curved one Newton on (p - x(u))·x_u = 0, clamped to [0, 1], from the nearest of
/// nine samples.
Real nearest_on_edge(const Vec3& p, const EdgeCurve& c) {
  if (!c.curved) {
    const Real len2 = (c.B - c.A).squaredNorm();
    return len2 > 0 ? std::clamp((p - c.A).dot(c.B - c.A) / len2, 0.0, 1.0) : 0.0;
  }
  Real u = 0, best = std::numeric_limits<Real>::infinity();
  for (int i = 0; i <= 8; ++i)
    if (const Real d = (p - c.at(i / 8.0)).squaredNorm(); d < best) {
      best = d;
      u = i / 8.0;
    }
  for (int it = 0; it < 30; ++it) {
    const Vec3 d = p - c.at(u), xu = c.tangent(u);
    const Real g = -d.dot(xu), tt = xu.squaredNorm();
    if (!(tt > 0))
      break;
    const Real H = tt - d.dot(c.second());
    const Real next = std::clamp(u - g / (H > 0 ? H : tt), 0.0, 1.0);
    const Real step = std::abs(next - u);
    u = next;
    if (step <= 1e-14)
      break;
  }
  return u;
}

/// Nearest point on the edges of the facet.
Projection boundary_projection(const Vec3& p, const FacetCoords& X, Real h) {
  const mesh::FacetType type = X.type();
  const int corners = X.num_corners();
  int best_edge = 0;
  Real best_u = 0, best_dist = std::numeric_limits<Real>::infinity();
  for (int e = 0; e < corners; ++e) {
    const EdgeCurve c = edge_curve(X, e);
    const Real u = nearest_on_edge(p, c);
    const Real dist = (p - c.at(u)).norm();
    if (dist < best_dist) {
      best_dist = dist;
      best_edge = e;
      best_u = u;
    }
  }
  Projection pr;
  pr.on_boundary = true;
  pr.edge = best_edge;
  pr.corner = best_u == 0.0 ? best_edge : best_u == 1.0 ? (best_edge + 1) % corners : -1;
  pr.xi = pr.corner >= 0
              ? facet_corner(type, pr.corner)
              : Vec2(facet_corner(type, best_edge) + best_u * edge_direction(type, best_edge));
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

std::optional<Projection> project_onto_facet(const Vec3& p, const FacetCoords& X,
                                             const ProjectionOptions& options) {
  const Real h = facet_size(X);
  if (!(h > 0) || !p.allFinite())
    return std::nullopt;
  // Candidates: the nearest edge/corner point, and interior stationary points of ½|p - x|²
  // found by Newton; the nearest wins, an interior point on ties (within 1e-10 h).
  Projection best = boundary_projection(p, X, h);
  const auto consider = [&](const NewtonResult& res) {
    if (res.status != NewtonStatus::Converged ||
        !inside_facet(X.type(), res.xi, options.xi_tolerance))
      return;
    const Projection pr = interior_projection(p, X, res.xi);
    if (std::abs(pr.gap) <= std::abs(best.gap) + 1e-10 * h)
      best = pr;
  };
  NewtonResult res = newton_closest_point(p, X, facet_centre(X.type()), h, options.max_iterations);
  if (res.status == NewtonStatus::Failed)
    res = newton_closest_point(p, X, facet_corner(X.type(), nearest_corner(p, X)), h,
                               options.max_iterations);
  consider(res);
  // Safeguard for strongly twisted facets (several stationary points): Newton again from the
  // nearest coarse sample unless it lies in the basin of the interior point already found.
  const Vec2 seed = coarse_sample(p, X);
  const Real basin = is_triangle(X.type()) ? 0.25 : 0.5; // an eighth of the facet
  if (best.on_boundary || (seed - best.xi).lpNorm<Eigen::Infinity>() > basin)
    consider(newton_closest_point(p, X, seed, h, options.max_iterations));
  return best;
}

namespace {

/// Lower bound of the distance from p to facet f: the distance to the box of its nodes grown
/// by twice its bulge (a linear or bilinear patch lies in the convex hull of its corners, a
/// quadratic one within twice its largest mid-edge offset of the bilinear or linear patch).
Real distance_bound(const Vec3& p, const FacetCoords& X) {
  const Real grow = 2 * facet_bulge(X);
  const Vec3 lo = X.x.colwise().minCoeff().transpose().array() - grow;
  const Vec3 hi = X.x.colwise().maxCoeff().transpose().array() + grow;
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
    const FacetCoords X = surface.coords(f, x);
    const Real tie = 1e-10 * facet_size(X);
    if (bound > options.search_distance || (best && bound > std::abs(best->gap) + tie))
      break;
    std::optional<Projection> pr = project_onto_facet(p, X, options);
    if (!pr)
      continue;
    pr->facet = f;
    if (pr->on_boundary)
      pr->on_free_boundary = surface.on_free_boundary(f, pr->edge, pr->corner);
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
