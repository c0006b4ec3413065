// SPDX-License-Identifier: MIT
#include "trifem/model/rigid_bodies.hpp"

#include "trifem/fe/hex8.hpp"
#include "trifem/model/conditions.hpp"
#include "trifem/model/rigid_connectors.hpp"
#include "trifem/physics/rigid_moment_term.hpp"
#include "trifem/physics/solid_cell.hpp"
#include "trifem/tensor/rotation.hpp"

#include <set>

namespace trifem::model {
namespace {

/// DOFs already constrained by `conditions`, for conflict messages.
std::set<Index> constrained_dofs(const std::vector<dofs::DirichletCondition>& conditions) {
  std::set<Index> out;
  for (const auto& c : conditions)
    out.insert(c.dofs.begin(), c.dofs.end());
  return out;
}

/// What the bodies collect while they are built.
struct Collected {
  std::set<Index> constrained; ///< by the other conditions
  std::set<Index> used;        ///< by a body
  std::vector<physics::NodalForce> forces;
  std::vector<physics::RigidMoment> moments;
  std::vector<physics::RigidFollowerLoad> followers;
  std::vector<dofs::RigidBodyDofs> rotating;
};

/// Registers displacement DOF `d` of node `n` with body `b`, or says why it cannot be.
void claim(const io::RigidBodySpec& b, const Model& model, Index n, int k, Index d, Collected& c) {
  TRIFEM_CHECK(c.used.insert(d).second, "{}: node {} belongs to two rigid bodies", b.key, n);
  TRIFEM_CHECK(!c.constrained.contains(d),
               "{}: component {} of node {} (at {:.6g} {:.6g} {:.6g}) of set '{}' is also "
               "constrained by a boundary condition; drive the rigid body's {} instead "
               "(e.g. {}.{} = {{ displacement = 0.0 }})",
               b.key, "xyz"[k], n, model.mesh.node(n).x(), model.mesh.node(n).y(),
               model.mesh.node(n).z(), b.set, "xyz"[k], b.key, "xyz"[k]);
}

/// A body that only translates: ties, prescribed components and forces.
RigidBody translating_body(const io::CaseSpec& spec, const io::RigidBodySpec& b, Model& model,
                           const std::vector<Index>& nodes, Collected& c,
                           std::vector<dofs::DirichletCondition>& conditions) {
  RigidBody body;
  body.name = b.name;
  for (int k : b.components) {
    const io::RigidComponentSpec& drive = b.drives[k];
    for (Index n : nodes) {
      const Index d = model.dofs.dof(model.fields.u, n, k);
      claim(b, model, n, k, d, c);
      body.dofs[k].push_back(d);
    }
    body.force[k].dof = body.dofs[k].front();
    body.tied[k] = true;
    if (drive.drive == io::RigidDrive::Displacement) {
      conditions.push_back({body.dofs[k], drive.value, make_curve(spec, drive.curve)});
      continue;
    }
    for (Index d : body.dofs[k])
      if (d != body.dofs[k].front())
        model.dofs.tie(d, body.dofs[k].front());
    if (drive.drive == io::RigidDrive::Force) {
      body.force[k].magnitude = drive.value;
      body.force[k].curve = make_curve(spec, drive.curve);
    }
  }
  for (const physics::NodalForce& f : body.force)
    if (f.magnitude != 0.0)
      c.forces.push_back(f);
  return body;
}

/// The facets of the surface mesh of a body with shells (`set` names a surface whose facets
/// bound no cell). InputError naming the key otherwise.
const std::vector<mesh::Facet>& shell_facets(const io::RigidBodySpec& b, const Model& model) {
  TRIFEM_CHECK(model.mesh.has_surface(b.set),
               "{}.shell_thickness: the set '{}' is no surface (shells are the facets of a surface "
               "mesh)",
               b.key, b.set);
  const std::vector<mesh::Facet>& facets = model.mesh.surface(b.set).facets;
  for (std::size_t i = 0; i < facets.size(); ++i)
    TRIFEM_CHECK(facets[i].cell < 0,
                 "{}.shell_thickness: facet {} of the surface '{}' is a face of cell {} (shells "
                 "are the facets of a surface mesh that bound no cell)",
                 b.key, i + 1, b.set, facets[i].cell);
  return facets;
}

fe::QuadCoords facet_coordinates(const mesh::Mesh& mesh, const mesh::Facet& f) {
  fe::QuadCoords X;
  for (int a = 0; a < 4; ++a)
    X.row(a) = mesh.node(f.nodes[a]).transpose();
  return X;
}

/// The first moment ∫ X dV and the volume of a cell of any family but hex8, by its family's rule.
std::pair<Vec3, Real> cell_first_moment(const io::RigidBodySpec& b, const mesh::Mesh& mesh, Index c,
                                        const std::string& block) {
  const fe::ReferenceCell& reference = fe::reference_cell(mesh.cell_type(c));
  const std::span<const Index> nodes = mesh.cell_nodes(c);
  fe::CellNodeCoords X(static_cast<Index>(nodes.size()), 3);
  for (std::size_t a = 0; a < nodes.size(); ++a)
    X.row(static_cast<Index>(a)) = mesh.node(nodes[a]).transpose();
  const std::optional<physics::CellGeometry> geo = physics::cell_geometry(reference, X);
  TRIFEM_CHECK(geo.has_value(), "{}.blocks: {} of block '{}' is inverted", b.key, mesh.describe(c),
               block);
  Vec3 moment = Vec3::Zero();
  Real volume = 0.0;
  for (std::size_t q = 0; q < geo->dV.size(); ++q) {
    moment += geo->dV[q] * (X.transpose() * reference.rule_shapes()[q]);
    volume += geo->dV[q];
  }
  return {moment, volume};
}

/// The center of a rotating body: given; else the centroid of its cells or shells (its center
/// of mass: they have a uniform density); else the centroid of its nodes.
Vec3 body_center(const io::RigidBodySpec& b, const Model& model, const std::vector<Index>& nodes) {
  if (b.center)
    return *b.center;
  Vec3 moment = Vec3::Zero();
  Real volume = 0.0;
  if (b.shell_thickness)
    for (const mesh::Facet& f : shell_facets(b, model)) {
      const Eigen::Matrix4d m = physics::consistent_shell_mass(facet_coordinates(model.mesh, f), 1);
      const Eigen::Vector4d area = m.rowwise().sum(); // ∫ N_a dA
      moment += facet_coordinates(model.mesh, f).transpose() * area;
      volume += area.sum();
    }
  for (const std::string& block : b.blocks)
    for (Index c : model.mesh.cell_block(block)) {
      if (model.mesh.cell_type(c) != mesh::CellType::Hex8) {
        const auto [cell_moment, cell_volume] = cell_first_moment(b, model.mesh, c, block);
        moment += cell_moment;
        volume += cell_volume;
        continue;
      }
      const fe::HexCoords X = fe::cell_coordinates(model.mesh, c);
      const std::optional<fe::HexGeometry> geo = fe::hex8_geometry(X);
      TRIFEM_CHECK(geo.has_value(), "{}.blocks: {} of block '{}' is inverted", b.key,
                   model.mesh.describe(c), block);
      const auto& points = fe::hex_gauss_2x2x2();
      for (std::size_t q = 0; q < points.size(); ++q) {
        moment += geo->dV[q] * (X.transpose() * fe::hex8_shape(points[q].xi));
        volume += geo->dV[q];
      }
    }
  if (volume > 0.0)
    return moment / volume;
  Vec3 sum = Vec3::Zero();
  for (Index n : nodes)
    sum += model.mesh.node(n);
  return sum / static_cast<Real>(nodes.size());
}

/// The nodes of a body: those of its set and of its cells, ascending.
std::vector<Index> body_nodes(const io::RigidBodySpec& b, const Model& model) {
  std::set<Index> nodes;
  if (!b.set.empty()) {
    const std::vector<Index>& in_set = with_context(
        b.key + ".set", [&]() -> const std::vector<Index>& { return model.mesh.node_set(b.set); });
    nodes.insert(in_set.begin(), in_set.end());
  }
  for (const std::string& block : b.blocks)
    for (Index c : model.mesh.cell_block(block))
      for (Index n : model.mesh.cell_nodes(c))
        nodes.insert(n);
  return {nodes.begin(), nodes.end()};
}

/// The rotation vector Θ(t) = log(R_z(γ) R_y(β) R_x(α)) of prescribed Euler angles (each angle
/// × its curve) as the values of the rotation DOFs `rotation`.
void prescribe_euler_angles(const io::CaseSpec& spec,
                            const std::array<io::RigidComponentSpec, 3>& angles,
                            const std::array<Index, 3>& rotation,
                            std::vector<dofs::DirichletCondition>& conditions) {
  std::array<dofs::LoadCurve, 3> curves{dofs::LoadCurve::constant(1.0),
                                        dofs::LoadCurve::constant(1.0),
                                        dofs::LoadCurve::constant(1.0)};
  Vec3 amplitude;
  for (int k = 0; k < 3; ++k) {
    curves[k] = make_curve(spec, angles[k].curve);
    amplitude[k] = angles[k].value;
  }
  const auto theta = [curves, amplitude](Real t) {
    Mat3 R = Mat3::Identity();
    for (int k = 0; k < 3; ++k) // x first: R = R_z R_y R_x
      R = rotation::matrix(amplitude[k] * curves[k](t) * Vec3::Unit(k)) * R;
    return rotation::vector(R);
  };
  for (int k = 0; k < 3; ++k) {
    dofs::DirichletCondition c{{rotation[k]}, 0.0};
    c.law = [theta, k](Real t) { return theta(t)[k]; };
    conditions.push_back(std::move(c));
  }
}

/// A rotating body (index `index` among them): its nodes follow its unknowns, whose driven
/// components are prescribed or loaded.
RigidBody rotating_body(const io::CaseSpec& spec, const io::RigidBodySpec& b, int index,
                        Model& model, const std::vector<Index>& nodes, Collected& c,
                        std::vector<dofs::DirichletCondition>& conditions) {
  RigidBody body;
  body.name = b.name;
  body.tied = {true, true, true};
  body.rotating = index;
  dofs::RigidBodyDofs r;
  r.centre = body_center(b, model, nodes);
  for (int k = 0; k < 3; ++k) {
    r.translation[k] = model.dofs.dof(model.rigid_translation, index, k);
    r.rotation[k] = model.dofs.dof(model.rigid_rotation, index, k);
  }
  for (Index n : nodes) {
    std::array<Index, 3> follower{};
    for (int k = 0; k < 3; ++k) {
      follower[k] = model.dofs.dof(model.fields.u, n, k);
      claim(b, model, n, k, follower[k], c);
      model.dofs.make_dependent(follower[k]);
      body.dofs[k].push_back(follower[k]);
    }
    r.followers.push_back(follower);
    r.arms.push_back(model.mesh.node(n) - r.centre);
  }
  for (int k = 0; k < 3; ++k) {
    const io::RigidComponentSpec& move = b.drives[k];
    const io::RigidComponentSpec& turn = b.rotation_drives[k];
    for (const auto& [drive, dof] : {std::pair{&move, r.translation[k]}, {&turn, r.rotation[k]}})
      if (drive->drive == io::RigidDrive::Displacement)
        conditions.push_back({{dof}, drive->value, make_curve(spec, drive->curve)});
    body.force[k].dof = r.translation[k];
    if (move.drive == io::RigidDrive::Force) {
      body.force[k].magnitude = move.value;
      body.force[k].curve = make_curve(spec, move.curve);
      c.forces.push_back(body.force[k]);
    }
    if (turn.drive == io::RigidDrive::Force)
      c.moments.push_back({r.rotation, turn.value * Vec3::Unit(k), make_curve(spec, turn.curve)});
  }
  if (b.euler_angles)
    prescribe_euler_angles(spec, *b.euler_angles, r.rotation, conditions);
  for (const io::RigidFollowerSpec& f : b.followers)
    c.followers.push_back({r.translation, r.rotation, f.point.value_or(r.centre) - r.centre,
                           f.force, f.moment, make_curve(spec, f.curve)});
  c.rotating.push_back(std::move(r));
  return body;
}

} // namespace

RigidBodyParts rigid_bodies(const io::CaseSpec& spec, Model& model,
                            std::vector<dofs::DirichletCondition>& conditions) {
  Collected c;
  c.constrained = constrained_dofs(conditions);
  int rotating = 0;
  for (const io::RigidBodySpec& b : spec.rigid_bodies)
    rotating += b.rotates ? 1 : 0;
  if (rotating > 0) {
    model.rigid_translation =
        model.dofs.add_field("rigid_translation", FieldRole::rigid_motion, rotating, 3);
    model.rigid_rotation =
        model.dofs.add_field("rigid_rotation", FieldRole::rigid_motion, rotating, 3);
  }
  for (const io::RigidBodySpec& b : spec.rigid_bodies) {
    const std::vector<Index> nodes = body_nodes(b, model);
    TRIFEM_CHECK(!nodes.empty(), "{}: the rigid body has no nodes (node set '{}' is empty)", b.key,
                 b.set);
    if (b.shell_thickness)
      shell_facets(b, model); // checks that its set is a surface mesh
    const int index = static_cast<int>(c.rotating.size());
    model.rigid_bodies.push_back(b.rotates
                                     ? rotating_body(spec, b, index, model, nodes, c, conditions)
                                     : translating_body(spec, b, model, nodes, c, conditions));
  }
  RigidBodyParts parts;
  if (!c.forces.empty())
    parts.loads.push_back(std::make_unique<physics::NodalForceTerm>(std::move(c.forces)));
  if (!c.moments.empty())
    parts.loads.push_back(std::make_unique<physics::RigidMomentTerm>(std::move(c.moments)));
  if (!c.followers.empty())
    parts.loads.push_back(std::make_unique<physics::RigidFollowerTerm>(std::move(c.followers)));
  if (auto connectors = rigid_connectors(spec, model, c.rotating, conditions))
    parts.loads.push_back(std::move(connectors));
  parts.map = dofs::RigidMap(std::move(c.rotating), model.dofs.num_dofs());
  return parts;
}

void check_frames_of_rotating_bodies(const io::CaseSpec& spec, const Model& model,
                                     const dofs::NodalFrames& frames) {
  if (frames.empty())
    return;
  for (std::size_t i = 0; i < spec.rigid_bodies.size(); ++i) {
    const RigidBody& body = model.rigid_bodies[i];
    if (body.rotating < 0)
      continue;
    for (Index d : body.dofs[0]) {
      const Index node = (d - model.dofs.field(model.fields.u).offset) / 3;
      for (dofs::FieldId f : {model.fields.w, model.fields.j_plus, model.fields.j_minus})
        TRIFEM_CHECK(!f.valid() || frames.frame_of(model.dofs.dof(f, node, 0)) < 0,
                     "{}: node {} of the rotating body lies on an impermeable surface "
                     "([[boundary.impermeable]]), whose normal would not turn with the body; "
                     "fix the fluxes of the body's nodes instead ([[boundary.fixed]] field = "
                     "\"fluxes\")",
                     spec.rigid_bodies[i].key, node);
    }
  }
}

std::vector<physics::MassElement> rigid_shell_masses(const io::CaseSpec& spec, const Model& model) {
  std::vector<physics::MassElement> out;
  for (const io::RigidBodySpec& b : spec.rigid_bodies) {
    if (!b.shell_thickness || !b.density)
      continue;
    for (const mesh::Facet& f : shell_facets(b, model))
      out.push_back({{f.nodes.begin(), f.nodes.end()},
                     physics::consistent_shell_mass(facet_coordinates(model.mesh, f),
                                                    *b.density * *b.shell_thickness)});
  }
  return out;
}

Vector initial_rigid_velocity(const io::CaseSpec& spec, const Model& model) {
  Vector v;
  for (std::size_t i = 0; i < spec.rigid_bodies.size(); ++i) {
    const io::RigidBodySpec& b = spec.rigid_bodies[i];
    if (b.velocity == Vec3::Zero() && b.angular_velocity == Vec3::Zero())
      continue;
    if (v.size() == 0)
      v = Vector::Zero(model.dofs.num_dofs());
    const RigidBody& body = model.rigid_bodies[i];
    if (body.rotating < 0) {
      for (int k = 0; k < 3; ++k)
        if (body.tied[k])
          for (Index d : body.dofs[k])
            v[d] = b.velocity[k];
      continue;
    }
    const dofs::RigidBodyDofs& r = model.problem->rigid_map().bodies()[body.rotating];
    for (int k = 0; k < 3; ++k) { // at the start Θ = 0: Θ' = ω
      v[r.translation[k]] = b.velocity[k];
      v[r.rotation[k]] = b.angular_velocity[k];
    }
    for (std::size_t a = 0; a < r.followers.size(); ++a) {
      const Vec3 va = b.velocity + b.angular_velocity.cross(r.arms[a]);
      for (int k = 0; k < 3; ++k)
        v[r.followers[a][k]] = va[k];
    }
  }
  return v;
}

Vec3 rigid_body_force(const Model& model, const RigidBody& b, Real time) {
  return rigid_body_force(b, time, model.problem->full_residual());
}

Vec3 rigid_body_force(const RigidBody& b, Real time, const Vector& R) {
  Vec3 f = Vec3::Zero();
  for (int k = 0; k < 3; ++k) {
    if (!b.tied[k])
      continue;
    if (b.rotating < 0) // the applied force is in the leader's residual
      f[k] = b.force[k].value(time);
    for (Index d : b.dofs[k])
      f[k] += R[d];
  }
  return f;
}

Vec3 rigid_body_displacement(const Model& model, const RigidBody& b) {
  const Vector& x = model.problem->state();
  Vec3 u = Vec3::Zero();
  for (int k = 0; k < 3; ++k)
    if (b.tied[k])
      u[k] = x[b.rotating >= 0 ? b.force[k].dof : b.dofs[k].front()];
  return u;
}

Vec3 rigid_body_rotation(const Model& model, const RigidBody& b) {
  const dofs::RigidBodyDofs& r = model.problem->rigid_map().bodies()[b.rotating];
  const Vector& x = model.problem->state();
  return {x[r.rotation[0]], x[r.rotation[1]], x[r.rotation[2]]};
}

Vec3 rigid_body_moment(const Model& model, const RigidBody& b) {
  return rigid_body_moment(model, b, model.problem->full_residual());
}

Vec3 rigid_body_moment(const Model& model, const RigidBody& b, const Vector& R) {
  const dofs::RigidBodyDofs& r = model.problem->rigid_map().bodies()[b.rotating];
  const Vector& x = model.problem->state();
  const Vec3 center =
      r.centre + Vec3(x[r.translation[0]], x[r.translation[1]], x[r.translation[2]]);
  Vec3 m = Vec3::Zero();
  for (std::size_t a = 0; a < r.followers.size(); ++a) {
    const auto& d = r.followers[a];
    const Vec3 position = r.centre + r.arms[a] + Vec3(x[d[0]], x[d[1]], x[d[2]]);
    m += (position - center).cross(Vec3(R[d[0]], R[d[1]], R[d[2]]));
  }
  return m;
}

} // namespace trifem::model
