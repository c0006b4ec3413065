// SPDX-License-Identifier: MIT
#include "trifem/explicit/stable_step.hpp"

#include "trifem/explicit/lambda_system.hpp"
#include "trifem/explicit/multiplier_stiffness.hpp"
#include "trifem/explicit/parallel.hpp"
#include "trifem/fe/quadrature.hpp"
#include "trifem/physics/cell_mass.hpp"
#include "trifem/physics/solid_kernel.hpp"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <span>
#include <type_traits>
#include <variant>

namespace trifem::explicit_dynamics {
namespace {

/// The solid element of a cell geometry, by its family.
bool solid_element(const fe::HexGeometry& geo, const fe::HexCoords& u,
                   const material::ElasticLaw& law, physics::HexMatrix& K) {
  physics::HexVector f;
  physics::solid_hex8(geo, u, law, f, &K);
  return true;
}
bool solid_element(const physics::CellGeometry& geo, const fe::CellNodeCoords& u,
                   const material::ElasticLaw& law, physics::CellMatrixX& K) {
  physics::CellVectorX f;
  return physics::solid_cell(geo, u, law, f, &K);
}

/// The nodal displacements of cell c from U, as its geometry's family takes them.
fe::HexCoords values(const ExplicitView& model, const fe::HexGeometry&, Index c, const Vector& U) {
  return model.hex8_values(c, U);
}
fe::CellNodeCoords values(const ExplicitView& model, const physics::CellGeometry&, Index c,
                          const Vector& U) {
  return model.node_values(c, U);
}

/// The cell matrix type of a geometry: 24 × 24 for a hex8, sized to the cell for the others.
template <class Geometry>
using CellMatrixOf = std::conditional_t<std::is_same_v<Geometry, fe::HexGeometry>,
                                        physics::HexMatrix, physics::CellMatrixX>;

/// K_e = K_W,e + K_Λ,e of cell c of geometry `geo` at U (K_Λ left out if `lambda` is empty).
template <class Geometry>
CellMatrixOf<Geometry> cell_stiffness(const ExplicitView& model, const Geometry& geo,
                                      Constraint constraint, const Vector& U, const Vector& lambda,
                                      Index c) {
  const auto u = values(model, geo, c, U);
  CellMatrixOf<Geometry> K, K_lambda;
  solid_element(geo, u, model.law(c), K);
  if (lambda.size() > 0 && lambda[c] != 0.0 &&
      multiplier_stiffness(geo, u, constraint, lambda[c], K_lambda))
    K += K_lambda;
  return K;
}

/// The lumped masses of cell c of geometry `geo` (those build_mass gives its nodes), three per
/// node.
physics::HexVector cell_mass(const ExplicitView& model, const fe::HexGeometry& geo, Index c) {
  const auto& rule = fe::hex_gauss_2x2x2();
  physics::HexVector m = physics::HexVector::Zero();
  for (int q = 0; q < 8; ++q) {
    const fe::HexShape N = fe::hex8_shape(rule[q].xi);
    for (int a = 0; a < 8; ++a)
      m.segment<3>(3 * a).array() += model.density(c) * N[a] * geo.dV[q];
  }
  return m;
}
physics::CellVectorX cell_mass(const ExplicitView& model, const physics::CellGeometry& geo,
                               Index c) {
  const Eigen::VectorXd nodal =
      physics::lumped_mass(physics::consistent_cell_mass(geo, model.density(c)));
  physics::CellVectorX m(3 * nodal.size());
  for (Index a = 0; a < nodal.size(); ++a)
    m.segment<3>(3 * a).setConstant(nodal[a]);
  return m;
}

/// y = K(U) v, element by element (never assembled).
void apply_stiffness(const ExplicitView& model, Constraint constraint, const Vector& U,
                     const Vector& lambda, const Vector& v, CellVectors& scratch, Vector& y) {
  const Index n = model.num_cells();
  const std::vector<Index>& offsets = model.cell_offsets();
  scratch.resize(offsets.back());
#pragma omp parallel for schedule(static) if (n >= kMinParallelLoop)
  for (Index c = 0; c < n; ++c) {
    if (!model.evaluates(c)) // (gather reads the cells of this process's nodes only)
      continue;
    auto out = scratch.segment(offsets[c], offsets[c + 1] - offsets[c]);
    if (!model.deformable(c)) {
      out.setZero();
      continue;
    }
    std::visit(
        [&](const auto& geo) {
          using Matrix = CellMatrixOf<std::decay_t<decltype(geo)>>;
          const Matrix K = cell_stiffness(model, geo, constraint, U, lambda, c);
          const auto vc = values(model, geo, c, v);
          Eigen::Matrix<Real, Matrix::RowsAtCompileTime, 1, 0, Matrix::MaxRowsAtCompileTime, 1> ve(
              K.rows());
          for (Index a = 0; a < vc.rows(); ++a)
            ve.template segment<3>(3 * a) = vc.row(a).transpose();
          out = K * ve;
        },
        model.geometry()[c]);
  }
  gather(model, scratch, nullptr, y);
}

/// The M-orthogonal projection on ker Hᵀ: w ← w − M⁻¹H (HᵀM⁻¹H + δ)⁻¹ Hᵀ w.
class Projector {
public:
  Projector(const ExplicitView& model, Constraint constraint, const Vector& U)
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
      const std::span<const Index> nodes = model.mesh().cell_nodes(c);
      for (std::size_t a = 0; a < nodes.size(); ++a)
        d += h_.segment<3>(model.cell_offsets()[c] + 3 * static_cast<Index>(a))
                 .cwiseAbs2()
                 .dot(model.frequency_inverse_mass().segment<3>(3 * nodes[a]));
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
  const ExplicitView& model_;
  LambdaSystem system_;
  CellVectors h_;
  bool ok_ = false;
};

/// A deterministic, non-smooth start vector (zero on fixed DOFs and those of rigid bodies): it has
/// components along the high-frequency modes that the power iteration must find.
Vector start_vector(const ExplicitView& model) {
  Vector v(model.num_dofs());
  for (Index i = 0; i < model.num_dofs(); ++i)
    v[i] = model.frequency_inverse_mass()[i] == 0.0
               ? 0.0
               : std::sin(12.9898 * i + 78.233 * (i % 7)) + 0.1;
  return v;
}

Real mass_norm(const ExplicitView& model, const Vector& v) {
  return std::sqrt(v.cwiseAbs2().dot(model.mass()));
}

} // namespace

FrequencyEstimate power_iteration_omega(const ExplicitView& model, Constraint constraint,
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
  CellVectors scratch;
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

FrequencyEstimate element_bound_omega(const ExplicitView& model, Constraint constraint,
                                      const Vector& U, const Vector& lambda) {
  const Index n = model.num_cells();
  Real max_omega2 = 0.0;
#pragma omp parallel for schedule(static) reduction(max : max_omega2) if (n >= kMinParallelLoop)
  for (Index c = 0; c < n; ++c) {
    if (!model.deformable(c))
      continue;
    std::visit(
        [&](const auto& geo) {
          using Matrix = CellMatrixOf<std::decay_t<decltype(geo)>>;
          const Matrix K = cell_stiffness(model, geo, constraint, U, lambda, c);
          const auto s = cell_mass(model, geo, c).cwiseSqrt().cwiseInverse().eval();
          const Matrix A = s.asDiagonal() * K * s.asDiagonal();
          Eigen::SelfAdjointEigenSolver<Matrix> eig(A, Eigen::EigenvaluesOnly);
          max_omega2 = std::max(max_omega2, eig.eigenvalues().maxCoeff());
        },
        model.geometry()[c]);
  }
  return {std::sqrt(max_omega2), 0, true};
}

} // namespace trifem::explicit_dynamics
