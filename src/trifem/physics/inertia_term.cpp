// SPDX-License-Identifier: MIT
#include "trifem/physics/inertia_term.hpp"

#include "trifem/core/error.hpp"

#include <algorithm>
#include <cmath>

namespace trifem::physics {

GeneralizedAlpha GeneralizedAlpha::from_spectral_radius(Real rho_inf) {
  TRIFEM_VERIFY(rho_inf >= 0.0 && rho_inf <= 1.0, "spectral radius outside [0, 1]");
  GeneralizedAlpha m;
  m.alpha_m = (2.0 * rho_inf - 1.0) / (rho_inf + 1.0);
  m.alpha_f = rho_inf / (rho_inf + 1.0);
  m.gamma = 0.5 - m.alpha_m + m.alpha_f;
  m.beta = 0.25 * (1.0 - m.alpha_m + m.alpha_f) * (1.0 - m.alpha_m + m.alpha_f);
  return m;
}

InertiaTerm::InertiaTerm(const dofs::DofMap& dofs, dofs::FieldId displacement,
                         std::vector<MassElement> elements, MassMatrix mass,
                         GeneralizedAlpha method, std::vector<Index> massless)
    : map_(dofs), u_(displacement), elements_(std::move(elements)), method_(method),
      dofs_(std::move(massless)) {
  if (mass == MassMatrix::Lumped)
    for (MassElement& e : elements_) {
      const Eigen::VectorXd lumped =
          physics::lumped_mass(e.mass); // evaluated before the matrix changes
      e.mass = lumped.asDiagonal();
    }
  std::vector<Index> element;
  for (Index e = 0; e < num_elements(); ++e) {
    element_dofs(e, element);
    dofs_.insert(dofs_.end(), element.begin(), element.end());
  }
  std::sort(dofs_.begin(), dofs_.end());
  dofs_.erase(std::unique(dofs_.begin(), dofs_.end()), dofs_.end());
  slot_of_dof_.assign(dofs.num_dofs(), -1);
  for (std::size_t i = 0; i < dofs_.size(); ++i)
    slot_of_dof_[dofs_[i]] = static_cast<Index>(i);
  v_ = a_ = g_ = Vector::Zero(static_cast<Index>(dofs_.size()));
}

InertiaTerm::InertiaTerm(const mesh::Mesh& mesh, const dofs::DofMap& dofs,
                         dofs::FieldId displacement, const std::vector<Index>& cells,
                         const std::vector<Real>& densities, MassMatrix mass,
                         GeneralizedAlpha method, std::vector<Index> massless)
    : InertiaTerm(dofs, displacement, cell_mass_elements(mesh, cells, densities), mass, method,
                  std::move(massless)) {}

void InertiaTerm::element_dofs(Index e, std::vector<Index>& dofs) const {
  const std::vector<Index>& nodes = elements_[e].nodes;
  dofs.resize(3 * nodes.size());
  for (std::size_t a = 0; a < nodes.size(); ++a)
    for (int k = 0; k < 3; ++k)
      dofs[3 * a + k] = map_.dof(u_, nodes[a], k);
}

Index InertiaTerm::slot(Index dof) const {
  return slot_of_dof_[dof];
}

Real InertiaTerm::acceleration_at(Index i, Real x, Real x_old, Real dt) const {
  const Real b = method_.beta;
  return (x - x_old - dt * v_[i] - dt * dt * (0.5 - b) * a_[i]) / (b * dt * dt);
}

bool InertiaTerm::evaluate(Index e, const EvalState& state, LocalVector& r, LocalMatrix* K) const {
  const std::vector<Index>& nodes = elements_[e].nodes;
  const auto n = static_cast<Index>(nodes.size());
  r.setZero(3 * n);
  if (K)
    K->setZero(3 * n, 3 * n);
  if (!(state.dt > 0.0))
    return true;
  NodalVectors accel(n, 3); // a_{n+1-α_m} at the nodes
  for (Index a = 0; a < n; ++a)
    for (int k = 0; k < 3; ++k) {
      const Index dof = map_.dof(u_, nodes[a], k);
      const Index i = slot(dof);
      const Real next = acceleration_at(i, state.x[dof], state.x_old[dof], state.dt);
      accel(a, k) = (1.0 - method_.alpha_m) * next + method_.alpha_m * a_[i];
    }
  const Eigen::MatrixXd& m = elements_[e].mass;
  const NodalVectors f = m * accel;
  for (Index a = 0; a < n; ++a)
    for (int k = 0; k < 3; ++k)
      r[3 * a + k] = f(a, k);
  if (K) {
    const Real c = (1.0 - method_.alpha_m) / (method_.beta * state.dt * state.dt);
    for (Index a = 0; a < n; ++a)
      for (Index b = 0; b < n; ++b)
        for (int k = 0; k < 3; ++k)
          (*K)(3 * a + k, 3 * b + k) = c * m(a, b);
  }
  return true;
}

void InertiaTerm::commit(const EvalState& state) {
  if (!(state.dt > 0.0))
    return;
  for (std::size_t i = 0; i < dofs_.size(); ++i) {
    const Index dof = dofs_[i];
    const auto s = static_cast<Index>(i);
    const Real next = acceleration_at(s, state.x[dof], state.x_old[dof], state.dt);
    v_[s] += state.dt * ((1.0 - method_.gamma) * a_[s] + method_.gamma * next);
    a_[s] = next;
  }
}

std::vector<double> InertiaTerm::history() const {
  std::vector<double> out;
  out.reserve(3 * dofs_.size());
  for (const Vector* v : {&v_, &a_, &g_})
    out.insert(out.end(), v->data(), v->data() + v->size());
  return out;
}

void InertiaTerm::restore_history(const std::vector<double>& values) {
  const std::size_t n = dofs_.size();
  if (values.size() != 3 * n)
    throw InputError(fmt::format("the inertia history holds {} values; this model needs {} "
                                 "(velocity, acceleration and residual of {} DOFs)",
                                 values.size(), 3 * n, n));
  for (double value : values)
    if (!std::isfinite(value))
      throw InputError("the inertia history holds a value that is not finite");
  const auto part = [&](std::size_t k) {
    return Eigen::Map<const Vector>(values.data() + k * n, static_cast<Index>(n));
  };
  v_ = part(0);
  a_ = part(1);
  g_ = part(2);
}

void InertiaTerm::set_motion(Vector velocity, Vector acceleration) {
  TRIFEM_VERIFY(velocity.size() == v_.size() && acceleration.size() == a_.size(),
                "one velocity and acceleration per DOF of the inertia term");
  v_ = std::move(velocity);
  a_ = std::move(acceleration);
}

void InertiaTerm::set_residual_history(Vector g) {
  TRIFEM_VERIFY(g.size() == g_.size(), "one residual per DOF of the inertia term");
  g_ = std::move(g);
}

Vector InertiaTerm::mass_times(const Vector& u) const {
  TRIFEM_VERIFY(u.size() == map_.num_dofs(), "mass_times: one value per DOF expected");
  Vector out = Vector::Zero(map_.num_dofs());
  std::vector<Index> element;
  for (Index e = 0; e < num_elements(); ++e) {
    element_dofs(e, element);
    const auto n = static_cast<Index>(elements_[e].nodes.size());
    NodalVectors ue(n, 3);
    for (Index a = 0; a < n; ++a)
      for (int k = 0; k < 3; ++k)
        ue(a, k) = u[element[3 * a + k]];
    const NodalVectors f = elements_[e].mass * ue;
    for (Index a = 0; a < n; ++a)
      for (int k = 0; k < 3; ++k)
        out[element[3 * a + k]] += f(a, k);
  }
  return out;
}

Vector InertiaTerm::lumped_mass() const {
  Vector out = Vector::Zero(map_.num_dofs());
  std::vector<Index> element;
  for (Index e = 0; e < num_elements(); ++e) {
    element_dofs(e, element);
    const Eigen::VectorXd rows = elements_[e].mass.rowwise().sum();
    for (Index a = 0; a < rows.size(); ++a)
      for (int k = 0; k < 3; ++k)
        out[element[3 * a + k]] += rows[a];
  }
  return out;
}

Vector InertiaTerm::diagonal_mass() const {
  Vector out = Vector::Zero(map_.num_dofs());
  std::vector<Index> element;
  for (Index e = 0; e < num_elements(); ++e) {
    element_dofs(e, element);
    const Eigen::MatrixXd& m = elements_[e].mass;
    for (Index a = 0; a < m.rows(); ++a)
      for (int k = 0; k < 3; ++k)
        out[element[3 * a + k]] += m(a, a);
  }
  return out;
}

} // namespace trifem::physics
