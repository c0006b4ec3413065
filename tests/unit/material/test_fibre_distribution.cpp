// SPDX-License-Identifier: MIT
// fibre-distribution: derivatives, tension-only switch, frame indifference, the closed form of
// a dilatation, uniaxial states against an independent one-dimensional integral (convergence of
// the rule on the sphere), the ellipsoidal density and bad input.
#include "trifem/core/error.hpp"
#include "trifem/material/fibre_distribution.hpp"
#include "trifem/material/registry.hpp"
#include "trifem/tensor/kinematics.hpp"

#include "law_differences.hpp"
#include "law_states.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

using namespace trifem;

using namespace trifem::test;

namespace {

/// Parameters of a fibre distribution.
struct Distribution {
  Real ksi, alpha, beta;
  Vec3 semi_axes;
  int resolution = 0; ///< 0: the default
};

material::ParameterValues values(const Distribution& d) {
  material::ParameterValues v = {{"ksi", d.ksi}, {"alpha", d.alpha}, {"beta", d.beta}};
  material::set_vector(v, "semi_axes", d.semi_axes);
  if (d.resolution > 0)
    v["resolution"] = d.resolution;
  return v;
}

std::shared_ptr<const material::ElasticLaw> law(const Distribution& d) {
  return material::create_law("fibre-distribution", values(d), "test");
}

std::string describe(const Distribution& d) {
  std::ostringstream out;
  out << "ksi=" << d.ksi << " alpha=" << d.alpha << " beta=" << d.beta << " semi_axes=("
      << d.semi_axes.transpose() << ") resolution=" << d.resolution;
  return out.str();
}

/// Spherical with alpha = 0 and beta = 2 (the tangent jumps at I_n = 1), spherical with
/// alpha > 0 and beta = 2.5, and an ellipsoidal density with a coarser rule.
const std::vector<Distribution>& cases() {
  static const std::vector<Distribution> c = {
      {5.0, 0.0, 2.0, Vec3(1, 1, 1)},
      {2.0, 1.5, 2.5, Vec3(1, 1, 1)},
      {3.0, 0.8, 2.5, Vec3(2.0, 1.0, 0.5), 8},
  };
  return c;
}

/// The exp-pow fibre of one direction: W_f, W_f' and W_f'' at x = I_n - 1 > 0 (FibreExpPow).
struct FibreTerms {
  Real W, dW, d2W;
};
FibreTerms fibre_terms(const Distribution& d, Real x) {
  const Real xb = std::pow(x, d.beta), e = std::exp(d.alpha * xb);
  return {d.alpha == 0.0 ? d.ksi / d.beta * xb : d.ksi / (d.alpha * d.beta) * (e - 1.0),
          d.ksi * std::pow(x, d.beta - 1.0) * e,
          d.ksi * std::pow(x, d.beta - 2.0) * (d.beta * (d.alpha * xb + 1.0) - 1.0) * e};
}

// ---------------------------------------------------------------------------------------------
// Independent reference: the mean over the sphere of an axisymmetric state as an integral over
// c = cos(theta) by Romberg's method.

/// int_0^1 f by Romberg's method (trapezoid rules of 2^n panels extrapolated), to a relative
/// 1e-14 for the smooth integrands here.
Real integral(const std::function<Real(Real)>& f) {
  std::vector<Real> previous = {0.5 * (f(0.0) + f(1.0))};
  for (int n = 1; n <= 20; ++n) {
    const int panels = 1 << n;
    Real midpoints = 0.0;
    for (int i = 1; i < panels; i += 2)
      midpoints += f(Real(i) / panels);
    std::vector<Real> row = {0.5 * previous[0] + midpoints / panels};
    for (int m = 1; m <= n; ++m)
      row.push_back(row[m - 1] + (row[m - 1] - previous[m - 1]) / (std::pow(4.0, m) - 1.0));
    if (n >= 4 && std::abs(row[n] - previous[n - 1]) <= 1e-14 * std::abs(row[n]))
      return row[n];
    previous = std::move(row);
  }
  ADD_FAILURE() << "Romberg integration did not converge";
  return previous.back();
}

/// W, S and D of the distribution `d` (semi-axes a_axial along `axis`, a_lateral across it) at
/// C = diag(p, q, q) in the frame (axis, axis+1, axis+2). The fibre n at angle theta from the
/// axis has I_n = p c^2 + q (1 - c^2), c = cos(theta), and the density R depends on c only, so
/// every mean over the sphere is <f> = int_0^1 R f dc / int_0^1 R dc with the phi-means
/// <n_b^2> = s^2/2, <n_b^4> = 3 s^4/8, <n_b^2 n_c^2> = s^4/8 (s^2 = 1 - c^2). The fibres in
/// tension form one interval of c with the kink I_n = 1 at one end; there c is substituted by
/// t^2 (c - c* ~ t^2) so that the integrand is smooth (for beta = 2 and 2.5) and Romberg's
/// extrapolation converges fast.
struct Reference {
  Real W;
  Mat3 S;
  Mat6 D;
};
Reference reference(const Distribution& d, int axis, Real p, Real q) {
  const Real a_axial = d.semi_axes[axis], a_lateral = d.semi_axes[(axis + 1) % 3];
  const auto density = [&](Real c) {
    return 1.0 / std::sqrt(c * c / (a_axial * a_axial) + (1 - c * c) / (a_lateral * a_lateral));
  };
  const Real norm = integral(density);
  // tension where (p - q) c^2 > 1 - q
  Real lo = 0.0, hi = 1.0;
  bool kink_at_lo = true;
  const Real root2 = (p == q) ? -1.0 : (1 - q) / (p - q);
  if (p > q && root2 > 0.0)
    lo = std::sqrt(std::min(root2, 1.0));
  else if (p < q && root2 < 1.0 && root2 > 0.0) {
    hi = std::sqrt(root2);
    kink_at_lo = false;
  }
  const auto mean = [&](const std::function<Real(Real c, const FibreTerms&)>& f) {
    const auto g = [&](Real t) {
      const Real c = kink_at_lo ? lo + (hi - lo) * t * t : hi - (hi - lo) * t * t;
      const Real x = p * c * c + q * (1 - c * c) - 1.0;
      if (!(x > 0.0))
        return 0.0;
      return density(c) * f(c, fibre_terms(d, x)) * 2 * (hi - lo) * t;
    };
    return integral(g) / norm;
  };
  const auto s2 = [](Real c) { return 1 - c * c; };
  Reference r;
  r.W = mean([](Real, const FibreTerms& t) { return t.W; });
  const Real S_aa = mean([](Real c, const FibreTerms& t) { return 2 * t.dW * c * c; });
  const Real S_bb = mean([&](Real c, const FibreTerms& t) { return 2 * t.dW * s2(c) / 2; });
  const Real D_aaaa = mean([](Real c, const FibreTerms& t) { return 4 * t.d2W * std::pow(c, 4); });
  const Real D_aabb =
      mean([&](Real c, const FibreTerms& t) { return 4 * t.d2W * c * c * s2(c) / 2; });
  const Real D_bbbb =
      mean([&](Real c, const FibreTerms& t) { return 4 * t.d2W * s2(c) * s2(c) * 3 / 8; });
  const Real D_bbcc =
      mean([&](Real c, const FibreTerms& t) { return 4 * t.d2W * s2(c) * s2(c) / 8; });
  r.S = S_bb * Mat3::Identity();
  r.S(axis, axis) = S_aa;
  r.D = Mat6::Zero();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      r.D(i, j) = (i == axis && j == axis)   ? D_aaaa
                  : (i == axis || j == axis) ? D_aabb
                  : (i == j)                 ? D_bbbb
                                             : D_bbcc;
  for (int k = 3; k < 6; ++k) // shear (12, 23, 13): D_abab = D_aabb, D_bcbc = D_bbcc
    r.D(k, k) = (voigt::kI[k] == axis || voigt::kJ[k] == axis) ? D_aabb : D_bbcc;
  return r;
}

/// C = diag(p, q, q) in the frame (axis, axis+1, axis+2).
Mat3 axisymmetric(int axis, Real p, Real q) {
  Vec3 c = Vec3::Constant(q);
  c[axis] = p;
  return c.asDiagonal();
}

} // namespace

// (a) S = 2 dW/dC and D = dS/dE by central differences at three random states with some fibres
// in tension and some in compression.
TEST(FibreDistribution, StressAndTangentMatchCentralDifferences) {
  Real max_stress = 0.0, max_tangent = 0.0;
  for (const Distribution& d : cases()) {
    const auto m = law(d);
    const auto& rule = dynamic_cast<const material::FibreDistribution&>(*m).directions();
    for (std::uint64_t seed : {11u, 12u, 13u}) {
      const Mat3 F = Mat3::Identity() + 0.3 * random_matrix(seed);
      const Mat3 C = F.transpose() * F;
      const Vec6 strain = voigt::strain(C - Mat3::Identity());
      const auto stretched = std::count_if(rule.begin(), rule.end(),
                                           [&](const auto& n) { return n.N.dot(strain) > 0.0; });
      ASSERT_GT(stretched, 0) << describe(d) << " seed " << seed;
      ASSERT_LT(stretched, static_cast<long>(rule.size())) << describe(d) << " seed " << seed;
      const material::StressTangent st = m->stress_tangent(C);
      EXPECT_EQ(st.S, m->stress(C)) << describe(d);
      const Real h = 1e-6;
      const Real e_stress = (st.S - stress_by_differences(*m, C, h)).norm() / st.S.norm();
      const Real e_tangent = (st.D - tangent_by_differences(*m, C, h)).norm() / st.D.norm();
      EXPECT_LE(e_stress, 1e-6) << describe(d) << " seed " << seed;
      EXPECT_LE(e_tangent, 1e-6) << describe(d) << " seed " << seed;
      EXPECT_LE((st.D - st.D.transpose()).norm(), 1e-14 * st.D.norm()) << describe(d);
      max_stress = std::max(max_stress, e_stress);
      max_tangent = std::max(max_tangent, e_tangent);
    }
  }
  RecordProperty("max_stress_error", scientific(max_stress));
  RecordProperty("max_tangent_error", scientific(max_tangent));
}

// (b) Inert at C = I and when every principal stretch is below 1 (every I_n < 1): W, S and D
// exactly 0; a principal stretch just above 1 loads the fibres around it.
TEST(FibreDistribution, InertAtTheReferenceStateAndInCompression) {
  for (const Distribution& d : cases()) {
    const auto m = law(d);
    EXPECT_EQ(m->p_wave_modulus(), 0.0);
    EXPECT_EQ(m->shear_modulus(), 0.0);
    std::vector<Mat3> states = {Mat3::Identity()};
    for (std::uint64_t seed : {21u, 22u, 23u}) {
      const Mat3 R1 = rotation(3.0 * uniform(seed), random_matrix(seed).col(0));
      const Mat3 R2 = rotation(3.0 * uniform(seed), random_matrix(seed).col(1));
      const Mat3 F = R1 * Vec3(0.7, 0.85, 0.995).asDiagonal() * R2; // stretches 0.7 to 0.995
      states.push_back(F.transpose() * F);
    }
    for (const Mat3& C : states) {
      const material::StressTangent st = m->stress_tangent(C);
      EXPECT_EQ(m->energy(C), 0.0) << describe(d);
      EXPECT_EQ(st.S.norm(), 0.0) << describe(d);
      EXPECT_EQ(st.D.norm(), 0.0) << describe(d);
    }
    const Mat3 C = Vec3(1.02 * 1.02, 0.64, 0.64).asDiagonal();
    EXPECT_GT(m->stress(C)(0, 0), 0.0) << describe(d);
    EXPECT_GT(m->energy(C), 0.0) << describe(d);
  }
}

// (c) sigma(QF) = Q sigma(F) Q^T (frame indifference). The spherical distribution is isotropic
// up to the error of the rule: S(Q^T C Q) = Q^T S(C) Q to the measured quadrature error.
TEST(FibreDistribution, FrameIndifferentAndIsotropicUpToTheRule) {
  const Mat3 Q = rotation(1.1, Vec3(-2, 1, 3));
  Real anisotropy = 0.0;
  for (const Distribution& d : cases()) {
    const auto m = law(d);
    for (std::uint64_t seed : {31u, 32u}) {
      const Mat3 F = Mat3::Identity() + 0.3 * random_matrix(seed);
      const Mat3 C = F.transpose() * F;
      const Mat3 sigma = kinematics::cauchy_from_pk2(F, m->stress(C));
      const Mat3 QF = Q * F;
      const Mat3 sigma_q = kinematics::cauchy_from_pk2(QF, m->stress(QF.transpose() * QF));
      EXPECT_LE((Q * sigma * Q.transpose() - sigma_q).norm(), 1e-13 * sigma.norm()) << describe(d);
      const Mat3 S = m->stress(C), S_rotated = m->stress(Q.transpose() * C * Q);
      const Real difference = (S_rotated - Q.transpose() * S * Q).norm() / S.norm();
      if (d.semi_axes == Vec3(1, 1, 1)) {
        EXPECT_LE(difference, 2e-3) << describe(d) << " seed " << seed;
        anisotropy = std::max(anisotropy, difference);
      } else { // the ellipsoidal density is anisotropic
        EXPECT_GT(difference, 0.05) << describe(d) << " seed " << seed;
      }
    }
  }
  RecordProperty("spherical_anisotropy_of_the_rule", scientific(anisotropy));
}

// (d) The rule has the symmetries of the cube (the cubed sphere): the spherical distribution
// responds alike along x, y and z (S(P C P^T) = P S(C) P^T for a permutation P), and the
// spherical and ellipsoidal ones are exactly orthotropic in x, y, z (the same for the
// reflections P = diag(-1, 1, 1), ...): a diagonal C gives a diagonal S.
TEST(FibreDistribution, RuleHasTheSymmetriesOfTheCube) {
  Mat3 cyclic = Mat3::Zero();
  cyclic(0, 1) = cyclic(1, 2) = cyclic(2, 0) = 1.0;
  Mat3 swap = Mat3::Zero();
  swap(0, 1) = swap(1, 0) = swap(2, 2) = 1.0;
  const std::vector<Mat3> reflections = {Vec3(-1, 1, 1).asDiagonal(), Vec3(1, -1, 1).asDiagonal(),
                                         Vec3(1, 1, -1).asDiagonal()};
  for (const Distribution& d : cases()) {
    const auto m = law(d);
    std::vector<Mat3> symmetries = reflections;
    if (d.semi_axes == Vec3(1, 1, 1)) {
      symmetries.push_back(cyclic);
      symmetries.push_back(swap);
    }
    for (std::uint64_t seed : {61u, 62u}) {
      const Mat3 F = Mat3::Identity() + 0.3 * random_matrix(seed);
      const Mat3 C = F.transpose() * F;
      const material::StressTangent st = m->stress_tangent(C);
      for (const Mat3& P : symmetries) {
        const Mat3 CP = P * C * P.transpose();
        EXPECT_LE((m->stress(CP) - P * st.S * P.transpose()).norm(), 1e-14 * st.S.norm())
            << describe(d) << "\n"
            << P;
        EXPECT_NEAR(m->energy(CP), m->energy(C), 1e-14 * m->energy(C)) << describe(d);
      }
    }
    const Mat3 C = Vec3(1.3, 0.9, 1.1).asDiagonal();
    const Mat3 S = m->stress(C);
    EXPECT_LE((S - Mat3(S.diagonal().asDiagonal())).norm(), 1e-15 * S.norm()) << describe(d);
  }
}

// (e) Dilatation C = l^2 I: every direction has I_n = l^2, so W = W_f(l^2) exactly, and with
// <n (x) n> = I/3 and <n (x) n (x) n (x) n> = (I (x) I + 2 I (.) I)/15 (integrated exactly by
// the rule at every resolution): S = 2 W_f'/3 I, D = 4 W_f''/15 (I (x) I + 2 I (.) I). For an
// ellipsoidal density W = W_f(l^2) and tr S = 2 W_f'(l^2) still hold (the weights sum to 1).
TEST(FibreDistribution, DilatationClosedFormAtEveryResolution) {
  const Mat6 II = voigt::outer(Mat3::Identity(), Mat3::Identity());
  const Mat6 Isym = voigt::symmetric_product(Mat3::Identity());
  Real worst = 0.0;
  for (int resolution : {3, 4, 5, 12, 40}) {
    for (const Distribution& base : cases()) {
      Distribution d = base;
      d.resolution = resolution;
      const auto m = law(d);
      for (Real l : {1.05, 1.3, 1.8}) {
        const Mat3 C = l * l * Mat3::Identity();
        const FibreTerms t = fibre_terms(d, l * l - 1.0);
        const material::StressTangent st = m->stress_tangent(C);
        const Real e_energy = std::abs(m->energy(C) - t.W) / t.W;
        EXPECT_LE(e_energy, 1e-13) << describe(d) << " l " << l;
        worst = std::max(worst, e_energy);
        const Real e_trace = std::abs(st.S.trace() - 2 * t.dW) / (2 * t.dW);
        EXPECT_LE(e_trace, 1e-13) << describe(d) << " l " << l;
        worst = std::max(worst, e_trace);
        if (d.semi_axes != Vec3(1, 1, 1))
          continue;
        const Mat3 S = 2 * t.dW / 3 * Mat3::Identity();
        const Mat6 D = 4 * t.d2W / 15 * (II + 2 * Isym);
        const Real e_stress = (st.S - S).norm() / S.norm(),
                   e_tangent = (st.D - D).norm() / D.norm();
        EXPECT_LE(e_stress, 1e-13) << describe(d) << " l " << l;
        EXPECT_LE(e_tangent, 1e-13) << describe(d) << " l " << l;
        worst = std::max({worst, e_stress, e_tangent});
      }
      // uniform compression: every fibre slack
      EXPECT_EQ(m->stress_tangent(0.81 * Mat3::Identity()).D.norm(), 0.0) << describe(d);
    }
  }
  RecordProperty("max_relative_error", scientific(worst));
}

// (f) The independent reference itself: at p = q (a dilatation) it is the closed form of (d),
// and a state with every fibre in tension has no kink.
TEST(FibreDistribution, ReferenceIntegralIsTheClosedFormOfADilatation) {
  const Distribution d = cases()[1];
  const Real l = 1.3;
  const FibreTerms t = fibre_terms(d, l * l - 1.0);
  const Reference r = reference(d, 0, l * l, l * l);
  EXPECT_NEAR(r.W, t.W, 1e-13 * t.W);
  EXPECT_LE((r.S - 2 * t.dW / 3 * Mat3::Identity()).norm(), 1e-13 * t.dW);
  const Mat6 D = 4 * t.d2W / 15 *
                 (voigt::outer(Mat3::Identity(), Mat3::Identity()) +
                  2 * voigt::symmetric_product(Mat3::Identity()));
  EXPECT_LE((r.D - D).norm(), 1e-13 * D.norm());
}

// (g) Uniaxial isochoric stretch C = diag(l^2, 1/l, 1/l) along x, y and z, and uniaxial
// compression, against the one-dimensional reference: the error of the rule falls as the
// resolution grows (the integrand has a kink where I_n = 1, so the rate is algebraic, about
// resolution^-2 for S). Ellipsoidal densities with semi-axes (a_axial, a_lateral, a_lateral)
// about the stretch axis are axisymmetric too and are checked the same way.
TEST(FibreDistribution, UniaxialConvergesToTheOneDimensionalIntegral) {
  const std::vector<int> resolutions = {4, 8, 16, 32, 64};
  struct Load {
    Real l;
    int axis;
    Vec3 semi_axes; // along (axis, axis + 1, axis + 2)
  };
  std::vector<Load> loads;
  for (int axis : {0, 1, 2})
    for (Real l : {1.1, 1.2, 1.5, 0.8})
      loads.push_back({l, axis, Vec3(1, 1, 1)});
  loads.push_back({1.2, 0, Vec3(2.0, 1.0, 1.0)});
  loads.push_back({1.2, 2, Vec3(0.5, 1.0, 1.0)});
  for (const Distribution& base : {cases()[0], cases()[1]}) {
    std::vector<Real> stress_error(resolutions.size()), energy_error(resolutions.size()),
        tangent_error(resolutions.size());
    std::vector<Real> default_error;
    Real moderate = 0.0; // the default resolution at stretch 1.2
    for (const Load& load : loads) {
      Distribution d = base;
      for (int i = 0; i < 3; ++i)
        d.semi_axes[(load.axis + i) % 3] = load.semi_axes[i];
      const Real p = load.l * load.l, q = 1.0 / load.l;
      const Reference r = reference(d, load.axis, p, q);
      const Mat3 C = axisymmetric(load.axis, p, q);
      for (std::size_t k = 0; k <= resolutions.size(); ++k) {
        d.resolution = k < resolutions.size() ? resolutions[k] : 0;
        const auto m = law(d);
        const material::StressTangent st = m->stress_tangent(C);
        const Real e_stress = (st.S - r.S).norm() / r.S.norm();
        if (k == resolutions.size()) {
          default_error.push_back(e_stress);
          if (load.l == 1.2)
            moderate = std::max(moderate, e_stress);
          continue;
        }
        stress_error[k] = std::max(stress_error[k], e_stress);
        energy_error[k] = std::max(energy_error[k], std::abs(m->energy(C) - r.W) / r.W);
        tangent_error[k] = std::max(tangent_error[k], (st.D - r.D).norm() / r.D.norm());
      }
    }
    const std::string name = "beta" + std::to_string(static_cast<int>(10 * base.beta));
    for (std::size_t k = 0; k < resolutions.size(); ++k) {
      const std::string at = name + "_resolution" + std::to_string(resolutions[k]);
      RecordProperty(at + "_stress_error", scientific(stress_error[k]));
      RecordProperty(at + "_energy_error", scientific(energy_error[k]));
      RecordProperty(at + "_tangent_error", scientific(tangent_error[k]));
      if (k > 0) { // each doubling at least halves the worst error of W and S
        EXPECT_LT(stress_error[k], 0.5 * stress_error[k - 1]) << at;
        EXPECT_LT(energy_error[k], 0.5 * energy_error[k - 1]) << at;
      }
    }
    EXPECT_LE(stress_error.back(), 5e-5) << name;
    EXPECT_LE(energy_error.back(), 1e-6) << name;
    EXPECT_LE(tangent_error.back(), 5e-3) << name; // the jump of W_f'' at beta = 2: slowest
    EXPECT_LT(tangent_error.back(), 0.2 * tangent_error.front()) << name;
    const Real default_worst = *std::max_element(default_error.begin(), default_error.end());
    EXPECT_LE(default_worst, 2e-3) << name;
    EXPECT_LE(moderate, 1e-3) << name;
    RecordProperty(name + "_default_resolution_stress_error_at_1.2", scientific(moderate));
    RecordProperty(name + "_default_resolution_stress_error", scientific(default_worst));
  }
}

// (h) Equal semi-axes are the spherical distribution (to round-off, at any scale); a density
// elongated along x makes the solid stiffer along x than along y, and y and z (equal semi-axes)
// alike up to the error of the rule.
TEST(FibreDistribution, EllipsoidalDensity) {
  const Distribution spherical = cases()[1];
  const auto sphere = law(spherical);
  for (const Vec3& a : {Vec3(1, 1, 1), Vec3(3, 3, 3), Vec3(0.2, 0.2, 0.2)}) {
    const auto m = law({spherical.ksi, spherical.alpha, spherical.beta, a});
    for (std::uint64_t seed : {41u, 42u}) {
      const Mat3 F = Mat3::Identity() + 0.3 * random_matrix(seed);
      const Mat3 C = F.transpose() * F;
      const material::StressTangent s = sphere->stress_tangent(C), e = m->stress_tangent(C);
      EXPECT_NEAR(m->energy(C), sphere->energy(C), 1e-14 * sphere->energy(C));
      EXPECT_LE((e.S - s.S).norm(), 1e-14 * s.S.norm()) << a.transpose();
      EXPECT_LE((e.D - s.D).norm(), 1e-14 * s.D.norm()) << a.transpose();
    }
  }
  const auto elongated = law({spherical.ksi, spherical.alpha, spherical.beta, Vec3(2, 1, 1)});
  const Real l2 = 1.2 * 1.2;
  const Real along_x = elongated->stress(axisymmetric(0, l2, 1.0))(0, 0);
  const Real along_y = elongated->stress(axisymmetric(1, l2, 1.0))(1, 1);
  const Real along_z = elongated->stress(axisymmetric(2, l2, 1.0))(2, 2);
  const Real isotropic = sphere->stress(axisymmetric(0, l2, 1.0))(0, 0);
  EXPECT_GT(along_x, 1.4 * along_y);
  EXPECT_GT(along_x, isotropic);
  EXPECT_LT(along_y, isotropic);
  EXPECT_NEAR(along_y, along_z, 2e-3 * along_y);
  RecordProperty("stiffness_ratio_x_to_y", scientific(along_x / along_y));
}

// (i) A constituent law only; its registry example is valid; the rule has 4 resolution^2
// directions on the half sphere with weights summing to 1.
TEST(FibreDistribution, RegistryEntryAndRule) {
  for (const auto& entry : material::registered_laws())
    EXPECT_NE(entry.type, "fibre-distribution");
  const material::LawEntry& entry = material::find_law("fibre-distribution", "m");
  const auto m = material::create_law(entry.type, entry.example, "example");
  EXPECT_EQ(m->type(), "fibre-distribution");
  const auto& rule = dynamic_cast<const material::FibreDistribution&>(*m).directions();
  EXPECT_EQ(rule.size(), 3u * 12u * 12u); // the default resolution 12
  for (int resolution : {3, 4, 7, 64}) {
    const auto coarse = law({1.0, 0.0, 2.0, Vec3(1, 2, 3), resolution});
    const auto& directions = dynamic_cast<const material::FibreDistribution&>(*coarse).directions();
    EXPECT_EQ(directions.size(), static_cast<std::size_t>(3 * resolution * resolution));
    Real total = 0.0;
    for (const auto& d : directions) {
      EXPECT_NEAR(d.N.head<3>().sum(), 1.0, 1e-15); // |n| = 1
      EXPECT_GT(d.weight, 0.0);
      total += d.weight;
    }
    EXPECT_NEAR(total, 1.0, 1e-14);
  }
  // in a solid mixture with a ground matrix
  const material::LawSpec spec{
      "solid-mixture",
      {},
      {{"neo-hookean", {{"E", 0.5}, {"nu", 0.1}}, {}}, {"fibre-distribution", entry.example, {}}}};
  const auto mixture = material::create_law(spec, "materials.cart.solid");
  const Mat3 C = Vec3(1.44, 0.9, 0.9).asDiagonal();
  const auto matrix = material::create_law("neo-hookean", {{"E", 0.5}, {"nu", 0.1}}, "m");
  EXPECT_NEAR(mixture->energy(C), matrix->energy(C) + m->energy(C), 1e-14);
}

// (j) Bad parameters are InputErrors naming the key path.
TEST(FibreDistribution, BadParametersAreRejectedWithTheKeyPath) {
  const std::string ctx = "materials.cart.solid.constituent[2]";
  const auto error = [&](const material::ParameterValues& v) {
    return input_error([&] { material::create_law("fibre-distribution", v, ctx); });
  };
  const auto with = [&](const std::string& key, Real value) {
    material::ParameterValues v = values({1.0, 0.0, 2.0, Vec3(1, 1, 1), 12});
    v[key] = value;
    return v;
  };
  material::ParameterValues no_axes = {{"ksi", 1.0}, {"alpha", 0.0}, {"beta", 2.0}};
  struct Bad {
    std::string message;
    std::vector<std::string> expected;
  };
  const std::vector<Bad> cases = {
      {error(with("resolution", 12.5)), {ctx + ".resolution = 12.5: must be an integer"}},
      {error(with("resolution", 2)), {ctx + ".resolution = 2: out of range", "[3, 64]"}},
      {error(with("resolution", 65)), {ctx + ".resolution = 65: out of range", "[3, 64]"}},
      {error(with("semi_axes.y", 0.0)), {ctx + ".semi_axes.y = 0: out of range", "(0, inf)"}},
      {error(with("semi_axes.z", -1.0)), {ctx + ".semi_axes.z = -1: out of range"}},
      {error(with("beta", 1.5)), {ctx + ".beta = 1.5: out of range", "[2, inf)"}},
      {error(with("ksi", -2.0)), {ctx + ".ksi = -2: out of range", "[0, inf)"}},
      {error(with("fibre.x", 1.0)), {ctx + ".fibre.x: unknown parameter"}},
      {error(no_axes), {ctx + ".semi_axes: missing required parameter"}},
  };
  for (const Bad& bad : cases) {
    EXPECT_FALSE(bad.message.empty());
    for (const std::string& part : bad.expected)
      EXPECT_NE(bad.message.find(part), std::string::npos) << bad.message;
  }
  // the constructor re-checks
  const material::LawEntry& entry = material::find_law("fibre-distribution", "m");
  EXPECT_THROW(entry.make(with("resolution", 3.5)), InputError);
  EXPECT_THROW(entry.make(with("semi_axes.x", 0.0)), InputError);
}
