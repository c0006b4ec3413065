// SPDX-License-Identifier: MIT
// Uniaxial large stretch (1.5 and 0.8) of a block with free lateral faces (symmetry planes):
// the FE stress equals the closed-form uniaxial stress of each law in every element. Also a
// neo-Hookean matrix reinforced by a fibre family (solid-mixture of neo-hookean and
// fibre-exp-pow), stretched along and across the fibre.
#include "solid_model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>
#include <sstream>

using namespace trifem;

namespace {

constexpr Real kE = 1.0, kNu = 0.3;

/// Closed-form uniaxial Cauchy stress and lateral stretches at axial stretch l.
struct Uniaxial {
  Real sigma;
  Real lateral;   ///< along y
  Real lateral_z; ///< along z (equal to `lateral` for isotropic laws)
};

Uniaxial neo_hookean_uniaxial(Real l) {
  const auto [lambda, mu] = material::lame_from_young(kE, kNu);
  Real t = 1.0; // lateral stretch: mu (t^2 - 1) + lambda ln(l t^2) = 0
  for (int it = 0; it < 60; ++it)
    t -= (mu * (t * t - 1) + lambda * std::log(l * t * t)) / (2 * mu * t + 2 * lambda / t);
  const Real J = l * t * t;
  return {(mu * (l * l - 1) + lambda * std::log(J)) / J, t, t};
}

Uniaxial svk_uniaxial(Real l) {
  // S22 = 0 gives E22 = -nu E11 and S11 = E E11; sigma11 = l^2 S11 / J
  const Real E11 = 0.5 * (l * l - 1), E22 = -kNu * E11;
  const Real t = std::sqrt(1 + 2 * E22);
  return {l * l * kE * E11 / (l * t * t), t, t};
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
  return {principal_stress(l, t)[0], t, t};
}

/// Records `value` as the property `key` of the running test if it is the largest so far (a
/// test may run several stretches).
void record_largest(const std::string& key, Real value) {
  static std::map<std::string, Real> largest;
  Real& v = largest[testing::UnitTest::GetInstance()->current_test_info()->name() + key];
  v = std::max(v, value);
  std::ostringstream text;
  text << std::scientific << v;
  testing::Test::RecordProperty(key, text.str());
}

/// Runs the uniaxial stretch of the block (axis x, free lateral faces) with `law` and checks the
/// stress of every element and the lateral displacements against `exact`; returns the final
/// state (displacements).
Vector run_uniaxial(std::shared_ptr<const material::ElasticLaw> law, const std::string& name,
                    Real stretch, Uniaxial exact) {
  mesh::BoxSpec spec;
  spec.divisions = {3, 2, 2};
  spec.size = Vec3(2.0, 1.0, 1.0);
  // SolidModel makes its law from a registered type; a solid mixture replaces it before build()
  test::SolidModel m(mesh::make_box(spec), "neo-hookean", {{"E", kE}, {"nu", kNu}});
  m.law = std::move(law);
  m.prescribe(m.mesh.node_set("box.xmin"), 0, 0.0);
  m.prescribe(m.mesh.node_set("box.ymin"), 1, 0.0);
  m.prescribe(m.mesh.node_set("box.zmin"), 2, 0.0);
  m.prescribe(m.mesh.node_set("box.xmax"), 0, 2.0 * (stretch - 1.0));
  m.build();
  const int steps = 4;
  for (int s = 1; s <= steps; ++s) {
    const auto report = m.solve_step(Real(s) / steps, 1.0 / steps);
    EXPECT_EQ(report.status, solver::SolveStatus::Converged) << name << " " << stretch;
    if (report.status != solver::SolveStatus::Converged)
      return m.problem->state();
  }
  Real worst = 0.0; // largest stress error relative to the exact axial stress
  for (Index e = 0; e < m.solid->num_elements(); ++e) {
    const Mat3 sigma = m.solid->stress(e, m.problem->state()).cauchy;
    EXPECT_NEAR(sigma(0, 0), exact.sigma, 1e-10 * std::abs(exact.sigma)) << name << " " << stretch;
    EXPECT_NEAR(sigma(1, 1), 0.0, 1e-10 * std::abs(exact.sigma)) << name << " " << stretch;
    EXPECT_NEAR(sigma(2, 2), 0.0, 1e-10 * std::abs(exact.sigma)) << name << " " << stretch;
    EXPECT_NEAR(sigma(0, 1), 0.0, 1e-10 * std::abs(exact.sigma)) << name << " " << stretch;
    const Real errors[] = {sigma(0, 0) - exact.sigma, sigma(1, 1), sigma(2, 2), sigma(0, 1)};
    for (Real error : errors)
      worst = std::max(worst, std::abs(error) / std::abs(exact.sigma));
  }
  const Index corner = m.mesh.num_nodes() - 1; // (2, 1, 1)
  const Real width = 1.0;                      // lateral size: u_y = (lateral - 1) width
  EXPECT_NEAR(m.displacement(corner).y(), (exact.lateral - 1.0) * width, 1e-10 * width) << name;
  EXPECT_NEAR(m.displacement(corner).z(), (exact.lateral_z - 1.0) * width, 1e-10 * width) << name;
  record_largest("max_relative_stress_error", worst);
  return m.problem->state();
}

Vector run_uniaxial(const std::string& law, const material::ParameterValues& params, Real stretch,
                    Uniaxial exact) {
  return run_uniaxial(material::create_law(law, params, "test"), law, stretch, exact);
}

// ---------------------------------------------------------------------------------------------
// Fibre-reinforced solid: neo-Hookean matrix (kE, kNu) + fibre-exp-pow (ksi, alpha, beta)

struct FibreParameters {
  Real ksi, alpha, beta;
};
constexpr FibreParameters kQuadraticFibre{5.0, 0.0, 2.0}; // the docs/input.md example
constexpr FibreParameters kExpPowFibre{2.0, 0.5, 2.5};

/// The solid mixture of the neo-Hookean matrix and one fibre family along `axis`.
std::shared_ptr<const material::ElasticLaw> fibre_reinforced(const FibreParameters& f, int axis) {
  material::ParameterValues fibre = {{"ksi", f.ksi}, {"alpha", f.alpha}, {"beta", f.beta}};
  material::set_vector(fibre, "fibre", Vec3::Unit(axis));
  const material::LawSpec spec{
      "solid-mixture",
      {},
      {{"neo-hookean", {{"E", kE}, {"nu", kNu}}, {}}, {"fibre-exp-pow", std::move(fibre), {}}}};
  return material::create_law(spec, "materials.cart");
}

/// Principal Cauchy stresses at principal stretches `stretch` (along x, y, z) of the matrix,
/// sigma_a = (mu (c_a - 1) + lambda ln J)/J with c_a = stretch_a^2, plus the fibre along `axis`:
/// S = 2 W'(I_n) a0 (x) a0 with I_n = c_axis, so sigma_axis += 2 c_axis W'(c_axis)/J,
/// W'(I_n) = ksi x^(beta-1) exp(alpha x^beta), x = I_n - 1 > 0 (0 in compression).
Vec3 fibre_reinforced_principal_stress(const FibreParameters& f, int axis, const Vec3& stretch) {
  const auto [lambda, mu] = material::lame_from_young(kE, kNu);
  const Real J = stretch.prod();
  const Vec3 c = stretch.array().square().matrix();
  Vec3 sigma = ((mu * (c.array() - 1.0) + lambda * std::log(J)) / J).matrix();
  const Real x = c[axis] - 1.0;
  if (x > 0.0)
    sigma[axis] += 2.0 * c[axis] * f.ksi * std::pow(x, f.beta - 1) *
                   std::exp(f.alpha * std::pow(x, f.beta)) / J;
  return sigma;
}

/// Uniaxial stress along x of the fibre-reinforced solid with the fibre along `axis`: the
/// lateral stretches (t_y, t_z) solve sigma_yy = sigma_zz = 0 by Newton with central-difference
/// slopes (for axis = x, t_y = t_z and this is the scalar Newton of lateral_stretch).
Uniaxial fibre_reinforced_uniaxial(const FibreParameters& f, int axis, Real l) {
  const auto lateral = [&](const Vec2& t) {
    return Vec2(fibre_reinforced_principal_stress(f, axis, Vec3(l, t[0], t[1])).tail<2>());
  };
  if (axis == 0) {
    const Real t = lateral_stretch([&](Real s) { return lateral(Vec2(s, s))[0]; });
    return {fibre_reinforced_principal_stress(f, axis, Vec3(l, t, t))[0], t, t};
  }
  Vec2 t(1.0, 1.0);
  for (int it = 0; it < 60; ++it) {
    const Real h = 1e-7;
    Mat2 slope;
    for (int k = 0; k < 2; ++k)
      slope.col(k) = (lateral(t + h * Vec2::Unit(k)) - lateral(t - h * Vec2::Unit(k))) / (2 * h);
    const Vec2 step = slope.lu().solve(lateral(t));
    t -= step;
    if (step.norm() <= 1e-15)
      break;
  }
  EXPECT_LE(lateral(t).norm(), 1e-14 * kE) << "lateral equilibrium";
  return {fibre_reinforced_principal_stress(f, axis, Vec3(l, t[0], t[1]))[0], t[0], t[1]};
}

// ---------------------------------------------------------------------------------------------
// Continuous fibre distribution: neo-Hookean matrix (kE, kNu) + fibre-distribution

/// The solid mixture of the neo-Hookean matrix and a fibre distribution with `parameters`.
std::shared_ptr<const material::ElasticLaw>
distribution_reinforced(const material::ParameterValues& parameters) {
  const material::LawSpec spec{
      "solid-mixture",
      {},
      {{"neo-hookean", {{"E", kE}, {"nu", kNu}}, {}}, {"fibre-distribution", parameters, {}}}};
  return material::create_law(spec, "materials.cart");
}

/// Uniaxial stress along x of an orthotropic `law` (diagonal S at diagonal C) from the law
/// itself: sigma = F S F^T / J at F = diag(l, t_y, t_z), with (t_y, t_z) solving
/// sigma_yy = sigma_zz = 0 by Newton with central-difference slopes.
Uniaxial law_uniaxial(const material::ElasticLaw& law, Real l) {
  const auto principal = [&](const Vec2& t) {
    const Vec3 stretch(l, t[0], t[1]);
    const Mat3 S = law.stress(Mat3(stretch.array().square().matrix().asDiagonal()));
    EXPECT_LE((S - Mat3(S.diagonal().asDiagonal())).norm(), 1e-14 * S.norm()) << "orthotropic";
    return Vec3((S.diagonal().array() * stretch.array().square()).matrix() / stretch.prod());
  };
  const auto lateral = [&](const Vec2& t) { return Vec2(principal(t).tail<2>()); };
  Vec2 t(1.0, 1.0);
  for (int it = 0; it < 60; ++it) {
    const Real h = 1e-7;
    Mat2 slope;
    for (int k = 0; k < 2; ++k)
      slope.col(k) = (lateral(t + h * Vec2::Unit(k)) - lateral(t - h * Vec2::Unit(k))) / (2 * h);
    const Vec2 step = slope.lu().solve(lateral(t));
    t -= step;
    if (step.norm() <= 1e-15)
      break;
  }
  EXPECT_LE(lateral(t).norm(), 1e-14 * kE) << "lateral equilibrium";
  return {principal(t)[0], t[0], t[1]};
}

/// max |a - b| / max |b|: the difference of two FE states relative to the displacements.
Real relative_difference(const Vector& a, const Vector& b) {
  return (a - b).lpNorm<Eigen::Infinity>() / b.lpNorm<Eigen::Infinity>();
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

// Fibre along the stretch: the fibre adds 2 l^2 W'(l^2)/J to the axial stress and nothing
// laterally, so the lateral stretch is the matrix's.
TEST(UniaxialFibreReinforced, AlongTheFibreStretch1p5) {
  for (const FibreParameters& f : {kQuadraticFibre, kExpPowFibre}) {
    const Uniaxial exact = fibre_reinforced_uniaxial(f, 0, 1.5);
    const Uniaxial matrix = neo_hookean_uniaxial(1.5);
    EXPECT_GT(exact.sigma, 2.0 * matrix.sigma); // the fibre carries most of the load
    EXPECT_NEAR(exact.lateral, matrix.lateral, 1e-14);
    run_uniaxial(fibre_reinforced(f, 0), "fibre along x", 1.5, exact);
  }
}

// Compression along the fibre: the fibre is slack, the solid is the matrix alone to round-off.
TEST(UniaxialFibreReinforced, AlongTheFibreStretch0p8IsTheMatrixAlone) {
  const Vector matrix =
      run_uniaxial("neo-hookean", {{"E", kE}, {"nu", kNu}}, 0.8, neo_hookean_uniaxial(0.8));
  for (const FibreParameters& f : {kQuadraticFibre, kExpPowFibre}) {
    const Uniaxial exact = fibre_reinforced_uniaxial(f, 0, 0.8);
    EXPECT_EQ(exact.sigma, neo_hookean_uniaxial(0.8).sigma);
    const Vector mixture = run_uniaxial(fibre_reinforced(f, 0), "fibre along x", 0.8, exact);
    const Real difference = relative_difference(mixture, matrix);
    EXPECT_LE(difference, 1e-14);
    record_largest("relative_difference_to_the_matrix", difference);
  }
}

// Stretch across the fibre (fibre along y): the lateral contraction shortens the fibre, which
// is slack: the matrix alone to round-off.
TEST(UniaxialFibreReinforced, AcrossTheFibreStretch1p5IsTheMatrixAlone) {
  const Vector matrix =
      run_uniaxial("neo-hookean", {{"E", kE}, {"nu", kNu}}, 1.5, neo_hookean_uniaxial(1.5));
  for (const FibreParameters& f : {kQuadraticFibre, kExpPowFibre}) {
    const Uniaxial exact = fibre_reinforced_uniaxial(f, 1, 1.5);
    EXPECT_LT(exact.lateral, 1.0);
    EXPECT_NEAR(exact.sigma, neo_hookean_uniaxial(1.5).sigma, 1e-13);
    const Vector mixture = run_uniaxial(fibre_reinforced(f, 1), "fibre along y", 1.5, exact);
    const Real difference = relative_difference(mixture, matrix);
    EXPECT_LE(difference, 1e-14);
    record_largest("relative_difference_to_the_matrix", difference);
  }
}

// Compression across the fibre (fibre along y): the lateral expansion stretches the fibre,
// which then restrains it: t_y < t_z, both from the 2x2 lateral equilibrium.
TEST(UniaxialFibreReinforced, AcrossTheFibreStretch0p8) {
  for (const FibreParameters& f : {kQuadraticFibre, kExpPowFibre}) {
    const Uniaxial exact = fibre_reinforced_uniaxial(f, 1, 0.8);
    EXPECT_GT(exact.lateral, 1.0);                    // the fibre is in tension
    EXPECT_LT(exact.lateral, exact.lateral_z - 1e-3); // and restrains the expansion along y
    run_uniaxial(fibre_reinforced(f, 1), "fibre along y", 0.8, exact);
  }
}

// A continuous fibre distribution (spherical, and ellipsoidal with semi-axes 2, 1, 0.5 along x,
// y, z) in a neo-Hookean matrix, stretched by 1.3 and 0.8 along x: the FE state is homogeneous
// and its stress and lateral stretches are those of the law itself (the rule on the sphere is
// orthotropic in x, y, z, so the lateral faces stay free of shear).
TEST(UniaxialFibreReinforced, FibreDistribution) {
  material::ParameterValues spherical = {{"ksi", 1.0}, {"alpha", 0.0}, {"beta", 2.0}};
  material::set_vector(spherical, "semi_axes", Vec3(1.0, 1.0, 1.0));
  material::ParameterValues ellipsoidal = {{"ksi", 2.0}, {"alpha", 0.5}, {"beta", 2.5}};
  material::set_vector(ellipsoidal, "semi_axes", Vec3(2.0, 1.0, 0.5));
  for (const auto& parameters : {spherical, ellipsoidal})
    for (Real stretch : {1.3, 0.8}) {
      const auto law = distribution_reinforced(parameters);
      const Uniaxial exact = law_uniaxial(*law, stretch);
      const Uniaxial matrix = neo_hookean_uniaxial(stretch);
      // the fibres carry load: along x in tension; in compression they restrain the lateral
      // expansion
      EXPECT_GT(std::abs(exact.sigma - matrix.sigma), 0.02 * std::abs(matrix.sigma)) << stretch;
      if (stretch < 1.0) {
        EXPECT_LT(exact.lateral, matrix.lateral - 1e-3);
      }
      if (parameters.at("semi_axes.z") != 1.0) { // orthotropic: the lateral stretches differ
        EXPECT_GT(std::abs(exact.lateral - exact.lateral_z), 1e-4) << stretch;
      }
      run_uniaxial(law, "fibre distribution", stretch, exact);
    }
}
