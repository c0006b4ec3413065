// SPDX-License-Identifier: MIT
// Finite rotations (exp, log, the tangent map T and its derivative H) and the condensation of
// element contributions onto rigid bodies' unknowns, against closed forms and central
// differences.
#include "trifem/dofs/rigid_map.hpp"
#include "trifem/tensor/rotation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace trifem;

namespace {

constexpr Real kPi = std::numbers::pi;

const Vec3 kAxis = Vec3(1.0, -2.0, 3.0).normalized();

/// The axial vector of a (nearly) skew matrix.
Vec3 axial(const Mat3& W) {
  return 0.5 * Vec3(W(2, 1) - W(1, 2), W(0, 2) - W(2, 0), W(1, 0) - W(0, 1));
}

/// Angles across the series threshold (0.3), up to π.
const Real kAngles[] = {0.0, 1e-9, 1e-3, 0.1, 0.3 - 1e-9, 0.3 + 1e-9, 1.0, 2.5, kPi - 1e-6};

} // namespace

TEST(Rotation, MatrixIsTheRodriguesRotationAboutTheAxis) {
  for (Real angle : kAngles) {
    const Mat3 R = rotation::matrix(angle * kAxis);
    const Mat3 expected = std::cos(angle) * Mat3::Identity() +
                          std::sin(angle) * rotation::skew(kAxis) +
                          (1.0 - std::cos(angle)) * kAxis * kAxis.transpose();
    EXPECT_LT((R - expected).norm(), 1e-15) << angle;
    EXPECT_LT((R.transpose() * R - Mat3::Identity()).norm(), 4e-15) << angle;
  }
}

TEST(Rotation, VectorInvertsMatrixUpToHalfATurn) {
  for (Real angle : kAngles) {
    const Vec3 theta = angle * kAxis;
    EXPECT_LT((rotation::vector(rotation::matrix(theta)) - theta).norm(), 1e-15 * (1.0 + angle))
        << angle;
  }
  const Vec3 half_turn = rotation::vector(rotation::matrix(kPi * kAxis)); // ±π n
  EXPECT_NEAR(half_turn.norm(), kPi, 1e-14);
  EXPECT_NEAR(std::abs(half_turn.dot(kAxis)), kPi, 1e-14);
  for (int k = 0; k < 3; ++k) // about each axis, through each branch of the quaternion
    EXPECT_LT(
        (rotation::vector(rotation::matrix(3.0 * Vec3::Unit(k))) - 3.0 * Vec3::Unit(k)).norm(),
        1e-14);
}

TEST(Rotation, TangentMapsAVariationOfTheVectorToTheSpatialAngularVariation) {
  const Vec3 direction = Vec3(0.3, 0.9, -0.4).normalized();
  const Real h = 1e-6;
  for (Real angle : kAngles) {
    const Vec3 theta = angle * kAxis;
    const Mat3 dR =
        (rotation::matrix(theta + h * direction) - rotation::matrix(theta - h * direction)) /
        (2.0 * h);
    const Vec3 expected = axial(dR * rotation::matrix(theta).transpose());
    EXPECT_LT((rotation::tangent(theta) * direction - expected).norm(), 1e-9) << angle;
  }
}

TEST(Rotation, TangentDerivativeIsTheDerivativeOfTTransposedTimesM) {
  const Vec3 m(0.7, -1.3, 0.4);
  const Real h = 1e-6;
  for (Real angle : kAngles) {
    const Vec3 theta = angle * kAxis;
    const Mat3 H = rotation::tangent_derivative(theta, m);
    for (int j = 0; j < 3; ++j) {
      const Vec3 e = h * Vec3::Unit(j);
      const Vec3 fd = (rotation::tangent(theta + e).transpose() * m -
                       rotation::tangent(theta - e).transpose() * m) /
                      (2.0 * h);
      EXPECT_LT((H.col(j) - fd).norm(), 1e-9 * m.norm()) << angle << " column " << j;
    }
  }
}

TEST(Rotation, SeriesAndClosedFormsAgreeAtTheThreshold) {
  const Vec3 m(0.7, -1.3, 0.4);
  // the largest angle of the series and the smallest of the closed forms (θ = |Θ| exactly)
  const Vec3 below(0.0, 0.0, std::nextafter(0.3, 0.0)), above(0.0, 0.0, 0.3);
  EXPECT_LT((rotation::matrix(below) - rotation::matrix(above)).norm(), 1e-15);
  EXPECT_LT((rotation::tangent(below) - rotation::tangent(above)).norm(), 1e-15);
  EXPECT_LT(
      (rotation::tangent_derivative(below, m) - rotation::tangent_derivative(above, m)).norm(),
      1e-14);
  // the series at θ = 0 give the limits: T = I, H = ½[m]×
  EXPECT_EQ(rotation::tangent(Vec3::Zero()), Mat3::Identity());
  EXPECT_LT((rotation::tangent_derivative(Vec3::Zero(), m) - 0.5 * rotation::skew(m)).norm(),
            1e-16);
}

namespace {

/// Two rigid bodies (DOFs 0–5 and 6–11), a free node (12–14), two nodes carried by the first
/// body (15–20) and one by the second (21–23), and a nonlinear energy of the nodes.
struct TwoBodies {
  static constexpr Index kDofs = 24;
  dofs::RigidMap map;
  std::vector<Index> element{21, 22, 23, 12, 13, 14, 15, 16, 17, 18, 19, 20};
  Eigen::MatrixXd A;
  Eigen::VectorXd g;

  TwoBodies() {
    dofs::RigidBodyDofs first{{0, 1, 2}, {3, 4, 5}, Vec3(0.5, -0.2, 0.1), {}, {}};
    first.followers = {{15, 16, 17}, {18, 19, 20}};
    first.arms = {Vec3(1.0, 0.3, -0.5), Vec3(-0.4, 0.8, 0.6)};
    dofs::RigidBodyDofs second{{6, 7, 8}, {9, 10, 11}, Vec3(2.0, 1.0, 0.0), {}, {}};
    second.followers = {{21, 22, 23}};
    second.arms = {Vec3(0.2, -0.9, 0.7)};
    map = dofs::RigidMap({first, second}, kDofs);
    const Index n = static_cast<Index>(element.size());
    A.setZero(n, n);
    for (Index i = 0; i < n; ++i)
      for (Index j = 0; j < n; ++j)
        A(i, j) = 1.0 / (1.0 + i + j) + (i == j ? 2.0 : 0.0); // symmetric positive
    g = Eigen::VectorXd::LinSpaced(n, -1.0, 1.0);
  }

  Eigen::VectorXd values(const Vector& x) const {
    Eigen::VectorXd u(element.size());
    for (std::size_t i = 0; i < element.size(); ++i)
      u[static_cast<Index>(i)] = x[element[i]];
    return u;
  }
  /// Π = gᵀu + ½uᵀAu + ¼ Σ u⁴, its gradient and Hessian in the element's DOFs.
  Real energy(const Vector& x) const {
    const Eigen::VectorXd u = values(x);
    return g.dot(u) + 0.5 * u.dot(A * u) + 0.25 * u.array().pow(4).sum();
  }
  Eigen::VectorXd gradient(const Vector& x) const {
    const Eigen::VectorXd u = values(x);
    return g + A * u + u.array().cube().matrix();
  }
  Eigen::MatrixXd hessian(const Vector& x) const {
    const Eigen::VectorXd u = values(x);
    return A + Eigen::MatrixXd((3.0 * u.array().square()).matrix().asDiagonal());
  }
  /// A state with the given rotation of both bodies, translations and a free node's
  /// displacement, followers applied.
  Vector state(const Vec3& theta) const {
    Vector x = Vector::Zero(kDofs);
    x.segment<3>(0) = Vec3(0.1, -0.2, 0.05);
    x.segment<3>(3) = theta;
    x.segment<3>(6) = Vec3(-0.1, 0.02, 0.3);
    x.segment<3>(9) = -0.7 * theta.reverse();
    x.segment<3>(12) = Vec3(0.2, 0.1, -0.3);
    map.apply(x);
    return x;
  }
};

} // namespace

TEST(RigidMap, FollowersMoveWithTheirBody) {
  const TwoBodies model;
  const Vec3 theta = 2.0 * kAxis;
  const Vector x = model.state(theta);
  const auto& body = model.map.bodies()[0];
  for (std::size_t f = 0; f < body.followers.size(); ++f) {
    const Vec3 X = body.centre + body.arms[f];
    const Vec3 x_expected = body.centre + x.segment<3>(0) + rotation::matrix(theta) * body.arms[f];
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(X[k] + x[body.followers[f][k]], x_expected[k], 1e-15);
  }
  EXPECT_EQ(model.map.body_of(16), 0);
  EXPECT_EQ(model.map.body_of(22), 1);
  EXPECT_EQ(model.map.body_of(13), -1);
  std::vector<Index> expanded;
  model.map.expand(model.element, expanded);
  EXPECT_EQ(expanded, (std::vector<Index>{12, 13, 14, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11}));
}

TEST(RigidMap, CondensationIsTheGradientAndHessianOfTheEnergyInTheBodiesUnknowns) {
  const TwoBodies model;
  for (const Real angle : {0.0, 1.0, 3.0}) {
    const Vector x = model.state(angle * kAxis);
    const Eigen::MatrixXd K = model.hessian(x);
    dofs::CondensedElement c;
    ASSERT_TRUE(model.map.condense(model.element, x, model.gradient(x), &K, c));
    const Index m = static_cast<Index>(c.dofs.size());
    ASSERT_EQ(c.first_body_dof, 3);
    Eigen::VectorXd fd_gradient(m);
    Eigen::MatrixXd fd_hessian(m, m);
    const Real h = 1e-5;
    for (Index j = 0; j < m; ++j) {
      Vector plus = x, minus = x;
      plus[c.dofs[j]] += h;
      minus[c.dofs[j]] -= h;
      model.map.apply(plus);
      model.map.apply(minus);
      fd_gradient[j] = (model.energy(plus) - model.energy(minus)) / (2.0 * h);
      dofs::CondensedElement cp, cm;
      model.map.condense(model.element, plus, model.gradient(plus), nullptr, cp);
      model.map.condense(model.element, minus, model.gradient(minus), nullptr, cm);
      fd_hessian.col(j) = (cp.residual - cm.residual) / (2.0 * h);
    }
    const Real scale = c.jacobian.cwiseAbs().maxCoeff();
    EXPECT_LT((c.residual - fd_gradient).norm(), 1e-7 * c.residual.norm()) << angle;
    EXPECT_LT((c.jacobian - fd_hessian).cwiseAbs().maxCoeff(), 1e-7 * scale) << angle;
    // the Hessian of an energy is symmetric, the geometric stiffness included
    EXPECT_LT((c.jacobian - c.jacobian.transpose()).cwiseAbs().maxCoeff(), 1e-13 * scale) << angle;
  }
}

TEST(RigidMap, AnElementOnNoBodyIsLeftAlone) {
  const TwoBodies model;
  const Vector x = model.state(kAxis);
  dofs::CondensedElement c;
  const std::vector<Index> free_node{12, 13, 14};
  EXPECT_FALSE(model.map.condense(free_node, x, Eigen::VectorXd::Ones(3), nullptr, c));
  EXPECT_TRUE(c.dofs.empty());
}
