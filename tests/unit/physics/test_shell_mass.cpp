// SPDX-License-Identifier: MIT
// Exact answers checked: the consistent mass of a flat quad4 shell (a parallelogram in space, and
// a triangle given as a quad whose last node repeats the third) sums to ρ t A, its first moment
// Σ_ab X_a m_ab is ρ t A X_c (the centroid), and its second moment Σ_ab X_a X_bᵀ m_ab is
// ρ t ∫ X Xᵀ dA, from the closed forms of the parallelogram and the triangle; m is symmetric
// and positive semi-definite.
#include "trifem/physics/cell_mass.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

using namespace trifem;

namespace {

/// ∫ X Xᵀ dA over the parallelogram O + s e1 + r e2, s, r ∈ [0, 1] (exact).
Mat3 parallelogram_second_moment(const Vec3& o, const Vec3& e1, const Vec3& e2) {
  const Real area = e1.cross(e2).norm();
  const Mat3 oo = o * o.transpose();
  const Mat3 mixed = 0.5 * (o * (e1 + e2).transpose() + (e1 + e2) * o.transpose());
  const Mat3 quad = e1 * e1.transpose() / 3 + e2 * e2.transpose() / 3 +
                    0.25 * (e1 * e2.transpose() + e2 * e1.transpose());
  return area * (oo + mixed + quad);
}

/// ∫ X Xᵀ dA over the triangle a, b, c (exact): A/12 (Σ X_i X_iᵀ + (Σ X_i)(Σ X_i)ᵀ).
Mat3 triangle_second_moment(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Real area = 0.5 * (b - a).cross(c - a).norm();
  const Vec3 s = a + b + c;
  return area / 12 *
         (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
}

void expect_moments(const fe::QuadCoords& X, Real rho_t, Real area, const Vec3& centroid,
                    const Mat3& second) {
  const Eigen::Matrix4d m = physics::consistent_shell_mass(X, rho_t);
  const Real mass = rho_t * area;
  EXPECT_NEAR(m.sum(), mass, 1e-14 * mass);
  EXPECT_LE((m - m.transpose()).norm(), 1e-15 * mass);
  EXPECT_GE(Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d>(m).eigenvalues().minCoeff(),
            -1e-15 * mass);
  const Vec3 first = X.transpose() * m.rowwise().sum();
  EXPECT_LE((first - mass * centroid).norm(), 1e-14 * mass * centroid.norm());
  const Mat3 inertia = X.transpose() * m * X;
  EXPECT_LE((inertia - rho_t * second).norm(), 1e-13 * (rho_t * second).norm());
}

} // namespace

TEST(ShellMass, AParallelogramInSpaceHasItsMassCentroidAndSecondMoment) {
  const Vec3 o(0.3, -1.0, 2.0), e1(2.0, 0.5, -0.3), e2(0.4, 1.5, 0.8);
  fe::QuadCoords X;
  X.row(0) = o.transpose();
  X.row(1) = (o + e1).transpose();
  X.row(2) = (o + e1 + e2).transpose();
  X.row(3) = (o + e2).transpose();
  const Real rho_t = 7e-9 * 0.3;
  expect_moments(X, rho_t, e1.cross(e2).norm(), o + 0.5 * (e1 + e2),
                 parallelogram_second_moment(o, e1, e2));
}

TEST(ShellMass, ATriangleGivenAsADegenerateQuadHasItsMassCentroidAndSecondMoment) {
  const Vec3 a(0.1, 0.2, 0.0), b(1.7, -0.4, 0.9), c(0.5, 1.3, -0.6);
  fe::QuadCoords X;
  X.row(0) = a.transpose();
  X.row(1) = b.transpose();
  X.row(2) = c.transpose();
  X.row(3) = c.transpose();
  expect_moments(X, 2.0, 0.5 * (b - a).cross(c - a).norm(), (a + b + c) / 3,
                 triangle_second_moment(a, b, c));
}
