// SPDX-License-Identifier: MIT
// Exact solutions of the incompressible neo-Hookean thick sphere
// (docs/theory/reference-solutions.md §R8.2, §R8.4): the static pressure-radius relation and the
// one-degree-of-freedom radial-oscillation ODE, integrated here with classical RK4.
#pragma once

#include "trifem/core/types.hpp"

#include <cmath>
#include <functional>
#include <vector>

namespace trifem::test::sphere {

/// Geometry and material of the sphere: inner/outer reference radii A, B [mm], μ [MPa],
/// ρ [t/mm³].
struct Sphere {
  Real A = 1.0, B = 2.0, mu = 1.0, rho = 1.0;

  /// Current outer radius from incompressibility: b³ − B³ = a³ − A³.
  Real outer(Real a) const { return std::cbrt(B * B * B + a * a * a - A * A * A); }

  /// Static pressure difference P_in − P_out holding inner radius a (reference-solutions.md §R8.2):
  /// P_el = μ [2/λ_b + 1/(2 λ_b⁴) − 2/λ_a − 1/(2 λ_a⁴)], λ_a = a/A, λ_b = b/B.
  Real static_pressure(Real a) const {
    const Real la = a / A, lb = outer(a) / B;
    return mu * (2.0 / lb + 0.5 / std::pow(lb, 4) - 2.0 / la - 0.5 / std::pow(la, 4));
  }

  /// Inner radius of the static state at pressure P (bisection on the rising branch a < 1.828 A).
  Real static_radius(Real P) const {
    Real lo = A, hi = 1.8 * A;
    for (int it = 0; it < 200; ++it) {
      const Real mid = 0.5 * (lo + hi);
      (static_pressure(mid) < P ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  }

  /// ä of reference-solutions.md §R8.4:
  /// ρ [(a² ä + 2 a ȧ²)(1/a − 1/b) − ½ a⁴ ȧ² (1/a⁴ − 1/b⁴)] = P(t) − P_el(a).
  Real acceleration(Real a, Real v, Real P) const {
    const Real b = outer(a);
    const Real k = 1.0 / a - 1.0 / b;
    const Real rhs = (P - static_pressure(a)) / rho +
                     0.5 * std::pow(a, 4) * v * v * (1.0 / std::pow(a, 4) - 1.0 / std::pow(b, 4)) -
                     2.0 * a * v * v * k;
    return rhs / (a * a * k);
  }
};

/// One sample of the ODE solution.
struct RadialState {
  Real t, a, v;
};

/// RK4 integration from rest (a = A, ȧ = 0) under P(t) with step h; samples every step.
inline std::vector<RadialState>
integrate_radial(const Sphere& s, const std::function<Real(Real)>& P, Real t_end, Real h) {
  std::vector<RadialState> out{{0.0, s.A, 0.0}};
  Real t = 0.0, a = s.A, v = 0.0;
  while (t < t_end - 0.5 * h) {
    const Real k1a = v, k1v = s.acceleration(a, v, P(t));
    const Real k2a = v + 0.5 * h * k1v,
               k2v = s.acceleration(a + 0.5 * h * k1a, k2a, P(t + 0.5 * h));
    const Real k3a = v + 0.5 * h * k2v,
               k3v = s.acceleration(a + 0.5 * h * k2a, k3a, P(t + 0.5 * h));
    const Real k4a = v + h * k3v, k4v = s.acceleration(a + h * k3a, k4a, P(t + h));
    a += h / 6.0 * (k1a + 2.0 * k2a + 2.0 * k3a + k4a);
    v += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
    t += h;
    out.push_back({t, a, v});
  }
  return out;
}

/// Linear interpolation of a(t) in an RK4 history with uniform steps.
inline Real radius_at(const std::vector<RadialState>& h, Real t) {
  const Real dt = h[1].t - h[0].t;
  const std::size_t i = std::min(static_cast<std::size_t>(t / dt), h.size() - 2);
  const Real w = (t - h[i].t) / dt;
  return (1.0 - w) * h[i].a + w * h[i + 1].a;
}

/// The first period of an oscillation from rest: the time of the first return to (near) rest
/// after the first maximum (where ȧ turns from negative to non-negative); 0 if there is none.
inline Real first_period(const std::vector<RadialState>& h) {
  for (std::size_t i = 1; i + 1 < h.size(); ++i)
    if (h[i - 1].v < 0.0 && h[i].v >= 0.0)
      return h[i].t;
  return 0.0;
}

} // namespace trifem::test::sphere
