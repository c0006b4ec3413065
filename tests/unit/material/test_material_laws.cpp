// SPDX-License-Identifier: MIT
// Holmes-Mow, Mooney-Rivlin, Ogden (uncoupled and unconstrained), Yeoh and the orthotropic
// elastic law: derivatives, small-strain limit, frame invariance, coincident principal
// stretches, closed forms, equivalences between the laws and bad parameters.
#include "trifem/core/error.hpp"
#include "trifem/material/registry.hpp"
#include "trifem/tensor/kinematics.hpp"

#include "law_differences.hpp"
#include "law_states.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

using namespace trifem;

using namespace trifem::test;

namespace {

/// A law by its registered type and parameters.
struct LawCase {
  std::string type;
  material::ParameterValues params;
};

/// Parameter sets of the new laws: cartilage-like values, plus sets that reach the special
/// branches (beta = 0, negative c2, three Ogden terms with non-integer exponents).
const std::vector<LawCase>& new_law_cases() {
  static const std::vector<LawCase> cases = {
      {"holmes-mow", {{"E", 1.0}, {"nu", 0.2}, {"beta", 0.5}}},
      {"holmes-mow", {{"E", 0.6}, {"nu", 0.0}, {"beta", 0.0}}},
      {"holmes-mow", {{"E", 2.0}, {"nu", 0.45}, {"beta", 1.5}}},
      {"mooney-rivlin", {{"c1", 0.3}, {"c2", 0.05}, {"k", 10.0}}},
      {"mooney-rivlin", {{"c1", 0.5}, {"c2", -0.1}, {"k", 2.0}}},
      {"ogden", {{"c1", 0.4}, {"m1", 4.0}, {"c2", 0.2}, {"m2", -2.0}, {"k", 10.0}}},
      {"ogden",
       {{"c1", 1.0},
        {"m1", 1.3},
        {"c2", -0.2},
        {"m2", -2.5},
        {"c3", 0.3},
        {"m3", 6.0},
        {"k", 5.0}}},
      {"ogden-unconstrained", {{"c1", 0.658}, {"m1", 6.83}, {"cp", 1.0}}},
      {"ogden-unconstrained",
       {{"c1", 0.4},
        {"m1", 4.0},
        {"c2", 0.2},
        {"m2", -2.0},
        {"c3", -0.1},
        {"m3", 1.5},
        {"c4", 0.05},
        {"m4", 3.0},
        {"c5", 0.02},
        {"m5", -1.0},
        {"c6", 0.01},
        {"m6", 8.0},
        {"cp", 0.0}}},
      {"veronda-westmann", {{"c1", 0.2}, {"c2", 1.5}, {"k", 10.0}}},
      {"veronda-westmann", {{"c1", 1.0}, {"c2", 0.5}, {"k", 100.0}}},
      {"yeoh", {{"c1", 0.57382}, {"c2", -0.074744}, {"c3", 0.011321}, {"k", 1000.0}}},
      {"yeoh",
       {{"c1", 0.3},
        {"c2", 0.1},
        {"c3", -0.02},
        {"c4", 0.004},
        {"c5", -0.001},
        {"c6", 0.0002},
        {"k", 3.0}}},
  };
  return cases;
}

std::unique_ptr<material::ElasticLaw> make(const LawCase& c) {
  return material::create_law(c.type, c.params, "test");
}

std::string describe(const LawCase& c) {
  std::string text = c.type;
  for (const auto& [key, value] : c.params)
    text += " " + key + "=" + std::to_string(value);
  return text;
}

/// F = I + 0.25 R, R with entries in [-1, 1]: stretches of about 0.5 to 1.5, det F > 0.
Mat3 random_deformation(std::uint64_t seed) {
  std::uint64_t state = seed;
  Mat3 F = Mat3::Identity();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      F(i, j) += 0.25 * uniform(state);
  EXPECT_GT(F.determinant(), 0.1);
  return F;
}

/// A symmetric matrix with entries in [-1, 1].
Mat3 random_symmetric(std::uint64_t seed) {
  std::uint64_t state = seed;
  Mat3 A;
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j)
      A(i, j) = A(j, i) = uniform(state);
  return A;
}

/// Relative differences of S and D against central differences at C.
struct DifferenceErrors {
  Real stress;
  Real tangent;
};

DifferenceErrors difference_errors(const material::ElasticLaw& m, const Mat3& C) {
  const Real h = 1e-6; // C is of order 1: truncation ~h^2, round-off ~1e-16/h
  const material::StressTangent st = m.stress_tangent(C);
  // the stress can vanish (C = I): relative to the modulus times the strain scale 1
  const Real stress_scale = std::max(st.S.norm(), m.shear_modulus());
  return {(st.S - stress_by_differences(m, C, h)).norm() / stress_scale,
          (st.D - tangent_by_differences(m, C, h)).norm() / st.D.norm()};
}

/// The isotropic small-strain tangent lambda I (x) I + 2 mu I_sym in Voigt form.
Mat6 isotropic_tangent(Real lambda, Real mu) {
  Mat6 D = Mat6::Zero();
  D.topLeftCorner<3, 3>().setConstant(lambda);
  for (int k = 0; k < 3; ++k) {
    D(k, k) += 2.0 * mu;
    D(k + 3, k + 3) = mu;
  }
  return D;
}

/// Small-strain (lambda, mu) of a case, computed from its parameters (not from the law).
material::Lame small_strain_moduli(const LawCase& c) {
  const auto& p = c.params;
  if (c.type == "holmes-mow")
    return material::lame_from_young(p.at("E"), p.at("nu"));
  Real mu = 0.0;
  if (c.type == "mooney-rivlin")
    mu = 2.0 * (p.at("c1") + (p.contains("c2") ? p.at("c2") : 0.0));
  else if (c.type == "yeoh")
    mu = 2.0 * p.at("c1");
  else if (c.type == "veronda-westmann")
    mu = p.at("c1") * p.at("c2");
  else // ogden: mu = (c1 + c2 + ...)/2 with FEBio's c_i/m_i^2 normalisation
    for (const char* key : {"c1", "c2", "c3", "c4", "c5", "c6"})
      mu += p.contains(key) ? 0.5 * p.at(key) : 0.0;
  if (c.type == "ogden-unconstrained") // lambda = cp
    return {p.at("cp"), mu};
  return {p.at("k") - 2.0 / 3.0 * mu, mu};
}

/// The message of the InputError thrown by create_law, or "" if none is thrown.
std::string input_error(const std::string& type, const material::ParameterValues& values) {
  try {
    material::create_law(type, values, "materials.cartilage");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

} // namespace

// (a) S = 2 dW/dC and D = dS/dE by central differences at three random states.
TEST(NewSolidLaws, StressAndTangentMatchCentralDifferences) {
  Real max_stress = 0.0, max_tangent = 0.0;
  for (const LawCase& c : new_law_cases()) {
    const auto m = make(c);
    for (std::uint64_t seed : {11u, 12u, 13u}) {
      const Mat3 F = random_deformation(seed);
      const DifferenceErrors e = difference_errors(*m, F.transpose() * F);
      EXPECT_LE(e.stress, 1e-6) << describe(c) << " seed " << seed;
      EXPECT_LE(e.tangent, 1e-6) << describe(c) << " seed " << seed;
      max_stress = std::max(max_stress, e.stress);
      max_tangent = std::max(max_tangent, e.tangent);
    }
  }
  RecordProperty("max_stress_error", scientific(max_stress));
  RecordProperty("max_tangent_error", scientific(max_tangent));
}

// (b) S = 0 at C = I, and D there is the isotropic tangent of the law's lambda and mu.
TEST(NewSolidLaws, SmallStrainLimitIsIsotropicLinearElasticity) {
  for (const LawCase& c : new_law_cases()) {
    const auto m = make(c);
    const auto [lambda, mu] = small_strain_moduli(c);
    const Real scale = lambda + 2.0 * mu;
    const material::StressTangent st = m->stress_tangent(Mat3::Identity());
    EXPECT_LE(st.S.norm(), 1e-14 * scale) << describe(c);
    EXPECT_LE((m->stress(Mat3::Identity()) - st.S).norm(), 1e-14 * scale) << describe(c);
    EXPECT_LE((st.D - isotropic_tangent(lambda, mu)).norm(), 1e-13 * scale) << describe(c);
    EXPECT_NEAR(m->shear_modulus(), mu, 1e-14 * scale) << describe(c);
    EXPECT_NEAR(m->p_wave_modulus(), lambda + 2.0 * mu, 1e-14 * scale) << describe(c);
    EXPECT_NEAR(m->energy(Mat3::Identity()), 0.0, 1e-15 * scale) << describe(c);
  }
}

// (c) sigma(QF) = Q sigma(F) Q^T, and isotropy: S(Q^T C Q) = Q^T S(C) Q and the same for the
// tangent applied to a strain increment, W(Q^T C Q) = W(C).
TEST(NewSolidLaws, FrameIndifferentAndIsotropic) {
  const Mat3 Q = rotation(1.1, Vec3(-2, 1, 3));
  for (const LawCase& c : new_law_cases()) {
    const auto m = make(c);
    for (std::uint64_t seed : {21u, 22u}) {
      const Mat3 F = random_deformation(seed);
      const Mat3 C = F.transpose() * F, Cr = Q.transpose() * C * Q;
      const Mat3 sigma = kinematics::cauchy_from_pk2(F, m->stress(C));
      const Mat3 QF = Q * F;
      const Mat3 sigma_rot = kinematics::cauchy_from_pk2(QF, m->stress(QF.transpose() * QF));
      EXPECT_LE((Q * sigma * Q.transpose() - sigma_rot).norm(), 1e-13 * sigma.norm())
          << describe(c);

      const material::StressTangent st = m->stress_tangent(C), st_r = m->stress_tangent(Cr);
      EXPECT_NEAR(m->energy(Cr), m->energy(C), 1e-13 * m->p_wave_modulus()) << describe(c);
      EXPECT_LE((st_r.S - Q.transpose() * st.S * Q).norm(), 1e-13 * st.S.norm()) << describe(c);
      const Mat3 dE = random_symmetric(seed + 100);
      const Mat3 dS = voigt::from_stress(st.D * voigt::strain(dE));
      const Mat3 dS_r = voigt::from_stress(st_r.D * voigt::strain(Q.transpose() * dE * Q));
      EXPECT_LE((dS_r - Q.transpose() * dS * Q).norm(), 1e-13 * st.D.norm() * dE.norm())
          << describe(c);
    }
  }
}

// (d) Ogden with equal and nearly equal principal stretches: the tangent is finite, matches
// central differences, and is continuous across coincidence.
TEST(Ogden, TangentWithEqualAndNearlyEqualStretches) {
  const Mat3 Q = rotation(0.9, Vec3(1, -1, 2));
  const auto rotated = [&](Real a, Real b, Real c) {
    return Mat3(Q * Vec3(a, b, c).asDiagonal() * Q.transpose());
  };
  const std::vector<std::pair<std::string, Mat3>> states = {
      {"C = I", Mat3::Identity()},
      {"three equal (1.2 I)", 1.2 * Mat3::Identity()},
      {"two equal, diagonal", Vec3(1.44, 0.8, 0.8).asDiagonal()},
      {"two equal, rotated", rotated(1.44, 0.8, 0.8)},
      {"gap 1e-9, rotated", rotated(1.44, 0.8, 0.8 * (1 + 1e-9))},
      {"three within 1e-9", rotated(1.1, 1.1 * (1 + 1e-9), 1.1 * (1 - 1e-9))},
      {"gap 1e-12, diagonal", Vec3(0.7, 1.3, 1.3 * (1 + 1e-12)).asDiagonal()},
  };
  Real max_tangent = 0.0;
  for (const LawCase& c : new_law_cases()) {
    if (c.type != "ogden")
      continue;
    const auto m = make(c);
    for (const auto& [name, C] : states) {
      const material::StressTangent st = m->stress_tangent(C);
      EXPECT_TRUE(st.D.allFinite() && st.S.allFinite()) << describe(c) << " " << name;
      const DifferenceErrors e = difference_errors(*m, C);
      EXPECT_LE(e.stress, 1e-6) << describe(c) << " " << name;
      EXPECT_LE(e.tangent, 1e-6) << describe(c) << " " << name;
      max_tangent = std::max(max_tangent, e.tangent);
    }
    // a gap of 1e-9 moves the tangent by O(1e-9) only (no cancellation in the divided
    // differences): nearly equal against exactly equal stretches
    const Mat6 D_equal = m->stress_tangent(rotated(1.44, 0.8, 0.8)).D;
    const Mat6 D_gap = m->stress_tangent(rotated(1.44, 0.8, 0.8 * (1 + 1e-9))).D;
    EXPECT_LE((D_gap - D_equal).norm(), 1e-8 * D_equal.norm()) << describe(c);
    const Mat6 D_triple = m->stress_tangent(1.1 * Mat3::Identity()).D;
    const Mat6 D_near = m->stress_tangent(rotated(1.1, 1.1 * (1 + 1e-9), 1.1 * (1 - 1e-9))).D;
    EXPECT_LE((D_near - D_triple).norm(), 1e-8 * D_triple.norm()) << describe(c);
  }
  RecordProperty("max_tangent_error", scientific(max_tangent));
}

// (e) sum_a l~_a^2 = I1~ and sum_a l~_a^-2 = I2~ (l~_1 l~_2 l~_3 = 1), so the Ogden terms
// c/m^2 (sum l~^m - 3) with m = 2 and m = -2 are c/4 (I1~ - 3) and c/4 (I2~ - 3): Ogden
// {c1 = 4 a, m1 = 2} is Mooney-Rivlin {c1 = a, c2 = 0}, and Ogden {c1 = 4 a, m1 = 2, c2 = 4 b,
// m2 = -2} is Mooney-Rivlin {c1 = a, c2 = b}, with the same k.
TEST(Ogden, SpecialCasesEqualMooneyRivlin) {
  const Real a = 0.3, b = 0.07, k = 4.0;
  const std::vector<std::pair<material::ParameterValues, material::ParameterValues>> pairs = {
      {{{"c1", 4 * a}, {"m1", 2.0}, {"k", k}}, {{"c1", a}, {"k", k}}},
      {{{"c1", 4 * a}, {"m1", 2.0}, {"c2", 4 * b}, {"m2", -2.0}, {"k", k}},
       {{"c1", a}, {"c2", b}, {"k", k}}},
      {{{"c1", 4 * b}, {"m1", -2.0}, {"c2", 4 * a}, {"m2", 2.0}, {"k", k}},
       {{"c1", a}, {"c2", b}, {"k", k}}},
  };
  for (const auto& [ogden_params, mooney_params] : pairs) {
    const auto ogden = material::create_law("ogden", ogden_params, "o");
    const auto mooney = material::create_law("mooney-rivlin", mooney_params, "mr");
    EXPECT_NEAR(ogden->shear_modulus(), mooney->shear_modulus(), 1e-15 * k);
    for (std::uint64_t seed : {31u, 32u, 33u}) {
      const Mat3 F = random_deformation(seed);
      const Mat3 C = F.transpose() * F;
      const material::StressTangent o = ogden->stress_tangent(C), r = mooney->stress_tangent(C);
      EXPECT_NEAR(ogden->energy(C), mooney->energy(C), 1e-13 * k) << seed;
      EXPECT_LE((o.S - r.S).norm(), 1e-13 * r.S.norm()) << seed;
      EXPECT_LE((o.D - r.D).norm(), 1e-13 * r.D.norm()) << seed;
    }
  }
}

// (f) Holmes-Mow: beta = 0 is the limit of beta -> 0, and small beta loses no digits.
TEST(HolmesMow, SmallBetaIsContinuousWithBetaZero) {
  const Real E = 1.0, nu = 0.2;
  const auto [lambda, mu] = material::lame_from_young(E, nu);
  const Real Ha = lambda + 2.0 * mu;
  const auto law = [&](Real beta) {
    return material::create_law("holmes-mow", {{"E", E}, {"nu", nu}, {"beta", beta}}, "hm");
  };
  const auto zero = law(0.0), small = law(1e-8);
  for (std::uint64_t seed : {41u, 42u, 43u}) {
    const Mat3 F = random_deformation(seed);
    const Mat3 C = F.transpose() * F;
    // P from the invariants, independently of the law: W(0) = P/4 and
    // W(beta) = P/4 (1 + x/2 + x^2/6 + ...), x = beta P / Ha
    const Real I1 = C.trace(), I2 = 0.5 * (I1 * I1 - (C * C).trace()), I3 = C.determinant();
    const Real P = (2 * mu - lambda) * (I1 - 3) + lambda * (I2 - 3) - Ha * std::log(I3);
    const Real x = 1e-8 * P / Ha;
    EXPECT_NEAR(zero->energy(C), 0.25 * P, 1e-14 * std::abs(P)) << seed;
    EXPECT_NEAR(small->energy(C), 0.25 * P * (1 + x / 2 + x * x / 6), 1e-14 * std::abs(P)) << seed;
    const material::StressTangent s0 = zero->stress_tangent(C), s1 = small->stress_tangent(C);
    EXPECT_TRUE(s1.D.allFinite());
    // the difference is O(beta): a few 1e-8 relative
    EXPECT_LE((s1.S - s0.S).norm(), 1e-7 * s0.S.norm()) << seed;
    EXPECT_LE((s1.D - s0.D).norm(), 1e-7 * s0.D.norm()) << seed;
    EXPECT_GT((s1.D - s0.D).norm(), 0.0) << seed; // beta is not dropped
  }
}

// (g) Missing keys, out-of-range values and failed cross-parameter checks name the key.
TEST(NewSolidLaws, BadParametersAreRejectedWithTheKeyPath) {
  struct Bad {
    std::string type;
    material::ParameterValues values;
    std::vector<std::string> expected; ///< substrings of the message
  };
  const std::vector<Bad> cases = {
      {"holmes-mow", {{"nu", 0.2}}, {"materials.cartilage.E", "missing"}},
      {"holmes-mow", {{"E", 1.0}, {"nu", 0.5}}, {"materials.cartilage.nu", "[0, 0.5)"}},
      {"holmes-mow", {{"E", 1.0}, {"nu", -0.1}}, {"materials.cartilage.nu", "[0, 0.5)"}},
      {"holmes-mow", {{"E", 1.0}, {"beta", -1.0}}, {"materials.cartilage.beta", "[0, inf)"}},
      {"holmes-mow", {{"E", 0.0}}, {"materials.cartilage.E", "(0, inf)"}},
      {"holmes-mow", {{"E", 1.0}, {"c1", 1.0}}, {"materials.cartilage.c1", "unknown"}},
      {"mooney-rivlin", {{"c2", 0.1}, {"k", 1.0}}, {"materials.cartilage.c1", "missing"}},
      {"mooney-rivlin", {{"c1", 0.1}}, {"materials.cartilage.k", "missing"}},
      {"mooney-rivlin", {{"c1", 0.1}, {"k", 0.0}}, {"materials.cartilage.k", "(0, inf)"}},
      {"mooney-rivlin",
       {{"c1", 0.1}, {"c2", -0.1}, {"k", 1.0}},
       {"materials.cartilage.c1 + materials.cartilage.c2", "> 0"}},
      {"mooney-rivlin",
       {{"c1", -0.3}, {"c2", 0.1}, {"k", 1.0}},
       {"materials.cartilage.c1 + materials.cartilage.c2", "> 0"}},
      {"ogden", {{"c1", 0.1}, {"k", 1.0}}, {"materials.cartilage.m1", "missing"}},
      {"ogden", {{"c1", 0.1}, {"m1", 2.0}}, {"materials.cartilage.k", "missing"}},
      {"ogden", {{"c1", 0.1}, {"m1", 2.0}, {"k", -1.0}}, {"materials.cartilage.k", "(0, inf)"}},
      {"ogden", {{"c1", 0.1}, {"m1", 0.0}, {"k", 1.0}}, {"materials.cartilage.m1", "nonzero"}},
      {"ogden",
       {{"c1", 0.1}, {"m1", 2.0}, {"c3", 0.2}, {"m3", 0.0}, {"k", 1.0}},
       {"materials.cartilage.m3", "nonzero"}},
      {"ogden",
       {{"c1", 0.1}, {"m1", 2.0}, {"c2", -0.3}, {"m2", 1.0}, {"k", 1.0}},
       {"materials.cartilage.c1 + materials.cartilage.c2 + materials.cartilage.c3", "> 0"}},
      {"ogden",
       {{"c1", 0.1}, {"m1", 2.0}, {"c4", 1.0}, {"k", 1.0}},
       {"materials.cartilage.c4", "unknown"}},
  };
  for (const Bad& bad : cases) {
    const std::string message = input_error(bad.type, bad.values);
    EXPECT_FALSE(message.empty()) << bad.type << " accepted " << describe({bad.type, bad.values});
    for (const std::string& part : bad.expected)
      EXPECT_NE(message.find(part), std::string::npos) << message;
  }
  // an absent term (c = 0) may keep m = 0, and the constructors re-check what create_law checks
  EXPECT_EQ(input_error("ogden", {{"c1", 0.1}, {"m1", 2.0}, {"m2", 0.0}, {"k", 1.0}}), "");
  const material::LawEntry& mooney = material::find_law("mooney-rivlin", "m");
  EXPECT_THROW(mooney.make({{"c1", 0.1}, {"c2", -0.2}, {"k", 1.0}}), InputError);
  const material::LawEntry& ogden = material::find_law("ogden", "m");
  EXPECT_THROW(ogden.make({{"c1", -0.1},
                           {"m1", 2.0},
                           {"c2", 0.0},
                           {"m2", 1.0},
                           {"c3", 0.0},
                           {"m3", 1.0},
                           {"k", 1.0}}),
               InputError);
}

// The example parameters of the registry pass every check and give the documented moduli.
TEST(NewSolidLaws, RegistryExamplesAreValid) {
  for (const auto& law : material::registered_laws()) {
    const auto m = material::create_law(law.type, law.example, "example");
    EXPECT_EQ(m->type(), law.type);
    EXPECT_GT(m->shear_modulus(), 0.0) << law.type;
    EXPECT_GT(m->p_wave_modulus(), m->shear_modulus()) << law.type;
  }
}

// ---------------------------------------------------------------------------------------------
// Closed forms of the FEBio laws added for .feb files, evaluated from the principal stretches
// (not from the laws' tensor algebra).

namespace {

/// A deformation with distinct principal stretches l along the axes of the rotation R: F = R
/// diag(l) (C = diag(l^2) in the rotated basis, the Cauchy stress R-rotated b's basis: sigma =
/// R diag(s) R^T with the principal values s).
struct PrincipalState {
  Mat3 R;
  Vec3 l;
  Mat3 F() const { return R * l.asDiagonal() * R.transpose(); }
};

const std::vector<PrincipalState>& principal_states() {
  static const std::vector<PrincipalState> states = {
      {rotation(0.4, Vec3(1, -2, 0.5)), Vec3(1.3, 0.9, 0.75)},
      {rotation(1.2, Vec3(0.2, 1, 1)), Vec3(0.7, 1.1, 1.45)},
      {Mat3::Identity(), Vec3(1.2, 1.0, 1.0)}, // two equal stretches
  };
  return states;
}

/// The Cauchy stress of `law` at F.
Mat3 cauchy(const material::ElasticLaw& law, const Mat3& F) {
  return kinematics::cauchy_from_pk2(F, law.stress(F.transpose() * F));
}

} // namespace

// Ogden unconstrained: sigma_a = sum_i c_i/m_i (l_a^m_i - 1)/J + cp (J - 1) (FEBio's principal
// Cauchy stresses) for distinct and for equal stretches.
TEST(OgdenUnconstrained, PrincipalCauchyStressesAreFebiosClosedForm) {
  const std::vector<std::pair<Real, Real>> terms = {{0.4, 4.0}, {0.2, -2.0}, {-0.1, 1.5}};
  const Real cp = 1.7;
  const auto law = material::create_law(
      "ogden-unconstrained",
      {{"c1", 0.4}, {"m1", 4.0}, {"c2", 0.2}, {"m2", -2.0}, {"c3", -0.1}, {"m3", 1.5}, {"cp", cp}},
      "o");
  for (const PrincipalState& st : principal_states()) {
    const Real J = st.l.prod();
    Vec3 s = Vec3::Constant(cp * (J - 1.0));
    for (int a = 0; a < 3; ++a)
      for (const auto& [c, m] : terms)
        s[a] += c / m * (std::pow(st.l[a], m) - 1.0) / J;
    const Mat3 exact = st.R * s.asDiagonal() * st.R.transpose();
    EXPECT_LE((cauchy(*law, st.F()) - exact).norm(), 1e-13 * exact.norm()) << st.l.transpose();
  }
}

// Yeoh: sigma = 2/J W'(I1~ - 3) dev(b~) + k ln J / J I (FEBio's deviatoric stress plus the
// volumetric pressure), W' = c1 + 2 c2 x + 3 c3 x^2.
TEST(Yeoh, CauchyStressIsFebiosClosedForm) {
  const Real c1 = 0.57382, c2 = -0.074744, c3 = 0.011321, k = 10.0;
  const auto law =
      material::create_law("yeoh", {{"c1", c1}, {"c2", c2}, {"c3", c3}, {"k", k}}, "y");
  for (const PrincipalState& st : principal_states()) {
    const Real J = st.l.prod();
    const Vec3 b_bar = st.l.array().square() / std::cbrt(J * J);
    const Real x = b_bar.sum() - 3.0, dW = c1 + 2.0 * c2 * x + 3.0 * c3 * x * x;
    const Vec3 s = (2.0 / J * dW * (b_bar.array() - b_bar.sum() / 3.0)).matrix() +
                   Vec3::Constant(k * std::log(J) / J);
    const Mat3 exact = st.R * s.asDiagonal() * st.R.transpose();
    EXPECT_LE((cauchy(*law, st.F()) - exact).norm(), 1e-13 * exact.norm()) << st.l.transpose();
  }
}

// Orthotropic elastic: a uniaxial stress S11 = sigma needs the strains of the compliance,
// E11 = sigma/E1, E22 = -v12 sigma/E1, E33 = -v31 sigma/E3 (FEBio's convention), and so on along
// e2 and e3; a shear strain 2 E12 = g gives S12 = G12 g alone. The law is linear in E: S = D E
// at any C, D symmetric, W = E : S / 2.
TEST(OrthotropicElastic, UniaxialStressesAndShearsFollowTheEngineeringConstants) {
  const material::ParameterValues p = {{"E1", 1.0},  {"E2", 2.0},  {"E3", 3.0},
                                       {"G12", 3.0}, {"G23", 2.0}, {"G31", 1.0},
                                       {"v12", 0.3}, {"v23", 0.2}, {"v31", 0.1}};
  const auto law = material::create_law("orthotropic-elastic", p, "ortho");
  const Real E1 = 1.0, E2 = 2.0, E3 = 3.0, v12 = 0.3, v23 = 0.2, v31 = 0.1, sigma = 0.01;
  const std::vector<std::pair<Vec3, Vec3>> uniaxial = {
      // (stress, strains) along e1, e2, e3
      {Vec3(sigma, 0, 0), Vec3(sigma / E1, -v12 * sigma / E1, -v31 * sigma / E3)},
      {Vec3(0, sigma, 0), Vec3(-v12 * sigma / E1, sigma / E2, -v23 * sigma / E2)},
      {Vec3(0, 0, sigma), Vec3(-v31 * sigma / E3, -v23 * sigma / E2, sigma / E3)}};
  for (const auto& [S, E] : uniaxial) {
    const Mat3 C = Mat3::Identity() + 2.0 * Mat3(E.asDiagonal());
    EXPECT_LE((law->stress(C) - Mat3(S.asDiagonal())).norm(), 1e-14) << S.transpose();
  }
  const std::vector<std::tuple<int, int, Real>> shears = {{0, 1, 3.0}, {1, 2, 2.0}, {0, 2, 1.0}};
  for (const auto& [i, j, G] : shears) {
    Mat3 C = Mat3::Identity();
    C(i, j) = C(j, i) = 0.02; // 2 E_ij = 0.02: the engineering shear strain
    Mat3 expected = Mat3::Zero();
    expected(i, j) = expected(j, i) = G * 0.02;
    EXPECT_LE((law->stress(C) - expected).norm(), 1e-15) << i << j;
  }
  const material::StressTangent st = law->stress_tangent(Mat3::Identity());
  EXPECT_LE((st.D - st.D.transpose()).norm(), 1e-14 * st.D.norm());
  for (std::uint64_t seed : {51u, 52u}) {
    const Mat3 F = random_deformation(seed);
    const Mat3 C = F.transpose() * F, E = 0.5 * (C - Mat3::Identity());
    const Mat3 S = law->stress(C);
    EXPECT_LE((voigt::stress(S) - st.D * voigt::strain(E)).norm(), 1e-14 * S.norm());
    EXPECT_NEAR(law->energy(C), 0.5 * (E.cwiseProduct(S)).sum(), 1e-14 * S.norm());
    EXPECT_LE((law->stress_tangent(C).D - st.D).norm(), 0.0);
    EXPECT_LE(difference_errors(*law, C).stress, 1e-8);
  }
  EXPECT_NEAR(law->p_wave_modulus(), st.D.diagonal().head<3>().maxCoeff(), 0.0);
  EXPECT_NEAR(law->shear_modulus(), 3.0, 0.0);
}

TEST(OrthotropicElastic, AnUnstableSetOfPoissonsRatiosIsRejectedNamingThem) {
  const std::string message = input_error("orthotropic-elastic", {{"E1", 1.0},
                                                                  {"E2", 1.0},
                                                                  {"E3", 1.0},
                                                                  {"G12", 1.0},
                                                                  {"G23", 1.0},
                                                                  {"G31", 1.0},
                                                                  {"v12", 0.6},
                                                                  {"v23", 0.6},
                                                                  {"v31", 0.6}});
  for (const char* part : {"materials.cartilage.v12 = 0.6", "materials.cartilage.v31 = 0.6",
                           "the compliance is not positive definite"})
    EXPECT_NE(message.find(part), std::string::npos) << message;
  EXPECT_NE(input_error("ogden-unconstrained", {{"c1", 0.0}, {"cp", 1.0}})
                .find("materials.cartilage.c1 + ... + materials.cartilage.c6 = 0: must be > 0"),
            std::string::npos);
  EXPECT_NE(input_error("ogden-unconstrained", {{"c2", 1.0}, {"m2", 0.0}, {"cp", 1.0}})
                .find("materials.cartilage.m2 = 0"),
            std::string::npos);
  EXPECT_NE(input_error("yeoh", {{"c1", -1.0}, {"k", 1.0}}).find("materials.cartilage.c1"),
            std::string::npos);
}

// Porous neo-Hookean: FEBio's Cauchy stress (FEPorousNeoHookean, lambda = 0)
// sigma = mu/J (R b + (phi_s R I1/3 - J)/(J - phi_s) I), R = (J~/J)^(2/3), J~ = (J - phi_s)/phi_w,
// mu = E/3 (1 + phi_w^2/2); the small-strain moduli: shear mu, bulk d2W/dJ2 = 2 mu/(3 phi_w^2).
TEST(PorousNeoHookean, CauchyStressIsFebiosClosedFormAndEIsItsYoungsModulus) {
  const Real E = 2.0, phi_s = 0.3, phi_w = 1.0 - phi_s;
  const auto law = material::create_law("porous-neo-hookean", {{"E", E}, {"phi0", phi_s}}, "m");
  const Real mu = E / 3.0 * (1.0 + 0.5 * phi_w * phi_w);
  for (const PrincipalState& st : principal_states()) {
    const Mat3 F = st.F();
    const Mat3 b = F * F.transpose();
    const Real J = F.determinant(), I1 = b.trace();
    const Real R = std::cbrt(std::pow((J - phi_s) / phi_w / J, 2.0));
    const Mat3 expected =
        mu / J * (R * b + (phi_s * R * I1 / 3.0 - J) / (J - phi_s) * Mat3::Identity());
    const Mat3 sigma = kinematics::cauchy_from_pk2(F, law->stress(F.transpose() * F));
    EXPECT_LE((sigma - expected).norm(), 1e-13 * mu) << st.l.transpose();
  }
  EXPECT_NEAR(law->shear_modulus(), mu, 1e-15 * mu);
  const Real bulk = 2.0 * mu / (3.0 * phi_w * phi_w);
  EXPECT_NEAR(law->p_wave_modulus(), bulk + 4.0 / 3.0 * mu, 1e-14 * mu);
  EXPECT_NEAR(9.0 * bulk * mu / (3.0 * bulk + mu), E, 1e-14 * E); // Young's modulus
  // the bulk modulus from the energy of dilatations C = J^(2/3) I
  const auto W = [&](Real J) { return law->energy(std::cbrt(J * J) * Mat3::Identity()); };
  const Real h = 1e-4;
  EXPECT_NEAR((W(1.0 + h) - 2.0 * W(1.0) + W(1.0 - h)) / (h * h), bulk, 1e-6 * bulk);
}

// Uncoupled Holmes-Mow: FEBio's deviatoric Cauchy stress dev(mu e^(beta (I1~ - 3)) b~)/J plus
// k ln J / J (FEHolmesMowUC), and the beta = 0 limit, an uncoupled neo-Hookean dev(mu b~)/J.
TEST(HolmesMowUncoupled, CauchyStressIsFebiosClosedForm) {
  const Real mu = 0.4, k = 10.0;
  for (const Real beta : {0.7, 0.0}) {
    const auto law =
        material::create_law("holmes-mow-uncoupled", {{"mu", mu}, {"beta", beta}, {"k", k}}, "h");
    for (const PrincipalState& st : principal_states()) {
      const Real J = st.l.prod();
      const Vec3 b_bar = st.l.array().square() / std::cbrt(J * J);
      const Real eQ = std::exp(beta * (b_bar.sum() - 3.0));
      const Vec3 s = (mu * eQ / J * (b_bar.array() - b_bar.sum() / 3.0)).matrix() +
                     Vec3::Constant(k * std::log(J) / J);
      const Mat3 exact = st.R * s.asDiagonal() * st.R.transpose();
      EXPECT_LE((cauchy(*law, st.F()) - exact).norm(), 1e-13 * exact.norm())
          << beta << " " << st.l.transpose();
    }
    EXPECT_LE(difference_errors(*law, 1.1 * principal_states()[0].F().transpose() *
                                          principal_states()[0].F())
                  .stress,
              1e-8);
  }
}
