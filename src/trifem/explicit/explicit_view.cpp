// SPDX-License-Identifier: MIT
#include "trifem/explicit/explicit_view.hpp"

#include "trifem/core/error.hpp"
#include "trifem/fe/quadrature.hpp"
#include "trifem/linalg/nested_dissection.hpp"
#include "trifem/mesh/hex_faces.hpp"
#include "trifem/model/cell_families.hpp"
#include "trifem/model/model.hpp"
#include "trifem/parallel/communicator.hpp"
#include "trifem/tensor/rotation.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>

namespace trifem::explicit_dynamics {

void ExplicitView::check_cells(const model::Model& model) {
  for (Index c = 0; c < model.mesh.num_cells(); ++c) {
    const mesh::CellType type = model.mesh.cell_type(c);
    TRIFEM_CHECK(model.materials[static_cast<std::size_t>(c)].rigid() ||
                     (type != mesh::CellType::Tet4 && type != mesh::CellType::Penta6),
                 "analysis: a dynamic-explicit analysis holds the volume of every cell with one "
                 "multiplier, and the mesh has {}: tet4 and penta6 cells lock there (too stiff: "
                 "one volume per tet, or per triangle of a wedge). Mesh the body with tet10, hex20 "
                 "or hex8 cells",
                 model::describe_cell(model.mesh, c));
  }
}

ExplicitView::ExplicitView(const model::Model& model,
                           const std::vector<physics::MassElement>& shells)
    : model_(model), mesh_(model.mesh) {
  TRIFEM_CHECK(mesh_.num_cells() > 0, "explicit model: the mesh has no cells");
  for (const model::CellMaterial& m : model.materials)
    TRIFEM_CHECK(m.rigid() || (m.solid && !m.mixture && m.density > 0.0),
                 "materials.{}: dynamic-explicit analyses need a solid law with a density", m.name);
  TRIFEM_CHECK(model.connectors == nullptr,
               "dynamic-explicit analyses do not take rigid connectors (joints need the implicit "
               "solver)");
  check_cells(model);
  for (const dofs::DirichletCondition& c : model.problem->conditions())
    prescribed_motion_ =
        prescribed_motion_ || (!c.dofs.empty() && c.magnitude != 0.0) || static_cast<bool>(c.law) ||
        std::any_of(c.offsets.begin(), c.offsets.end(), [](Real offset) { return offset != 0.0; });
  build_geometry();
  build_mass();
  for (const physics::MassElement& shell : shells) // row sums: the lumped shell mass
    for (std::size_t a = 0; a < shell.nodes.size(); ++a)
      mass_.segment<3>(3 * shell.nodes[a]).array() +=
          shell.mass.row(static_cast<Eigen::Index>(a)).sum();
  fixed_.resize(num_dofs());
  local_.assign(model.dofs.num_dofs(), -1);
  for (Index a = 0; a < mesh_.num_nodes(); ++a)
    for (int k = 0; k < 3; ++k) {
      const Index i = 3 * a + k, dof = model.dofs.dof(model.fields.u, a, k);
      dofs_.push_back(dof);
      local_[dof] = i;
      fixed_[i] = model.problem->dof_map().is_constrained(dof) ? 1 : 0;
    }
  build_bodies();
  inverse_mass_.resize(num_dofs());
  free_mass_.resize(num_dofs());
  kinetic_mass_.resize(num_dofs());
  frequency_inverse_mass_.resize(num_dofs());
  std::vector<char> carried(num_dofs(), 0);
  for (const ExplicitBody& b : bodies_)
    for (Index a : b.nodes)
      for (int k = 0; k < 3; ++k)
        carried[3 * a + k] = b.moves[k] ? 1 : 0;
  for (Index i = 0; i < num_dofs(); ++i) {
    TRIFEM_CHECK(fixed_[i] || carried[i] || mass_[i] > 0.0,
                 "explicit model: node {} belongs to no cell", i / 3);
    const bool free = !fixed_[i] && !carried[i];
    inverse_mass_[i] = free ? 1.0 / mass_[i] : 0.0;
    free_mass_[i] = free ? mass_[i] : 0.0;
    kinetic_mass_[i] = fixed_[i] ? 0.0 : mass_[i];
    frequency_inverse_mass_[i] = fixed_[i] || mass_[i] == 0.0 ? 0.0 : 1.0 / mass_[i];
  }
  set_deformable();
  build_incidence();
  build_partition();
}

void ExplicitView::external_force(const Vector& U, Real time, Vector& f,
                                  const std::vector<BodyMotion>& motions,
                                  std::vector<BodyLoad>* loads) const {
  f.setZero(num_dofs());
  if (loads)
    loads->assign(bodies_.size(), BodyLoad{});
  if (model_.loads.empty())
    return;
  Vector x = Vector::Zero(model_.dofs.num_dofs());
  scatter_state(U, motions, time, x);
  const physics::EvalState state{x, x, time, 0.0};
  std::vector<Index> dofs;
  physics::LocalVector r;
  Vector generalized; // the loads on the bodies' unknowns
  for (const physics::Term* load : model_.loads)
    for (Index e = 0; e < load->num_elements(); ++e) {
      load->element_dofs(e, dofs);
      load->evaluate(e, state, r, nullptr);
      for (std::size_t j = 0; j < dofs.size(); ++j) {
        if (const Index i = local_[dofs[j]]; i >= 0) {
          f[i] -= r[static_cast<Eigen::Index>(j)];
          continue;
        }
        if (generalized.size() == 0)
          generalized = Vector::Zero(model_.dofs.num_dofs());
        generalized[dofs[j]] -= r[static_cast<Eigen::Index>(j)];
      }
    }
  if (loads && generalized.size() > 0)
    for (std::size_t b = 0; b < motions.size(); ++b)
      (*loads)[b] = applied_load(b, motions[b], generalized, x);
}

BodyLoad ExplicitView::applied_load(std::size_t b, const BodyMotion& motion,
                                    const Vector& generalized, const Vector& x) const {
  if (rotating_[b] < 0) // the forces on a body that only translates act on its nodes
    return {};
  const dofs::RigidBodyDofs& r =
      model_.problem->rigid_map().bodies()[static_cast<std::size_t>(rotating_[b])];
  Vec3 force, load_on_theta, theta; // Tᵀ M is the load on Θ of a moment M about the center
  for (int k = 0; k < 3; ++k) {
    force[k] = generalized[r.translation[k]];
    load_on_theta[k] = generalized[r.rotation[k]];
    theta[k] = x[r.rotation[k]];
  }
  const Vec3 moment = rotation::tangent(theta).transpose().partialPivLu().solve(load_on_theta);
  const ExplicitBody& body = bodies_[b];
  return {force, moment + (motion.R * (body.center - body.pivot)).cross(force)};
}

void ExplicitView::prescribe(Real time, Vector& U) const {
  Vector x = Vector::Zero(model_.dofs.num_dofs());
  dofs::prescribed_values(model_.problem->conditions(), time, x);
  model_.problem->rigid_map().apply(x); // the nodes of the bodies whose motion is prescribed
  for (Index i = 0; i < num_dofs(); ++i)
    if (fixed_[i])
      U[i] = x[dofs_[i]];
}

void ExplicitView::scatter_state(const Vector& U, const std::vector<BodyMotion>& motions, Real time,
                                 Vector& x) const {
  if (!model_.rigid_bodies.empty()) // the unknowns of the bodies that move as prescribed
    dofs::prescribed_values(model_.problem->conditions(), time, x);
  scatter(U, x);
  for (std::size_t b = 0; b < motions.size(); ++b)
    scatter_body(b, motions[b], x);
}

void ExplicitView::scatter(const Vector& v, Vector& x) const {
  for (Index i = 0; i < num_dofs(); ++i)
    x[dofs_[i]] = v[i];
}

Vector ExplicitView::gather(const Vector& x) const {
  Vector v(num_dofs());
  for (Index i = 0; i < num_dofs(); ++i)
    v[i] = x[dofs_[i]];
  return v;
}

const material::ElasticLaw& ExplicitView::law(Index c) const {
  return *model_.materials[c].solid;
}

Real ExplicitView::density(Index c) const {
  return model_.materials[c].density;
}

fe::HexCoords ExplicitView::hex8_values(Index c, const Vector& U) const {
  const mesh::Hex8& nodes = mesh_.cell(c);
  fe::HexCoords u;
  for (int a = 0; a < 8; ++a)
    u.row(a) = U.segment<3>(3 * nodes[a]).transpose();
  return u;
}

fe::CellNodeCoords ExplicitView::node_values(Index c, const Vector& U) const {
  const std::span<const Index> nodes = mesh_.cell_nodes(c);
  fe::CellNodeCoords u(static_cast<Index>(nodes.size()), 3);
  for (std::size_t a = 0; a < nodes.size(); ++a)
    u.row(static_cast<Index>(a)) = U.segment<3>(3 * nodes[a]).transpose();
  return u;
}

namespace {

/// The largest area of a face of cell c, each face taken as the flat face through its corners
/// (a triangle's, or a quadrilateral's by its diagonals).
Real largest_face_area(const mesh::Mesh& mesh, Index c) {
  const std::span<const Index> nodes = mesh.cell_nodes(c);
  const auto X = [&](int a) -> Vec3 { return mesh.node(nodes[static_cast<std::size_t>(a)]); };
  Real largest = 0.0;
  for (const mesh::CellFace& face : mesh::cell_faces(mesh.cell_type(c))) {
    const std::vector<int>& f = face.nodes;
    const Vec3 normal = mesh::num_corners(face.type) == 3
                            ? Vec3((X(f[1]) - X(f[0])).cross(X(f[2]) - X(f[0])))
                            : Vec3((X(f[2]) - X(f[0])).cross(X(f[3]) - X(f[1])));
    largest = std::max(largest, 0.5 * normal.norm());
  }
  return largest;
}

} // namespace

void ExplicitView::build_geometry() {
  const Index n = mesh_.num_cells();
  geometry_.clear();
  geometry_.reserve(static_cast<std::size_t>(n));
  volumes_.resize(n);
  lengths_.resize(n);
  cell_offsets_.assign(1, 0);
  for (Index c = 0; c < n; ++c) {
    try {
      geometry_.push_back(physics::reference_geometry(mesh_, c));
    } catch (const InputError&) {
      throw InputError(
          fmt::format("explicit model: {} is inverted or degenerate", mesh_.describe(c)));
    }
    Real volume = 0.0;
    std::visit(
        [&](const auto& geo) {
          for (Real dV : geo.dV)
            volume += dV;
        },
        geometry_.back());
    volumes_[c] = volume;
    lengths_[c] = volume / largest_face_area(mesh_, c);
    cell_offsets_.push_back(cell_offsets_.back() +
                            3 * static_cast<Index>(mesh_.cell_nodes(c).size()));
  }
}

void ExplicitView::build_mass() {
  const auto& rule = fe::hex_gauss_2x2x2();
  Vector nodal = Vector::Zero(mesh_.num_nodes());
  for (Index c = 0; c < mesh_.num_cells(); ++c) {
    const Real rho = density(c);
    if (const auto* hex = std::get_if<fe::HexGeometry>(&geometry_[c])) {
      for (int q = 0; q < 8; ++q) {
        const fe::HexShape N = fe::hex8_shape(rule[q].xi);
        for (int a = 0; a < 8; ++a)
          nodal[mesh_.cell(c)[a]] += rho * N[a] * hex->dV[q];
      }
      continue;
    }
    const Eigen::VectorXd m = physics::lumped_mass(
        physics::consistent_cell_mass(std::get<physics::CellGeometry>(geometry_[c]), rho));
    const std::span<const Index> nodes = mesh_.cell_nodes(c);
    for (std::size_t a = 0; a < nodes.size(); ++a)
      nodal[nodes[a]] += m[static_cast<Index>(a)];
  }
  mass_.resize(num_dofs());
  for (Index a = 0; a < mesh_.num_nodes(); ++a)
    mass_.segment<3>(3 * a).setConstant(nodal[a]);
}

void ExplicitView::build_partition() {
  if (!parallel::active())
    return;
  const Index nn = mesh_.num_nodes();
  rank_ = parallel::rank();
  node_owner_.assign(nn, 0);
  if (parallel::is_root()) { // the node graph: nodes sharing a cell
    std::vector<Index> start = {0}, column;
    for (Index a = 0; a < nn; ++a) {
      const auto first = static_cast<std::ptrdiff_t>(column.size());
      for (Index i = incidence_.offsets[a]; i < incidence_.offsets[a + 1]; ++i)
        for (Index b : mesh_.cell_nodes(incidence_.entries[i].first))
          column.push_back(b);
      std::sort(column.begin() + first, column.end());
      column.erase(std::unique(column.begin() + first, column.end()), column.end());
      start.push_back(static_cast<Index>(column.size()));
    }
    node_owner_ = linalg::partition_rows({nn, start.data(), column.data()}, parallel::size());
  }
  parallel::broadcast(node_owner_);
  const Index n = mesh_.num_cells();
  cell_owner_.resize(n);
  evaluated_.assign(n, 0);
  for (Index c = 0; c < n; ++c) {
    cell_owner_[c] = node_owner_[mesh_.cell_nodes(c)[0]];
    for (Index a : mesh_.cell_nodes(c))
      evaluated_[c] = evaluated_[c] || node_owner_[a] == rank_;
  }
}

void ExplicitView::build_incidence() {
  const Index nn = mesh_.num_nodes();
  incidence_.offsets.assign(nn + 1, 0);
  for (Index c = 0; c < mesh_.num_cells(); ++c)
    for (Index a : mesh_.cell_nodes(c))
      ++incidence_.offsets[a + 1];
  for (Index a = 0; a < nn; ++a)
    incidence_.offsets[a + 1] += incidence_.offsets[a];
  incidence_.entries.resize(incidence_.offsets[nn]);
  std::vector<Index> next(incidence_.offsets.begin(), incidence_.offsets.end() - 1);
  for (Index c = 0; c < mesh_.num_cells(); ++c) { // increasing c: entries sorted by cell
    const std::span<const Index> nodes = mesh_.cell_nodes(c);
    for (std::size_t l = 0; l < nodes.size(); ++l)
      incidence_.entries[next[nodes[l]]++] = {c, static_cast<int>(l)};
  }
}

} // namespace trifem::explicit_dynamics

namespace trifem::explicit_dynamics {
namespace {

const char* const kAxes = "xyz";

/// The free component of a rotation held in the other two, or −1 if not exactly one is free.
int single_free_axis(const std::array<bool, 3>& held) {
  int axis = -1, free = 0;
  for (int k = 0; k < 3; ++k)
    if (!held[k]) {
      axis = k;
      ++free;
    }
  return free == 1 ? axis : -1;
}

/// true if `rigid` moves under its loads in some component (its motion is not wholly
/// prescribed in the model's current step).
bool moves_itself(const model::Model& model, const model::RigidBody& rigid) {
  const auto constrained = [&](Index dof) { return model.problem->dof_map().is_constrained(dof); };
  if (rigid.rotating < 0) {
    for (int k = 0; k < 3; ++k)
      if (rigid.tied[k] && !constrained(rigid.dofs[k].front()))
        return true;
    return false;
  }
  const dofs::RigidBodyDofs& r =
      model.problem->rigid_map().bodies()[static_cast<std::size_t>(rigid.rotating)];
  return !std::all_of(r.translation.begin(), r.translation.end(), constrained) ||
         !std::all_of(r.rotation.begin(), r.rotation.end(), constrained);
}

} // namespace

std::size_t ExplicitView::count_bodies(const model::Model& model) {
  return static_cast<std::size_t>(
      std::count_if(model.rigid_bodies.begin(), model.rigid_bodies.end(),
                    [&](const model::RigidBody& b) { return moves_itself(model, b); }));
}

void ExplicitView::build_bodies() {
  carrier_.assign(mesh_.num_nodes(), -1);
  for (std::size_t i = 0; i < model_.rigid_bodies.size(); ++i) {
    const model::RigidBody& rigid = model_.rigid_bodies[i];
    if (rigid.tied == std::array<bool, 3>{true, true, true})
      for (Index d : rigid.dofs[0])
        carrier_[local_[d] / 3] = static_cast<Index>(i);
    if (rigid.rotating >= 0)
      add_rotating_body(rigid);
    else if (moves_itself(model_, rigid))
      add_translating_body(rigid);
  }
}

void ExplicitView::add_rotating_body(const model::RigidBody& rigid) {
  const dofs::RigidBodyDofs& r =
      model_.problem->rigid_map().bodies()[static_cast<std::size_t>(rigid.rotating)];
  std::array<bool, 3> driven{}, held{};
  for (int k = 0; k < 3; ++k) {
    driven[k] = model_.problem->dof_map().is_constrained(r.translation[k]);
    held[k] = model_.problem->dof_map().is_constrained(r.rotation[k]);
  }
  const std::array<bool, 3> all{true, true, true};
  if (!moves_itself(model_, rigid)) { // its nodes are constrained DOFs (prescribe())
    for (const auto& follower : r.followers)
      for (Index d : follower)
        fixed_[local_[d]] = 1;
    return;
  }
  ExplicitBody body;
  body.name = rigid.name;
  body.moves = all;
  body.driven = driven;
  body.center = r.centre;
  for (const auto& follower : r.followers)
    body.nodes.push_back(local_[follower[0]] / 3);
  if (held == std::array<bool, 3>{false, false, false})
    body.rotation = BodyRotation::Free;
  else if (held == all)
    body.rotation = BodyRotation::Prescribed;
  else if ((body.axis = single_free_axis(held)) >= 0)
    body.rotation = BodyRotation::Axis;
  else
    throw InputError(fmt::format(
        "rigid body '{}': a dynamic-explicit step takes a rotation that is free, prescribed in "
        "all three components, or free about one axis (the other two held at 0)",
        rigid.name));
  set_mass_properties(body, driven == all);
  const std::array<bool, 3> none{};
  TRIFEM_CHECK(
      driven == all || driven == none ||
          (body.center - body.pivot).norm() <= 1e-9 * model_.length_scale,
      "rigid body '{}': a dynamic-explicit step drives the translation of a body in all three "
      "components or in none, unless its center is its center of mass (here {:.6g} mm apart)",
      rigid.name, (body.center - body.pivot).norm());
  rotating_.push_back(rigid.rotating);
  leaders_.push_back({-1, -1, -1});
  bodies_.push_back(std::move(body));
}

void ExplicitView::add_translating_body(const model::RigidBody& rigid) {
  ExplicitBody body;
  body.name = rigid.name;
  std::array<Index, 3> leaders{-1, -1, -1};
  for (int k = 0; k < 3; ++k) {
    if (!rigid.tied[k] || model_.problem->dof_map().is_constrained(rigid.dofs[k].front()))
      continue; // a prescribed component: its DOFs are constrained
    body.moves[k] = true;
    leaders[k] = rigid.dofs[k].front();
    if (body.nodes.empty())
      for (Index d : rigid.dofs[k])
        body.nodes.push_back(local_[d] / 3);
  }
  set_mass_properties(body, false);
  rotating_.push_back(-1);
  leaders_.push_back(leaders);
  bodies_.push_back(std::move(body));
}

void ExplicitView::set_mass_properties(ExplicitBody& body, bool center_is_pivot) const {
  Vec3 first_moment = Vec3::Zero();
  for (Index a : body.nodes) {
    body.mass += mass_[3 * a];
    first_moment += mass_[3 * a] * mesh_.node(a);
  }
  TRIFEM_CHECK(body.mass > 0.0,
               "rigid body '{}' has no mass: a dynamic-explicit step needs the mass of its nodes "
               "(give its cells or shells a density, or carry nodes of tissue cells)",
               body.name);
  const Vec3 mass_center = first_moment / body.mass;
  body.pivot = center_is_pivot ? body.center : mass_center;
  body.offset = mass_center - body.pivot;
  for (Index a : body.nodes) {
    const Vec3 arm = mesh_.node(a) - body.pivot;
    body.arms.push_back(arm);
    body.inertia += mass_[3 * a] * (arm.squaredNorm() * Mat3::Identity() - arm * arm.transpose());
  }
  if (body.rotation == BodyRotation::Free) {
    const Real smallest = body.inertia.selfadjointView<Eigen::Lower>().eigenvalues().minCoeff();
    TRIFEM_CHECK(smallest > 1e-12 * body.inertia.trace(),
                 "rigid body '{}': its nodes lie on a line, so it has no inertia about that line "
                 "(hold that rotation, or give it nodes off the line)",
                 body.name);
  }
  if (body.rotation == BodyRotation::Axis)
    TRIFEM_CHECK(body.inertia(body.axis, body.axis) > 0.0,
                 "rigid body '{}': its nodes lie on its axis of rotation {} (no inertia)",
                 body.name, kAxes[body.axis]);
}

void ExplicitView::set_deformable() {
  deformable_.assign(static_cast<std::size_t>(mesh_.num_cells()), 0);
  for (Index c = 0; c < mesh_.num_cells(); ++c) {
    const std::span<const Index> nodes = mesh_.cell_nodes(c);
    const Index carrier = carrier_[nodes[0]];
    const bool carried = carrier >= 0 && std::all_of(nodes.begin(), nodes.end(), [&](Index a) {
                           return carrier_[a] == carrier;
                         });
    deformable_[c] = model_.materials[c].solid && !carried ? 1 : 0;
  }
}

BodyTarget ExplicitView::target(std::size_t b, Real time) const {
  BodyTarget t;
  if (rotating_[b] < 0)
    return t; // a body that only translates has no driven component
  const ExplicitBody& body = bodies_[b];
  const dofs::RigidBodyDofs& r =
      model_.problem->rigid_map().bodies()[static_cast<std::size_t>(rotating_[b])];
  Vector x = Vector::Zero(model_.dofs.num_dofs());
  dofs::prescribed_values(model_.problem->conditions(), time, x);
  Vec3 theta;
  for (int k = 0; k < 3; ++k) {
    t.u[k] = x[r.translation[k]];
    theta[k] = x[r.rotation[k]];
  }
  if (body.rotation == BodyRotation::Axis)
    for (int k = 0; k < 3; ++k)
      TRIFEM_CHECK(k == body.axis || theta[k] == 0.0,
                   "rigid body '{}': at t = {:.6g} s its rotation about {} is prescribed to {:.6g} "
                   "rad; a dynamic-explicit step turns a body about one axis with the other two "
                   "rotations held at 0",
                   body.name, time, kAxes[k], theta[k]);
  if (body.rotation == BodyRotation::Prescribed) {
    t.R = rotation::matrix(theta);
    t.u += (t.R - Mat3::Identity()) * (body.pivot - body.center);
  }
  return t;
}

BodyMotion ExplicitView::motion(std::size_t b, const Vector& x, const Vector& v) const {
  const ExplicitBody& body = bodies_[b];
  BodyMotion m;
  if (rotating_[b] < 0) {
    for (int k = 0; k < 3; ++k)
      if (body.moves[k]) {
        m.u[k] = x[leaders_[b][k]];
        m.v[k] = v.size() > 0 ? v[leaders_[b][k]] : 0.0;
      }
    m.mass_velocity = m.v;
    return m;
  }
  const dofs::RigidBodyDofs& r =
      model_.problem->rigid_map().bodies()[static_cast<std::size_t>(rotating_[b])];
  Vec3 uc, theta, vc = Vec3::Zero(), theta_rate = Vec3::Zero();
  for (int k = 0; k < 3; ++k) {
    uc[k] = x[r.translation[k]];
    theta[k] = x[r.rotation[k]];
    if (v.size() > 0) {
      vc[k] = v[r.translation[k]];
      theta_rate[k] = v[r.rotation[k]];
    }
  }
  m.R = rotation::matrix(theta);
  m.u = uc + (m.R - Mat3::Identity()) * (body.pivot - body.center);
  const Vec3 omega = rotation::tangent(theta) * theta_rate;
  m.v = vc + omega.cross(m.R * (body.pivot - body.center));
  m.L = body.rotation == BodyRotation::Axis
            ? Vec3(body.inertia(body.axis, body.axis) * omega[body.axis] * Vec3::Unit(body.axis))
            : Vec3(m.R * body.inertia * m.R.transpose() * omega);
  m.mass_velocity = m.v + omega.cross(m.R * body.offset);
  return m;
}

void ExplicitView::scatter_body(std::size_t b, const BodyMotion& motion, Vector& x) const {
  if (rotating_[b] < 0)
    return;
  const ExplicitBody& body = bodies_[b];
  const dofs::RigidBodyDofs& r =
      model_.problem->rigid_map().bodies()[static_cast<std::size_t>(rotating_[b])];
  const Vec3 uc = motion.u + (motion.R - Mat3::Identity()) * (body.center - body.pivot);
  const Vec3 theta = rotation::vector(motion.R);
  for (int k = 0; k < 3; ++k) {
    x[r.translation[k]] = uc[k];
    x[r.rotation[k]] = theta[k];
  }
}

void ExplicitView::scatter_body_velocity(std::size_t b, const BodyMotion& motion,
                                         const Vec3& pivot_velocity, const Vec3& omega,
                                         Vector& v) const {
  if (rotating_[b] < 0)
    return;
  const ExplicitBody& body = bodies_[b];
  const dofs::RigidBodyDofs& r =
      model_.problem->rigid_map().bodies()[static_cast<std::size_t>(rotating_[b])];
  const Vec3 vc = pivot_velocity + omega.cross(motion.R * (body.center - body.pivot));
  const Vec3 theta_rate = rotation::tangent(rotation::vector(motion.R)).partialPivLu().solve(omega);
  for (int k = 0; k < 3; ++k) {
    v[r.translation[k]] = vc[k];
    v[r.rotation[k]] = theta_rate[k];
  }
}

} // namespace trifem::explicit_dynamics
