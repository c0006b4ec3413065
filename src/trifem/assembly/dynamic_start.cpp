// SPDX-License-Identifier: MIT
// The start of a dynamic step from a state at rest or in motion: the given velocity and the
// acceleration that satisfies the equation of motion M a_0 = −g(x_0, t_0) at the free
// displacement equations.
#include "trifem/assembly/fe_problem.hpp"
#include "trifem/core/error.hpp"

#include <cmath>

namespace trifem::assembly {
namespace {

/// The mass matrix over the free equations of the inertia term's DOFs: y = Pᵀ Qᵀ M Q P z,
/// where P spreads an equation to its (tied) DOFs and Q rotates local to global components.
class EquationMass {
public:
  EquationMass(const physics::InertiaTerm& inertia, const dofs::DofMap& map,
               const dofs::NodalFrames& frames)
      : inertia_(inertia), map_(map), frames_(frames) {
    inverse_diagonal_ = Vector::Zero(map.num_equations());
    Vector lumped = inertia.lumped_mass(); // isotropic per node: no rotation needed
    for (Index dof : inertia.dofs())
      if (const Index eq = map.equation(dof); eq >= 0)
        inverse_diagonal_[eq] += lumped[dof];
    for (Index eq = 0; eq < map.num_equations(); ++eq)
      inverse_diagonal_[eq] = inverse_diagonal_[eq] > 0.0 ? 1.0 / inverse_diagonal_[eq] : 0.0;
  }

  Vector apply(const Vector& z) const {
    Vector u = Vector::Zero(map_.num_dofs());
    for (Index dof : inertia_.dofs())
      if (const Index eq = map_.equation(dof); eq >= 0)
        u[dof] = z[eq];
    frames_.to_global(u);
    Vector f = inertia_.mass_times(u);
    frames_.to_local(f);
    return gather(f);
  }

  /// Σ over the DOFs of every equation with mass (zero elsewhere).
  Vector gather(const Vector& at_dofs) const {
    Vector y = Vector::Zero(map_.num_equations());
    for (Index dof : inertia_.dofs())
      if (const Index eq = map_.equation(dof); eq >= 0)
        y[eq] += at_dofs[dof];
    return y;
  }

  /// Jacobi preconditioner: the inverse lumped mass (zero on equations without mass).
  Vector precondition(const Vector& r) const { return inverse_diagonal_.cwiseProduct(r); }

private:
  const physics::InertiaTerm& inertia_;
  const dofs::DofMap& map_;
  const dofs::NodalFrames& frames_;
  Vector inverse_diagonal_;
};

/// Solves M z = b by conjugate gradients with the lumped-mass preconditioner (a mass matrix
/// is as well conditioned as its cells: a few tens of iterations at any mesh size).
Vector solve_mass(const EquationMass& mass, const Vector& b) {
  Vector z = Vector::Zero(b.size());
  const Real scale = b.norm();
  if (scale == 0.0)
    return z;
  Vector r = b, s = mass.precondition(r), p = s;
  Real rs = r.dot(s);
  for (int iteration = 0; iteration < 1000; ++iteration) {
    const Vector q = mass.apply(p);
    const Real step = rs / p.dot(q);
    z += step * p;
    r -= step * q;
    if (r.norm() <= 1e-13 * scale)
      return z;
    s = mass.precondition(r);
    const Real next = r.dot(s);
    p = s + (next / rs) * p;
    rs = next;
  }
  TRIFEM_VERIFY(false, "the mass matrix solve for the initial acceleration did not converge");
  return z;
}

} // namespace

void FeProblem::start_motion(const Vector& velocity) {
  const Vector g = static_residual(); // g(x_0, t_0) at every DOF, assembled components
  const EquationMass mass(*inertia_, map_, frames_);
  const Vector a_equations = solve_mass(mass, -mass.gather(g));
  Vector a = Vector::Zero(map_.num_dofs()); // prescribed DOFs: no acceleration at the start
  for (Index dof : inertia_->dofs())
    if (const Index eq = map_.equation(dof); eq >= 0)
      a[dof] = a_equations[eq];
  frames_.to_global(a);
  Vector a_inertia(static_cast<Index>(inertia_->dofs().size()));
  Vector g_inertia(a_inertia.size());
  Vector v_inertia = Vector::Zero(a_inertia.size());
  for (std::size_t i = 0; i < inertia_->dofs().size(); ++i) {
    const Index dof = inertia_->dofs()[i];
    a_inertia[static_cast<Index>(i)] = a[dof];
    g_inertia[static_cast<Index>(i)] = g[dof];
    if (velocity.size() > 0)
      v_inertia[static_cast<Index>(i)] = velocity[dof];
  }
  inertia_->set_motion(std::move(v_inertia), std::move(a_inertia));
  inertia_->set_residual_history(std::move(g_inertia));
}

} // namespace trifem::assembly
