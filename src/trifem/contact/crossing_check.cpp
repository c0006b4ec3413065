// SPDX-License-Identifier: MIT
// Detection of tunnelling: a step in which a slave node crossed the master surface and ended
// behind it beyond the search distance, where the projection no longer finds it (the node is
// then inactive and the bodies pass through each other without a contact force).
#include "trifem/contact/contact_term.hpp"

#include <algorithm>
#include <cmath>

namespace trifem::contact {
namespace {

/// Largest displacement of the given nodes between the states x0 and x1 [length].
Real largest_motion(const std::vector<Index>& nodes, const std::function<Vec3(Index)>& p0,
                    const std::function<Vec3(Index)>& p1) {
  Real m = 0;
  for (Index n : nodes)
    m = std::max(m, (p1(n) - p0(n)).norm());
  return m;
}

} // namespace

std::optional<Projection> ContactTerm::nearest_on_master(const Vec3& p, const Vector& x) const {
  const NodePositions pos([this, &x](Index n) { return position(n, x); });
  ProjectionOptions options;
  options.xi_tolerance = settings_.xi_tolerance; // no distance limit
  options.free_edge_tolerance = settings_.slave_free_edge_tolerance;
  return project(p, master_, pos, options);
}

bool ContactTerm::crossing_candidate(Index k, bool large_motion) const {
  const auto& pr = slave_proj_[k];
  if (pr && !pr->on_free_boundary)
    return false; // found by the search: the active set handles it
  return large_motion || committed_projected_[k] != 0;
}

std::string ContactTerm::crossing_rejection(const physics::EvalState& state) const {
  const Vector& x = state.x;
  if (state.x_old.size() != x.size())
    return {}; // no start-of-step state to compare with
  const auto p0 = [this, &state](Index n) { return position(n, state.x_old); };
  const auto p1 = [this, &x](Index n) { return position(n, x); };
  const Real d = settings_.search_distance;
  const bool large_motion =
      std::max(largest_motion(slave_.nodes(), p0, p1), largest_motion(master_.nodes(), p0, p1)) > d;
  for (Index k = 0; k < slave_.num_nodes(); ++k) {
    if (!crossing_candidate(k, large_motion))
      continue;
    const Index node = slave_.nodes()[k];
    const auto now = nearest_on_master(p1(node), x);
    if (!now || now->on_free_boundary || now->gap >= -d)
      continue; // beside the master surface or in front of it
    const auto before = nearest_on_master(p0(node), state.x_old);
    if (!before || before->gap < -d)
      continue; // was behind the master surface already
    const Vec3& X = mesh_.node(node);
    return fmt::format(
        "slave node {} (reference position {:.4g} {:.4g} {:.4g}) crossed the master surface "
        "within the step: its gap went from {:.4g} to {:.4g} mm, beyond the search distance "
        "{:.4g} mm where contact is no longer detected; reduce the step (time.dt, time.dt_max) "
        "or the load increment, or raise the pair's search_distance",
        node, X.x(), X.y(), X.z(), before->gap, now->gap, d);
  }
  return {};
}

} // namespace trifem::contact
