// SPDX-License-Identifier: MIT
// Material laws: closed-form uniaxial stretch, registry-wide generic checks, bad parameters.
#include "trifem/core/error.hpp"
#include "trifem/material/registry.hpp"
#include "trifem/tensor/kinematics.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace trifem;

namespace {

Mat3 rotation(Real angle, Vec3 axis) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

Mat3 random_deformation(unsigned seed) {
  std::srand(seed);
  Mat3 F = Mat3::Identity() + 0.25 * Mat3::Random();
  EXPECT_GT(F.determinant(), 0.0);
  return F;
}

material::ParameterValues params(Real E, Real nu) {
  return {{"E", E}, {"nu", nu}};
}

} // namespace

TEST(MaterialRegistry, EveryLawHasZeroStressAtIdentity) {
  for (const auto& law : material::registered_laws()) {
    auto m = material::create_law(law.type, law.example, "m");
    // relative to the modulus (the stress is exactly 0 at F = I)
    EXPECT_LT(m->stress(Mat3::Identity()).norm(), 5e-15 * m->p_wave_modulus()) << law.type;
  }
}

TEST(MaterialRegistry, EveryLawTangentMatchesCentralDifferences) {
  for (const auto& law : material::registered_laws()) {
    auto m = material::create_law(law.type, law.example, "m");
    for (unsigned seed : {1u, 2u, 3u}) {
      const Mat3 F = random_deformation(seed);
      const Mat3 C = F.transpose() * F;
      const Mat6 D = m->stress_tangent(C).D;
      Mat6 D_fd;
      const Real h = 1e-6;
      for (int c = 0; c < 6; ++c) {
        // perturb E in strain-like Voigt component c: dC = 2 dE
        Vec6 dE = Vec6::Zero();
        dE[c] = h;
        const Mat3 dC = 2.0 * voigt::from_strain(dE);
        D_fd.col(c) = voigt::stress(m->stress(C + dC) - m->stress(C - dC)) / (2 * h);
      }
      EXPECT_LE((D - D_fd).norm() / D.norm(), 1e-6) << law.type << " seed " << seed;
      // stress = 2 dW/dC by central differences of the energy
      Mat3 S_fd;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          Mat3 dC = Mat3::Zero();
          dC(i, j) += 0.5 * h;
          dC(j, i) += 0.5 * h;
          S_fd(i, j) = 2.0 * (m->energy(C + dC) - m->energy(C - dC)) / (2 * h);
        }
      EXPECT_LE((m->stress(C) - S_fd).norm() / m->stress(C).norm(), 1e-6) << law.type;
    }
  }
}

TEST(MaterialRegistry, EveryLawIsObjectiveAndHasMajorSymmetry) {
  for (const auto& law : material::registered_laws()) {
    auto m = material::create_law(law.type, law.example, "m");
    const Mat3 F = random_deformation(7);
    const Mat3 Q = rotation(0.7, Vec3(1, 2, 3));
    const Mat3 sigma = kinematics::cauchy_from_pk2(F, m->stress(F.transpose() * F));
    const Mat3 sigma_rot =
        kinematics::cauchy_from_pk2(Q * F, m->stress((Q * F).transpose() * Q * F));
    EXPECT_LE((Q * sigma * Q.transpose() - sigma_rot).norm(), 1e-12 * sigma.norm()) << law.type;
    const Mat6 D = m->stress_tangent(F.transpose() * F).D;
    EXPECT_LE((D - D.transpose()).norm(), 1e-12 * D.norm()) << law.type;
  }
}

/// Uniaxial stress with nu = 0 (no lateral contraction for SVK): closed forms.
TEST(SaintVenantKirchhoff, UniaxialStretchMatchesClosedForm) {
  const Real E = 0.3;
  auto m = material::create_law("saint-venant-kirchhoff", params(E, 0.0), "m");
  for (Real stretch : {1.5, 0.8}) {
    Mat3 F = Mat3::Identity();
    F(0, 0) = stretch;
    const Mat3 S = m->stress(F.transpose() * F);
    // S11 = E (l^2 - 1)/2, Cauchy sigma11 = l S11 (J = l)
    const Real S11 = E * (stretch * stretch - 1.0) / 2.0;
    // relative to the modulus E (S22 vanishes, S11 is of order E)
    EXPECT_NEAR(S(0, 0), S11, 3e-15 * E);
    EXPECT_NEAR(S(1, 1), 0.0, 3e-15 * E);
    EXPECT_NEAR(kinematics::cauchy_from_pk2(F, S)(0, 0), stretch * S11, 3e-15 * E);
  }
}

/// Uniaxial stretch with lateral stretch solved from sigma22 = 0 (neo-Hookean, nu = 0.3):
/// sigma11 = mu/J (l^2 - 1) + lambda lnJ / J with mu (t^2 - 1) + lambda ln(l t^2) = 0.
TEST(NeoHookean, UniaxialStretchMatchesClosedForm) {
  const Real E = 1.0, nu = 0.3;
  const auto [lambda, mu] = material::lame_from_young(E, nu);
  auto m = material::create_law("neo-hookean", params(E, nu), "m");
  for (Real l : {1.5, 0.8}) {
    Real t = 1.0; // lateral stretch by Newton on g(t) = mu (t^2-1) + lambda ln(l t^2)
    for (int it = 0; it < 50; ++it)
      t -= (mu * (t * t - 1) + lambda * std::log(l * t * t)) / (2 * mu * t + 2 * lambda / t);
    const Mat3 F = Eigen::Vector3d(l, t, t).asDiagonal();
    const Mat3 sigma = kinematics::cauchy_from_pk2(F, m->stress(F.transpose() * F));
    const Real J = l * t * t;
    const Real expected = (mu * (l * l - 1) + lambda * std::log(J)) / J;
    EXPECT_NEAR(sigma(0, 0), expected, 1e-12 * std::abs(expected));
    // zero lateral stress, relative to the modulus (t is a Newton root to round-off)
    EXPECT_NEAR(sigma(1, 1), 0.0, 1e-12 * E);
    EXPECT_NEAR(sigma(2, 2), 0.0, 1e-12 * E);
  }
}

TEST(MaterialRegistry, BadParametersAreRejectedWithTheKeyPath) {
  try {
    material::create_law("neo-hookean", params(-1.0, 0.3), "materials.cartilage");
    FAIL() << "negative modulus accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("materials.cartilage.E"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("(0, inf)"), std::string::npos) << e.what();
  }
  EXPECT_THROW(material::create_law("neo-hookean", params(1.0, 0.5), "m"), InputError);
  EXPECT_THROW(material::create_law("neo-hookean", {{"E", 1.0}, {"G", 1.0}}, "m"), InputError);
  EXPECT_THROW(material::create_law("neo-hookean", {{"nu", 0.1}}, "m"), InputError);
  EXPECT_THROW(material::create_law("mooney", params(1.0, 0.1), "m"), InputError);
}
