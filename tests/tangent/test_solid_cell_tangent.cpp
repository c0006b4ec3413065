// SPDX-License-Identifier: MIT
// Finite-difference checks of the solid element of every cell family (physics/solid_cell.hpp)
// for every registered law, on distorted cells at random deformed states: the force is the
// gradient of the stored energy and the tangent the Jacobian of the force.
#include "cell_families.hpp"
#include "trifem/material/registry.hpp"
#include "trifem/physics/solid_cell.hpp"

#include <gtest/gtest.h>

using namespace trifem;
using test::kCellFamilies;
using test::Noise;

namespace {

fe::CellNodeCoords as_rows(const Eigen::VectorXd& v) {
  fe::CellNodeCoords u(v.size() / 3, 3);
  for (Index a = 0; a < u.rows(); ++a)
    u.row(a) = v.segment<3>(3 * a).transpose();
  return u;
}

/// Π(u) = Σ_q W(C_q) dV_q, from its definition.
Real stored_energy(const physics::CellGeometry& geo, const fe::CellNodeCoords& u,
                   const material::ElasticLaw& law) {
  Real energy = 0.0;
  for (std::size_t q = 0; q < geo.dV.size(); ++q) {
    const Mat3 F = Mat3::Identity() + u.transpose() * geo.dN_dX[q];
    energy += law.energy(F.transpose() * F) * geo.dV[q];
  }
  return energy;
}

} // namespace

TEST(SolidCell, ForceIsTheGradientOfTheEnergyAndTangentTheJacobianOfTheForce) {
  for (const fe::CellType type : kCellFamilies)
    for (const auto& entry : material::registered_laws()) {
      SCOPED_TRACE(::testing::Message()
                   << "cell type " << static_cast<int>(type) << ", law " << entry.type);
      const auto law = material::create_law(entry.type, entry.example, "m");
      const auto geo =
          physics::cell_geometry(fe::reference_cell(type), test::distorted_cell(type, 7, 0.08));
      ASSERT_TRUE(geo.has_value());
      const Index n = 3 * geo->num_nodes();
      Noise noise(11);
      Eigen::VectorXd u0(n);
      for (Index i = 0; i < n; ++i)
        u0[i] = 0.1 * noise.next();
      physics::CellVectorX f;
      physics::CellMatrixX K;
      ASSERT_TRUE(physics::solid_cell(*geo, as_rows(u0), *law, f, &K));
      physics::CellVectorX f_only;
      ASSERT_TRUE(physics::solid_cell(*geo, as_rows(u0), *law, f_only, nullptr));
      EXPECT_LE((f - f_only).norm(), 1e-13 * f.norm());
      const Real h = 1e-6;
      Eigen::VectorXd f_fd(n);
      Eigen::MatrixXd K_fd(n, n);
      for (Index j = 0; j < n; ++j) {
        Eigen::VectorXd up = u0, um = u0;
        up[j] += h;
        um[j] -= h;
        f_fd[j] =
            (stored_energy(*geo, as_rows(up), *law) - stored_energy(*geo, as_rows(um), *law)) /
            (2 * h);
        physics::CellVectorX fp, fm;
        ASSERT_TRUE(physics::solid_cell(*geo, as_rows(up), *law, fp, nullptr));
        ASSERT_TRUE(physics::solid_cell(*geo, as_rows(um), *law, fm, nullptr));
        K_fd.col(j) = (fp - fm) / (2 * h);
      }
      EXPECT_LE((Eigen::VectorXd(f) - f_fd).norm() / f.norm(), 1e-6);
      EXPECT_LE((Eigen::MatrixXd(K) - K_fd).norm() / K.norm(), 1e-6);
      EXPECT_LE((K - K.transpose()).norm() / K.norm(), 1e-12);
    }
}
