// SPDX-License-Identifier: MIT
// Material axes: the rotated law (a law evaluated in a local basis) against the law with rotated
// directions, central differences, rotation of body and axes together, the identity basis, the
// Voigt rotation, and the construction of the local bases (vector, cylindrical, spherical,
// completed from one direction) with their degenerate inputs.
#include "trifem/core/error.hpp"
#include "trifem/material/material_axes.hpp"
#include "trifem/material/registry.hpp"
#include "trifem/material/rotated_law.hpp"
#include "trifem/material/solid_mixture.hpp"

#include "law_differences.hpp"
#include "law_states.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

using namespace trifem;
using namespace trifem::test;

namespace {

using Law = std::shared_ptr<const material::ElasticLaw>;

/// A neo-Hookean matrix and one exp-pow fibre family along `fibre`.
Law fibre_mixture(const Vec3& fibre) {
  material::LawSpec matrix{"neo-hookean", {{"E", 0.5}, {"nu", 0.1}}, {}};
  material::LawSpec family{"fibre-exp-pow", {{"ksi", 5.0}, {"alpha", 0.8}, {"beta", 2.5}}, {}};
  material::set_vector(family.parameters, "fibre", fibre);
  return material::create_law(
      material::LawSpec{std::string(material::kSolidMixtureType), {}, {matrix, family}}, "test");
}

/// A fibre distribution with the ellipsoid `semi_axes` (alone: it is a constituent law).
Law distribution(const Vec3& semi_axes) {
  material::ParameterValues v = {{"ksi", 2.0}, {"alpha", 0.5}, {"beta", 2.5}};
  material::set_vector(v, "semi_axes", semi_axes);
  return material::create_law("fibre-distribution", v, "test");
}

/// A random rotation (the axis and angle of `seed`).
Mat3 random_rotation(std::uint64_t seed) {
  std::uint64_t state = seed;
  const Vec3 axis(uniform(state), uniform(state), uniform(state) + 2.0);
  return rotation(3.0 * uniform(state), axis);
}

/// C = F^T F of F = I + 0.2 R (random, stretches and shears of order 0.2, J > 0) times a
/// stretch of 1.4 along `stretched`, so that the fibres along it are in tension.
Mat3 random_state(std::uint64_t seed, const Vec3& stretched) {
  const Vec3 a = stretched.normalized();
  const Mat3 F =
      (Mat3::Identity() + 0.2 * random_matrix(seed)) * (Mat3::Identity() + 0.4 * a * a.transpose());
  return F.transpose() * F;
}

Real relative(const Mat3& a, const Mat3& b) {
  return (a - b).norm() / b.norm();
}
Real relative(const Mat6& a, const Mat6& b) {
  return (a - b).norm() / b.norm();
}

void expect_rotation(const Mat3& Q) {
  EXPECT_LE((Q.transpose() * Q - Mat3::Identity()).norm(), 1e-15) << Q;
  EXPECT_NEAR(Q.determinant(), 1.0, 1e-15) << Q;
}

} // namespace

TEST(RotatedLaw, EqualsTheLawWithTheRotatedFibre) {
  // The fibre a in the local basis Q is the global fibre Q a: the two laws are one.
  const Vec3 a = Vec3(1.0, 2.0, -0.5).normalized();
  Real worst_S = 0.0, worst_D = 0.0;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const Mat3 Q = random_rotation(seed);
    const material::RotatedLaw local(fibre_mixture(a), Q);
    const Law global = fibre_mixture(Q * a);
    const Mat3 C = random_state(seed + 100, Q * a);
    const auto r = local.stress_tangent(C);
    const auto g = global->stress_tangent(C);
    ASSERT_GT((Q * a).dot(C * (Q * a)), 1.05) << "fibre in tension, seed " << seed;
    EXPECT_NEAR(local.energy(C), global->energy(C), 1e-14 * global->energy(C)) << seed;
    worst_S = std::max(worst_S, relative(r.S, g.S));
    worst_D = std::max(worst_D, relative(r.D, g.D));
    EXPECT_LE(relative(local.stress(C), g.S), 1e-13) << seed;
  }
  EXPECT_LE(worst_S, 1e-13);
  EXPECT_LE(worst_D, 1e-13);
  RecordProperty("max_stress_difference", scientific(worst_S));
  RecordProperty("max_tangent_difference", scientific(worst_D));
}

TEST(RotatedLaw, DistributionInAPermutedBasisEqualsThePermutedSemiAxes) {
  // Q maps local x, y, z to global y, z, x: the semi-axes (1, 2, 3) in that basis are the
  // global semi-axes (3, 1, 2). The cubed-sphere rule is invariant under axis permutations, so
  // only the summation order differs.
  Mat3 Q;
  Q << 0, 0, 1, 1, 0, 0, 0, 1, 0;
  const material::RotatedLaw local(distribution(Vec3(1, 2, 3)), Q);
  const Law global = distribution(Vec3(3, 1, 2));
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const Mat3 C = random_state(seed, Vec3(1, 1, 1));
    const auto r = local.stress_tangent(C);
    const auto g = global->stress_tangent(C);
    EXPECT_NEAR(local.energy(C), global->energy(C), 1e-13 * global->energy(C)) << seed;
    EXPECT_LE(relative(r.S, g.S), 1e-13) << seed;
    EXPECT_LE(relative(r.D, g.D), 1e-13) << seed;
  }
}

TEST(RotatedLaw, StressAndTangentMatchCentralDifferences) {
  Real worst_S = 0.0, worst_D = 0.0;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const Mat3 Q = random_rotation(seed + 7);
    const Vec3 a = Vec3(0.3, -1.0, 0.6).normalized();
    const material::RotatedLaw law(fibre_mixture(a), Q);
    const Mat3 C = random_state(seed + 50, Q * a);
    const auto st = law.stress_tangent(C);
    const Real h = 1e-6; // C is of order 1: truncation ~h^2, round-off ~1e-16/h
    worst_S = std::max(worst_S, relative(st.S, stress_by_differences(law, C, h)));
    worst_D = std::max(worst_D, relative(st.D, tangent_by_differences(law, C, h)));
    EXPECT_LE((st.D - st.D.transpose()).norm(), 1e-14 * st.D.norm()) << seed;
  }
  EXPECT_LE(worst_S, 1e-7);
  EXPECT_LE(worst_D, 1e-7);
  RecordProperty("max_stress_error", scientific(worst_S));
  RecordProperty("max_tangent_error", scientific(worst_D));
}

TEST(RotatedLaw, RotatingTheBodyWithItsAxesRotatesTheStress) {
  // Axes R Q at C' = R C R^T is the same material point seen in a rotated frame:
  // W' = W, S' = R S R^T, D' = T(R) D T(R)^T.
  const Vec3 a = Vec3(1.0, 0.5, 0.2).normalized();
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const Mat3 Q = random_rotation(seed);
    const Mat3 R = random_rotation(seed + 1000);
    const material::RotatedLaw law(fibre_mixture(a), Q);
    const material::RotatedLaw turned(fibre_mixture(a), R * Q);
    const Mat3 C = random_state(seed + 20, Q * a);
    const auto st = law.stress_tangent(C);
    const auto tt = turned.stress_tangent(R * C * R.transpose());
    const Mat6 T = material::voigt_rotation(R);
    EXPECT_NEAR(turned.energy(R * C * R.transpose()), law.energy(C), 1e-14 * law.energy(C));
    EXPECT_LE(relative(tt.S, R * st.S * R.transpose()), 1e-13) << seed;
    EXPECT_LE(relative(tt.D, Mat6(T * st.D * T.transpose())), 1e-13) << seed;
  }
}

TEST(RotatedLaw, LocalFibreAlongXLoadsTheGlobalY) {
  // Q maps local x to global y; C stretches y by 1.2: the fibre adds S_yy = 2 W'(I_n) with
  // W' = ksi x^(beta-1) e^(alpha x^beta), x = I_n - 1 = 0.44, and nothing else.
  Mat3 Q;
  Q << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  const Law plain = fibre_mixture(Vec3(1, 0, 0));
  const material::RotatedLaw law(plain, Q);
  const Law matrix = material::create_law("neo-hookean", {{"E", 0.5}, {"nu", 0.1}}, "m");
  const Mat3 C = Vec3(1.0, 1.44, 1.0).asDiagonal();
  const Real x = 0.44;
  const Real dW = 5.0 * std::pow(x, 1.5) * std::exp(0.8 * std::pow(x, 2.5));
  Mat3 fibre = Mat3::Zero();
  fibre(1, 1) = 2.0 * dW;
  EXPECT_LE((law.stress(C) - matrix->stress(C) - fibre).norm(), 1e-14 * 2.0 * dW);
  EXPECT_LE((plain->stress(C) - matrix->stress(C)).norm(), 1e-15 * 2.0 * dW); // I_n = 1: inert
}

TEST(RotatedLaw, IdentityBasisGivesTheSameBits) {
  const Law plain = fibre_mixture(Vec3(1.0, 2.0, -0.5));
  const material::RotatedLaw same(plain, Mat3::Identity());
  EXPECT_EQ(same.type(), plain->type());
  EXPECT_EQ(same.p_wave_modulus(), plain->p_wave_modulus());
  EXPECT_EQ(same.shear_modulus(), plain->shear_modulus());
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const Mat3 C = random_state(seed, Vec3(1.0, 2.0, -0.5));
    const auto r = same.stress_tangent(C);
    const auto p = plain->stress_tangent(C);
    EXPECT_EQ(same.energy(C), plain->energy(C)) << seed;
    EXPECT_TRUE(r.S == p.S) << seed;
    EXPECT_TRUE(r.D == p.D) << seed;
    EXPECT_TRUE(same.stress(C) == p.S) << seed;
  }
}

TEST(RotatedLaw, RejectsABasisThatIsNoRotation) {
  const Law plain = fibre_mixture(Vec3(1, 0, 0));
  EXPECT_THROW(material::RotatedLaw(plain, 2.0 * Mat3::Identity()), LogicError);
  EXPECT_THROW(material::RotatedLaw(plain, Mat3(Vec3(1, 1, -1).asDiagonal())), LogicError);
}

TEST(VoigtRotation, RotatesStressLikeAndTransposeMapsStrainLikeBack) {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const Mat3 Q = random_rotation(seed);
    const Mat3 A = random_matrix(seed + 1) + random_matrix(seed + 1).transpose();
    const Mat3 B = random_matrix(seed + 2) + random_matrix(seed + 2).transpose();
    const Mat6 T = material::voigt_rotation(Q);
    const Mat3 QAQ = Q * A * Q.transpose();
    EXPECT_LE((T * voigt::stress(A) - voigt::stress(QAQ)).norm(), 1e-15 * 6 * A.norm());
    // S : E is invariant, so T^T takes the strain-like components of Q B Q^T back to B's
    const Vec6 back = T.transpose() * voigt::strain(Q * B * Q.transpose());
    EXPECT_LE((back - voigt::strain(B)).norm(), 1e-15 * 6 * B.norm());
    EXPECT_LE((material::voigt_rotation(Q.transpose()) * T - Mat6::Identity()).norm(), 1e-14);
  }
  EXPECT_TRUE(material::voigt_rotation(Mat3::Identity()) == Mat6::Identity());
}

// --- bases -----------------------------------------------------------------------------------

TEST(MaterialAxes, VectorBasis) {
  EXPECT_TRUE(material::vector_basis(Vec3(2, 0, 0), Vec3(1, 1, 0), "x") == Mat3::Identity());
  // e1 = y, e2 = x: e3 = y x x = -z
  Mat3 yx;
  yx << 0, 1, 0, 1, 0, 0, 0, 0, -1;
  EXPECT_TRUE(material::vector_basis(Vec3(0, 3, 0), Vec3(5, 0, 0), "x") == yx);
  // a = (1, 1, 0), d = y: e2 is the part of d normal to a
  const Mat3 Q = material::vector_basis(Vec3(1, 1, 0), Vec3(0, 1, 0), "x");
  const Real s = 1.0 / std::sqrt(2.0);
  EXPECT_LE((Q.col(0) - Vec3(s, s, 0)).norm(), 4e-16);
  EXPECT_LE((Q.col(1) - Vec3(-s, s, 0)).norm(), 4e-16);
  EXPECT_LE((Q.col(2) - Vec3(0, 0, 1)).norm(), 4e-16);
  expect_rotation(Q);
}

TEST(MaterialAxes, VectorBasisRejectsParallelAndZeroVectors) {
  const std::string parallel = input_error(
      [] { material::vector_basis(Vec3(1, 2, 3), Vec3(-2, -4, -6), "materials.m.axes"); });
  EXPECT_NE(parallel.find("materials.m.axes.d = [-2, -4, -6]: must not be parallel to "
                          "materials.m.axes.a = [1, 2, 3]"),
            std::string::npos)
      << parallel;
  const std::string zero =
      input_error([] { material::vector_basis(Vec3::Zero(), Vec3(1, 0, 0), "materials.m.axes"); });
  EXPECT_NE(zero.find("materials.m.axes.a = [0, 0, 0]: must be a nonzero vector"),
            std::string::npos)
      << zero;
}

TEST(MaterialAxes, CylindricalBasis) {
  // axis along z through (1, 2, 0); the point (1, 5, 7) lies at radius 3 along +y
  const Mat3 Q = material::cylindrical_basis(Vec3(1, 2, 0), Vec3(0, 0, 2), Vec3(1, 5, 7), "c");
  EXPECT_TRUE(Q.col(0) == Vec3(0, 1, 0)) << Q;  // radial
  EXPECT_TRUE(Q.col(1) == Vec3(-1, 0, 0)) << Q; // circumferential, counter-clockwise about z
  EXPECT_TRUE(Q.col(2) == Vec3(0, 0, 1)) << Q;  // axial
  // a tilted axis: the radial direction is normal to it
  const Vec3 axis = Vec3(1, 1, 1);
  const Vec3 point(2.0, -1.0, 0.5);
  const Mat3 T = material::cylindrical_basis(Vec3::Zero(), axis, point, "c");
  expect_rotation(T);
  EXPECT_NEAR(T.col(0).dot(axis), 0.0, 1e-15);
  EXPECT_LE((T.col(2) - axis.normalized()).norm(), 4e-16);
  EXPECT_NEAR(T.col(1).dot(point), 0.0, 1e-15); // circumferential: normal to the radius vector
}

TEST(MaterialAxes, CylindricalBasisRejectsAPointOnTheAxis) {
  const std::string m = input_error([] {
    material::cylindrical_basis(Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(0, 0, 3),
                                "materials.m.axes (cell 4)");
  });
  EXPECT_NE(m.find("materials.m.axes (cell 4): the cell centroid [0, 0, 3] lies on the cylinder "
                   "axis"),
            std::string::npos)
      << m;
}

TEST(MaterialAxes, SphericalBasis) {
  const Mat3 Q = material::spherical_basis(Vec3::Zero(), Vec3(0, 0, 1), Vec3(3, 0, 4), "s");
  EXPECT_LE((Q.col(0) - Vec3(0.6, 0, 0.8)).norm(), 4e-16) << Q;  // radial
  EXPECT_LE((Q.col(1) - Vec3(0, 1, 0)).norm(), 4e-16) << Q;      // azimuthal about z
  EXPECT_LE((Q.col(2) - Vec3(-0.8, 0, 0.6)).norm(), 4e-16) << Q; // meridian, towards +z
  expect_rotation(Q);
  // a shifted centre and pole axis x
  const Mat3 X = material::spherical_basis(Vec3(1, 1, 1), Vec3(2, 0, 0), Vec3(1, 1, 3), "s");
  EXPECT_LE((X.col(0) - Vec3(0, 0, 1)).norm(), 4e-16) << X;
  EXPECT_LE((X.col(1) - Vec3(0, -1, 0)).norm(), 4e-16) << X; // x cross z = -y
  EXPECT_LE((X.col(2) - Vec3(1, 0, 0)).norm(), 4e-16) << X;
}

TEST(MaterialAxes, SphericalBasisRejectsTheCentreAndThePoleAxis) {
  const std::string centre = input_error(
      [] { material::spherical_basis(Vec3(1, 2, 3), Vec3(0, 0, 1), Vec3(1, 2, 3), "s.axes"); });
  EXPECT_NE(centre.find("s.axes: the cell centroid [1, 2, 3] is the centre"), std::string::npos)
      << centre;
  const std::string pole = input_error(
      [] { material::spherical_basis(Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(0, 0, -2), "s.axes"); });
  EXPECT_NE(pole.find("lies on the pole axis"), std::string::npos) << pole;
}

TEST(MaterialAxes, CompletedBasis) {
  // e1 = z: x and y are equally normal to it, x comes first; e3 = z x x = y
  const Mat3 Z = material::completed_basis(Vec3(0, 0, 5), "v");
  EXPECT_TRUE(Z.col(0) == Vec3(0, 0, 1));
  EXPECT_TRUE(Z.col(1) == Vec3(1, 0, 0));
  EXPECT_TRUE(Z.col(2) == Vec3(0, 1, 0));
  // e1 = (0.6, 0.8, 0): z is the least aligned axis and already normal to e1
  const Mat3 Q = material::completed_basis(Vec3(3, 4, 0), "v");
  EXPECT_LE((Q.col(0) - Vec3(0.6, 0.8, 0)).norm(), 4e-16);
  EXPECT_TRUE(Q.col(1) == Vec3(0, 0, 1));
  EXPECT_LE((Q.col(2) - Vec3(0.8, -0.6, 0)).norm(), 4e-16);
  expect_rotation(material::completed_basis(Vec3(1, 1, 1), "v"));
  EXPECT_NE(input_error([] {
              material::completed_basis(Vec3::Zero(), "view 'fibre' of cell 3");
            }).find("view 'fibre' of cell 3: the direction [0, 0, 0] must be a nonzero vector"),
            std::string::npos);
}

TEST(MaterialAxes, AxesBasisDispatches) {
  material::AxesSpec axes;
  axes.kind = material::AxesKind::Cylindrical;
  axes.center = Vec3(0, 0, 0);
  axes.axis = Vec3(0, 0, 1);
  EXPECT_TRUE(material::axes_basis(axes, Vec3(2, 0, 1), "a").col(1) == Vec3(0, 1, 0));
  axes.kind = material::AxesKind::Vector;
  axes.a = Vec3(0, 0, 1);
  axes.d = Vec3(1, 0, 0);
  EXPECT_TRUE(material::axes_basis(axes, Vec3(2, 0, 1), "a").col(2) == Vec3(0, 1, 0));
}
