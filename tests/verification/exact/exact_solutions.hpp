// SPDX-License-Identifier: MIT
// Closed-form reference solutions (Donnan, swelling, confined compression) for verification tests.
#pragma once

#include "trifem/core/error.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

/// Exact (closed-form, or closed-form up to a scalar root) solutions used as references by the
/// verification tests; stated with their tables in docs/theory/reference-solutions.md (section
/// numbers §R… below). Units: mm, N, s, MPa, mmol, K (§R0); concentrations are per unit
/// interstitial water volume in mmol/mm³ (1 M = 1e-3 mmol/mm³), RT in mJ/mmol, so RT·c is MPa;
/// η = F·ψ in mJ/mmol and ψ[mV] = η/F with F in C/mmol.
namespace trifem::exact {

// =================================================================================================
// Parameters
// =================================================================================================

/// Material and bath data of the seed paper's §4.1 (reference-solutions.md §R0), cF0 per water
/// volume.
struct PaperParameters {
  double E = 0.3;          ///< Young's modulus of the drained solid [MPa]
  double nu = 0.0;         ///< Poisson's ratio of the drained solid [-]
  double phi_s0 = 0.25;    ///< solid volume fraction at J = 1 [-]
  double cF0 = 2.0e-4;     ///< fixed-charge density at J = 1, per water volume [mmol/mm³]
  double c_bath = 1.5e-4;  ///< bath NaCl concentration c* [mmol/mm³]
  double kappa = 1.07e-3;  ///< hydraulic permeability [mm⁴/(N s)]
  double d_plus = 5.0e-4;  ///< Na⁺ diffusivity [mm²/s]
  double d_minus = 8.0e-4; ///< Cl⁻ diffusivity [mm²/s]
  double R = 8.314;        ///< gas constant [mJ/(mmol K)]
  double T = 298.0;        ///< absolute temperature [K]
  double faraday = 96.485; ///< Faraday constant [C/mmol]

  /// RT [mJ/mmol].
  [[nodiscard]] constexpr double RT() const { return R * T; }
};

/// The paper's parameter set as a compile-time constant.
inline constexpr PaperParameters paper_parameters{};

// =================================================================================================
// 1. Donnan equilibrium (reference-solutions.md §R3)
// =================================================================================================

/// Interstitial state of a charged tissue in equilibrium with a NaCl bath (bath p* = 0, η* = 0).
struct DonnanState {
  double c_plus;   ///< c⁺ per water volume [mmol/mm³]
  double c_minus;  ///< c⁻ per water volume [mmol/mm³]
  double pressure; ///< p − p* = Π, the Donnan osmotic pressure [MPa]
  double eta;      ///< η − η* = F(ψ − ψ*) [mJ/mmol]
  double psi_mV;   ///< ψ − ψ* [mV]
};

/// Donnan equilibrium for a fixed-charge density cF ≥ 0 (magnitude of the negative charge):
///   c⁺ c⁻ = K c*²,  K = γ⁺* γ⁻* / (γ⁺ γ⁻),   c⁺ − c⁻ = cF
///   c⁺ = (cF + sqrt(cF² + 4 K c*²)) / 2,      c⁻ = c⁺ − cF  (evaluated as K c*²/c⁺, same value)
///   Π  = RT [Φ (c⁺ + c⁻) − 2 Φ* c*]           (evaluated without cancellation for small cF)
///   η  = −RT ln(γ⁺ c⁺ / (γ⁺* c*)),             ψ = η / F
/// Source: reference-solutions.md §R3.1.
inline DonnanState donnan(double cF, double c_bath, double RT, double faraday,
                          double gamma_ratio_K = 1.0, double phi = 1.0, double phi_bath = 1.0,
                          double gamma_plus = 1.0, double gamma_plus_bath = 1.0) {
  TRIFEM_CHECK(cF >= 0.0 && c_bath > 0.0 && RT > 0.0 && faraday > 0.0 && gamma_ratio_K > 0.0,
               "donnan: need cF >= 0, c* > 0, RT > 0, F > 0, K > 0");
  const double root_K_c2 = 2.0 * std::sqrt(gamma_ratio_K) * c_bath; // sqrt(4 K c*²)
  const double sum = std::hypot(cF, root_K_c2);                     // c⁺ + c⁻
  const double c_plus = 0.5 * (cF + sum);
  const double c_minus = gamma_ratio_K * c_bath * c_bath / c_plus;
  // Φ(c⁺ + c⁻) − 2Φ*c* = Φ (sum − 2√K c*) + 2c*(Φ√K − Φ*),  sum − 2√K c* = cF²/(sum + 2√K c*)
  const double excess = cF * cF / (sum + root_K_c2);
  const double pressure =
      RT * (phi * excess + c_bath * (phi * 2.0 * std::sqrt(gamma_ratio_K) - 2.0 * phi_bath));
  const double eta = -RT * std::log(gamma_plus * c_plus / (gamma_plus_bath * c_bath));
  return {c_plus, c_minus, pressure, eta, eta / faraday};
}

/// Fixed-charge density per water volume after a volume change J from the reference where
/// φˢ = φˢ₀ and cF = cF0 (charge moves with the solid, both phases intrinsically incompressible):
///   cF(J) = cF0 (1 − φˢ₀) / (J − φˢ₀).
/// Source: reference-solutions.md §R3.2.
inline double fixed_charge(double cF0, double phi_s0, double J) {
  TRIFEM_CHECK(J > phi_s0, "fixed_charge: J = {} must exceed phi_s0 = {}", J, phi_s0);
  return cF0 * (1.0 - phi_s0) / (J - phi_s0);
}

/// dΠ/dJ of the Donnan pressure Π(cF(J)) by analytic differentiation:
///   dΠ/dJ = RT Φ d(c⁺ + c⁻)/dcF · dcF/dJ = −RT Φ cF² / (sqrt(cF² + 4Kc*²) (J − φˢ₀)).
/// (Φ, Φ*, K constant.) At J = 1, φˢ₀ = 0.25, cF0 = 0.2 M, c* = 0.15 M, T = 298 K: −0.36648 MPa
/// (reference-solutions.md §R3.2, §R3.5).
inline double donnan_pressure_derivative_dJ(double cF0, double phi_s0, double J, double c_bath,
                                            double RT, double gamma_ratio_K = 1.0,
                                            double phi = 1.0) {
  const double cF = fixed_charge(cF0, phi_s0, J);
  const double sum = std::hypot(cF, 2.0 * std::sqrt(gamma_ratio_K) * c_bath);
  return -RT * phi * cF * cF / (sum * (J - phi_s0));
}

/// A charged tissue and its bath: everything the Donnan state at a given J depends on.
struct ChargedMedium {
  double cF0;                   ///< fixed charge at J = 1, per water volume [mmol/mm³]
  double phi_s0;                ///< solid volume fraction at J = 1 [-]
  double c_bath;                ///< bath concentration c* [mmol/mm³]
  double RT;                    ///< [mJ/mmol]
  double faraday;               ///< [C/mmol]
  double gamma_ratio_K = 1.0;   ///< K = γ⁺*γ⁻*/(γ⁺γ⁻)
  double phi = 1.0;             ///< interstitial osmotic coefficient Φ
  double phi_bath = 1.0;        ///< bath osmotic coefficient Φ*
  double gamma_plus = 1.0;      ///< interstitial cation activity coefficient γ⁺
  double gamma_plus_bath = 1.0; ///< bath cation activity coefficient γ⁺*
};

/// The paper's tissue and bath (ideal: γ = Φ = 1); pass a modified PaperParameters for other data.
inline ChargedMedium paper_medium(const PaperParameters& p = paper_parameters) {
  return {p.cF0, p.phi_s0, p.c_bath, p.RT(), p.faraday};
}

/// Donnan state of the medium at volume ratio J: donnan(cF(J), ...).
inline DonnanState donnan_at(const ChargedMedium& m, double J) {
  return donnan(fixed_charge(m.cF0, m.phi_s0, J), m.c_bath, m.RT, m.faraday, m.gamma_ratio_K, m.phi,
                m.phi_bath, m.gamma_plus, m.gamma_plus_bath);
}

/// dΠ/dJ of the medium (see donnan_pressure_derivative_dJ).
inline double donnan_pressure_dJ(const ChargedMedium& m, double J) {
  return donnan_pressure_derivative_dJ(m.cF0, m.phi_s0, J, m.c_bath, m.RT, m.gamma_ratio_K, m.phi);
}

// =================================================================================================
// 2. Homogeneous solid stress and swelling equilibria (reference-solutions.md §R4)
// =================================================================================================

/// Drained solid laws with closed-form homogeneous stress.
enum class SolidLaw {
  StVenantKirchhoff, ///< S = λ tr(E) I + 2μE, σ = F S Fᵀ/J (the paper's solid)
  NeoHookean,        ///< σ = (μ/J)(B − I) + (λ/J) ln J I (FEBio compressible neo-Hookean)
  Linear             ///< small-strain Hooke law written with the volumetric strain e = J − 1
};

/// Homogeneous deformation modes of a swelling specimen.
enum class Deformation {
  Isotropic, ///< F = λ I, J = λ³ (free swelling of an unconstrained body)
  Confined   ///< F = diag(1, 1, λ), J = λ (laterally confined column, stress σ_zz)
};

/// Lamé constants.
struct Lame {
  double lambda; ///< first Lamé constant λ_L [MPa]
  double mu;     ///< shear modulus μ [MPa]
};

/// λ_L = Eν/((1 + ν)(1 − 2ν)), μ = E/(2(1 + ν)).
constexpr Lame lame(double E, double nu) {
  return {E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)), E / (2.0 * (1.0 + nu))};
}

/// Aggregate (confined, P-wave) modulus H_A = λ_L + 2μ = E(1 − ν)/((1 + ν)(1 − 2ν)).
constexpr double aggregate_modulus(double E, double nu) {
  return E * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu));
}

/// Volume ratio of the mode: J = λ³ (isotropic) or λ (confined).
constexpr double volume_ratio(Deformation mode, double stretch) {
  return mode == Deformation::Isotropic ? stretch * stretch * stretch : stretch;
}

/// A stress value and its derivative with respect to the stretch.
struct StressSlope {
  double stress; ///< Cauchy σ^e (the equal principal value, or σ_zz when confined) [MPa]
  double slope;  ///< dσ^e/dλ [MPa]
};

/// Drained Cauchy stress of a homogeneous mode, with K = λ_L + 2μ/3 and H_A = λ_L + 2μ.
/// St Venant–Kirchhoff (E_GL = (λ² − 1)/2 on the stretched axes):
///   isotropic  σ = (3K/2)(λ² − 1)/λ          (ν = 0: E(λ² − 1)/(2λ), §R4.4)
///   confined   σ_zz = λ H_A (λ² − 1)/2         (ν = 0: λE(λ² − 1)/2, §R4.4, §R5.3)
/// Neo-Hookean (reference-solutions.md §R4.2):
///   isotropic  σ = [μ(λ² − 1) + λ_L ln λ³]/λ³,   confined σ_zz = [μ(λ² − 1) + λ_L ln λ]/λ
/// Linear (§R4.2, e = J − 1): isotropic σ = K e, confined σ_zz = H_A e.
inline StressSlope solid_stress(SolidLaw law, Deformation mode, Lame c, double stretch) {
  const double l = stretch;
  const double K = c.lambda + 2.0 * c.mu / 3.0;
  const double H = c.lambda + 2.0 * c.mu;
  const bool iso = mode == Deformation::Isotropic;
  switch (law) {
  case SolidLaw::StVenantKirchhoff:
    if (iso)
      return {1.5 * K * (l * l - 1.0) / l, 1.5 * K * (1.0 + 1.0 / (l * l))};
    return {0.5 * H * l * (l * l - 1.0), 0.5 * H * (3.0 * l * l - 1.0)};
  case SolidLaw::NeoHookean:
    if (iso) {
      const double l3 = l * l * l;
      return {(c.mu * (l * l - 1.0) + 3.0 * c.lambda * std::log(l)) / l3,
              c.mu * (3.0 / (l3 * l) - 1.0 / (l * l)) +
                  3.0 * c.lambda * (1.0 - 3.0 * std::log(l)) / (l3 * l)};
    }
    return {c.mu * (l - 1.0 / l) + c.lambda * std::log(l) / l,
            c.mu * (1.0 + 1.0 / (l * l)) + c.lambda * (1.0 - std::log(l)) / (l * l)};
  case SolidLaw::Linear:
    if (iso)
      return {K * (l * l * l - 1.0), 3.0 * K * l * l};
    return {H * (l - 1.0), H};
  }
  TRIFEM_VERIFY(false, "solid_stress: unknown law");
  return {};
}

namespace detail {

/// Safeguarded Newton iteration on a bracket [a, b] with f(a) < 0 < f(b); `f(x)` returns
/// {f, f'}. Newton steps leaving the bracket or not halving the previous step are replaced by
/// bisection. Stops when the step is below rel_tol·|x|.
template <class Fn>
double safeguarded_newton(Fn&& f, double a, double b, double rel_tol = 1e-14) {
  double x = 0.5 * (a + b);
  double last_step = b - a;
  for (int it = 0; it < 400; ++it) {
    const auto [fx, dfx] = f(x);
    if (fx == 0.0)
      return x;
    (fx < 0.0 ? a : b) = x;
    double next = dfx != 0.0 ? x - fx / dfx : a;
    if (!(next > a && next < b) || std::abs(next - x) > 0.5 * last_step)
      next = 0.5 * (a + b);
    last_step = std::abs(next - x);
    x = next;
    if (last_step <= rel_tol * std::abs(x) ||
        b - a <= 4.0 * std::numeric_limits<double>::epsilon() * std::abs(x))
      return x;
  }
  TRIFEM_VERIFY(false, "safeguarded_newton: no convergence on [{}, {}]", a, b);
  return x;
}

} // namespace detail

/// A swollen (or osmotically loaded) homogeneous equilibrium.
struct SwellingState {
  double stretch;      ///< λ
  double J;            ///< J = λ³ (isotropic) or λ (confined)
  double cF;           ///< cF(J) [mmol/mm³]
  double solid_stress; ///< σ^e at λ (= Π at equilibrium) [MPa]
  DonnanState donnan;  ///< interstitial state at J (pressure = Π(J))
};

/// Free swelling in a bath with p* = 0: total stress σ^e − Π(J) I = 0 on the loaded axes, i.e.
///   f(λ) = σ^e(λ) − Π(cF(J(λ)), c*) = 0      (reference-solutions.md §R4.1).
/// SVK, ν = 0: isotropic E(λ² − 1)/(2λ) = Π(J = λ³), confined λE(λ² − 1)/2 = Π(J = λ)
/// (§R4.4). The stress-free reference is J = 1 with cF = cF0. Root: the first sign
/// change of f scanning away from λ = 1 (upward if Π(1) > 0: the state reached by ramping the
/// charge), refined by safeguarded Newton to 1e-14 relative.
inline SwellingState swelling_equilibrium(SolidLaw law, Deformation mode, double E, double nu,
                                          const ChargedMedium& m) {
  const Lame c = lame(E, nu);
  const auto f = [&](double l) {
    const StressSlope s = solid_stress(law, mode, c, l);
    const double J = volume_ratio(mode, l);
    const double dJ = mode == Deformation::Isotropic ? 3.0 * l * l : 1.0;
    return std::pair{s.stress - donnan_at(m, J).pressure, s.slope - donnan_pressure_dJ(m, J) * dJ};
  };
  double a = 1.0;
  double b = 1.0;
  const double f1 = f(1.0).first;
  if (f1 < 0.0) { // swelling: march upward
    for (b = 1.05; f(b).first < 0.0; b *= 1.05) {
      a = b;
      TRIFEM_CHECK(b < 1e4, "swelling_equilibrium: no root below stretch 1e4");
    }
  } else if (f1 > 0.0) { // shrinking: march toward J = phi_s0, where Π → ∞ if cF0 > 0
    const double l_min = mode == Deformation::Isotropic ? std::cbrt(m.phi_s0) : m.phi_s0;
    for (a = 0.5 * (1.0 + l_min); f(a).first > 0.0; a = 0.5 * (a + l_min)) {
      b = a;
      TRIFEM_CHECK(a - l_min > 1e-12, "swelling_equilibrium: no root above J = phi_s0");
    }
  }
  const double l = f1 == 0.0 ? 1.0 : detail::safeguarded_newton(f, a, b);
  const double J = volume_ratio(mode, l);
  return {l, J, fixed_charge(m.cF0, m.phi_s0, J), solid_stress(law, mode, c, l).stress,
          donnan_at(m, J)};
}

// =================================================================================================
// 3. Triphasic confined column at equilibrium (reference-solutions.md §R5.3, "∞" row)
// =================================================================================================

/// Equilibrium of a laterally confined column held at axial stretch λ in a bath.
struct ColumnEquilibrium {
  double total_stress; ///< σ_zz = σ^e_zz − p [MPa], reference state IC-1 (no prestress)
  double solid_stress; ///< σ^e_zz [MPa]
  DonnanState donnan;  ///< p = Π(J = λ), η, c± (uniform at equilibrium)
};

/// Confined column compressed (or stretched) to λ from the IC-1 Donnan reference (solid
/// stress-free at J = 1, p = Π0): at equilibrium p = Π(J = λ) everywhere and
///   σ_zz = σ^e_zz(λ) − Π(λ);   SVK, ν = 0: λE(λ² − 1)/2 − Π(λ).
/// Paper data, λ = 0.95: σ_zz = −0.18403 MPa, p = 0.17014 MPa, η = −1645.93 mJ/mmol.
/// Under IC-3a (Cauchy prestress Π0 I) add +Π0 to total_stress. Source: reference-solutions.md
/// §R5.3; initial states: docs/theory/triphasic.md §6.
inline ColumnEquilibrium confined_column_equilibrium(double stretch, double E, double nu,
                                                     const ChargedMedium& m,
                                                     SolidLaw law = SolidLaw::StVenantKirchhoff) {
  const double s = solid_stress(law, Deformation::Confined, lame(E, nu), stretch).stress;
  const DonnanState d = donnan_at(m, stretch);
  return {s - d.pressure, s, d};
}

// =================================================================================================
// 4. Biphasic confined compression (reference-solutions.md §R1)
// =================================================================================================

/// Layer 0 ≤ z ≤ h: rigid impermeable bottom at z = 0 (u = 0, ∂p/∂z = 0), free-draining loaded
/// top at z = h (p = 0). Linear biphasic theory: ∂u/∂t = c_v ∂²u/∂z², c_v = H_A κ, τ = h²/c_v.
struct ConfinedLayer {
  double h;     ///< thickness [mm]
  double H_A;   ///< aggregate modulus [MPa]
  double kappa; ///< permeability [mm⁴/(N s)]

  [[nodiscard]] constexpr double c_v() const { return H_A * kappa; }
  [[nodiscard]] constexpr double tau() const { return h * h / c_v(); }
};

namespace detail {

inline constexpr double series_tol = 1e-18;
inline constexpr double sqrt_pi = 1.7724538509055160273; // √π

/// ierfc(x) = ∫_x^∞ erfc(s) ds = e^{−x²}/√π − x erfc(x).
inline double ierfc(double x) {
  return std::exp(-x * x) / sqrt_pi - x * std::erfc(x);
}

/// Creep, eigenfunction series (z from the bottom, ζ = z/h, T = t/τ, M_n = (2n + 1)π/2):
///   p/σ0 = Σ (2(−1)ⁿ/M_n) cos(M_n ζ) e^{−M_n² T}
///   u/(σ0 h/H_A) = −ζ + Σ (2(−1)ⁿ/M_n²) sin(M_n ζ) e^{−M_n² T}
/// Returns {u, p} nondimensional. Efficient for T ≳ 0.05.
inline std::pair<double, double> creep_eigen(double zeta, double T) {
  double u = -zeta;
  double p = 0.0;
  for (int n = 0;; ++n) {
    const double M = (2 * n + 1) * std::numbers::pi / 2.0;
    const double decay = std::exp(-M * M * T);
    const double sign = n % 2 == 0 ? 1.0 : -1.0;
    p += sign * 2.0 / M * std::cos(M * zeta) * decay;
    u += sign * 2.0 / (M * M) * std::sin(M * zeta) * decay;
    if (2.0 / M * decay < series_tol)
      break;
  }
  return {u, p};
}

/// Creep, method-of-images (short-time) series, s = 2 sqrt(T), a_n± = (2n + 1 ∓ ζ)/s:
///   p/σ0 = 1 − Σ (−1)ⁿ [erfc(a_n−) + erfc(a_n+)]
///   u/(σ0 h/H_A) = −s Σ (−1)ⁿ [ierfc(a_n−) − ierfc(a_n+)]
/// (u = ∫_0^z (p − σ0)/H_A dz). Early-time limit: u(h) ≈ −2 sqrt(T/π). Efficient for T ≲ 0.3.
inline std::pair<double, double> creep_images(double zeta, double T) {
  const double s = 2.0 * std::sqrt(T);
  double u = 0.0;
  double p = 1.0;
  for (int n = 0;; ++n) {
    const double sign = n % 2 == 0 ? 1.0 : -1.0;
    const double am = (2 * n + 1 - zeta) / s;
    const double ap = (2 * n + 1 + zeta) / s;
    p -= sign * (std::erfc(am) + std::erfc(ap));
    u -= sign * s * (ierfc(am) - ierfc(ap));
    if (std::erfc(am) < series_tol)
      break;
  }
  return {u, p};
}

/// Nondimensional creep {u/(σ0 h/H_A), p/σ0} at ζ = z/h, T = t/τ (series chosen by T).
inline std::pair<double, double> creep_nd(double zeta, double T) {
  TRIFEM_CHECK(T >= 0.0 && zeta >= 0.0 && zeta <= 1.0, "creep: need t >= 0 and 0 <= z <= h");
  if (T == 0.0)
    return {0.0, zeta < 1.0 ? 1.0 : 0.0}; // undrained response at t = 0+
  return T < 0.1 ? creep_images(zeta, T) : creep_eigen(zeta, T);
}

/// G(S) = Σ_{n≥1} (1 − e^{−n²π² S})/(n²π²), eigen form using Σ 1/(n²π²) = 1/6:
///   G(S) = 1/6 − Σ e^{−n²π² S}/(n²π²).   Efficient for S ≳ 0.05.
inline double ramp_g_eigen(double S) {
  double g = 1.0 / 6.0;
  for (int n = 1;; ++n) {
    const double k2 = n * n * std::numbers::pi * std::numbers::pi;
    const double term = std::exp(-k2 * S) / k2;
    g -= term;
    if (term < series_tol)
      break;
  }
  return g;
}

/// The same G(S) by Poisson summation (short-time form):
///   G(S) = sqrt(S/π) − S/2 + 2 sqrt(S) Σ_{k≥1} ierfc(k/sqrt(S)).   Efficient for S ≲ 0.3.
inline double ramp_g_images(double S) {
  if (S == 0.0)
    return 0.0;
  const double r = std::sqrt(S);
  double g = r / sqrt_pi - 0.5 * S;
  for (int k = 1;; ++k) {
    const double term = 2.0 * r * ierfc(k / r);
    g += term;
    if (term < series_tol)
      break;
  }
  return g;
}

inline double ramp_g(double S) {
  return S < 0.1 ? ramp_g_images(S) : ramp_g_eigen(S);
}

} // namespace detail

/// Creep displacement u(z, t) under a step compressive stress σ0 > 0 (total stress −σ0) applied at
/// t = 0 on the free-draining top; z from the impermeable bottom, M_n = (2n + 1)π/2:
///   u(z, t) = −(σ0/H_A) [ z − h Σ (2(−1)ⁿ/M_n²) sin(M_n z/h) e^{−M_n² t/τ} ]
///   u(h, t) = −(σ0 h/H_A) [ 1 − Σ (2/M_n²) e^{−M_n² t/τ} ]
/// (reference-solutions.md §R1.2, also in the form 2/M_n² = 8/((2n + 1)²π²), M_n²/τ = λ_n² c_v).
/// For t < 0.1τ the equivalent image series (detail::creep_images) is summed instead; both
/// converge to < 1e-16.
inline double creep_displacement(const ConfinedLayer& layer, double sigma0, double z, double t) {
  return sigma0 * layer.h / layer.H_A * detail::creep_nd(z / layer.h, t / layer.tau()).first;
}

/// Surface (top, z = h) creep displacement u(h, t); see creep_displacement.
inline double creep_surface_displacement(const ConfinedLayer& layer, double sigma0, double t) {
  return creep_displacement(layer, sigma0, layer.h, t);
}

/// Creep pore pressure with z measured from the impermeable bottom (∂p/∂z = 0 at z = 0, p = 0 at
/// the draining top z = h, p = σ0 at t = 0+), λ_n = (2n + 1)π/(2h):
///   p(z, t) = σ0 Σ 4(−1)ⁿ/((2n + 1)π) cos(λ_n z) e^{−λ_n² c_v t},
///   p(0, t) = σ0 Σ (2/M_n)(−1)ⁿ e^{−M_n² t/τ}         (reference-solutions.md §R1.2).
/// NB: the factor (−1)ⁿ is essential (an early statement lacked it); without it p ≠ 0 at z = h.
inline double creep_pressure(const ConfinedLayer& layer, double sigma0, double z, double t) {
  return sigma0 * detail::creep_nd(z / layer.h, t / layer.tau()).second;
}

/// Surface total stress under a top displacement ramped to compressive strain ε0 over [0, t0] and
/// then held (Mow et al. 1980), with S = t/τ, S0 = t0/τ, G(S) = Σ (1 − e^{−n²π²S})/(n²π²):
///   0 ≤ t ≤ t0:  σ = −H_A ε0 [ S/S0 + (2/S0) G(S) ]
///   t > t0:      σ = −H_A ε0 [ 1 + (2/S0) (G(S) − G(S − S0)) ]
/// Peak at t0; σ → −H_A ε0. For t0 ≪ τ the peak is −H_A ε0 · 2/sqrt(π S0). Source:
/// reference-solutions.md §R1.4 (a first tabulation printed the peaks from a 4000-term truncation,
/// see the test file).
inline double ramp_relaxation_stress(const ConfinedLayer& layer, double eps0, double t0, double t) {
  TRIFEM_CHECK(t0 > 0.0 && t >= 0.0, "ramp_relaxation_stress: need t0 > 0, t >= 0");
  const double S = t / layer.tau();
  const double S0 = t0 / layer.tau();
  const double bracket = S <= S0 ? S / S0 + 2.0 / S0 * detail::ramp_g(S)
                                 : 1.0 + 2.0 / S0 * (detail::ramp_g(S) - detail::ramp_g(S - S0));
  return -layer.H_A * eps0 * bracket;
}

} // namespace trifem::exact
