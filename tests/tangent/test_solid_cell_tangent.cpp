// SPDX-License-Identifier: MIT
// Finite-difference checks of the solid element of every cell family (physics/solid_cell.hpp)
// and of its mean-dilatation element (mean_dilatation_cell) for every registered law, on
// distorted cells at random deformed states: the force is the gradient of the stored energy and
// the tangent the Jacobian of the force.
#include "cell_families.hpp"
#include "trifem/material/registry.hpp"
#include "trifem/physics/mean_dilatation_kernel.hpp"
#include "trifem/physics/solid_cell.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace trifem;
using test::as_rows;
using test::kCellFamilies;
using test::Noise;

namespace {

/// Π(u) = Σ_q W(C_q) dV_q, from its definition.
Real cell_stored_energy(const physics::CellGeometry& geo, const fe::CellNodeCoords& u,
                        const material::ElasticLaw& law) {
  Real energy = 0.0;
  for (std::size_t q = 0; q < geo.dV.size(); ++q) {
    const Mat3 F = Mat3::Identity() + u.transpose() * geo.dN_dX[q];
    energy += law.energy(F.transpose() * F) * geo.dV[q];
  }
  return energy;
}

/// Π(u) = Σ_q W(C̄_q) dV_q with C̄ = (J̄/J)^(2/3) C and J̄ = v/V: the mean-dilatation element's
/// potential, from its definition.
Real cell_mean_dilatation_energy(const physics::CellGeometry& geo, const fe::CellNodeCoords& u,
                                 const material::ElasticLaw& law) {
  Real V = 0.0, v = 0.0;
  for (std::size_t q = 0; q < geo.dV.size(); ++q) {
    const Mat3 F = Mat3::Identity() + u.transpose() * geo.dN_dX[q];
    V += geo.dV[q];
    v += F.determinant() * geo.dV[q];
  }
  Real energy = 0.0;
  for (std::size_t q = 0; q < geo.dV.size(); ++q) {
    const Mat3 F = Mat3::Identity() + u.transpose() * geo.dN_dX[q];
    const Real alpha2 = std::pow(v / V / F.determinant(), 2.0 / 3.0);
    energy += law.energy(alpha2 * F.transpose() * F) * geo.dV[q];
  }
  return energy;
}

/// For every law on a distorted cell of every family (cell seed `cell_seed`) at a random state
/// (seed `state_seed`): kernel(geo, u, law, f, K) gives f = ∂Π/∂u of Π = energy(geo, u, law) and
/// K = ∂f/∂u, symmetric, by central differences; the force alone is the same without K.
template <class Kernel, class Energy>
void expect_force_and_tangent_of_the_potential(Kernel kernel, Energy energy, unsigned cell_seed,
                                               unsigned state_seed) {
  for (const fe::CellType type : kCellFamilies)
    for (const auto& entry : material::registered_laws()) {
      SCOPED_TRACE(::testing::Message()
                   << "cell type " << static_cast<int>(type) << ", law " << entry.type);
      const auto law = material::create_law(entry.type, entry.example, "m");
      const auto geo = physics::cell_geometry(fe::reference_cell(type),
                                              test::distorted_cell(type, cell_seed, 0.08));
      ASSERT_TRUE(geo.has_value());
      const Index n = 3 * geo->num_nodes();
      Noise noise(state_seed);
      Eigen::VectorXd u0(n);
      for (Index i = 0; i < n; ++i)
        u0[i] = 0.1 * noise.next();
      physics::CellVectorX f, f_only;
      physics::CellMatrixX K;
      ASSERT_TRUE(kernel(*geo, as_rows(u0), *law, f, &K));
      ASSERT_TRUE(kernel(*geo, as_rows(u0), *law, f_only, nullptr));
      EXPECT_LE((f - f_only).norm(), 1e-13 * f.norm());
      const Real h = 1e-6;
      Eigen::VectorXd f_fd(n);
      Eigen::MatrixXd K_fd(n, n);
      for (Index j = 0; j < n; ++j) {
        Eigen::VectorXd up = u0, um = u0;
        up[j] += h;
        um[j] -= h;
        f_fd[j] = (energy(*geo, as_rows(up), *law) - energy(*geo, as_rows(um), *law)) / (2 * h);
        physics::CellVectorX fp, fm;
        ASSERT_TRUE(kernel(*geo, as_rows(up), *law, fp, nullptr));
        ASSERT_TRUE(kernel(*geo, as_rows(um), *law, fm, nullptr));
        K_fd.col(j) = (fp - fm) / (2 * h);
      }
      EXPECT_LE((Eigen::VectorXd(f) - f_fd).norm() / f.norm(), 1e-6);
      EXPECT_LE((Eigen::MatrixXd(K) - K_fd).norm() / K.norm(), 1e-6);
      EXPECT_LE((K - K.transpose()).norm() / K.norm(), 1e-12);
    }
}

} // namespace

// The same checks for the mean-dilatation element of every family: f = ∂Π/∂u of the potential
// Σ W(C̄) dV and K = ∂f/∂u, symmetric.
TEST(MeanDilatationCell, ForceIsTheGradientOfItsPotentialAndTangentTheJacobianOfTheForce) {
  expect_force_and_tangent_of_the_potential(physics::mean_dilatation_cell,
                                            cell_mean_dilatation_energy, 5, 13);
}

// On a hex8 the element of any family is the hex8 kernel: the same force and tangent.
TEST(MeanDilatationCell, EqualsTheHex8KernelOnAHex8) {
  const auto law = material::create_law("neo-hookean", {{"E", 1.0}, {"nu", 0.45}}, "m");
  const fe::CellNodeCoords X = test::distorted_cell(fe::CellType::Hex8, 3, 0.08);
  const auto geo = physics::cell_geometry(fe::reference_cell(fe::CellType::Hex8), X);
  const auto hex = fe::hex8_geometry(fe::HexCoords(X));
  ASSERT_TRUE(geo && hex);
  Noise noise(17);
  fe::CellNodeCoords u(8, 3);
  for (Index a = 0; a < 8; ++a)
    for (int k = 0; k < 3; ++k)
      u(a, k) = 0.1 * noise.next();
  physics::CellVectorX f;
  physics::CellMatrixX K;
  physics::HexVector f8;
  physics::HexMatrix K8;
  ASSERT_TRUE(physics::mean_dilatation_cell(*geo, u, *law, f, &K));
  ASSERT_TRUE(physics::mean_dilatation_hex8(*hex, fe::HexCoords(u), *law, f8, &K8));
  EXPECT_LE((Eigen::VectorXd(f) - Eigen::VectorXd(f8)).norm(), 1e-13 * f8.norm());
  EXPECT_LE((Eigen::MatrixXd(K) - Eigen::MatrixXd(K8)).norm(), 1e-13 * K8.norm());
}

TEST(SolidCell, ForceIsTheGradientOfTheEnergyAndTangentTheJacobianOfTheForce) {
  expect_force_and_tangent_of_the_potential(physics::solid_cell, cell_stored_energy, 7, 11);
}
