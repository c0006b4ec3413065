// SPDX-License-Identifier: MIT
#include "trifem/contact/contact_term.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace trifem::contact {
namespace {

/// Row weights of the nodes of facet X (reference; tributary_area()): ∫ N_a dA on linear
/// facets, the facet area shared in proportion to ∫ N_a² dA on quadratic ones.
fe::FacetShapeValues nodal_areas(const FacetCoords& X) {
  const Index n = X.num_nodes();
  fe::FacetShapeValues w = fe::FacetShapeValues::Zero(n), w2 = fe::FacetShapeValues::Zero(n);
  Real area = 0;
  for (const auto& qp : X.reference->rule().points) {
    const FacetPoint fp = evaluate_facet(X, qp.xi);
    const Real da = fp.jacobian * qp.weight;
    w += fp.N * da;
    w2 += fp.N.cwiseAbs2() * da;
    area += da;
  }
  if (X.reference->order() == 1)
    return w;
  return w2 * (area / w2.sum());
}

void check_disjoint(const ContactSurface& master, const ContactSurface& slave) {
  TRIFEM_CHECK(master.num_facets() > 0, "contact: the master surface is empty");
  TRIFEM_CHECK(slave.num_facets() > 0, "contact: the slave surface is empty");
  std::vector<Index> common;
  std::set_intersection(master.nodes().begin(), master.nodes().end(), slave.nodes().begin(),
                        slave.nodes().end(), std::back_inserter(common));
  TRIFEM_CHECK(common.empty(),
               "contact: master and slave surfaces share {} node(s) (e.g. node {}); they must "
               "belong to different bodies",
               common.size(), common.empty() ? -1 : common.front());
}

} // namespace

ContactTerm::ContactTerm(const mesh::Mesh& mesh, const dofs::DofMap& dofs,
                         dofs::FieldId displacement, dofs::FieldId multiplier,
                         const mesh::Surface& master, const mesh::Surface& slave,
                         std::shared_ptr<const ContactLaw> law, ContactSettings settings)
    : mesh_(mesh), dofs_(dofs), u_(displacement), lambda_(multiplier), master_(master),
      slave_(slave), law_(std::move(law)), settings_(settings),
      active_(slave_.num_nodes(), ActiveSetSettings{}),
      committed_active_(slave_.num_nodes(), ActiveSetSettings{}) {
  check_disjoint(master_, slave_);
  TRIFEM_CHECK(law_ != nullptr, "contact: no contact law given");
  const dofs::FieldInfo& info = dofs.field(lambda_);
  TRIFEM_CHECK(info.num_entities == slave_.num_nodes() && info.components == law_->num_components(),
               "contact: the multiplier field '{}' must have {} entities (slave nodes) with {} "
               "component(s), not {} with {}",
               info.name, slave_.num_nodes(), law_->num_components(), info.num_entities,
               info.components);
  TRIFEM_CHECK(settings_.scale > 0, "contact: the scale c_N = {} must be > 0 (≈ E/h)",
               settings_.scale);
  bool corner_fields = false;
  for (int c = 0; c < law_->num_components(); ++c)
    corner_fields = corner_fields || law_->corner_interpolated(c);
  TRIFEM_CHECK(!(corner_fields && settings_.integration == Integration::SlaveNodes &&
                 (master_.has_quadratic_facets() || slave_.has_quadratic_facets())),
               "contact: the slave-node integration of the {} law takes linear facets only "
               "(its fields are linear from the corners of quadratic facets)",
               law_->name());
  for (int c = 0; c < law_->num_components(); ++c)
    if (std::find(paired_.begin(), paired_.end(), law_->paired_field(c)) == paired_.end())
      paired_.push_back(law_->paired_field(c));
  area_.assign(slave_.num_nodes(), 0.0);
  for (Index f = 0; f < slave_.num_facets(); ++f) {
    const auto nodes = slave_.facet_nodes(f);
    const fe::FacetShapeValues w = nodal_areas(slave_.coords(f, mesh.nodes()));
    std::array<Index, fe::kMaxFacetNodes> k{};
    k.fill(-1);
    for (std::size_t a = 0; a < nodes.size(); ++a) {
      k[a] = slave_.local_node(nodes[a]);
      area_[k[a]] += w[static_cast<Index>(a)];
    }
    slave_facet_k_.push_back(k);
  }
  resolve_defaults();
  committed_active_ = active_;
  project_all(Vector::Zero(dofs.num_dofs()));
  committed_projected_ = admissible_projections();
  rebuild_stencils();
}

void ContactTerm::resolve_defaults() {
  Real sum = 0;
  for (const ContactSurface* s : {&master_, &slave_})
    for (Index f = 0; f < s->num_facets(); ++f)
      sum += facet_size(s->coords(f, mesh_.nodes()));
  h_ = sum / (master_.num_facets() + slave_.num_facets());
  if (settings_.search_distance <= 0)
    settings_.search_distance = 0.5 * h_;
  if (settings_.release_threshold < 0)
    settings_.release_threshold = 1e-8 * settings_.scale * h_;
  if (settings_.gap_tolerance < 0)
    settings_.gap_tolerance = 1e-6 * h_;
  active_.settings() = {settings_.release_threshold, settings_.gap_tolerance,
                        settings_.max_active_set_updates, settings_.max_active_set_resolves,
                        settings_.update_active_set};
}

std::pair<ContactTerm::Kind, Index> ContactTerm::locate(Index e) const {
  const Index ns = slave_.num_facets();
  if (e < ns)
    return {Kind::SlaveFacet, e};
  e -= ns;
  if (settings_.integration == Integration::BothSurfaces) {
    if (e < master_.num_facets())
      return {Kind::MasterFacet, e};
    e -= master_.num_facets();
  }
  return {Kind::SlaveNode, e};
}

Vec3 ContactTerm::position(Index node, const Vector& x) const {
  return mesh_.node(node) + Vec3(x[u_dof(node, 0)], x[u_dof(node, 1)], x[u_dof(node, 2)]);
}

FacetCoords ContactTerm::coords(const ContactSurface& surface, Index f, const Vector& x) const {
  return surface.coords(f, NodePositions([this, &x](Index n) { return position(n, x); }));
}

FacetMultipliers ContactTerm::facet_multipliers(Index f, const Vector& x) const {
  const int C = law_->num_components();
  const auto n = static_cast<Index>(slave_.facet_nodes(f).size());
  FacetMultipliers lam(n, C);
  for (Index a = 0; a < n; ++a)
    for (int c = 0; c < C; ++c)
      lam(a, c) = x[multiplier_dof(slave_facet_k_[f][static_cast<std::size_t>(a)], c)];
  return lam;
}

void ContactTerm::project_all(const Vector& x) {
  const NodePositions pos([this, &x](Index n) { return position(n, x); });
  ProjectionOptions options;
  options.xi_tolerance = settings_.xi_tolerance;
  options.free_edge_tolerance = settings_.slave_free_edge_tolerance;
  options.search_distance = settings_.search_distance;
  const BucketSearch on_master(master_, pos, settings_.search_distance);
  slave_proj_ = project_nodes(slave_.nodes(), master_, pos, on_master, options);
  master_proj_.assign(master_.num_nodes(), std::nullopt);
  if (settings_.integration == Integration::BothSurfaces) {
    const BucketSearch on_slave(slave_, pos, settings_.search_distance);
    options.xi_tolerance = settings_.master_xi_tolerance;
    master_proj_ = project_nodes(master_.nodes(), slave_, pos, on_slave, options);
  }
}

std::vector<char> ContactTerm::admissible_projections() const {
  std::vector<char> flags(slave_.num_nodes(), 0);
  for (Index k = 0; k < slave_.num_nodes(); ++k)
    flags[k] = slave_proj_[k] && !slave_proj_[k]->on_free_boundary ? 1 : 0;
  return flags;
}

void ContactTerm::update_active_set(const physics::EvalState& state) {
  std::vector<NodeStatus> status(slave_.num_nodes());
  for (Index k = 0; k < slave_.num_nodes(); ++k) {
    const auto& pr = slave_proj_[k];
    if (!pr || pr->on_free_boundary)
      continue;
    SlaveNodeRows node;
    describe_node(k, state, node);
    status[k] = {true,
                 pr->gap,
                 law_->indicator(node),
                 law_->wettable(),
                 law_->frictional(),
                 law_->frictional() ? law_->slip_indicator(node) : 0.0};
  }
  active_.update(state.time, status);
}

bool ContactTerm::prepare(const physics::EvalState& state) {
  project_all(state.x);
  update_active_set(state);
  return rebuild_stencils();
}

void ContactTerm::commit(const physics::EvalState& state) {
  if (law_->frictional())
    accumulate_slip(state);
  active_.commit();
  committed_active_ = active_;
  committed_projected_ = admissible_projections();
  committed_pressure_.assign(slave_.num_nodes(), 0.0);
  for (Index k = 0; k < slave_.num_nodes(); ++k)
    if (active_.active(k))
      committed_pressure_[k] = std::abs(state.x[multiplier_dof(k, 0)]);
}

std::vector<double> ContactTerm::history() const {
  const Index n = slave_.num_nodes();
  std::vector<double> out(3 * static_cast<std::size_t>(n), 0.0);
  for (Index k = 0; k < n; ++k) {
    out[3 * k] = committed_active_.flags()[k];
    out[3 * k + 1] =
        k < static_cast<Index>(committed_projected_.size()) ? committed_projected_[k] : 0;
    out[3 * k + 2] =
        k < static_cast<Index>(committed_pressure_.size()) ? committed_pressure_[k] : 0;
  }
  if (law_->frictional()) {
    for (Index k = 0; k < n; ++k)
      out.push_back(accumulated_slip(k));
    out.push_back(dissipation_);
  }
  return out;
}

void ContactTerm::restore_history(const std::vector<double>& values) {
  const Index n = slave_.num_nodes();
  // a frictional pair's slips and dissipation follow (absent from files written before them)
  const std::size_t with_slips = law_->frictional() ? 4 * static_cast<std::size_t>(n) + 1 : 0;
  TRIFEM_CHECK(values.size() == 3 * static_cast<std::size_t>(n) || values.size() == with_slips,
               "the restart file holds {} contact history values, this contact pair needs {}",
               values.size(), law_->frictional() ? with_slips : 3 * static_cast<std::size_t>(n));
  if (values.size() == with_slips) {
    slip_.assign(values.begin() + 3 * n, values.begin() + 4 * n);
    dissipation_ = values.back();
    TRIFEM_CHECK(std::isfinite(dissipation_) &&
                     std::all_of(slip_.begin(), slip_.end(),
                                 [](Real s) { return std::isfinite(s) && s >= 0.0; }),
                 "the restart file holds an invalid accumulated slip or frictional dissipation");
  }
  std::vector<char> flags(n);
  committed_projected_.assign(n, 0);
  committed_pressure_.assign(n, 0.0);
  for (Index k = 0; k < n; ++k) {
    const Real status = values[3 * k], projected = values[3 * k + 1];
    TRIFEM_CHECK((status == 0 || status == 1 || status == 2 || status == 3) &&
                     (projected == 0 || projected == 1) && std::isfinite(values[3 * k + 2]),
                 "the restart file holds an invalid contact state of slave node {} (status {}, "
                 "projected {}, pressure {})",
                 k, status, projected, values[3 * k + 2]);
    flags[k] = static_cast<char>(status);
    committed_projected_[k] = static_cast<char>(projected);
    committed_pressure_[k] = values[3 * k + 2];
  }
  active_.assign(flags);
  active_.commit();
  committed_active_ = active_;
}

std::string ContactTerm::step_rejection(const physics::EvalState& state) const {
  if (active_.pending() > 0)
    return fmt::format("the contact status of {} slave node(s) did not settle within the step",
                       active_.pending());
  return crossing_rejection(state);
}

std::string ContactTerm::step_caution(const physics::EvalState& /*state*/) const {
  if (committed_pressure_.empty())
    return {};
  const Real peak = *std::max_element(committed_pressure_.begin(), committed_pressure_.end());
  for (Index k = 0; k < slave_.num_nodes(); ++k) {
    const auto& pr = slave_proj_[k];
    if (committed_pressure_[k] > kReleaseFraction * peak && peak > 0 &&
        (!pr || pr->on_free_boundary))
      return fmt::format("slave node {} (reference position {:.4g} {:.4g} {:.4g}) left the "
                         "master surface while carrying {:.0f}% of the peak contact pressure",
                         slave_.nodes()[k], mesh_.node(slave_.nodes()[k]).x(),
                         mesh_.node(slave_.nodes()[k]).y(), mesh_.node(slave_.nodes()[k]).z(),
                         100.0 * committed_pressure_[k] / peak);
  }
  return {};
}

void ContactTerm::add_node_dofs(Index node, bool rows, std::vector<Index>& dofs) const {
  for (int i = 0; i < 3; ++i)
    dofs.push_back(u_dof(node, i));
  if (!rows)
    return;
  for (dofs::FieldId f : paired_)
    if (f != u_)
      for (int i = 0; i < 3; ++i)
        dofs.push_back(dofs_.dof(f, node, i));
}

void ContactTerm::stencil_of(Kind kind, Index i, std::vector<Index>& dofs) const {
  const int C = law_->num_components();
  const auto add_lambda = [&](Index k) {
    for (int c = 0; c < C; ++c)
      dofs.push_back(multiplier_dof(k, c));
  };
  dofs.clear();
  if (kind == Kind::SlaveFacet) {
    const auto facet_nodes = slave_.facet_nodes(i);
    for (std::size_t a = 0; a < facet_nodes.size(); ++a) {
      add_node_dofs(facet_nodes[a], true, dofs);
      add_lambda(slave_facet_k_[i][a]);
      const auto& pr = slave_proj_[slave_facet_k_[i][a]];
      if (settings_.integration == Integration::SlaveNodes && pr)
        for (Index q : master_.facet_nodes(pr->facet))
          add_node_dofs(q, true, dofs);
    }
  } else if (kind == Kind::MasterFacet) {
    for (Index m : master_.facet_nodes(i)) {
      add_node_dofs(m, true, dofs);
      const auto& pr = master_proj_[master_.local_node(m)];
      if (!pr)
        continue;
      const auto slave_nodes = slave_.facet_nodes(pr->facet);
      for (std::size_t b = 0; b < slave_nodes.size(); ++b) {
        add_node_dofs(slave_nodes[b], false, dofs);
        add_lambda(slave_facet_k_[pr->facet][b]);
      }
    }
  } else {
    add_lambda(i);
    std::vector<Index> nodes{slave_.nodes()[i]};
    if (const auto& pr = slave_proj_[i]) {
      const auto master_nodes = master_.facet_nodes(pr->facet);
      nodes.insert(nodes.end(), master_nodes.begin(), master_nodes.end());
    }
    for (Index n : nodes) {
      add_node_dofs(n, false, dofs);
      for (dofs::FieldId f : law_->constraint_fields())
        for (int c = 0; c < 3; ++c)
          dofs.push_back(dofs_.dof(f, n, c));
    }
  }
  std::sort(dofs.begin(), dofs.end());
  dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
}

bool ContactTerm::rebuild_stencils() {
  Index n = slave_.num_facets() + slave_.num_nodes();
  if (settings_.integration == Integration::BothSurfaces)
    n += master_.num_facets();
  const bool resized = static_cast<Index>(stencils_.size()) != n;
  stencils_.resize(n);
  bool changed = resized;
  std::vector<Index> dofs;
  for (Index e = 0; e < n; ++e) {
    const auto [kind, i] = locate(e);
    stencil_of(kind, i, dofs);
    if (dofs != stencils_[e]) {
      stencils_[e] = dofs;
      changed = true;
    }
  }
  return changed;
}

bool ContactTerm::evaluate(Index e, const physics::EvalState& state, physics::LocalVector& r,
                           physics::LocalMatrix* K) const {
  LocalSystem out(stencils_[e], r, K);
  const auto [kind, i] = locate(e);
  if (kind == Kind::SlaveNode)
    slave_node_rows(i, state, out);
  else if (kind == Kind::MasterFacet)
    master_facet_work(i, state.x, state.dt, out);
  else if (settings_.integration == Integration::SlaveNodes)
    slave_point_forces(i, state.x, state.dt, out);
  else
    slave_facet_work(i, state.x, state.dt, out);
  return true;
}

void ContactTerm::describe_node(Index k, const physics::EvalState& state,
                                SlaveNodeRows& node) const {
  node.slave = k;
  node.state = &state;
  node.dofs = &dofs_;
  node.weight = area_[k];
  node.scale = settings_.scale;
  node.dt = state.dt;
  node.multiplier.resize(law_->num_components());
  for (int c = 0; c < law_->num_components(); ++c)
    node.multiplier[c] = state.x[multiplier_dof(k, c)];
  node.wetted = active_.wetted(k);
  node.slipping = active_.slipping(k);
  node.mid_edge = slave_.is_mid_edge_node(k);
  const auto& pr = slave_proj_[k];
  if (!pr) {
    node.nodes.nodes[0] = slave_.nodes()[k];
    node.nodes.size = 1;
    return;
  }
  node.nodes = stencil_nodes(slave_.nodes()[k], master_, pr->facet);
  node.projection = &*pr;
  node.facet_type = master_.facet_type(pr->facet);
  if (!law_->frictional())
    return; // the slip data below is for frictional laws only
  for (int j = 0; j < node.nodes.size; ++j)
    node.x_old[static_cast<std::size_t>(j)] = position(node.nodes[j], state.x_old);
  // held: the slave node is held in i, and the master facet's nodes are held in i or carried by
  // a rigid body (held in i in the models this rule is for: plane strain)
  const dofs::DofMap& current = state.dofs ? *state.dofs : dofs_;
  for (int i = 0; i < 3; ++i) {
    bool held = current.is_constrained(u_dof(node.nodes[0], i));
    for (int j = 1; j < node.nodes.size && held; ++j) {
      const Index dof = u_dof(node.nodes[j], i);
      held = current.is_constrained(dof) || current.is_dependent(dof);
    }
    node.held[static_cast<std::size_t>(i)] = held;
  }
}

void ContactTerm::slave_node_rows(Index k, const physics::EvalState& state,
                                  LocalSystem& out) const {
  SlaveNodeRows node;
  describe_node(k, state, node);
  node.lambda_at = out.at(multiplier_dof(k, 0));
  for (int j = 0; j < node.nodes.size; ++j)
    node.x_at[j] = out.at(u_dof(node.nodes[j], 0));
  const auto& pr = slave_proj_[k];
  ProjectionDerivatives d;
  if (active_.active(k) && pr && !pr->on_free_boundary) {
    d = projection_derivatives(*pr, coords(master_, pr->facet, state.x));
    node.derivatives = &d;
    law_->active_rows(node, out);
  } else {
    law_->inactive_rows(node, out);
  }
}

} // namespace trifem::contact
