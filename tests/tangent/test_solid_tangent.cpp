// SPDX-License-Identifier: MIT
// Finite-difference checks of element tangents at random deformed states on distorted cells.
#include "mixture_setup.hpp"
#include "trifem/material/registry.hpp"
#include "trifem/mesh/box.hpp"
#include "trifem/mesh/convert_cells.hpp"
#include "trifem/physics/mean_dilatation_kernel.hpp"
#include "trifem/physics/solid_kernel.hpp"
#include "trifem/physics/surface_load_term.hpp"

#include <gtest/gtest.h>

using namespace trifem;
using trifem::test::distorted_unit_cube;

namespace {

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

fe::HexCoords as_coords(const Eigen::VectorXd& u) {
  fe::HexCoords U;
  for (int a = 0; a < 8; ++a)
    U.row(a) = u.segment<3>(3 * a).transpose();
  return U;
}

/// Π(u) = Σ_q W(C̄_q) w_q of the mean-dilatation element, computed directly from its
/// definition C̄ = (J̄/J)^(2/3) C, J̄ = v/V (independent of the kernel's force and tangent).
Real mean_dilatation_energy(const fe::HexGeometry& geo, const fe::HexCoords& u,
                            const material::ElasticLaw& law) {
  Real V = 0.0, v = 0.0;
  for (int q = 0; q < 8; ++q) {
    V += geo.dV[q];
    v += physics::deformation_gradient(geo.dN_dX[q], u).determinant() * geo.dV[q];
  }
  Real energy = 0.0;
  for (int q = 0; q < 8; ++q) {
    const Mat3 F = physics::deformation_gradient(geo.dN_dX[q], u);
    const Real scale = std::pow(v / V / F.determinant(), 2.0 / 3.0);
    energy += law.energy(scale * F.transpose() * F) * geo.dV[q];
  }
  return energy;
}

} // namespace

TEST(MeanDilatationHex8, ForceIsTheGradientOfThePotentialAndTangentItsHessian) {
  for (const auto& law : material::registered_laws()) {
    auto m = material::create_law(law.type, law.example, "m");
    for (unsigned seed : {21u, 22u, 23u}) {
      const auto geo = fe::hex8_geometry(distorted_unit_cube(seed));
      ASSERT_TRUE(geo.has_value());
      std::srand(seed + 100);
      const Eigen::VectorXd u0 = 0.12 * Eigen::VectorXd::Random(24);
      auto force = [&](const Eigen::VectorXd& u) {
        physics::HexVector f;
        EXPECT_TRUE(physics::mean_dilatation_hex8(*geo, as_coords(u), *m, f, nullptr));
        return Eigen::VectorXd(f);
      };
      physics::HexVector f;
      physics::HexMatrix K;
      ASSERT_TRUE(physics::mean_dilatation_hex8(*geo, as_coords(u0), *m, f, &K));
      EXPECT_LE((f - force(u0)).norm(), 1e-13 * f.norm());
      // f = dΠ/du by central differences of the independently computed potential
      const Real h = 1e-6;
      Eigen::VectorXd f_fd(24);
      for (int j = 0; j < 24; ++j) {
        Eigen::VectorXd up = u0, um = u0;
        up[j] += h;
        um[j] -= h;
        f_fd[j] = (mean_dilatation_energy(*geo, as_coords(up), *m) -
                   mean_dilatation_energy(*geo, as_coords(um), *m)) /
                  (2 * h);
      }
      EXPECT_LE((f - f_fd).norm() / f.norm(), 1e-6) << law.type << " seed " << seed;
      const Eigen::MatrixXd K_fd = fd_jacobian(force, u0, h);
      EXPECT_LE((K - K_fd).norm() / K.norm(), 1e-6) << law.type << " seed " << seed;
      EXPECT_LE((K - K.transpose()).norm() / K.norm(), 1e-12) << law.type << " seed " << seed;
    }
  }
}

TEST(MeanDilatationHex8, EqualsTheDisplacementElementUnderHomogeneousDeformation) {
  // J is uniform, so J̄ = J, F̄ = F: force, tangent and stress equal the displacement element's.
  auto m = material::create_law("neo-hookean", {{"E", 3.0}, {"nu", 0.45}}, "m");
  const auto geo = fe::hex8_geometry(distorted_unit_cube(31));
  ASSERT_TRUE(geo.has_value());
  Mat3 H;
  H << 0.10, 0.03, -0.02, 0.01, -0.08, 0.04, 0.02, 0.05, 0.06;
  fe::HexCoords X = distorted_unit_cube(31), U;
  for (int a = 0; a < 8; ++a)
    U.row(a) = (H * X.row(a).transpose()).transpose();
  physics::HexVector f1, f2;
  physics::HexMatrix K1, K2;
  ASSERT_TRUE(physics::solid_hex8(*geo, U, *m, f1, &K1));
  ASSERT_TRUE(physics::mean_dilatation_hex8(*geo, U, *m, f2, &K2));
  EXPECT_LE((f1 - f2).norm(), 1e-12 * f1.norm());
  // the tangents differ by design (the mean-dilatation one is the Hessian of its own
  // potential), but their action on a homogeneous increment is the same
  Mat3 dH;
  dH << 0.3, -0.1, 0.2, 0.05, 0.1, -0.2, 0.1, 0.0, -0.3;
  Eigen::VectorXd du(24);
  for (int a = 0; a < 8; ++a)
    du.segment<3>(3 * a) = dH * X.row(a).transpose();
  EXPECT_LE((K1 * du - K2 * du).norm(), 1e-12 * (K1 * du).norm());
  const physics::CellStress s1 = physics::solid_hex8_stress(*geo, U, *m);
  const physics::CellStress s2 = physics::mean_dilatation_hex8_stress(*geo, U, *m);
  EXPECT_LE((s1.cauchy - s2.cauchy).norm(), 1e-12 * s1.cauchy.norm());
  EXPECT_NEAR(s1.J, s2.J, 1e-14);
}

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
  const auto u = map.add_field("displacement", FieldRole::displacement, mesh.num_nodes(), 3);
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

// A traction per current area in a fixed direction, f_a = t int N_a |x_s1 x x_s2| ds, on the
// top facets of every family (quad4, tri3, tri6, quad8) at a random deformed state: its tangent
// is that of central differences, and on the undeformed flat face the total force is t times the
// face's area.
TEST(TractionPerCurrentArea, TangentMatchesFiniteDifferencesOnEveryFacetFamily) {
  const Vec3 t(0.3, -0.2, 0.7);
  for (const mesh::CellType type :
       {mesh::CellType::Hex8, mesh::CellType::Tet4, mesh::CellType::Tet10, mesh::CellType::Hex20}) {
    mesh::BoxSpec spec;
    spec.divisions = {1, 1, 1};
    const mesh::Mesh mesh = mesh::convert_cells(mesh::make_box(spec), type);
    dofs::DofMap map;
    const auto u = map.add_field("displacement", FieldRole::displacement, mesh.num_nodes(), 3);
    map.finalize();
    const auto& facets = mesh.surface("box.zmax").facets;
    physics::TractionTerm term(mesh, map, u, facets, t, dofs::LoadCurve::constant(),
                               physics::TractionArea::Current);
    Vector x = Vector::Zero(map.num_dofs());
    Vec3 total = Vec3::Zero();
    for (Index e = 0; e < term.num_elements(); ++e) {
      physics::LocalVector r;
      term.evaluate(e, physics::EvalState{x, x, 1.0, 1.0}, r, nullptr);
      for (Index a = 0; a < r.size() / 3; ++a)
        total -= r.segment<3>(3 * a); // R = -f_ext
    }
    EXPECT_LE((total - t).norm(), 1e-14) << static_cast<int>(type); // the unit face
    std::srand(11);
    x = 0.15 * Vector::Random(map.num_dofs());
    std::vector<Index> dofs;
    term.element_dofs(0, dofs);
    const int n = static_cast<int>(dofs.size());
    auto residual = [&](const Eigen::VectorXd& local) {
      Vector y = x;
      for (int i = 0; i < n; ++i)
        y[dofs[i]] = local[i];
      physics::LocalVector r;
      term.evaluate(0, physics::EvalState{y, x, 1.0, 1.0}, r, nullptr);
      return Eigen::VectorXd(r);
    };
    Eigen::VectorXd local(n);
    for (int i = 0; i < n; ++i)
      local[i] = x[dofs[i]];
    physics::LocalVector r;
    physics::LocalMatrix K;
    term.evaluate(0, physics::EvalState{x, x, 1.0, 1.0}, r, &K);
    const Eigen::MatrixXd K_fd = fd_jacobian(residual, local, 1e-6);
    EXPECT_GT(K.norm(), 0.0);
    EXPECT_LE((K - K_fd).norm() / K.norm(), 1e-7) << static_cast<int>(type);
  }
}
