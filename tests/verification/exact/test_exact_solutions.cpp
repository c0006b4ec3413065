// SPDX-License-Identifier: MIT
// Checks the closed-form references against the tables of docs/theory/reference-solutions.md and
// independent derivations.
#include "exact_solutions.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace trifem::exact;

namespace {

constexpr double mM = 1e-6;  // 1 mmol/L in mmol/mm³
constexpr double Mol = 1e-3; // 1 mol/L in mmol/mm³
constexpr double R = 8.314;
constexpr double F = 96.485;
constexpr double pi = std::numbers::pi;

// Independent ierfc for the test-side short-time formulas.
double ierfc_test(double x) {
  return std::exp(-x * x) / std::sqrt(pi) - x * std::erfc(x);
}

ChargedMedium medium(double cF0, double phi_s0, double c_bath, double T) {
  return {cF0, phi_s0, c_bath, R * T, F};
}

} // namespace

// ------------------------------------------------------------------------------------------------
// 1. Donnan
// ------------------------------------------------------------------------------------------------

// reference-solutions.md §R3.3 worked examples: ideal case, T = 298 K.
TEST(Donnan, WorkedExampleTable) {
  struct Row {
    double cF, cs, cp, cm, pi, psi, tol_c;
  };
  const Row rows[] = {
      {200, 150, 280.2776, 80.2776, 0.150030, -16.053, 5e-5},
      {200, 15, 201.1187, 1.1187, 0.426731, -66.657, 5e-5},
      {200, 1000, 1104.988, 904.988, 0.024714, -2.564, 5e-4},
      {100, 150, 208.1139, 108.1139, 0.040205, -8.408, 5e-5},
      {300, 150, 362.1320, 62.1320, 0.307873, -22.632, 5e-5},
  };
  for (const Row& r : rows) {
    SCOPED_TRACE(testing::Message() << "cF = " << r.cF << " mM, c* = " << r.cs << " mM");
    const DonnanState d = donnan(r.cF * mM, r.cs * mM, R * 298.0, F);
    EXPECT_NEAR(d.c_plus / mM, r.cp, r.tol_c);
    EXPECT_NEAR(d.c_minus / mM, r.cm, r.tol_c);
    EXPECT_NEAR(d.pressure, r.pi, 5e-7);
    EXPECT_NEAR(d.psi_mV, r.psi, 5e-4);
  }
}

// reference-solutions.md §R3.5 and §R3.6 (paper data at J = 1), through the paper parameter set.
TEST(Donnan, PaperReferenceState) {
  constexpr PaperParameters p = paper_parameters;
  static_assert(p.E == 0.3 && p.cF0 == 2.0e-4 && p.c_bath == 1.5e-4 && p.faraday == 96.485);
  EXPECT_NEAR(p.RT(), 2477.572, 1e-9);
  const DonnanState d = donnan_at(paper_medium(), 1.0);
  EXPECT_NEAR(d.c_plus, 2.80278e-4, 5e-10);
  EXPECT_NEAR(d.c_minus, 8.02776e-5, 5e-11);
  EXPECT_NEAR(d.pressure, 0.150030, 5e-7);
  EXPECT_NEAR(d.eta, -1548.84, 5e-3);
  EXPECT_NEAR(d.psi_mV, -16.05, 5e-3);
}

// reference-solutions.md §R3.3 non-ideal variants.
TEST(Donnan, NonIdealVariants) {
  const double RT = R * 298.0;
  // Φ = Φ* = 0.93, γ± = γ* = 0.75: K = 1, concentrations unchanged, π scaled by 0.93.
  const DonnanState a = donnan(200 * mM, 150 * mM, RT, F, 1.0, 0.93, 0.93, 0.75, 0.75);
  EXPECT_NEAR(a.c_plus / mM, 280.2776, 5e-5);
  EXPECT_NEAR(a.pressure, 0.139528, 5e-7);
  // γ* = 0.75, γ± = 0.60: K = (γ*/γ±)², Φ = 1. Exact π = RT · 125 mM = 0.3096965 (a rounding tie,
  // printed 0.309696), hence the tolerance of half a printed digit plus round-off.
  const double K = std::pow(0.75 / 0.60, 2);
  const DonnanState b = donnan(200 * mM, 150 * mM, RT, F, K, 1.0, 1.0, 0.60, 0.75);
  EXPECT_NEAR(b.c_plus / mM, 312.50, 5e-3);
  EXPECT_NEAR(b.c_minus / mM, 112.50, 5e-3);
  EXPECT_NEAR(b.pressure, 0.309696, 5e-7 * (1 + 1e-9));
}

// Defining relations hold to round-off, including the anion form of ψ (reference-solutions.md
// §R3.1).
TEST(Donnan, DefiningRelations) {
  const double RT = R * 310.0;
  struct Case {
    double cF, cs, K, phi, phib, gp, gpb;
  };
  const Case cases[] = {{2e-4, 1.5e-4, 1.0, 1.0, 1.0, 1.0, 1.0},
                        {5e-4, 1e-5, 1.7, 0.9, 0.95, 0.6, 0.75},
                        {1e-7, 1e-3, 0.8, 0.93, 0.93, 0.7, 0.8},
                        {0.0, 1.5e-4, 1.0, 1.0, 1.0, 1.0, 1.0}};
  for (const Case& c : cases) {
    const DonnanState d = donnan(c.cF, c.cs, RT, F, c.K, c.phi, c.phib, c.gp, c.gpb);
    EXPECT_NEAR(d.c_plus - d.c_minus, c.cF, 1e-15 * d.c_plus);
    EXPECT_NEAR(d.c_plus * d.c_minus, c.K * c.cs * c.cs, 1e-15 * c.K * c.cs * c.cs);
    const double pi_direct = RT * (c.phi * (d.c_plus + d.c_minus) - 2.0 * c.phib * c.cs);
    EXPECT_NEAR(d.pressure, pi_direct, 1e-12 * RT * c.cs);
    // Anion form: η = RT ln(γ⁻c⁻/(γ⁻*c*)), with γ⁻*/γ⁻ = K γ⁺/γ⁺*.
    const double gm_ratio = c.K * c.gp / c.gpb; // γ⁻*/γ⁻
    EXPECT_NEAR(d.eta, RT * std::log(d.c_minus / (gm_ratio * c.cs)), 1e-9 * RT);
    EXPECT_NEAR(d.psi_mV * F, d.eta, 1e-12 * RT);
  }
  // Ideal, weak charge: Π → RT cF²/(4c*) with no cancellation.
  const DonnanState w = donnan(1e-9, 1.5e-4, RT, F);
  EXPECT_NEAR(w.pressure, RT * 1e-18 / (4.0 * 1.5e-4), 1e-6 * RT * 1e-18 / (4.0 * 1.5e-4));
}

// reference-solutions.md §R3.4, cF versus J (cF0 = 200 mEq/L, c* = 150 mM, T = 298 K). Three
// printed concentrations are off by one unit in the last digit (c⁺ = 304.6295 and 262.2625,
// c⁻ = 66.3555 is printed as c⁺ − cF of the rounded values), so c± are checked to one printed
// unit (1e-3 mM).
TEST(Donnan, FixedChargeVersusJTable) {
  struct Row {
    double phi_s0, J, phi_w, cF, cp, cm, pi;
  };
  const Row rows[] = {{0.25, 0.8, 0.6875, 272.727, 339.083, 66.356, 0.261231},
                      {0.25, 0.9, 0.72222, 230.769, 304.630, 73.860, 0.194464},
                      {0.25, 1.0, 0.75, 200.000, 280.278, 80.278, 0.150030},
                      {0.25, 1.1, 0.77273, 176.471, 262.263, 85.792, 0.119058},
                      {0.20, 0.9, 0.77778, 228.571, 302.863, 74.291, 0.191154},
                      {0.20, 1.2, 0.83333, 160.000, 250.000, 90.000, 0.099103}};
  for (const Row& r : rows) {
    SCOPED_TRACE(testing::Message() << "phi_s0 = " << r.phi_s0 << ", J = " << r.J);
    EXPECT_NEAR(1.0 - r.phi_s0 / r.J, r.phi_w, 5e-6);
    const double cF = fixed_charge(200 * mM, r.phi_s0, r.J);
    EXPECT_NEAR(cF / mM, r.cF, 5e-4);
    // Charge moves with the solid: J φʷ cF = φʷ₀ cF0.
    EXPECT_NEAR(r.J * (1.0 - r.phi_s0 / r.J) * cF, (1.0 - r.phi_s0) * 200 * mM,
                5e-15 * (1.0 - r.phi_s0) * 200 * mM);
    const DonnanState d = donnan_at(medium(200 * mM, r.phi_s0, 150 * mM, 298.0), r.J);
    EXPECT_NEAR(d.c_plus / mM, r.cp, 1e-3);
    EXPECT_NEAR(d.c_minus / mM, r.cm, 1e-3);
    // salt equilibrium, c* = 150 mM (to 20 ulp of c*^2)
    EXPECT_NEAR(d.c_plus * d.c_minus, 150 * mM * 150 * mM, 4e-15 * 150 * mM * 150 * mM);
    EXPECT_NEAR(d.pressure, r.pi, 5e-7);
  }
  EXPECT_THROW(fixed_charge(2e-4, 0.25, 0.25), trifem::InputError);
}

// reference-solutions.md §R3.2 and §R3.5: dπ/dJ = −0.36648 MPa at J = 1, plus FD.
TEST(Donnan, PressureDerivative) {
  const double RT = R * 298.0;
  const double dpdJ = donnan_pressure_derivative_dJ(0.2 * Mol, 0.25, 1.0, 0.15 * Mol, RT);
  EXPECT_NEAR(dpdJ, -0.36648, 5e-6);
  EXPECT_NEAR(0.3 - dpdJ, 0.666, 5e-4); // §R3.5: 1-D equilibrium modulus E − dΠ/dJ
  ChargedMedium m = medium(0.2 * Mol, 0.25, 0.15 * Mol, 298.0);
  for (double K : {1.0, 1.6}) {
    m.gamma_ratio_K = K;
    m.phi = K == 1.0 ? 1.0 : 0.9;
    for (double J : {0.4, 0.8, 1.0, 1.7, 3.0}) {
      const double h = 1e-6;
      const double fd = (donnan_at(m, J + h).pressure - donnan_at(m, J - h).pressure) / (2 * h);
      EXPECT_NEAR(donnan_pressure_dJ(m, J), fd, 1e-8 * std::abs(fd)) << "J = " << J;
    }
  }
}

// ------------------------------------------------------------------------------------------------
// 2. Solid stresses and swelling
// ------------------------------------------------------------------------------------------------

// The closed-form homogeneous stresses equal the tensor definitions (general ν), and for ν = 0
// the SVK forms reduce to reference-solutions.md §R4.4's λE(λ² − 1)/2 and E(λ² − 1)/(2λ).
TEST(SolidStress, MatchesTensorDefinitions) {
  using Mat = Eigen::Matrix3d;
  const Mat I = Mat::Identity();
  for (double nu : {0.0, 0.3, 0.45}) {
    const double E = 0.7;
    const Lame c = lame(E, nu);
    // two formulas with (1 - 2 nu) = 0.1 at nu = 0.45: a few ulp of H_A = 2.66 (1e-15 was 2 ulp)
    EXPECT_NEAR(c.lambda + 2 * c.mu, aggregate_modulus(E, nu), 1e-15 * aggregate_modulus(E, nu));
    for (double l : {0.8, 1.0, 1.3}) {
      for (Deformation mode : {Deformation::Isotropic, Deformation::Confined}) {
        const bool iso = mode == Deformation::Isotropic;
        const Mat Fm = iso ? Mat(l * I) : Mat(Eigen::Vector3d(1, 1, l).asDiagonal());
        const double J = Fm.determinant();
        const Mat Egl = 0.5 * (Fm.transpose() * Fm - I);
        const Mat S = c.lambda * Egl.trace() * I + 2 * c.mu * Egl;
        const Mat sigma_svk = Fm * S * Fm.transpose() / J;
        const Mat B = Fm * Fm.transpose();
        const Mat sigma_nh = c.mu / J * (B - I) + c.lambda / J * std::log(J) * I;
        const double s_svk = solid_stress(SolidLaw::StVenantKirchhoff, mode, c, l).stress;
        const double s_nh = solid_stress(SolidLaw::NeoHookean, mode, c, l).stress;
        EXPECT_NEAR(s_svk, sigma_svk(2, 2), 1e-14);
        EXPECT_NEAR(s_nh, sigma_nh(2, 2), 1e-14);
        EXPECT_NEAR(volume_ratio(mode, l), J, 1e-15);
        if (nu == 0.0) {
          EXPECT_NEAR(s_svk, iso ? E * (l * l - 1) / (2 * l) : l * E * (l * l - 1) / 2, 1e-15);
        }
        for (SolidLaw law : {SolidLaw::StVenantKirchhoff, SolidLaw::NeoHookean, SolidLaw::Linear}) {
          const double h = 1e-6;
          const double fd = (solid_stress(law, mode, c, l + h).stress -
                             solid_stress(law, mode, c, l - h).stress) /
                            (2 * h);
          const StressSlope s = solid_stress(law, mode, c, l);
          EXPECT_NEAR(s.slope, fd, 1e-8 * std::abs(fd));
          // Small-strain limit: dσ/dλ at λ = 1 is 3K (isotropic) or H_A (confined).
          if (l == 1.0) {
            EXPECT_NEAR(s.slope, iso ? 3 * (c.lambda + 2 * c.mu / 3) : c.lambda + 2 * c.mu, 1e-14);
          }
        }
      }
    }
  }
}

// reference-solutions.md §R4.3 table (a): E = 0.3, ν = 0, φs0 = 0.2, cF0 = 200 mEq/L, T = 293 K.
TEST(Swelling, TableA) {
  struct Row {
    double cs, nh_iso, nh_conf, lin_iso_e, lin_conf_e;
  };
  const Row rows[] = {{1, 1.865098, 1.957356, 1.585725, 0.797297},
                      {15, 1.565078, 1.784244, 1.280278, 0.672006},
                      {150, 1.215042, 1.304634, 0.549790, 0.280562},
                      {300, 1.142894, 1.189013, 0.372961, 0.177898},
                      {1000, 1.060855, 1.070736, 0.166585, 0.068717},
                      {2000, 1.034371, 1.037692, 0.096863, 0.037063}};
  for (const Row& r : rows) {
    SCOPED_TRACE(testing::Message() << "c* = " << r.cs << " mM");
    const ChargedMedium m = medium(200 * mM, 0.2, r.cs * mM, 293.0);
    const auto solve = [&](SolidLaw law, Deformation mode) {
      return swelling_equilibrium(law, mode, 0.3, 0.0, m);
    };
    EXPECT_NEAR(solve(SolidLaw::NeoHookean, Deformation::Isotropic).stretch, r.nh_iso, 5e-7);
    EXPECT_NEAR(solve(SolidLaw::NeoHookean, Deformation::Confined).stretch, r.nh_conf, 5e-7);
    EXPECT_NEAR(solve(SolidLaw::Linear, Deformation::Isotropic).J - 1, r.lin_iso_e, 5e-7);
    EXPECT_NEAR(solve(SolidLaw::Linear, Deformation::Confined).J - 1, r.lin_conf_e, 5e-7);
  }
  const ChargedMedium m = medium(200 * mM, 0.2, 150 * mM, 293.0);
  const SwellingState iso =
      swelling_equilibrium(SolidLaw::NeoHookean, Deformation::Isotropic, 0.3, 0.0, m);
  EXPECT_NEAR(iso.J, 1.793799, 5e-7);
  EXPECT_NEAR(iso.donnan.pressure, 0.039831, 5e-7);
  const SwellingState conf =
      swelling_equilibrium(SolidLaw::NeoHookean, Deformation::Confined, 0.3, 0.0, m);
  EXPECT_NEAR(conf.donnan.pressure, 0.080720, 5e-7);
  const double h0 = 1.0; // tr01: swollen height of the 1 mm specimen
  EXPECT_NEAR(conf.stretch * h0, 1.304634, 5e-7);
}

// reference-solutions.md §R4.3 tables (b) (φs0 = 0.25, T = 298) and (c) (E = 1, φs0 = 0.2,
// T = 298).
TEST(Swelling, TablesBandC) {
  struct Row {
    double E, phi_s0, cs, iso, conf;
  };
  const Row rows[] = {{0.3, 0.25, 15, 1.547212, 1.771320},   {0.3, 0.25, 150, 1.209410, 1.300923},
                      {0.3, 0.25, 1000, 1.060438, 1.071117}, {1.0, 0.20, 15, 1.273853, 1.325597},
                      {1.0, 0.20, 150, 1.099640, 1.122024},  {1.0, 0.20, 1000, 1.022182, 1.023594}};
  for (const Row& r : rows) {
    SCOPED_TRACE(testing::Message() << "E = " << r.E << ", c* = " << r.cs << " mM");
    const ChargedMedium m = medium(200 * mM, r.phi_s0, r.cs * mM, 298.0);
    EXPECT_NEAR(
        swelling_equilibrium(SolidLaw::NeoHookean, Deformation::Isotropic, r.E, 0, m).stretch,
        r.iso, 5e-7);
    EXPECT_NEAR(
        swelling_equilibrium(SolidLaw::NeoHookean, Deformation::Confined, r.E, 0, m).stretch,
        r.conf, 5e-7);
  }
}

// reference-solutions.md §R4.3, osmotic loading of a free cube (isotropic NH, table (a) data).
TEST(Swelling, OsmoticLoading) {
  const auto stretch = [](double cs) {
    return swelling_equilibrium(SolidLaw::NeoHookean, Deformation::Isotropic, 0.3, 0.0,
                                medium(200 * mM, 0.2, cs * mM, 293.0))
        .stretch;
  };
  const double l150 = stretch(150);
  EXPECT_NEAR(stretch(15) / l150, 1.288085, 5e-7);
  EXPECT_NEAR(stretch(1500) / l150, 0.859104, 5e-7);
  EXPECT_NEAR(stretch(15), 1.565078, 5e-7);
  EXPECT_NEAR(stretch(1500), 1.043847, 5e-7);
}

// reference-solutions.md §R4.4 (case V4; also the IC-2 swelling of docs/theory/triphasic.md §6):
// the paper's SVK solid (E = 0.3, ν = 0).
TEST(Swelling, PaperSvkV4) {
  const PaperParameters p = paper_parameters;
  const ChargedMedium m = paper_medium();
  const SwellingState c =
      swelling_equilibrium(SolidLaw::StVenantKirchhoff, Deformation::Confined, p.E, p.nu, m);
  EXPECT_NEAR(c.stretch, 1.225066, 5e-7);
  EXPECT_NEAR(c.donnan.c_plus / Mol, 0.245489, 5e-7);
  EXPECT_NEAR(c.donnan.c_minus / Mol, 0.091654, 5e-7);
  EXPECT_NEAR(c.donnan.pressure, 0.092025, 5e-7);
  EXPECT_NEAR(c.donnan.eta, -1220.50, 5e-3);
  // The root satisfies the 1-D equation λE(λ² − 1)/2 = Π(J = λ) of §R4.4, evaluated here.
  const double l = c.stretch;
  EXPECT_NEAR(l * p.E * (l * l - 1) / 2, donnan_at(m, l).pressure, 1e-13);

  const SwellingState iso =
      swelling_equilibrium(SolidLaw::StVenantKirchhoff, Deformation::Isotropic, p.E, p.nu, m);
  EXPECT_NEAR(iso.stretch, 1.17354, 5e-6);
  EXPECT_NEAR(iso.J, 1.6162, 5e-5);
  EXPECT_NEAR(iso.donnan.pressure, 0.04821, 5e-6);
  const double li = iso.stretch;
  EXPECT_NEAR(p.E * (li * li - 1) / (2 * li), donnan_at(m, li * li * li).pressure, 1e-13);

  // Other baths (§R4.4; these are the isotropic cube).
  for (auto [cs, expected] : {std::pair{0.015, 1.38074}, std::pair{1.5, 1.04095}}) {
    PaperParameters q = p;
    q.c_bath = cs * Mol;
    EXPECT_NEAR(swelling_equilibrium(SolidLaw::StVenantKirchhoff, Deformation::Isotropic, q.E, q.nu,
                                     paper_medium(q))
                    .stretch,
                expected, 5e-6)
        << "c* = " << cs << " M";
  }
}

// General ν and the shrinking branch (Φ < Φ*: Π(1) < 0), checked by the residual itself.
TEST(Swelling, ResidualVanishesOnBothBranches) {
  for (double nu : {0.0, 0.25, 0.4}) {
    for (bool shrink : {false, true}) {
      ChargedMedium m = medium(shrink ? 1e-5 : 2e-4, 0.2, 1.5e-4, 298.0);
      if (shrink)
        m.phi = 0.9; // Φ < Φ* = 1: net osmotic suction at J = 1
      for (SolidLaw law : {SolidLaw::StVenantKirchhoff, SolidLaw::NeoHookean}) {
        for (Deformation mode : {Deformation::Isotropic, Deformation::Confined}) {
          const SwellingState s = swelling_equilibrium(law, mode, 0.3, nu, m);
          EXPECT_EQ(s.stretch < 1.0, shrink);
          EXPECT_NEAR(s.solid_stress, s.donnan.pressure, 1e-13);
          EXPECT_NEAR(s.cF, fixed_charge(m.cF0, m.phi_s0, s.J), 1e-20);
          // Total stress with an independent evaluation of Π = RT[Φ(c⁺ + c⁻) − 2Φ*c*].
          const double cF = s.cF;
          const double Pi = m.RT * (m.phi * std::sqrt(cF * cF + 4 * m.c_bath * m.c_bath) -
                                    2 * m.phi_bath * m.c_bath);
          EXPECT_NEAR(s.solid_stress - Pi, 0.0, 1e-13);
        }
      }
    }
  }
}

// ------------------------------------------------------------------------------------------------
// 3. Triphasic confined column (reference-solutions.md §R5.3)
// ------------------------------------------------------------------------------------------------

TEST(ConfinedColumn, PaperEquilibriumV5) {
  const PaperParameters p = paper_parameters;
  const ChargedMedium m = paper_medium();
  const ColumnEquilibrium e = confined_column_equilibrium(0.95, p.E, p.nu, m);
  EXPECT_NEAR(e.total_stress, -0.18403, 5e-6);
  EXPECT_NEAR(e.donnan.pressure, 0.17014, 5e-6);
  EXPECT_NEAR(e.donnan.eta, -1645.93, 5e-3);
  const double Pi0 = donnan_at(m, 1.0).pressure;
  EXPECT_NEAR(e.total_stress + Pi0, -0.03400, 5e-6); // change from −Π0; IC-3a value
  EXPECT_NEAR(e.solid_stress, 0.95 * p.E * (0.95 * 0.95 - 1) / 2, 1e-15);
  // At λ = 1 the column carries −Π0; at the 1-D swelling stretch it is traction free.
  EXPECT_NEAR(confined_column_equilibrium(1.0, p.E, p.nu, m).total_stress, -0.150030, 5e-7);
  const double ls =
      swelling_equilibrium(SolidLaw::StVenantKirchhoff, Deformation::Confined, p.E, p.nu, m)
          .stretch;
  EXPECT_NEAR(confined_column_equilibrium(ls, p.E, p.nu, m).total_stress, 0.0, 1e-14);
}

// ------------------------------------------------------------------------------------------------
// 4. Biphasic confined compression
// ------------------------------------------------------------------------------------------------

// reference-solutions.md §R1.2 creep table (nondimensional: h = H_A = σ0 = τ = 1).
TEST(ConfinedCompression, CreepTable) {
  const ConfinedLayer unit{1.0, 1.0, 1.0};
  ASSERT_EQ(unit.tau(), 1.0);
  struct Row {
    double T, u, p0;
  };
  const Row rows[] = {{0.01, -0.112838, 1.000000}, {0.1, -0.356823, 0.949305},
                      {0.2, -0.504088, 0.772312},  {0.5, -0.763950, 0.370777},
                      {1.0, -0.931260, 0.107977},  {2.0, -0.994170, 0.009157}};
  for (const Row& r : rows) {
    EXPECT_NEAR(creep_surface_displacement(unit, 1.0, r.T), r.u, 5e-7) << "t/tau = " << r.T;
    EXPECT_NEAR(creep_pressure(unit, 1.0, 0.0, r.T), r.p0, 5e-7) << "t/tau = " << r.T;
  }
  // Early times: u ≈ −(σ0h/H_A) 2 sqrt(t/(πτ)) (exact up to e^{−τ/t} terms).
  for (double T : {1e-10, 1e-4, 0.01})
    EXPECT_NEAR(creep_surface_displacement(unit, 1.0, T), -2 * std::sqrt(T / pi),
                1e-12 * std::sqrt(T));
  EXPECT_EQ(creep_surface_displacement(unit, 1.0, 0.0), 0.0);
  EXPECT_EQ(creep_pressure(unit, 1.0, 0.5, 0.0), 1.0);
  EXPECT_NEAR(creep_surface_displacement(unit, 1.0, 60.0), -1.0, 1e-15); // 4 ulp of the limit
}

// reference-solutions.md §R1.3 (case V1): h = 1 mm, σ0 = 1e-4 MPa, H_A = 0.3 MPa,
// κ = 1.07e-3 mm⁴/(N s).
TEST(ConfinedCompression, FormulationV1) {
  const PaperParameters p = paper_parameters;
  const ConfinedLayer layer{1.0, aggregate_modulus(p.E, p.nu), p.kappa};
  // a few roundings each: 5 and 18 ulp (a wrong formula is off by order 1)
  EXPECT_NEAR(layer.H_A, 0.3, 1e-15 * 0.3);
  EXPECT_NEAR(layer.c_v(), 3.21e-4, 3e-15 * 3.21e-4);
  EXPECT_NEAR(creep_surface_displacement(layer, 1e-4, 400.0), -1.347711e-4, 5e-11);
}

// The eigen and image series are different derivations of the same solution.
TEST(ConfinedCompression, EigenAndImageSeriesAgree) {
  for (double T : {0.02, 0.05, 0.1, 0.2, 0.5}) {
    for (double zeta : {0.0, 0.3, 0.7, 1.0}) {
      const auto [ue, pe] = trifem::exact::detail::creep_eigen(zeta, T);
      const auto [ui, pi_] = trifem::exact::detail::creep_images(zeta, T);
      EXPECT_NEAR(ue, ui, 1e-14) << "T = " << T << ", zeta = " << zeta;
      EXPECT_NEAR(pe, pi_, 1e-14) << "T = " << T << ", zeta = " << zeta;
    }
  }
  for (double S : {0.005, 0.05, 0.1, 0.3, 1.0})
    EXPECT_NEAR(trifem::exact::detail::ramp_g_eigen(S), trifem::exact::detail::ramp_g_images(S),
                1e-15)
        << "S = " << S;
}

// Boundary conditions, equilibrium H_A ∂u/∂z − p = −σ0 and the diffusion equation (FD checks).
TEST(ConfinedCompression, CreepFieldsSatisfyTheProblem) {
  const ConfinedLayer L{2.0, 0.5, 2e-3}; // τ = 4000 s
  const double s0 = 0.01;
  for (double t : {40.0, 400.0, 2000.0, 8000.0}) {
    SCOPED_TRACE(testing::Message() << "t = " << t);
    EXPECT_NEAR(creep_pressure(L, s0, L.h, t), 0.0, 1e-15 * s0);                   // drained top
    EXPECT_NEAR(creep_displacement(L, s0, 0.0, t), 0.0, 1e-16 * s0 * L.h / L.H_A); // fixed bottom
    const double d = 1e-4; // impermeable bottom
    EXPECT_LT(std::abs(creep_pressure(L, s0, d, t) - creep_pressure(L, s0, 0.0, t)) / d,
              1e-3 * s0 / L.h);
    for (double z : {0.3, 1.1, 1.9}) {
      const double hz = 1e-5;
      const double uz =
          (creep_displacement(L, s0, z + hz, t) - creep_displacement(L, s0, z - hz, t)) / (2 * hz);
      EXPECT_NEAR(L.H_A * uz - creep_pressure(L, s0, z, t), -s0, 1e-8 * s0);
      const double hz2 = 1e-3;
      const double ht = 1e-3 * t;
      const double pzz = (creep_pressure(L, s0, z + hz2, t) - 2 * creep_pressure(L, s0, z, t) +
                          creep_pressure(L, s0, z - hz2, t)) /
                         (hz2 * hz2);
      const double pt =
          (creep_pressure(L, s0, z, t + ht) - creep_pressure(L, s0, z, t - ht)) / (2 * ht);
      EXPECT_NEAR(pt, L.c_v() * pzz, 1e-4 * std::abs(pt) + 1e-6 * s0 / L.tau());
    }
  }
}

// reference-solutions.md §R1.4 ramp table, columns t = 2t0, 5t0, 10t0 (printed digits).
TEST(ConfinedCompression, RampRelaxationTable) {
  const ConfinedLayer unit{1.0, 1.0, 1.0};
  struct Row {
    double S0, at2, at5, at10;
  };
  const Row rows[] = {{0.01, -4.673900, -2.663742, -1.831209},
                      {0.1, -1.483389, -1.024529, -1.000176},
                      {1.0, -1.000010, -1.000000, std::nan("")}};
  for (const Row& r : rows) {
    SCOPED_TRACE(testing::Message() << "t0/tau = " << r.S0);
    EXPECT_NEAR(ramp_relaxation_stress(unit, 1.0, r.S0, 2 * r.S0), r.at2, 5e-7);
    EXPECT_NEAR(ramp_relaxation_stress(unit, 1.0, r.S0, 5 * r.S0), r.at5, 5e-7);
    if (!std::isnan(r.at10)) {
      EXPECT_NEAR(ramp_relaxation_stress(unit, 1.0, r.S0, 10 * r.S0), r.at10, 5e-7);
    }
    // Continuous at t0 with a sqrt onset of relaxation: σ(t0 + δ) − σ(t0) = (2/S0) sqrt(δ/π) +
    // O(δ).
    const double peak = ramp_relaxation_stress(unit, 1.0, r.S0, r.S0);
    const double delta = 1e-10 * r.S0;
    EXPECT_NEAR(ramp_relaxation_stress(unit, 1.0, r.S0, r.S0 + delta) - peak,
                2 / r.S0 * std::sqrt(delta / pi), 1e-9);
    EXPECT_NEAR(ramp_relaxation_stress(unit, 1.0, r.S0, r.S0 + 50.0), -1.0, 1e-15);
  }
  EXPECT_EQ(ramp_relaxation_stress(unit, 1.0, 0.1, 0.0), 0.0);
}

// The peak (t = t0) from derivations independent of the header's series choice:
//   t0 ≪ τ: half-space solution σ = −H_A ε0 · 2/sqrt(π S0) (corrections ~ e^{−1/S0});
//   any S0: Poisson form G(S0) = sqrt(S0/π) − S0/2 + 2 sqrt(S0) Σ ierfc(k/sqrt(S0)), and the
//   eigen form G = 1/6 − Σ e^{−n²π²S0}/(n²π²), each summed here.
// A first tabulation (reference-solutions.md §R1.4) printed −11.278726, −3.567756, −1.333272 for
// the peaks: those are the series Σ_{n≤4000} (1 − e^{−n²π²S0})/(n²π²) truncated at 4000 terms
// (tail 2/(π² · 4000 S0)), reproduced below; the converged values are −11.283792, −3.568262,
// −1.333323.
TEST(ConfinedCompression, RampPeak) {
  const ConfinedLayer unit{1.0, 1.0, 1.0};
  const auto g_poisson = [](double S) {
    double g = std::sqrt(S / pi) - S / 2;
    for (int k = 1; k < 20; ++k)
      g += 2 * std::sqrt(S) * ierfc_test(k / std::sqrt(S));
    return g;
  };
  const auto g_eigen = [](double S) {
    double g = 1.0 / 6.0;
    for (int n = 1; n < 100; ++n)
      g -= std::exp(-n * n * pi * pi * S) / (n * n * pi * pi);
    return g;
  };
  const auto g_truncated = [](double S, int N) {
    double g = 0;
    for (int n = 1; n <= N; ++n)
      g += (1 - std::exp(-n * n * pi * pi * S)) / (n * n * pi * pi);
    return g;
  };
  EXPECT_NEAR(ramp_relaxation_stress(unit, 1.0, 0.01, 0.01), -2 / std::sqrt(pi * 0.01), 1e-12);
  const double printed[] = {-11.278726, -3.567756, -1.333272};
  int i = 0;
  for (double S0 : {0.01, 0.1, 1.0}) {
    const double peak = ramp_relaxation_stress(unit, 1.0, S0, S0);
    EXPECT_NEAR(peak, -(1 + 2 / S0 * g_poisson(S0)), 1e-12) << "S0 = " << S0;
    EXPECT_NEAR(peak, -(1 + 2 / S0 * g_eigen(S0)), 1e-12) << "S0 = " << S0;
    EXPECT_NEAR(-(1 + 2 / S0 * g_truncated(S0, 4000)), printed[i++], 5e-7) << "S0 = " << S0;
  }
  // Early times of the ramp (t ≤ t0 ≪ τ): σ ≈ −H_A ε0 (2/S0) sqrt(S/π).
  EXPECT_NEAR(ramp_relaxation_stress(unit, 1.0, 0.01, 0.004), -(2 / 0.01) * std::sqrt(0.004 / pi),
              1e-12);
}
