// SPDX-License-Identifier: MIT
#include "trifem/model/rigid_bodies.hpp"

#include "trifem/model/conditions.hpp"

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

/// One rigid body: ties, prescribed components and forces.
RigidBody make_body(const io::CaseSpec& spec, const io::RigidBodySpec& b, Model& model,
                    const std::set<Index>& constrained, std::set<Index>& used,
                    std::vector<dofs::DirichletCondition>& conditions) {
  const std::vector<Index>& nodes = with_context(
      b.key + ".set", [&]() -> const std::vector<Index>& { return model.mesh.node_set(b.set); });
  RigidBody body;
  body.name = b.name;
  for (int k : b.components) {
    const io::RigidComponentSpec& c = b.drives[k];
    for (Index n : nodes) {
      const Index d = model.dofs.dof(model.fields.u, n, k);
      TRIFEM_CHECK(used.insert(d).second, "{}: node {} belongs to two rigid bodies", b.key, n);
      TRIFEM_CHECK(!constrained.contains(d),
                   "{}: component {} of node {} (at {:.6g} {:.6g} {:.6g}) of set '{}' is also "
                   "constrained by a boundary condition; drive the rigid body's {} instead "
                   "(e.g. {}.{} = {{ displacement = 0.0 }})",
                   b.key, "xyz"[k], n, model.mesh.node(n).x(), model.mesh.node(n).y(),
                   model.mesh.node(n).z(), b.set, "xyz"[k], b.key, "xyz"[k]);
      body.dofs[k].push_back(d);
    }
    body.force[k].dof = body.dofs[k].front();
    body.tied[k] = true;
    if (c.drive == io::RigidDrive::Displacement) {
      conditions.push_back({body.dofs[k], c.value, make_curve(spec, c.curve)});
      continue;
    }
    for (Index d : body.dofs[k])
      if (d != body.dofs[k].front())
        model.dofs.tie(d, body.dofs[k].front());
    if (c.drive == io::RigidDrive::Force) {
      body.force[k].magnitude = c.value;
      body.force[k].curve = make_curve(spec, c.curve);
    }
  }
  return body;
}

} // namespace

std::unique_ptr<physics::Term> rigid_bodies(const io::CaseSpec& spec, Model& model,
                                            std::vector<dofs::DirichletCondition>& conditions) {
  const std::set<Index> constrained = constrained_dofs(conditions);
  std::set<Index> used;
  std::vector<physics::NodalForce> forces;
  for (const io::RigidBodySpec& b : spec.rigid_bodies) {
    model.rigid_bodies.push_back(make_body(spec, b, model, constrained, used, conditions));
    for (const physics::NodalForce& f : model.rigid_bodies.back().force)
      if (f.magnitude != 0.0)
        forces.push_back(f);
  }
  if (forces.empty())
    return nullptr;
  return std::make_unique<physics::NodalForceTerm>(std::move(forces));
}

Vec3 rigid_body_force(const Model& model, const RigidBody& b, Real time) {
  const Vector& R = model.problem->full_residual();
  Vec3 f = Vec3::Zero();
  for (int k = 0; k < 3; ++k) {
    if (!b.tied[k])
      continue;
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
      u[k] = x[b.dofs[k].front()];
  return u;
}

} // namespace trifem::model
