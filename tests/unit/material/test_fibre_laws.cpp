// SPDX-License-Identifier: MIT
// fibre-exp-pow and solid-mixture: derivatives, tension-only switch, closed forms, frame
// indifference, rotated material, sums of constituents and bad input.
#include "trifem/core/error.hpp"
#include "trifem/material/fibre_exp_pow.hpp"
#include "trifem/material/registry.hpp"
#include "trifem/material/solid_mixture.hpp"
#include "trifem/tensor/kinematics.hpp"

#include "law_differences.hpp"
#include "law_states.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

using namespace trifem;

using namespace trifem::test;

namespace {

/// Parameters of one fibre family.
struct Fibre {
  Real ksi, alpha, beta;
  Vec3 direction; ///< not normalised: the law normalises it
};

material::ParameterValues values(const Fibre& f) {
  material::ParameterValues v = {{"ksi", f.ksi}, {"alpha", f.alpha}, {"beta", f.beta}};
  material::set_vector(v, "fibre", f.direction);
  return v;
}

std::shared_ptr<const material::ElasticLaw> fibre_law(const Fibre& f) {
  return material::create_law("fibre-exp-pow", values(f), "test");
}

std::string describe(const Fibre& f) {
  std::ostringstream out;
  out << "ksi=" << f.ksi << " alpha=" << f.alpha << " beta=" << f.beta << " fibre=("
      << f.direction.transpose() << ")";
  return out.str();
}

/// alpha = 0 and alpha > 0, beta = 2 and beta = 2.5, in directions off the axes.
const std::vector<Fibre>& fibre_cases() {
  static const std::vector<Fibre> cases = {
      {5.0, 0.0, 2.0, Vec3(1.0, 2.0, -0.5)},
      {5.0, 0.8, 2.0, Vec3(-0.3, 1.0, 0.7)},
      {2.0, 0.0, 2.5, Vec3(0.2, -0.4, 1.0)},
      {2.0, 1.5, 2.5, Vec3(3.0, 1.0, 1.0)},
  };
  return cases;
}

/// F = (I + 0.15 R)(I + s a a^T), a = unit(direction): a random state with the fibre stretched
/// (s > 0) or shortened (s < 0) by about s.
Mat3 deformation(std::uint64_t seed, const Vec3& direction, Real s) {
  const Vec3 a = direction.normalized();
  return (Mat3::Identity() + 0.15 * random_matrix(seed)) *
         (Mat3::Identity() + s * a * a.transpose());
}

Real fibre_invariant(const Mat3& C, const Vec3& direction) {
  const Vec3 a = direction.normalized();
  return a.dot(C * a);
}

/// A neo-Hookean ground matrix.
std::shared_ptr<const material::ElasticLaw> matrix_law() {
  return material::create_law("neo-hookean", {{"E", 0.5}, {"nu", 0.1}}, "matrix");
}

} // namespace

// (a) S = 2 dW/dC and D = dS/dE by central differences at three random states with the fibre
// in tension, for alpha = 0 and > 0, beta = 2 and 2.5.
TEST(FibreExpPow, StressAndTangentMatchCentralDifferences) {
  Real max_stress = 0.0, max_tangent = 0.0;
  for (const Fibre& f : fibre_cases()) {
    const auto m = fibre_law(f);
    for (std::uint64_t seed : {11u, 12u, 13u}) {
      const Mat3 F = deformation(seed, f.direction, 0.3);
      const Mat3 C = F.transpose() * F;
      ASSERT_GT(fibre_invariant(C, f.direction), 1.1) << describe(f) << " seed " << seed;
      const material::StressTangent st = m->stress_tangent(C);
      ASSERT_GT(st.S.norm(), 0.0);
      EXPECT_EQ(st.S, m->stress(C)) << describe(f);
      const Real h = 1e-6; // C is of order 1: truncation ~h^2, round-off ~1e-16/h
      const Real e_stress = (st.S - stress_by_differences(*m, C, h)).norm() / st.S.norm();
      const Real e_tangent = (st.D - tangent_by_differences(*m, C, h)).norm() / st.D.norm();
      EXPECT_LE(e_stress, 1e-6) << describe(f) << " seed " << seed;
      EXPECT_LE(e_tangent, 1e-6) << describe(f) << " seed " << seed;
      EXPECT_LE((st.D - st.D.transpose()).norm(), 1e-14 * st.D.norm()) << describe(f);
      max_stress = std::max(max_stress, e_stress);
      max_tangent = std::max(max_tangent, e_tangent);
    }
  }
  RecordProperty("max_stress_error", scientific(max_stress));
  RecordProperty("max_tangent_error", scientific(max_tangent));
}

// (b) Closed form along the fibre: C = diag(l^2, c2, c3), a0 = e1, x = l^2 - 1:
// W = ksi/(alpha beta)(e^(alpha x^beta) - 1) (ksi/beta x^beta at alpha = 0),
// S11 = 2 ksi x^(beta-1) e^(alpha x^beta), D1111 = 4 ksi x^(beta-2) (beta(alpha x^beta + 1) - 1)
// e^(alpha x^beta), every other component 0.
TEST(FibreExpPow, UniaxialClosedForm) {
  for (const Fibre& f : fibre_cases()) {
    const auto m = fibre_law({f.ksi, f.alpha, f.beta, Vec3(2.0, 0.0, 0.0)});
    for (Real l : {1.05, 1.3, 1.6}) {
      const Mat3 C = Vec3(l * l, 0.8, 1.3).asDiagonal();
      const Real x = l * l - 1, xb = std::pow(x, f.beta), e = std::exp(f.alpha * xb);
      const Real W = f.alpha == 0.0 ? f.ksi / f.beta * xb : f.ksi / (f.alpha * f.beta) * (e - 1);
      const Real S11 = 2 * f.ksi * std::pow(x, f.beta - 1) * e;
      const Real D1111 =
          4 * f.ksi * std::pow(x, f.beta - 2) * (f.beta * (f.alpha * xb + 1) - 1) * e;
      const material::StressTangent st = m->stress_tangent(C);
      EXPECT_NEAR(m->energy(C), W, 1e-14 * W) << describe(f) << " l " << l;
      EXPECT_NEAR(st.S(0, 0), S11, 1e-14 * S11) << describe(f) << " l " << l;
      EXPECT_NEAR(st.D(0, 0), D1111, 1e-14 * D1111) << describe(f) << " l " << l;
      EXPECT_EQ(st.S.norm(), std::abs(st.S(0, 0))) << "only S11 is nonzero";
      EXPECT_EQ(st.D.norm(), std::abs(st.D(0, 0))) << "only D1111 is nonzero";
    }
  }
}

// (c) No load in compression (I_n < 1) and at C = I: W, S and D exactly 0, so p_wave_modulus()
// and shear_modulus() are 0.
TEST(FibreExpPow, InertInCompressionAndAtTheReferenceState) {
  for (const Fibre& f : fibre_cases()) {
    const auto m = fibre_law(f);
    EXPECT_EQ(m->p_wave_modulus(), 0.0);
    EXPECT_EQ(m->shear_modulus(), 0.0);
    std::vector<Mat3> states = {Mat3::Identity()};
    for (std::uint64_t seed : {21u, 22u, 23u}) {
      const Mat3 F = deformation(seed, f.direction, -0.4);
      states.push_back(F.transpose() * F);
      EXPECT_LT(fibre_invariant(states.back(), f.direction), 0.9) << describe(f) << seed;
    }
    // stretched across the fibre (stretches 1.5 and 0.7), fibre slightly shortened: I_n = 0.98
    const Vec3 a = f.direction.normalized();
    const Vec3 b = a.unitOrthogonal(), c = a.cross(b);
    states.push_back(0.98 * a * a.transpose() + 2.25 * b * b.transpose() +
                     0.49 * c * c.transpose());
    for (const Mat3& C : states) {
      const material::StressTangent st = m->stress_tangent(C);
      EXPECT_EQ(m->energy(C), 0.0) << describe(f);
      EXPECT_EQ(m->stress(C).norm(), 0.0) << describe(f);
      EXPECT_EQ(st.S.norm(), 0.0) << describe(f);
      EXPECT_EQ(st.D.norm(), 0.0) << describe(f);
    }
  }
}

// (d) At I_n -> 1+: S -> 0 for beta >= 2; D -> 0 for beta > 2, while beta = 2 jumps to
// 4 ksi a0(x)a0(x)a0(x)a0 (FEBio's beta >= 2 keeps the stress, not the tangent, continuous).
// Near x = 0+, |S| = 2 ksi x^(beta-1) and |D| = 4 ksi (beta - 1) x^(beta-2) to O(x^beta).
TEST(FibreExpPow, OneSidedLimitsAtUnitFibreStretch) {
  for (const Fibre& f : fibre_cases()) {
    const auto m = fibre_law(f);
    const Vec3 a = f.direction.normalized();
    const Mat3 A = a * a.transpose();
    const Real x = 1e-8; // evaluated as a0.C a0 - 1: relative round-off ~1e-8
    const material::StressTangent st = m->stress_tangent(Mat3::Identity() + x * A);
    const Real dW = f.ksi * std::pow(x, f.beta - 1),
               d2W = f.ksi * (f.beta - 1) * std::pow(x, f.beta - 2);
    EXPECT_LE((st.S - 2 * dW * A).norm(), 1e-6 * 2 * dW) << describe(f); // |A| = 1
    const Mat6 AA = voigt::outer(A, A);
    EXPECT_LE((st.D - 4 * d2W * AA).norm(), 1e-6 * 4 * d2W * AA.norm()) << describe(f);
    if (f.beta == 2.0) // the jump: d2W = ksi
      EXPECT_LE((st.D - 4 * f.ksi * AA).norm(), 1e-6 * 4 * f.ksi * AA.norm()) << describe(f);
    else // beta = 2.5: D = O(x^0.5)
      EXPECT_LE(st.D.norm(), 1e-3 * 4 * f.ksi * AA.norm()) << describe(f);
  }
}

// (e) alpha -> 0 is continuous with the exact alpha = 0 branch (expm1 loses no digits):
// W(alpha) = ksi/beta x^beta (1 + alpha x^beta/2 + ...).
TEST(FibreExpPow, SmallAlphaIsContinuousWithAlphaZero) {
  for (Real beta : {2.0, 2.5}) {
    const auto zero = fibre_law({3.0, 0.0, beta, Vec3(0, 1, 0)});
    const auto small = fibre_law({3.0, 1e-9, beta, Vec3(0, 1, 0)});
    const Mat3 C = Vec3(0.9, 1.44, 1.1).asDiagonal();
    const Real xb = std::pow(0.44, beta), W0 = 3.0 / beta * xb;
    EXPECT_NEAR(zero->energy(C), W0, 1e-15 * W0);
    EXPECT_NEAR(small->energy(C), W0 * (1 + 1e-9 * xb / 2), 1e-15 * W0);
    EXPECT_GT(small->energy(C), zero->energy(C)); // alpha is not dropped
  }
}

// (f) sigma(QF) = Q sigma(F) Q^T (frame indifference), and the rotated material:
// W, S and D at (Q^T C Q, Q^T a0) are those at (C, a0) rotated by Q^T.
TEST(FibreExpPow, FrameIndifferentAndRotatedMaterial) {
  const Mat3 Q = rotation(1.1, Vec3(-2, 1, 3));
  for (const Fibre& f : fibre_cases()) {
    const auto m = fibre_law(f);
    const auto rotated = fibre_law({f.ksi, f.alpha, f.beta, Q.transpose() * f.direction});
    for (std::uint64_t seed : {31u, 32u}) {
      const Mat3 F = deformation(seed, f.direction, 0.3);
      const Mat3 C = F.transpose() * F, Cr = Q.transpose() * C * Q;
      const Mat3 sigma = kinematics::cauchy_from_pk2(F, m->stress(C));
      const Mat3 QF = Q * F;
      const Mat3 sigma_q = kinematics::cauchy_from_pk2(QF, m->stress(QF.transpose() * QF));
      EXPECT_LE((Q * sigma * Q.transpose() - sigma_q).norm(), 1e-13 * sigma.norm()) << describe(f);

      const material::StressTangent st = m->stress_tangent(C), st_r = rotated->stress_tangent(Cr);
      EXPECT_NEAR(rotated->energy(Cr), m->energy(C), 1e-13 * m->energy(C)) << describe(f);
      EXPECT_LE((st_r.S - Q.transpose() * st.S * Q).norm(), 1e-13 * st.S.norm()) << describe(f);
      const Mat3 dE = random_matrix(seed + 100) + random_matrix(seed + 100).transpose();
      const Mat3 dS = voigt::from_stress(st.D * voigt::strain(dE));
      const Mat3 dS_r = voigt::from_stress(st_r.D * voigt::strain(Q.transpose() * dE * Q));
      EXPECT_LE((dS_r - Q.transpose() * dS * Q).norm(), 1e-13 * st.D.norm() * dE.norm())
          << describe(f);
      // the fibre is anisotropic: the unrotated law at Cr differs
      EXPECT_GT((m->stress(Cr) - Q.transpose() * st.S * Q).norm(), 1e-3 * st.S.norm());
    }
  }
}

// (g) A solid mixture is the sum of its constituents (W, S, D, moduli), and a mixture of one
// constituent is that constituent.
TEST(SolidMixture, IsTheSumOfItsConstituents) {
  const auto matrix = matrix_law();
  const auto f1 = fibre_law(fibre_cases()[1]), f2 = fibre_law(fibre_cases()[3]);
  const material::SolidMixture mix({matrix, f1, f2}, "mix");
  EXPECT_EQ(mix.type(), "solid-mixture");
  EXPECT_EQ(mix.constituents().size(), 3u);
  EXPECT_EQ(mix.p_wave_modulus(), matrix->p_wave_modulus());
  EXPECT_EQ(mix.shear_modulus(), matrix->shear_modulus());
  const material::SolidMixture single({f1, matrix}, "single");
  const material::SolidMixture alone({matrix}, "alone");
  for (std::uint64_t seed : {41u, 42u, 43u}) {
    const Mat3 F = Mat3::Identity() + 0.25 * random_matrix(seed);
    const Mat3 C = F.transpose() * F;
    const material::StressTangent a = matrix->stress_tangent(C), b = f1->stress_tangent(C),
                                  c = f2->stress_tangent(C), sum = mix.stress_tangent(C);
    const Real W = matrix->energy(C) + f1->energy(C) + f2->energy(C);
    EXPECT_NEAR(mix.energy(C), W, 1e-15 * std::abs(W)) << seed;
    EXPECT_LE((sum.S - (a.S + b.S + c.S)).norm(), 1e-15 * sum.S.norm()) << seed;
    EXPECT_LE((mix.stress(C) - sum.S).norm(), 1e-15 * sum.S.norm()) << seed;
    EXPECT_LE((sum.D - (a.D + b.D + c.D)).norm(), 1e-15 * sum.D.norm()) << seed;
    EXPECT_LE((single.stress_tangent(C).D - (b.D + a.D)).norm(), 1e-15 * sum.D.norm()) << seed;
    // one constituent: the same numbers
    EXPECT_EQ(alone.energy(C), matrix->energy(C)) << seed;
    EXPECT_EQ(alone.stress(C), a.S) << seed;
    EXPECT_EQ(alone.stress_tangent(C).D, a.D) << seed;
  }
  // at C = I the fibres add nothing: the mixture's small-strain tangent is the matrix's
  EXPECT_EQ(mix.stress_tangent(Mat3::Identity()).D, matrix->stress_tangent(Mat3::Identity()).D);
}

// (h) The mixture's S and D match central differences (fibres in tension and matrix together).
TEST(SolidMixture, StressAndTangentMatchCentralDifferences) {
  material::LawSpec spec{"solid-mixture", {}, {{"neo-hookean", {{"E", 0.5}, {"nu", 0.1}}, {}}}};
  for (const Fibre& f : fibre_cases())
    spec.constituents.push_back({"fibre-exp-pow", values(f), {}});
  const auto mix = material::create_law(spec, "materials.cart.solid");
  EXPECT_EQ(mix->type(), "solid-mixture");
  Real worst = 0.0;
  for (std::uint64_t seed : {51u, 52u, 53u}) {
    const Mat3 F = deformation(seed, fibre_cases()[seed % 4].direction, 0.3);
    const Mat3 C = F.transpose() * F;
    int stretched = 0;
    for (const Fibre& f : fibre_cases())
      stretched += fibre_invariant(C, f.direction) > 1.0;
    EXPECT_GT(stretched, 0) << seed;
    const material::StressTangent st = mix->stress_tangent(C);
    const Real e_stress = (st.S - stress_by_differences(*mix, C, 1e-6)).norm() / st.S.norm();
    const Real e_tangent = (st.D - tangent_by_differences(*mix, C, 1e-6)).norm() / st.D.norm();
    EXPECT_LE(e_stress, 1e-6) << seed;
    EXPECT_LE(e_tangent, 1e-6) << seed;
    worst = std::max({worst, e_stress, e_tangent});
  }
  RecordProperty("max_relative_error", scientific(worst));
}

// (i) The fibre is only a constituent law; its registry example is valid.
TEST(FibreExpPow, RegistryEntries) {
  for (const auto& law : material::registered_laws())
    EXPECT_NE(law.type, "fibre-exp-pow");
  // and fibre-distribution, fibre-exp-linear (uncoupled and coupled), the ellipsoidal ones
  ASSERT_EQ(material::constituent_laws().size(), 6u);
  EXPECT_EQ(material::constituent_laws()[0].type, "fibre-exp-pow");
  const material::LawEntry& entry = material::find_law("fibre-exp-pow", "m");
  const auto m = material::create_law(entry.type, entry.example, "example");
  EXPECT_EQ(m->type(), "fibre-exp-pow");
  const auto& fibre = dynamic_cast<const material::FibreExpPow&>(*m);
  EXPECT_NEAR(fibre.direction().norm(), 1.0, 1e-15);
  // normalised: [0, 3, 4] is [0, 0.6, 0.8]
  const auto scaled = fibre_law({1.0, 0.0, 2.0, Vec3(0.0, 3.0, 4.0)});
  EXPECT_LE(
      (dynamic_cast<const material::FibreExpPow&>(*scaled).direction() - Vec3(0, 0.6, 0.8)).norm(),
      1e-15);
}

// (j) Bad parameters and bad mixtures are InputErrors naming the key path.
TEST(FibreExpPow, BadParametersAreRejectedWithTheKeyPath) {
  const std::string ctx = "materials.cart.solid.constituent[2]";
  const auto fibre = [&](Fibre f) {
    return input_error([&] { material::create_law("fibre-exp-pow", values(f), ctx); });
  };
  struct Bad {
    std::string message;
    std::vector<std::string> expected;
  };
  material::ParameterValues no_fibre = {{"ksi", 1.0}, {"alpha", 0.0}, {"beta", 2.0}};
  material::ParameterValues partial = no_fibre;
  partial["fibre.x"] = 1.0;
  material::ParameterValues stray = values({1.0, 0.0, 2.0, Vec3(1, 0, 0)});
  stray["fibre.w"] = 1.0;
  const auto raw = [&](const material::ParameterValues& v) {
    return input_error([&] { material::create_law("fibre-exp-pow", v, ctx); });
  };
  const std::vector<Bad> cases = {
      {fibre({1.0, 0.0, 2.0, Vec3::Zero()}), {ctx + ".fibre = [0, 0, 0]", "nonzero"}},
      {fibre({1.0, 0.0, 1.9, Vec3(1, 0, 0)}), {ctx + ".beta = 1.9", "[2, inf)"}},
      {fibre({-1.0, 0.0, 2.0, Vec3(1, 0, 0)}), {ctx + ".ksi = -1", "[0, inf)"}},
      {fibre({1.0, -0.5, 2.0, Vec3(1, 0, 0)}), {ctx + ".alpha = -0.5", "[0, inf)"}},
      {fibre({1.0, 0.0, 2.0, Vec3(1, NAN, 0)}), {ctx + ".fibre.y = nan", "out of range"}},
      {raw(no_fibre), {ctx + ".fibre: missing required parameter"}},
      {raw(partial), {ctx + ".fibre: incomplete vector"}},
      {raw(stray), {ctx + ".fibre.w: unknown parameter"}},
  };
  for (const Bad& bad : cases) {
    EXPECT_FALSE(bad.message.empty());
    for (const std::string& part : bad.expected)
      EXPECT_NE(bad.message.find(part), std::string::npos) << bad.message;
  }
  // the constructor re-checks the direction
  const material::LawEntry& entry = material::find_law("fibre-exp-pow", "m");
  EXPECT_THROW(entry.make(values({1.0, 0.0, 2.0, Vec3::Zero()})), InputError);
}

TEST(SolidMixture, BadMixturesAreRejectedWithTheKeyPath) {
  const std::string ctx = "materials.cart.solid";
  const material::LawSpec matrix{"neo-hookean", {{"E", 1.0}}, {}};
  const material::LawSpec fibre{"fibre-exp-pow", values({1.0, 0.0, 2.0, Vec3(1, 0, 0)}), {}};
  const auto error = [&](const material::LawSpec& spec) {
    return input_error([&] { material::create_law(spec, ctx); });
  };
  struct Bad {
    material::LawSpec spec;
    std::vector<std::string> expected;
  };
  const std::vector<Bad> cases = {
      {{"solid-mixture", {}, {}}, {ctx + ".constituent", "at least one constituent"}},
      {{"solid-mixture", {}, {fibre, fibre}}, {ctx + ": the solid mixture", "no stiffness"}},
      {{"solid-mixture", {}, {matrix, {"solid-mixture", {}, {matrix}}}},
       {ctx + ".constituent[2].type = 'solid-mixture'", "nested"}},
      {{"solid-mixture", {}, {matrix, {"fibre-exp-pow", {{"ksi", 1.0}}, {}}}},
       {ctx + ".constituent[2].alpha: missing"}},
      {{"solid-mixture", {}, {matrix, {"fibre-exp-pw", {}, {}}}},
       {ctx + ".constituent[2].type = 'fibre-exp-pw': unknown"}},
      {{"solid-mixture", {{"E", 1.0}}, {matrix}}, {ctx + ".E: unknown key"}},
      {{"neo-hookean", {{"E", 1.0}}, {matrix}}, {ctx + ".constituent: only a solid-mixture"}},
  };
  for (const Bad& bad : cases) {
    const std::string message = error(bad.spec);
    EXPECT_FALSE(message.empty()) << bad.spec.type;
    for (const std::string& part : bad.expected)
      EXPECT_NE(message.find(part), std::string::npos) << message;
  }
  EXPECT_THROW(material::SolidMixture({}, ctx), InputError);
}

// ---------------------------------------------------------------------------------------------
// fibre-exp-linear (the fibre of FEBio's trans iso Mooney-Rivlin / Veronda-Westmann)

namespace {

material::ParameterValues exp_linear(Real c3, Real c4, Real c5, Real lam_max, const Vec3& a) {
  material::ParameterValues v = {{"c3", c3}, {"c4", c4}, {"c5", c5}, {"lam_max", lam_max}};
  material::set_vector(v, "fibre", a);
  return v;
}

/// F = I + 0.2 R with R in [-1, 1] (a state where the fibre of direction (1, 2, 2)/3 is
/// stretched past lam_max or not, by the scale).
Mat3 stretched_along(const Vec3& a, Real stretch, std::uint64_t seed) {
  std::uint64_t state = seed;
  Mat3 F = Mat3::Identity() + (stretch - 1.0) * a * a.transpose() / a.squaredNorm();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      F(i, j) += 0.03 * uniform(state);
  return F;
}

} // namespace

// S and D against central differences of W and S, in the exponential and the linear part, with
// c3 given and with c3 = 0 (FEBio's derived c3), uncoupled and coupled.
TEST(FibreExpLinear, StressAndTangentAreTheDerivativesOfItsEnergy) {
  const Vec3 a(1.0, 2.0, 2.0);
  for (const char* type : {"fibre-exp-linear", "fibre-exp-linear-coupled"})
    for (const Real c3 : {0.5, 0.0})
      for (const Real stretch : {1.03, 1.12}) // below and above lam_max = 1.06
        for (std::uint64_t seed : {61u, 62u}) {
          const auto law = material::create_law(type, exp_linear(c3, 20.0, 80.0, 1.06, a), "f");
          EXPECT_EQ(law->type(), type);
          const Mat3 F = stretched_along(a, stretch, seed);
          const Mat3 C = F.transpose() * F;
          const material::StressTangent st = law->stress_tangent(C);
          ASSERT_GT(st.S.norm(), 0.0);
          const Real h = 1e-6;
          EXPECT_LE((st.S - stress_by_differences(*law, C, h)).norm(), 1e-6 * st.S.norm())
              << c3 << " " << stretch;
          EXPECT_LE((st.D - tangent_by_differences(*law, C, h)).norm(), 1e-6 * st.D.norm())
              << c3 << " " << stretch;
        }
}

// Along the fibre at J = 1 (l~ = l): the Cauchy stress's fibre component minus its lateral one
// is the fibre's F(l) = c3 (exp(c4 (l - 1)) - 1) below lam_max and c5 l + c6 above (FEBio's
// closed form), none in compression, and the law is inert at C = I.
TEST(FibreExpLinear, IsochoricStretchAlongTheFibreGivesFebiosFibreStress) {
  const Real c3 = 0.5, c4 = 20.0, c5 = 80.0, lam_max = 1.06;
  const auto law =
      material::create_law("fibre-exp-linear", exp_linear(c3, c4, c5, lam_max, Vec3::UnitX()), "f");
  const Real c6 = c3 * (std::exp(c4 * (lam_max - 1.0)) - 1.0) - c5 * lam_max;
  for (const Real l : {1.02, 1.05, 1.06, 1.1, 1.3}) {
    Mat3 F = Mat3::Identity();
    F(0, 0) = l;
    F(1, 1) = F(2, 2) = 1.0 / std::sqrt(l);
    const Mat3 sigma = kinematics::cauchy_from_pk2(F, law->stress(F.transpose() * F));
    const Real expected = l < lam_max ? c3 * (std::exp(c4 * (l - 1.0)) - 1.0) : c5 * l + c6;
    EXPECT_NEAR(sigma(0, 0) - sigma(1, 1), expected, 1e-12 * c5) << l;
    EXPECT_NEAR(sigma.trace(), 0.0, 1e-12 * c5) << l; // deviatoric
  }
  Mat3 F = Mat3::Identity();
  F(0, 0) = 0.9;
  EXPECT_EQ(law->stress(F.transpose() * F).norm(), 0.0);
  EXPECT_EQ(law->stress_tangent(Mat3::Identity()).D.norm(), 0.0);
  EXPECT_EQ(law->energy(Mat3::Identity()), 0.0);
}

// The coupled fibre stretched along x by l with the lateral stretch s (J = l s^2): the Cauchy
// stress is F(l)/J along the fibre and nothing else (FEBio's FEFiberExpLinear), l the whole
// stretch; none in compression.
TEST(FibreExpLinear, CoupledFibreStressIsThatOfItsWholeStretch) {
  const Real c3 = 0.5, c4 = 20.0, c5 = 80.0, lam_max = 1.06;
  const auto law = material::create_law("fibre-exp-linear-coupled",
                                        exp_linear(c3, c4, c5, lam_max, Vec3::UnitX()), "f");
  const Real c6 = c3 * (std::exp(c4 * (lam_max - 1.0)) - 1.0) - c5 * lam_max;
  for (const Real l : {1.02, 1.05, 1.1, 1.3})
    for (const Real lateral : {0.9, 1.0, 1.1}) {
      Mat3 F = Mat3::Identity();
      F(0, 0) = l;
      F(1, 1) = F(2, 2) = lateral;
      const Real J = l * lateral * lateral;
      const Mat3 sigma = kinematics::cauchy_from_pk2(F, law->stress(F.transpose() * F));
      const Real expected = l < lam_max ? c3 * (std::exp(c4 * (l - 1.0)) - 1.0) : c5 * l + c6;
      EXPECT_NEAR(sigma(0, 0), expected / J, 1e-12 * c5) << l << " " << lateral;
      EXPECT_NEAR(sigma(1, 1), 0.0, 1e-12 * c5) << l << " " << lateral;
      EXPECT_NEAR(sigma(2, 2), 0.0, 1e-12 * c5) << l << " " << lateral;
    }
  Mat3 F = Mat3::Identity() * 1.2; // stretched laterally, shortened along the fibre
  F(0, 0) = 0.95;
  EXPECT_EQ(law->stress(F.transpose() * F).norm(), 0.0);
}

// FEBio's trans iso Mooney-Rivlin as a solid mixture: c1, c2, k and the fibre. Stretched by 1.2
// along the fibre (x) or across it (y), the difference of the two stresses along the stretch
// is the fibre's deviatoric part 2/3 F(l~)/J, l~ = 1.2^(2/3), J = 1.2 (stretched across, the
// fibre is shortened and inert); the two lateral directions across the fibre agree.
TEST(FibreExpLinear, TransverselyIsotropicMixtureIsStifferAlongItsFibre) {
  material::LawSpec mix{"solid-mixture",
                        {},
                        {{"mooney-rivlin", {{"c1", 1.0}, {"c2", 0.0}, {"k", 100.0}}, {}},
                         {"fibre-exp-linear", exp_linear(1.0, 1.0, 1.0, 10.0, Vec3::UnitX()), {}}}};
  const auto law = material::create_law(mix, "m");
  const auto along = [&](int k) {
    Mat3 F = Mat3::Identity();
    F(k, k) = 1.2;
    return kinematics::cauchy_from_pk2(F, law->stress(F.transpose() * F))(k, k);
  };
  const Real l = std::pow(1.2, 2.0 / 3.0), fibre = std::exp(l - 1.0) - 1.0;
  EXPECT_NEAR(along(0) - along(1), 2.0 / 3.0 * fibre / 1.2, 1e-12);
  EXPECT_NEAR(along(1), along(2), 1e-12);
}

TEST(FibreExpLinear, BadParametersAreRejectedWithTheKeyPath) {
  const auto message = [](const material::ParameterValues& v) {
    return input_error([&] { material::create_law("fibre-exp-linear", v, "materials.lig"); });
  };
  EXPECT_NE(message(exp_linear(1.0, 1.0, 1.0, 1.0, Vec3::Zero())).find("materials.lig.fibre"),
            std::string::npos);
  EXPECT_NE(message(exp_linear(0.0, 0.0, 1.0, 1.1, Vec3::UnitX())).find("materials.lig.c4 = 0"),
            std::string::npos);
  EXPECT_NE(message(exp_linear(1.0, 1.0, 1.0, 0.9, Vec3::UnitX())).find("materials.lig.lam_max"),
            std::string::npos);
}

// ---------------------------------------------------------------------------------------------
// ellipsoidal-fibre-distribution (FEBio's "ellipsoidal fiber distribution")

namespace {

material::ParameterValues efd(const Vec3& ksi, const Vec3& beta, Real resolution = 12.0) {
  material::ParameterValues v = {{"resolution", resolution}};
  material::set_vector(v, "ksi", ksi);
  material::set_vector(v, "beta", beta);
  return v;
}

/// W = int_S2 ksi(n) (I_n - 1)^beta(n) dS by the midpoint rule in (theta, phi) with `m` x 2m
/// cells: an integration independent of the law's.
Real efd_energy_by_angles(const Mat3& C, const Vec3& ksi, const Vec3& beta, int m) {
  const auto ellipsoid = [](const Vec3& n, const Vec3& a) {
    return 1.0 / std::sqrt((n.array() / a.array()).square().sum());
  };
  Real W = 0.0;
  const Real dphi = std::numbers::pi / m, dtheta = std::numbers::pi / m;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < 2 * m; ++j) {
      const Real phi = (i + 0.5) * dphi, theta = (j + 0.5) * dtheta;
      const Vec3 n(std::cos(theta) * std::sin(phi), std::sin(theta) * std::sin(phi), std::cos(phi));
      const Real x = n.dot(C * n) - 1.0;
      if (x > 0.0)
        W += ellipsoid(n, ksi) * std::pow(x, ellipsoid(n, beta)) * std::sin(phi) * dphi * dtheta;
    }
  return W;
}

} // namespace

// S and D against central differences of W and S at states where some fibres are in tension
// and others not.
TEST(EllipsoidalFibreDistribution, StressAndTangentAreTheDerivativesOfItsEnergy) {
  for (const char* type :
       {"ellipsoidal-fibre-distribution", "ellipsoidal-fibre-distribution-uncoupled"}) {
    const auto law =
        material::create_law(type, efd(Vec3(4.0, 2.0, 1.0), Vec3(2.5, 3.0, 3.5), 8.0), "f");
    EXPECT_EQ(law->type(), type);
    for (std::uint64_t seed : {71u, 72u, 73u}) {
      const Mat3 F = stretched_along(Vec3(1.0, 2.0, 2.0), 1.1, seed);
      const Mat3 C = F.transpose() * F;
      const material::StressTangent st = law->stress_tangent(C);
      ASSERT_GT(st.S.norm(), 0.0);
      const Real h = 1e-6;
      EXPECT_LE((st.S - stress_by_differences(*law, C, h)).norm(), 1e-6 * st.S.norm())
          << type << " " << seed;
      EXPECT_LE((st.D - tangent_by_differences(*law, C, h)).norm(), 1e-6 * st.D.norm())
          << type << " " << seed;
    }
  }
}

// The uncoupled distribution sees the deviatoric deformation only: at J = 1 it has the coupled
// one's energy, its Cauchy stress is deviatoric, and a dilatation loads no fibre.
TEST(EllipsoidalFibreDistribution, TheUncoupledOneSeesTheDeviatoricDeformation) {
  const auto params = efd(Vec3(4.0, 2.0, 1.0), Vec3(2.5, 3.0, 3.5));
  const auto coupled = material::create_law("ellipsoidal-fibre-distribution", params, "f");
  const auto uncoupled =
      material::create_law("ellipsoidal-fibre-distribution-uncoupled", params, "f");
  for (std::uint64_t seed : {81u, 82u}) {
    Mat3 F = stretched_along(Vec3(1.0, 2.0, 2.0), 1.15, seed);
    const Mat3 isochoric = F / std::cbrt(F.determinant());
    const Mat3 C = isochoric.transpose() * isochoric;
    EXPECT_NEAR(uncoupled->energy(C), coupled->energy(C), 1e-13 * coupled->energy(C)) << seed;
    F *= 1.1; // a dilatation on top changes nothing but J
    const Mat3 sigma = kinematics::cauchy_from_pk2(F, uncoupled->stress(F.transpose() * F));
    ASSERT_GT(sigma.norm(), 0.0);
    EXPECT_NEAR(sigma.trace(), 0.0, 1e-12 * sigma.norm()) << seed;
    EXPECT_NEAR(uncoupled->energy(F.transpose() * F), coupled->energy(C),
                1e-12 * coupled->energy(C))
        << seed;
  }
  // (J^(-2/3) I_n - 1 is round-off there: the stress is at most ksi times its power)
  EXPECT_LE(uncoupled->stress(1.2 * Mat3::Identity()).norm(), 1e-14 * 4.0);
}

// A dilatation C = c^2 I stretches every fibre alike: W = 4 pi ksi (c^2 - 1)^beta and
// S = 8 pi/3 ksi beta (c^2 - 1)^(beta - 1) I for equal semi-axes, exactly at every resolution
// (the rule integrates constants and n (x) n exactly); a contraction loads no fibre.
TEST(EllipsoidalFibreDistribution, ADilatationGivesTheClosedForm) {
  const Real ksi = 3.0, beta = 2.5, c = 1.1, x = c * c - 1.0;
  for (const Real resolution : {3.0, 12.0}) {
    const auto law =
        material::create_law("ellipsoidal-fibre-distribution",
                             efd(Vec3::Constant(ksi), Vec3::Constant(beta), resolution), "f");
    const Mat3 C = c * c * Mat3::Identity();
    const Real W = 4.0 * std::numbers::pi * ksi * std::pow(x, beta);
    EXPECT_NEAR(law->energy(C), W, 1e-13 * W) << resolution;
    const Real S = 8.0 * std::numbers::pi / 3.0 * ksi * beta * std::pow(x, beta - 1.0);
    EXPECT_LE((law->stress(C) - S * Mat3::Identity()).norm(), 1e-13 * S) << resolution;
    EXPECT_EQ(law->stress(0.9 * Mat3::Identity()).norm(), 0.0);
  }
}

// With unequal semi-axes the energy of a stretch along a skew direction equals an independent
// integration over the angles (a 1000 x 2000 midpoint rule) within the rules' errors.
TEST(EllipsoidalFibreDistribution, EnergyIsTheIntegralOverTheSphere) {
  const Vec3 ksi(4.0, 2.0, 1.0), beta(2.5, 3.0, 3.5);
  const auto law = material::create_law("ellipsoidal-fibre-distribution", efd(ksi, beta), "f");
  const Vec3 a = Vec3(1.0, 2.0, 2.0) / 3.0;
  const Mat3 F = Mat3::Identity() + 0.2 * a * a.transpose(); // stretched along a, 1 across
  const Mat3 C = F.transpose() * F;
  const Real expected = efd_energy_by_angles(C, ksi, beta, 1000);
  EXPECT_NEAR(law->energy(C), expected, 1e-5 * expected);
}
