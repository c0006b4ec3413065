// SPDX-License-Identifier: MIT
// Finite-difference checks of element tangents at random deformed states on distorted cells.
#include "trifem/material/registry.hpp"
#include "trifem/mesh/box.hpp"
#include "trifem/physics/solid_kernel.hpp"
#include "trifem/physics/surface_load_term.hpp"

#include <gtest/gtest.h>

using namespace trifem;

namespace {

fe::HexCoords distorted_unit_cube(unsigned seed) {
  std::srand(seed);
  fe::HexCoords X;
  const Real r[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                        {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (int a = 0; a < 8; ++a)
    for (int k = 0; k < 3; ++k)
      X(a, k) = r[a][k] + 0.15 * (std::rand() / Real(RAND_MAX) - 0.5);
  return X;
}

/// Central-difference Jacobian of f(u) (24 -> 24), step relative to the displacement scale.
template <class F>
Eigen::MatrixXd fd_jacobian(F&& residual, Eigen::VectorXd u, Real h) {
  const Eigen::VectorXd r0 = residual(u);
  Eigen::MatrixXd K(r0.size(), u.size());
  for (int j = 0; j < u.size(); ++j) {
    Eigen::VectorXd up = u, um = u;
    up[j] += h;
    um[j] -= h;
    K.col(j) = (residual(up) - residual(um)) / (2 * h);
  }
  return K;
}

} // namespace

TEST(SolidHex8, TangentMatchesFiniteDifferences) {
  for (const auto& law : material::registered_laws()) {
    auto m = material::create_law(law.type, law.example, "m");
    for (unsigned seed : {11u, 12u}) {
      const auto geo = fe::hex8_geometry(distorted_unit_cube(seed));
      ASSERT_TRUE(geo.has_value());
      std::srand(seed + 100);
      Eigen::VectorXd u0 = 0.12 * Eigen::VectorXd::Random(24);
      auto residual = [&](const Eigen::VectorXd& u) {
        physics::HexVector f;
        fe::HexCoords Ur;
        for (int a = 0; a < 8; ++a)
          Ur.row(a) = u.segment<3>(3 * a).transpose();
        EXPECT_TRUE(physics::solid_hex8(*geo, Ur, *m, f, nullptr));
        return Eigen::VectorXd(f);
      };
      fe::HexCoords U;
      for (int a = 0; a < 8; ++a)
        U.row(a) = u0.segment<3>(3 * a).transpose();
      physics::HexVector f;
      physics::HexMatrix K;
      ASSERT_TRUE(physics::solid_hex8(*geo, U, *m, f, &K));
      // residual from the tangent path equals the residual-only path
      EXPECT_LE((f - residual(u0)).norm(), 1e-13 * f.norm());
      const Eigen::MatrixXd K_fd = fd_jacobian(residual, u0, 1e-6);
      EXPECT_LE((K - K_fd).norm() / K.norm(), 1e-6) << law.type << " seed " << seed;
    }
  }
}

TEST(PressureLoad, FollowerTangentMatchesFiniteDifferences) {
  mesh::BoxSpec spec;
  spec.divisions = {1, 1, 1};
  const mesh::Mesh mesh = mesh::make_box(spec);
  dofs::DofMap map;
  const auto u = map.add_field("displacement", mesh.num_nodes(), 3);
  map.finalize();
  const auto& facets = mesh.surface("box.zmax").facets;
  physics::PressureTerm term(mesh, map, u, facets, 0.7, dofs::LoadCurve::constant());
  std::vector<Index> dofs;
  term.element_dofs(0, dofs);
  std::srand(5);
  Vector x = 0.2 * Vector::Random(map.num_dofs());
  const Vector x_old = x;
  auto residual = [&](const Eigen::VectorXd& local) {
    Vector y = x;
    for (int i = 0; i < 12; ++i)
      y[dofs[i]] = local[i];
    physics::LocalVector r;
    term.evaluate(0, physics::EvalState{y, x_old, 1.0, 1.0}, r, nullptr);
    return Eigen::VectorXd(r);
  };
  Eigen::VectorXd local(12);
  for (int i = 0; i < 12; ++i)
    local[i] = x[dofs[i]];
  physics::LocalVector r;
  physics::LocalMatrix K;
  term.evaluate(0, physics::EvalState{x, x_old, 1.0, 1.0}, r, &K);
  const Eigen::MatrixXd K_fd = fd_jacobian(residual, local, 1e-6);
  EXPECT_LE((K - K_fd).norm() / K.norm(), 1e-7);
  // total force on a flat undeformed facet is p * area along the inward normal
  x.setZero();
  term.evaluate(0, physics::EvalState{x, x_old, 1.0, 1.0}, r, nullptr);
  Vec3 total = Vec3::Zero();
  for (int a = 0; a < 4; ++a)
    total += r.segment<3>(3 * a);
  const Real pA = 0.7 * 1.0;              // p times the unit facet area
  EXPECT_NEAR(total.z(), pA, 1e-14 * pA); // R = -f_ext, f_ext = -p n A with n = +z
}
