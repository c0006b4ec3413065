// SPDX-License-Identifier: MIT
// Interface measures of a contact pair for output and input checks: per-slave-node gap,
// normals, area vectors and multipliers in a given state, and the current contact area.
#include "trifem/contact/contact_term.hpp"
#include "trifem/physics/facet_area_any.hpp"

namespace trifem::contact {
namespace {

/// a_k = ∫ M_k n da of every node k of `surface` (index into surface.nodes()) in the
/// configuration x, by each facet's rule (exact for flat facets).
std::vector<Vec3> nodal_area_vectors(const ContactSurface& surface, const NodePositions& x) {
  std::vector<Vec3> a(surface.num_nodes(), Vec3::Zero());
  for (Index f = 0; f < surface.num_facets(); ++f) {
    const FacetCoords X = surface.coords(f, x);
    const physics::FacetVectorX A = physics::facet_area_vectors(*X.reference, X.x);
    const auto nodes = surface.facet_nodes(f);
    for (std::size_t i = 0; i < nodes.size(); ++i)
      a[surface.local_node(nodes[i])] += A.segment<3>(3 * static_cast<Index>(i));
  }
  return a;
}

/// Copies an admissible projection into the state (see SlaveNodeState).
void set_projection(const std::optional<Projection>& pr, SlaveNodeState& s) {
  if (!pr || pr->on_free_boundary)
    return;
  s.projected = true;
  s.gap = pr->gap;
  s.master_normal = pr->normal;
}

} // namespace

std::vector<SlaveNodeState> ContactTerm::slave_states(const Vector& x) const {
  const NodePositions pos([this, &x](Index n) { return position(n, x); });
  ProjectionOptions options;
  options.xi_tolerance = settings_.xi_tolerance;
  options.free_edge_tolerance = settings_.slave_free_edge_tolerance;
  options.search_distance = settings_.search_distance;
  const BucketSearch on_master(master_, pos, settings_.search_distance);
  const auto projections = project_nodes(slave_.nodes(), master_, pos, on_master, options);
  const std::vector<Vec3> area = nodal_area_vectors(slave_, pos);
  std::vector<SlaveNodeState> states(slave_.num_nodes());
  for (Index k = 0; k < slave_.num_nodes(); ++k) {
    SlaveNodeState& s = states[k];
    s.node = slave_.nodes()[k];
    s.position = pos(s.node);
    s.area_vector = area[k];
    const Real norm = area[k].norm();
    if (norm > 0)
      s.normal = area[k] / norm;
    s.active = active_.active(k);
    s.frictional = law_->frictional();
    s.slipping = active_.slipping(k);
    s.accumulated_slip = accumulated_slip(k);
    set_projection(projections[k], s);
    s.multiplier.resize(law_->num_components());
    const std::array<Index, 2> ends = slave_.edge_corners(k);
    for (int c = 0; c < law_->num_components(); ++c)
      s.multiplier[c] = ends[0] >= 0 && law_->corner_interpolated(c)
                            ? 0.5 * (x[multiplier_dof(ends[0], c)] + x[multiplier_dof(ends[1], c)])
                            : x[multiplier_dof(k, c)];
    if (ends[0] >= 0)
      s.edge_corners = {slave_.nodes()[ends[0]], slave_.nodes()[ends[1]]};
  }
  return states;
}

void ContactTerm::accumulate_slip(const physics::EvalState& state) {
  slip_.resize(static_cast<std::size_t>(slave_.num_nodes()), 0.0);
  const NodePositions now([this, &state](Index n) { return position(n, state.x); });
  const NodePositions before([this, &state](Index n) { return position(n, state.x_old); });
  const std::vector<Vec3> area = nodal_area_vectors(slave_, now);
  for (Index k = 0; k < slave_.num_nodes(); ++k) {
    const std::optional<Projection>& p = slave_proj_[k];
    if (!active_.active(k) || !p)
      continue;
    // the slave node's motion over the step relative to the (material) master point it meets
    const Index node = slave_.nodes()[k];
    const Vec3 master_motion =
        master_.evaluate(p->facet, p->xi, now).x - master_.evaluate(p->facet, p->xi, before).x;
    const Vec3 relative = now(node) - before(node) - master_motion;
    const Vec3 tangential = relative - relative.dot(p->normal) * p->normal;
    slip_[k] += tangential.norm();
    Vec3 traction = Vec3::Zero(); // the friction multipliers: components 1-3
    for (int c = 1; c < law_->num_components(); ++c)
      if (const int axis = law_->work_axis(c); axis >= 0)
        traction[axis] = state.x[multiplier_dof(k, c)];
    dissipation_ -= traction.dot(tangential) * area[k].norm();
  }
}

Real ContactTerm::contact_area(const Vector& x) const {
  const NodePositions pos([this, &x](Index n) { return position(n, x); });
  const std::vector<Vec3> area = nodal_area_vectors(slave_, pos);
  Real sum = 0;
  for (Index k = 0; k < slave_.num_nodes(); ++k)
    if (active_.active(k))
      sum += area[k].norm();
  return sum;
}

} // namespace trifem::contact
