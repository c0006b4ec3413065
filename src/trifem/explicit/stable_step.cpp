// SPDX-License-Identifier: MIT
#include "trifem/explicit/stable_step.hpp"

#include "trifem/explicit/lambda_system.hpp"
#include "trifem/explicit/multiplier_stiffness.hpp"
#include "trifem/explicit/parallel.hpp"
#include "trifem/fe/quadrature.hpp"
#include "trifem/physics/solid_kernel.hpp"

#include <Eigen/Eigenvalues>

#include <cmath>

namespace trifem::explicit_dynamics {
namespace {

/// K_e = K_W,e + K_Λ,e of cell c at U (K_Λ left out if `lambda` is empty).
physics::HexMatrix cell_stiffness(const ExplicitModel& model, Constraint constraint,
                                  const Vector& U, const Vector& lambda, Index c) {
  const fe::HexCoords u = model.cell_values(c, U);
  physics::HexVector f;
  physics::HexMatrix K, K_lambda;
  physics::solid_hex8(model.geometry()[c], u, model.law(c), f, &K);
  if (lambda.size() > 0 && lambda[c] != 0.0 &&
      multiplier_stiffness(model.geometry()[c], u, constraint, lambda[c], K_lambda))
    K += K_lambda;
  return K;
}

/// y = K(U) v, element by element (never assembled).
void apply_stiffness(const ExplicitModel& model, Constraint constraint, const Vector& U,
                     const Vector& lambda, const Vector& v, std::vector<CellVector>& scratch,
                     Vector& y) {
  const Index n = model.num_cells();
  scratch.resize(n);
#pragma omp parallel for schedule(static) if (n >= kMinParallelLoop)
  for (Index c = 0; c < n; ++c) {
    if (!model.evaluates(c)) // (gather reads the cells of this process's nodes only)
      continue;
    if (!model.deformable(c)) {
      scratch[c].setZero();
      continue;
    }
    const physics::HexMatrix K = cell_stiffness(model, constraint, U, lambda, c);
    const fe::HexCoords vc = model.cell_values(c, v);
    CellVector ve;
    for (int a = 0; a < 8; ++a)
      ve.segment<3>(3 * a) = vc.row(a).transpose();
    scratch[c] = K * ve;
  }
  gather(model, scratch, nullptr, y);
}

/// The M-orthogonal projection on ker Hᵀ: w ← w − M⁻¹H (HᵀM⁻¹H + δ)⁻¹ Hᵀ w.
class Projector {
public:
  Projector(const ExplicitModel& model, Constraint constraint, const Vector& U)
      : model_(model), system_(model) {
    CellFields fields;
    evaluate_cells(model, constraint, U, {false, true, false}, fields);
    h_ = std::move(fields.gradient);
    Vector diagonal = Vector::Zero(model.num_cells());
    for (Index c = 0; c < model.num_cells(); ++c) {
      if (!model.evaluates(c))
        continue;
      if (!model.deformable(c)) { // H_e = 0: a row of its own
        diagonal[c] = 1.0;
        continue;
      }
      Real d = 0.0;
      for (int a = 0; a < 8; ++a) {
        const Index node = model.mesh().cell(c)[a];
        d += h_[c].segment<3>(3 * a).cwiseAbs2().dot(
            model.frequency_inverse_mass().segment<3>(3 * node));
      }
      diagonal[c] = 1e-10 * d;
    }
    ok_ = system_.factorize(h_, model.frequency_inverse_mass(), 1.0, diagonal);
  }
  bool ok() const { return ok_; }
  void apply(Vector& w) {
    Vector rhs, mu, Hmu;
    cell_dot(model_, h_, w, rhs);
    system_.solve(rhs, mu);
    gather(model_, h_, &mu, Hmu);
    w -= model_.frequency_inverse_mass().cwiseProduct(Hmu);
  }

private:
  const ExplicitModel& model_;
  LambdaSystem system_;
  std::vector<CellVector> h_;
  bool ok_ = false;
};

/// A deterministic, non-smooth start vector (zero on fixed DOFs and those of rigid bodies): it has
/// components along the high-frequency modes that the power iteration must find.
Vector start_vector(const ExplicitModel& model) {
  Vector v(model.num_dofs());
  for (Index i = 0; i < model.num_dofs(); ++i)
    v[i] = model.frequency_inverse_mass()[i] == 0.0
               ? 0.0
               : std::sin(12.9898 * i + 78.233 * (i % 7)) + 0.1;
  return v;
}

Real mass_norm(const ExplicitModel& model, const Vector& v) {
  return std::sqrt(v.cwiseAbs2().dot(model.mass()));
}

} // namespace

FrequencyEstimate power_iteration_omega(const ExplicitModel& model, Constraint constraint,
                                        const Vector& U, const Vector& lambda, bool project,
                                        int max_iterations, Real tolerance) {
  std::unique_ptr<Projector> projector;
  if (project) {
    projector = std::make_unique<Projector>(model, constraint, U);
    if (!projector->ok())
      projector.reset(); // H numerically singular even with δ: estimate without projection
  }
  Vector v = start_vector(model), y;
  if (projector)
    projector->apply(v);
  if (mass_norm(model, v) == 0.0) // nothing moves freely: no frequency of the mesh
    return {0.0, 0, true};
  v /= mass_norm(model, v);
  std::vector<CellVector> scratch;
  FrequencyEstimate est;
  Real previous = 0.0;
  for (int it = 1; it <= max_iterations; ++it) {
    apply_stiffness(model, constraint, U, lambda, v, scratch, y);
    const Real omega2 = v.dot(y); // vᵀ K v with vᵀ M v = 1
    est = {std::sqrt(std::max(omega2, 0.0)), it, false};
    if (it > 1 && std::abs(omega2 - previous) <= tolerance * std::abs(omega2)) {
      est.converged = true;
      break;
    }
    previous = omega2;
    v = model.frequency_inverse_mass().cwiseProduct(y);
    if (projector)
      projector->apply(v);
    v /= mass_norm(model, v);
  }
  return est;
}

FrequencyEstimate element_bound_omega(const ExplicitModel& model, Constraint constraint,
                                      const Vector& U, const Vector& lambda) {
  const Index n = model.num_cells();
  const auto& rule = fe::hex_gauss_2x2x2();
  Real max_omega2 = 0.0;
#pragma omp parallel for schedule(static) reduction(max : max_omega2) if (n >= kMinParallelLoop)
  for (Index c = 0; c < n; ++c) {
    if (!model.deformable(c))
      continue;
    const fe::HexGeometry& geo = model.geometry()[c];
    const physics::HexMatrix K = cell_stiffness(model, constraint, U, lambda, c);
    CellVector m = CellVector::Zero();
    for (int q = 0; q < 8; ++q) {
      const fe::HexShape N = fe::hex8_shape(rule[q].xi);
      for (int a = 0; a < 8; ++a)
        m.segment<3>(3 * a).array() += model.density(c) * N[a] * geo.dV[q];
    }
    const CellVector s = m.cwiseSqrt().cwiseInverse();
    const physics::HexMatrix A = s.asDiagonal() * K * s.asDiagonal();
    Eigen::SelfAdjointEigenSolver<physics::HexMatrix> eig(A, Eigen::EigenvaluesOnly);
    max_omega2 = std::max(max_omega2, eig.eigenvalues().maxCoeff());
  }
  return {std::sqrt(max_omega2), 0, true};
}

} // namespace trifem::explicit_dynamics
