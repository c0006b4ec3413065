// SPDX-License-Identifier: MIT
// Uniaxial large stretch (1.5 and 0.8) of a block with free lateral faces (symmetry planes):
// the FE stress equals the closed-form uniaxial stress of each law in every element.
#include "solid_model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <sstream>

using namespace trifem;

namespace {

constexpr Real kE = 1.0, kNu = 0.3;

/// Closed-form uniaxial Cauchy stress and lateral stretch at axial stretch l.
struct Uniaxial {
  Real sigma;
  Real lateral;
};

Uniaxial neo_hookean_uniaxial(Real l) {
  const auto [lambda, mu] = material::lame_from_young(kE, kNu);
  Real t = 1.0; // lateral stretch: mu (t^2 - 1) + lambda ln(l t^2) = 0
  for (int it = 0; it < 60; ++it)
    t -= (mu * (t * t - 1) + lambda * std::log(l * t * t)) / (2 * mu * t + 2 * lambda / t);
  const Real J = l * t * t;
  return {(mu * (l * l - 1) + lambda * std::log(J)) / J, t};
}

Uniaxial svk_uniaxial(Real l) {
  // S22 = 0 gives E22 = -nu E11 and S11 = E E11; sigma11 = l^2 S11 / J
  const Real E11 = 0.5 * (l * l - 1), E22 = -kNu * E11;
  const Real t = std::sqrt(1 + 2 * E22);
  return {l * l * kE * E11 / (l * t * t), t};
}

// Cartilage-like parameters of the laws added after the paper's two.
const material::ParameterValues kHolmesMow = {{"E", 1.0}, {"nu", 0.2}, {"beta", 0.5}};
const material::ParameterValues kMooneyRivlin = {{"c1", 0.3}, {"c2", 0.05}, {"k", 10.0}};
const material::ParameterValues kOgden = {
    {"c1", 0.4}, {"m1", 4.0}, {"c2", 0.2}, {"m2", -2.0}, {"k", 5.0}};

/// The root t near 1 of the lateral stress g(t) = 0, by Newton with a central-difference slope
/// (the root is as accurate as g; the slope only sets the speed).
Real lateral_stretch(const std::function<Real(Real)>& g) {
  Real t = 1.0;
  for (int it = 0; it < 60; ++it) {
    const Real h = 1e-7;
    const Real step = g(t) / ((g(t + h) - g(t - h)) / (2 * h));
    t -= step;
    if (std::abs(step) <= 1e-15)
      break;
  }
  return t;
}

/// Holmes-Mow principal stresses at stretches (l, t, t): S_a = e^Q/2 dP_a with
/// dP_a = 2 mu - lambda + lambda I1 - lambda c_a - Ha/c_a (c_a = squared stretch), and
/// sigma_a = c_a S_a / J.
Vec3 holmes_mow_principal_stress(Real l, Real t) {
  const auto [lambda, mu] = material::lame_from_young(kHolmesMow.at("E"), kHolmesMow.at("nu"));
  const Real beta = kHolmesMow.at("beta"), Ha = lambda + 2 * mu;
  const Vec3 c(l * l, t * t, t * t);
  const Real I1 = c.sum(), I2 = c[0] * c[1] + c[1] * c[2] + c[0] * c[2], I3 = c.prod();
  const Real Q = beta / Ha * ((2 * mu - lambda) * (I1 - 3) + lambda * (I2 - 3) - Ha * std::log(I3));
  const Real J = std::sqrt(I3);
  Vec3 sigma;
  for (int a = 0; a < 3; ++a)
    sigma[a] =
        c[a] * 0.5 * std::exp(Q) * (2 * mu - lambda + lambda * I1 - lambda * c[a] - Ha / c[a]) / J;
  return sigma;
}

/// Principal Cauchy stress of an uncoupled law from its Kirchhoff-like isochoric stresses
/// tau_a = l~_a dW~/dl~_a (Holzapfel, Nonlinear Solid Mechanics, ch. 6):
/// sigma_a = (tau_a - mean tau)/J + dU/dJ with U = k/2 (ln J)^2.
Vec3 uncoupled_principal_stress(const Vec3& tau, Real k, Real J) {
  return ((tau.array() - tau.mean()) / J + k * std::log(J) / J).matrix();
}

/// Mooney-Rivlin: tau_a = 2 c1 l~_a^2 + 2 c2 l~_a^2 (I1~ - l~_a^2).
Vec3 mooney_rivlin_principal_stress(Real l, Real t) {
  const Real c1 = kMooneyRivlin.at("c1"), c2 = kMooneyRivlin.at("c2");
  const Real J = l * t * t;
  const Vec3 squared = (Vec3(l, t, t) / std::cbrt(J)).array().square().matrix();
  const Vec3 tau =
      (2 * c1 * squared.array() + 2 * c2 * squared.array() * (squared.sum() - squared.array()))
          .matrix();
  return uncoupled_principal_stress(tau, kMooneyRivlin.at("k"), J);
}

/// Ogden: tau_a = sum_i c_i/m_i l~_a^m_i.
Vec3 ogden_principal_stress(Real l, Real t) {
  const Real J = l * t * t;
  const Vec3 stretch = Vec3(l, t, t) / std::cbrt(J);
  Vec3 tau = Vec3::Zero();
  for (const char* i : {"1", "2"}) {
    const Real c = kOgden.at(std::string("c") + i), m = kOgden.at(std::string("m") + i);
    tau += (c / m * stretch.array().pow(m)).matrix();
  }
  return uncoupled_principal_stress(tau, kOgden.at("k"), J);
}

/// Uniaxial stress of a law given by its principal Cauchy stresses at stretches (l, t, t).
Uniaxial principal_uniaxial(const std::function<Vec3(Real, Real)>& principal_stress, Real l) {
  const Real t = lateral_stretch([&](Real s) { return principal_stress(l, s)[1]; });
  return {principal_stress(l, t)[0], t};
}

void run_uniaxial(const std::string& law, const material::ParameterValues& params, Real stretch,
                  Uniaxial exact) {
  mesh::BoxSpec spec;
  spec.divisions = {3, 2, 2};
  spec.size = Vec3(2.0, 1.0, 1.0);
  test::SolidModel m(mesh::make_box(spec), law, params);
  m.prescribe(m.mesh.node_set("box.xmin"), 0, 0.0);
  m.prescribe(m.mesh.node_set("box.ymin"), 1, 0.0);
  m.prescribe(m.mesh.node_set("box.zmin"), 2, 0.0);
  m.prescribe(m.mesh.node_set("box.xmax"), 0, 2.0 * (stretch - 1.0));
  m.build();
  const int steps = 4;
  for (int s = 1; s <= steps; ++s)
    ASSERT_EQ(m.solve_step(Real(s) / steps, 1.0 / steps).status, solver::SolveStatus::Converged);
  Real worst = 0.0; // largest stress error relative to the exact axial stress
  for (Index e = 0; e < m.solid->num_elements(); ++e) {
    const Mat3 sigma = m.solid->stress(e, m.problem->state()).cauchy;
    EXPECT_NEAR(sigma(0, 0), exact.sigma, 1e-10 * std::abs(exact.sigma)) << law << " " << stretch;
    EXPECT_NEAR(sigma(1, 1), 0.0, 1e-10 * std::abs(exact.sigma));
    EXPECT_NEAR(sigma(2, 2), 0.0, 1e-10 * std::abs(exact.sigma));
    EXPECT_NEAR(sigma(0, 1), 0.0, 1e-10 * std::abs(exact.sigma));
    const Real errors[] = {sigma(0, 0) - exact.sigma, sigma(1, 1), sigma(2, 2), sigma(0, 1)};
    for (Real error : errors)
      worst = std::max(worst, std::abs(error) / std::abs(exact.sigma));
  }
  const Index corner = m.mesh.num_nodes() - 1; // (2, 1, 1)
  const Real width = 1.0;                      // lateral size: u_y = (lateral - 1) width
  EXPECT_NEAR(m.displacement(corner).y(), (exact.lateral - 1.0) * width, 1e-10 * width);
  std::ostringstream text;
  text << std::scientific << worst;
  testing::Test::RecordProperty("max_relative_stress_error", text.str());
}

} // namespace

TEST(Uniaxial, NeoHookeanStretch1p5) {
  run_uniaxial("neo-hookean", {{"E", kE}, {"nu", kNu}}, 1.5, neo_hookean_uniaxial(1.5));
}
TEST(Uniaxial, NeoHookeanStretch0p8) {
  run_uniaxial("neo-hookean", {{"E", kE}, {"nu", kNu}}, 0.8, neo_hookean_uniaxial(0.8));
}
TEST(Uniaxial, SaintVenantKirchhoffStretch1p5) {
  run_uniaxial("saint-venant-kirchhoff", {{"E", kE}, {"nu", kNu}}, 1.5, svk_uniaxial(1.5));
}
TEST(Uniaxial, SaintVenantKirchhoffStretch0p8) {
  run_uniaxial("saint-venant-kirchhoff", {{"E", kE}, {"nu", kNu}}, 0.8, svk_uniaxial(0.8));
}
TEST(Uniaxial, HolmesMowStretch1p5) {
  run_uniaxial("holmes-mow", kHolmesMow, 1.5, principal_uniaxial(holmes_mow_principal_stress, 1.5));
}
TEST(Uniaxial, HolmesMowStretch0p8) {
  run_uniaxial("holmes-mow", kHolmesMow, 0.8, principal_uniaxial(holmes_mow_principal_stress, 0.8));
}
TEST(Uniaxial, MooneyRivlinStretch1p5) {
  run_uniaxial("mooney-rivlin", kMooneyRivlin, 1.5,
               principal_uniaxial(mooney_rivlin_principal_stress, 1.5));
}
TEST(Uniaxial, MooneyRivlinStretch0p8) {
  run_uniaxial("mooney-rivlin", kMooneyRivlin, 0.8,
               principal_uniaxial(mooney_rivlin_principal_stress, 0.8));
}
TEST(Uniaxial, OgdenStretch1p5) {
  run_uniaxial("ogden", kOgden, 1.5, principal_uniaxial(ogden_principal_stress, 1.5));
}
TEST(Uniaxial, OgdenStretch0p8) {
  run_uniaxial("ogden", kOgden, 0.8, principal_uniaxial(ogden_principal_stress, 0.8));
}
