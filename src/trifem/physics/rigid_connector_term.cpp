// SPDX-License-Identifier: MIT
#include "trifem/physics/rigid_connector_term.hpp"

#include "trifem/core/error.hpp"
#include "trifem/tensor/rotation.hpp"

#include <cmath>
#include <numbers>

namespace trifem::physics {
namespace {

using rigid::MeasureValue;
using rigid::PairMatrix;
using rigid::PairVector;

/// a − b in (−π, π].
Real angle_difference(Real a, Real b) {
  constexpr Real pi = std::numbers::pi;
  Real d = std::remainder(a - b, 2.0 * pi);
  return d <= -pi ? d + 2.0 * pi : d;
}

/// ψ'(g) and ψ''(g) of an energy at `state`; g_old is the measure in the converged state.
std::pair<Real, Real> energy_derivatives(const ConnectorEnergy& e, Real g, Real g_old,
                                         const EvalState& state) {
  switch (e.kind) {
  case ConnectorEnergyKind::Spring:
    return {e.stiffness * (g - e.rest), e.stiffness};
  case ConnectorEnergyKind::Cable:
    return g > e.rest ? std::pair{e.stiffness * (g - e.rest), e.stiffness} : std::pair{0.0, 0.0};
  case ConnectorEnergyKind::Force:
    return {-e.value * e.curve(state.time), 0.0};
  case ConnectorEnergyKind::Viscous:
    if (state.dt <= 0.0)
      return {0.0, 0.0};
    return {e.stiffness * (g - g_old) / state.dt, e.stiffness / state.dt};
  }
  return {0.0, 0.0};
}

/// The positions in the element's DOFs of the pair's 12 unknowns (−1: a body fixed in space).
std::array<int, rigid::kPairDofs> pair_positions(const Connector& c) {
  std::array<int, rigid::kPairDofs> at{};
  int next = 0;
  for (int k = 0; k < 2; ++k)
    for (int i = 0; i < 6; ++i)
      at[6 * k + i] = c.bodies[k] ? next++ : -1;
  return at;
}

} // namespace

RigidConnectorTerm::RigidConnectorTerm(std::vector<Connector> connectors)
    : connectors_(std::move(connectors)), committed_(connectors_.size()) {}

void RigidConnectorTerm::commit(const EvalState& state) {
  // the damper's velocity needs the state before the step: measured now
  for (std::size_t e = 0; e < connectors_.size(); ++e)
    committed_[e] = wrench(static_cast<Index>(e), state);
}

std::vector<double> RigidConnectorTerm::history() const {
  std::vector<double> out;
  for (const ConnectorWrench& w : committed_)
    out.insert(out.end(),
               {w.force.x(), w.force.y(), w.force.z(), w.moment.x(), w.moment.y(), w.moment.z()});
  return out;
}

void RigidConnectorTerm::restore_history(const std::vector<double>& values) {
  TRIFEM_CHECK(values.size() == 6 * committed_.size(),
               "the restart file holds {} values for {} rigid connectors (expected 6 each)",
               values.size(), committed_.size());
  for (std::size_t e = 0; e < committed_.size(); ++e) {
    committed_[e].force = Vec3(values[6 * e], values[6 * e + 1], values[6 * e + 2]);
    committed_[e].moment = Vec3(values[6 * e + 3], values[6 * e + 4], values[6 * e + 5]);
  }
}

void RigidConnectorTerm::element_dofs(Index e, std::vector<Index>& dofs) const {
  const Connector& c = connectors_[e];
  dofs.clear();
  for (const auto& body : c.bodies)
    if (body) {
      dofs.insert(dofs.end(), body->translation.begin(), body->translation.end());
      dofs.insert(dofs.end(), body->rotation.begin(), body->rotation.end());
    }
  for (const ConnectorConstraint& g : c.constraints)
    dofs.push_back(g.multiplier);
}

rigid::PairState RigidConnectorTerm::pair_state(Index e, const Vector& x) const {
  rigid::PairState s;
  for (int k = 0; k < 2; ++k) {
    const auto& body = connectors_[e].bodies[k];
    if (!body)
      continue;
    s.moving[k] = true;
    s.centre[k] = body->centre;
    for (int i = 0; i < 3; ++i) {
      s.u[k][i] = x[body->translation[i]];
      s.theta[k][i] = x[body->rotation[i]];
    }
  }
  return s;
}

Real RigidConnectorTerm::measure(Index e, const rigid::Measure& m, const Vector& x) const {
  const auto y = rigid::evaluate(connectors_[e].attachments, pair_state(e, x));
  MeasureValue v;
  rigid::evaluate(m, y, false, v);
  return v.value;
}

bool RigidConnectorTerm::pair_residual(Index e, const EvalState& state, PairVector& rq,
                                       Eigen::VectorXd& rl, PairMatrix* Kqq,
                                       Eigen::MatrixXd* Kql) const {
  const Connector& c = connectors_[e];
  const auto y = rigid::evaluate(c.attachments, pair_state(e, state.x));
  const bool derivatives = true;
  rq.setZero();
  rl.setZero(static_cast<Index>(c.constraints.size()));
  if (Kqq)
    Kqq->setZero();
  if (Kql)
    Kql->setZero(rigid::kPairDofs, rl.size());
  MeasureValue v;
  for (std::size_t i = 0; i < c.constraints.size(); ++i) {
    const ConnectorConstraint& g = c.constraints[i];
    if (!rigid::evaluate(g.measure, y, derivatives, v))
      return false;
    const Real target = g.value * g.curve(state.time);
    const Real lambda = state.x[g.multiplier];
    rq += lambda * v.gradient;
    rl[static_cast<Index>(i)] = g.measure.kind == rigid::MeasureKind::Angle
                                    ? angle_difference(v.value, target)
                                    : v.value - target;
    if (Kqq)
      *Kqq += lambda * v.hessian;
    if (Kql)
      Kql->col(static_cast<Index>(i)) = v.gradient;
  }
  std::vector<rigid::AttachmentValue> y_old;
  for (const ConnectorEnergy& energy : c.energies) {
    if (!rigid::evaluate(energy.measure, y, derivatives, v))
      return false;
    Real g_old = 0.0;
    if (energy.kind == ConnectorEnergyKind::Viscous) {
      if (y_old.empty())
        y_old = rigid::evaluate(c.attachments, pair_state(e, state.x_old));
      MeasureValue old;
      if (!rigid::evaluate(energy.measure, y_old, false, old))
        return false;
      g_old = old.value;
    }
    const auto [d1, d2] = energy_derivatives(energy, v.value, g_old, state);
    rq += d1 * v.gradient;
    if (Kqq)
      *Kqq += d2 * v.gradient * v.gradient.transpose() + d1 * v.hessian;
  }
  return true;
}

bool RigidConnectorTerm::evaluate(Index e, const EvalState& state, LocalVector& r,
                                  LocalMatrix* K) const {
  const Connector& c = connectors_[e];
  const auto at = pair_positions(c);
  const int nq = (c.bodies[0] ? 6 : 0) + (c.bodies[1] ? 6 : 0);
  const Index nl = static_cast<Index>(c.constraints.size());
  PairVector rq;
  Eigen::VectorXd rl;
  PairMatrix Kqq;
  Eigen::MatrixXd Kql;
  if (!pair_residual(e, state, rq, rl, K ? &Kqq : nullptr, K ? &Kql : nullptr))
    return false;
  r.setZero(nq + nl);
  r.tail(nl) = rl;
  if (K)
    K->setZero(nq + nl, nq + nl);
  for (int i = 0; i < rigid::kPairDofs; ++i) {
    if (at[i] < 0)
      continue;
    r[at[i]] = rq[i];
    if (!K)
      continue;
    for (int j = 0; j < rigid::kPairDofs; ++j)
      if (at[j] >= 0)
        (*K)(at[i], at[j]) = Kqq(i, j);
    K->row(at[i]).tail(nl) = Kql.row(i);
    K->col(at[i]).tail(nl) = Kql.row(i).transpose();
  }
  return true;
}

Eigen::MatrixXd RigidConnectorTerm::constraint_gradients(Index e, const Vector& x) const {
  const Connector& c = connectors_[e];
  const auto at = pair_positions(c);
  const int nq = (c.bodies[0] ? 6 : 0) + (c.bodies[1] ? 6 : 0);
  const auto y = rigid::evaluate(c.attachments, pair_state(e, x));
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(nq, static_cast<Index>(c.constraints.size()));
  MeasureValue v;
  for (std::size_t i = 0; i < c.constraints.size(); ++i)
    if (rigid::evaluate(c.constraints[i].measure, y, true, v))
      for (int k = 0; k < rigid::kPairDofs; ++k)
        if (at[k] >= 0)
          G(at[k], static_cast<Index>(i)) = v.gradient[k];
  return G;
}

ConnectorWrench RigidConnectorTerm::wrench(Index e, const EvalState& state) const {
  const Connector& c = connectors_[e];
  PairVector rq;
  Eigen::VectorXd rl;
  ConnectorWrench w;
  if (!pair_residual(e, state, rq, rl, nullptr, nullptr))
    return w;
  const rigid::PairState s = pair_state(e, state.x);
  // the body whose unknowns carry the connector's load: b, else a (whose load is opposite)
  const int k = c.bodies[1] ? 1 : 0;
  const Real sign = k == 1 ? 1.0 : -1.0;
  if (!c.bodies[k])
    return w;
  // R_u = −F and R_Θ = −Tᵀ M_c of the load F, M_c (about the center) on the body
  const Vec3 force = -rq.segment<3>(6 * k);
  const Vec3 moment_c =
      -rotation::tangent(s.theta[k]).transpose().lu().solve(Vec3(rq.segment<3>(6 * k + 3)));
  const Vec3 centre = s.centre[k] + s.u[k];
  Vec3 point = centre;
  if (c.origin_b >= 0) {
    const auto y = rigid::evaluate(std::span(&c.attachments[c.origin_b], 1), s);
    point = y[0].y;
  }
  w.force = sign * force;
  w.moment = sign * (moment_c - (point - centre).cross(force));
  return w;
}

} // namespace trifem::physics
