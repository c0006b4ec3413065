// SPDX-License-Identifier: MIT
// The start of a dynamic step from a state at rest or in motion: the given velocity and the
// acceleration that satisfies the equation of motion M a_0 = −g(x_0, t_0) at the free
// displacement equations and the unknowns of rigid bodies.
#include "trifem/assembly/fe_problem.hpp"
#include "trifem/core/error.hpp"
#include "trifem/tensor/rotation.hpp"

#include <cmath>

namespace trifem::assembly {
namespace {

/// The mass matrix over the free equations of the inertia term's DOFs: y = Pᵀ Qᵀ Λᵀ M Λ Q P z,
/// where P spreads an equation to its (tied) DOFs, Q rotates local to global components and Λ
/// moves the nodes of rigid bodies with the bodies' unknowns (at the state x).
class EquationMass {
public:
  EquationMass(const physics::InertiaTerm& inertia, const dofs::DofMap& map,
               const dofs::NodalFrames& frames, const dofs::RigidMap& rigid, const Vector& x)
      : inertia_(inertia), map_(map), frames_(frames), rigid_(rigid), x_(x) {
    inverse_diagonal_ = Vector::Zero(map.num_equations());
    Vector lumped = inertia.lumped_mass(); // isotropic per node: no rotation needed
    // (the corners of quadratic cells have a negative lumped mass: their mass diagonal there)
    const Vector diagonal = inertia.diagonal_mass();
    for (Index dof = 0; dof < lumped.size(); ++dof)
      if (!(lumped[dof] > 0.0) && diagonal[dof] > 0.0)
        lumped[dof] = diagonal[dof];
    add_body_diagonal(lumped);
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
    rigid_.spread(x_, u);
    return gather(mass_times(u));
  }

  /// M u for u in global components, condensed onto the bodies' unknowns, in local components.
  Vector mass_times(const Vector& u) const {
    Vector f = inertia_.mass_times(u);
    rigid_.add_condensed(x_, f, f);
    frames_.to_local(f);
    return f;
  }

  /// Σ over the DOFs of every equation with mass (zero elsewhere), of local components.
  Vector gather(const Vector& at_dofs) const {
    Vector y = Vector::Zero(map_.num_equations());
    for (Index dof : inertia_.dofs())
      if (const Index eq = map_.equation(dof); eq >= 0)
        y[eq] += at_dofs[dof];
    return y;
  }

  /// Jacobi preconditioner: the inverse lumped mass, or of the mass diagonal where the lumped
  /// mass is not positive (zero on equations without mass).
  Vector precondition(const Vector& r) const { return inverse_diagonal_.cwiseProduct(r); }

private:
  /// The lumped mass of each body's nodes at its translation DOFs, their moments of inertia
  /// Σ m_a (|s_a|² − s_ak²) about its center at its rotation DOFs.
  void add_body_diagonal(Vector& lumped) const {
    for (const dofs::RigidBodyDofs& b : rigid_.bodies()) {
      const Mat3 R =
          rotation::matrix(Vec3(x_[b.rotation[0]], x_[b.rotation[1]], x_[b.rotation[2]]));
      for (std::size_t a = 0; a < b.followers.size(); ++a) {
        const Real m = lumped[b.followers[a][0]];
        const Vec3 s = R * b.arms[a];
        for (int k = 0; k < 3; ++k) {
          lumped[b.translation[k]] += m;
          lumped[b.rotation[k]] += m * (s.squaredNorm() - s[k] * s[k]);
        }
      }
    }
  }

  const physics::InertiaTerm& inertia_;
  const dofs::DofMap& map_;
  const dofs::NodalFrames& frames_;
  const dofs::RigidMap& rigid_;
  const Vector& x_;
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

/// The centripetal accelerations ω × (ω × s_a) of the nodes of rigid bodies that turn with the
/// angular velocity ω their nodes' velocities `v` (global components) give: ω solves the least
/// squares fit v_a − v̄ = ω × (s_a − s̄) (exact for a rigid motion). Zero elsewhere.
Vector centripetal(const dofs::RigidMap& rigid, const Vector& x, const Vector& v) {
  Vector c = Vector::Zero(x.size());
  if (v.size() == 0)
    return c;
  const auto at = [](const Vector& y, const std::array<Index, 3>& d) {
    return Vec3(y[d[0]], y[d[1]], y[d[2]]);
  };
  for (const dofs::RigidBodyDofs& b : rigid.bodies()) {
    const Index n = static_cast<Index>(b.followers.size());
    if (n < 2)
      continue;
    const Mat3 R = rotation::matrix(at(x, b.rotation));
    std::vector<Vec3> s(n);
    Vec3 s_mean = Vec3::Zero(), v_mean = Vec3::Zero();
    for (Index a = 0; a < n; ++a) {
      s[a] = R * b.arms[a];
      s_mean += s[a] / Real(n);
      v_mean += at(v, b.followers[a]) / Real(n);
    }
    Mat3 J = Mat3::Zero();
    Vec3 h = Vec3::Zero();
    for (Index a = 0; a < n; ++a) {
      const Vec3 d = s[a] - s_mean;
      J += d.squaredNorm() * Mat3::Identity() - d * d.transpose();
      h += d.cross(at(v, b.followers[a]) - v_mean);
    }
    const Vec3 omega = J.completeOrthogonalDecomposition().solve(h);
    for (Index a = 0; a < n; ++a) {
      const Vec3 ca = omega.cross(omega.cross(s[a]));
      for (int k = 0; k < 3; ++k)
        c[b.followers[a][k]] = ca[k];
    }
  }
  return c;
}

} // namespace

void FeProblem::start_motion(const Vector& velocity) {
  const Vector g = static_residual(); // g(x_0, t_0) at every DOF, assembled components
  const EquationMass mass(*inertia_, map_, frames_, rigid_, x_global_);
  // the nodes of a turning rigid body accelerate towards its axis already: M c moves to the
  // right-hand side, a = Λ z + c
  const Vector c = centripetal(rigid_, x_global_, velocity);
  const Vector a_equations = solve_mass(mass, -mass.gather(g) - mass.gather(mass.mass_times(c)));
  Vector a = Vector::Zero(map_.num_dofs()); // prescribed DOFs: no acceleration at the start
  for (Index dof : inertia_->dofs())
    if (const Index eq = map_.equation(dof); eq >= 0)
      a[dof] = a_equations[eq];
  frames_.to_global(a);
  rigid_.spread(x_global_, a);
  a += c;
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
