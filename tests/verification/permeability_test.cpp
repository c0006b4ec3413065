// SPDX-License-Identifier: MIT
// Strain-dependent permeability in whole biphasic models (docs/theory/reference-solutions.md
// §R10): steady permeation through a confined layer compacted by the drag (exact 1-D steady
// state by RK4), stress relaxation converging under refinement, and the Holmes-Mow law with
// M = alpha = 0 reproducing the constant permeability.
#include "mixture_model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

using namespace trifem;

namespace {

constexpr Real kE = 0.3;      ///< Young's modulus of the solid (nu = 0) [MPa]
constexpr Real kPhiS0 = 0.25; ///< solid volume fraction
constexpr Real kK0 = 1.07e-3; ///< permeability in the reference state [mm^4/(N s)]
constexpr Real kM = 4.6;      ///< Holmes-Mow exponential coefficient
constexpr Real kAlpha = 2.0;  ///< Holmes-Mow power
constexpr Real kH = 1.0;      ///< layer thickness [mm]
constexpr Real kT = 0.04;     ///< compressive total traction on the top [MPa]
constexpr Real kQ = 2e-5;     ///< downward water flux through the layer [mm/s]
constexpr Real kRamp = 100.0; ///< load ramp [s]

/// The biphasic tissue: solid E = 0.3 MPa, nu = 0 (SVK, or neo-Hookean, which keeps its stiffness
/// under strong compaction), phi_s0 = 0.25, Holmes-Mow permeability (M, alpha) or, if
/// `constant`, kappa = k0.
material::MixtureProperties tissue(Real M, Real alpha, bool constant = false,
                                   const std::string& solid_law = "saint-venant-kirchhoff") {
  auto solid = material::create_law(solid_law, {{"E", kE}, {"nu", 0.0}}, "solid");
  material::ParameterValues v = {{"phi_s0", kPhiS0}};
  if (constant) {
    v["permeability"] = kK0;
  } else {
    v[material::transport_law_key("permeability", "holmes-mow", "k0")] = kK0;
    v[material::transport_law_key("permeability", "holmes-mow", "M")] = M;
    v[material::transport_law_key("permeability", "holmes-mow", "alpha")] = alpha;
  }
  return material::make_mixture(false, std::move(solid), v, "tissue");
}

/// Cauchy stress sigma_zz of the solid in confined uniaxial stretch lambda and its derivative:
/// SVK with nu = 0 gives S_zz = E (lambda^2 - 1)/2 and sigma_zz = lambda S_zz.
Real sigma_e(Real lambda) {
  return kE * lambda * (lambda * lambda - 1.0) / 2.0;
}
Real dsigma_e(Real lambda) {
  return kE * (3.0 * lambda * lambda - 1.0) / 2.0;
}

/// Exact steady state of the permeation layer (reference-solutions.md §R10.2) on the grid
/// Z_i = i h/N: stretch lambda, displacement u and pressure p = sigma_e(lambda) + T.
struct SteadyLayer {
  std::vector<Real> lambda, u;
  Real pressure(std::size_t i) const { return sigma_e(lambda[i]) + kT; }
};

/// Classical RK4 for d(lambda, u)/dZ = (lambda q/(kappa(lambda) sigma_e'(lambda)), lambda - 1)
/// from lambda(0) = the root of sigma_e(lambda) = -T (Newton), u(0) = 0.
SteadyLayer steady_layer(const material::PermeabilityLaw& kappa, int N) {
  Real lambda = 1.0;
  for (int i = 0; i < 50; ++i)
    lambda -= (sigma_e(lambda) + kT) / dsigma_e(lambda);
  const auto f = [&](Real l) { return l * kQ / (kappa.value(l) * dsigma_e(l)); };
  const Real dZ = kH / N;
  SteadyLayer s{{lambda}, {0.0}};
  Real u = 0.0;
  for (int i = 0; i < N; ++i) {
    const Real k1 = f(lambda), l2 = lambda + dZ / 2 * k1, k2 = f(l2), l3 = lambda + dZ / 2 * k2,
               k3 = f(l3), l4 = lambda + dZ * k3, k4 = f(l4);
    u += dZ * ((lambda - 1) + 2 * (l2 - 1) + 2 * (l3 - 1) + (l4 - 1)) / 6;
    lambda += dZ * (k1 + 2 * k2 + 2 * k3 + k4) / 6;
    s.lambda.push_back(lambda);
    s.u.push_back(u);
  }
  return s;
}

/// Laterally confined and impermeable column of n cells (one across); the caller sets the
/// conditions of its bottom and top faces.
test::MixtureModel confined_column(int n, material::MixtureProperties props) {
  mesh::BoxSpec spec;
  spec.size = {1.0, 1.0, kH};
  spec.divisions = {1, 1, n};
  test::MixtureModel m(mesh::make_box(spec), std::move(props));
  for (int k = 0; k < 2; ++k) {
    m.fix("box.all", m.f.u, k);
    m.impermeable("box.all", k); // one cell across: every node is on a lateral face
  }
  return m;
}

/// Errors of the FE steady state against the exact one.
struct PermeationErrors {
  Real u_top;    ///< |u_top - u(h)| / |u(h)|
  Real pressure; ///< max over cells |p_e - p(Z_e)| / (p(h) - p(0))
  Real stretch;  ///< max over cells |V_e/V0_e - lambda(Z_e)| / (lambda(h) - lambda(0))
};

/// Steady permeation (§R10.1): bottom on a porous platen (u_z = 0, free-draining), top loaded
/// by the total traction -T and a prescribed water flux w_z = -q, both ramped over kRamp s and
/// then held until the flow is steady (backward Euler steps growing to 1e7 s).
PermeationErrors permeation_errors(int n, const SteadyLayer& exact, int N) {
  test::MixtureModel m = confined_column(n, tissue(kM, kAlpha));
  m.fix("box.zmin", m.f.u, 2);
  const dofs::LoadCurve ramp({{0.0, 0.0}, {kRamp, 1.0}}, dofs::Interpolation::Linear);
  m.fix("box.zmax", m.f.w, 2, -kQ, ramp);
  m.loads.push_back(std::make_unique<physics::TractionTerm>(
      m.mesh, m.dofs, m.f.u, m.mesh.surface("box.zmax").facets, Vec3(0, 0, -kT), ramp));
  m.build();
  const solver::RunReport run = m.run(1e8, 10.0, 1e7, {kRamp});
  EXPECT_TRUE(run.success) << run.failure;
  PermeationErrors e{0.0, 0.0, 0.0};
  const Index top = m.mesh.node_set("box.zmax").front();
  e.u_top = std::abs(m.value(m.f.u, top, 2) - exact.u.back()) / std::abs(exact.u.back());
  const Real dp = exact.pressure(N) - exact.pressure(0);
  const Real dl = exact.lambda.back() - exact.lambda.front();
  for (Index c = 0; c < m.mesh.num_cells(); ++c) {
    Real Z = 0.0;
    for (Index node : m.mesh.cell(c))
      Z += m.mesh.node(node).z() / 8;
    const auto i = static_cast<std::size_t>(std::lround(Z / kH * N)); // a grid point
    EXPECT_NEAR(Z / kH * N, Real(i), 1e-9);
    e.pressure = std::max(e.pressure, std::abs(m.value(m.f.p, c) - exact.pressure(i)) / dp);
    const Real J = m.mixture->output(c, m.problem->state()).chem.V / (kH / n);
    e.stretch = std::max(e.stretch, std::abs(J - exact.lambda[i]) / dl);
  }
  // steady: the flux is uniform and equal to the prescribed one at every node
  for (Index node = 0; node < m.mesh.num_nodes(); ++node)
    EXPECT_NEAR(m.value(m.f.w, node, 2), -kQ, 1e-9 * kQ) << "node " << node;
  return e;
}

} // namespace

/// (a) Steady permeation with Holmes-Mow permeability: the drag compacts the layer, so kappa
/// varies along it (by a factor of 3 here). u_top converges to the exact steady state at second
/// order from the coarsest mesh on; the cell pressures and stretches (maximum over the cells)
/// approach second order from below (rates 1.84 ... 1.97 on 16 ... 128 cells).
TEST(Permeability, SteadyPermeationMatchesExactSolutionAndConvergesAtSecondOrder) {
  const material::MixtureProperties props = tissue(kM, kAlpha);
  constexpr int N = 3840; // the cell centres of 16 ... 128 cells are grid points
  const SteadyLayer exact = steady_layer(*props.permeability_law, N);
  const SteadyLayer half = steady_layer(*props.permeability_law, N / 2);
  // the reference is converged: RK4 on N/2 and N steps agree to round-off
  EXPECT_NEAR(half.u.back(), exact.u.back(), 1e-13 * std::abs(exact.u.back()));
  EXPECT_NEAR(exact.lambda.front(), 0.821923, 1e-6); // sigma_e(lambda_0) = -T
  std::cout << "exact: lambda " << exact.lambda.front() << " -> " << exact.lambda.back()
            << ", kappa/k0 " << props.permeability_law->value(exact.lambda.front()) / kK0 << " -> "
            << props.permeability_law->value(exact.lambda.back()) / kK0 << ", u_top "
            << exact.u.back() << " mm, p_top " << exact.pressure(N) << " MPa\n";
  std::vector<PermeationErrors> errors;
  for (int n : {16, 32, 64, 128}) {
    errors.push_back(permeation_errors(n, exact, N));
    std::cout << "n = " << n << ": u_top " << errors.back().u_top << ", pressure "
              << errors.back().pressure << ", stretch " << errors.back().stretch << "\n";
  }
  for (std::size_t k = 1; k < errors.size(); ++k) {
    const Real rate_u = std::log2(errors[k - 1].u_top / errors[k].u_top);
    const Real rate_p = std::log2(errors[k - 1].pressure / errors[k].pressure);
    const Real rate_l = std::log2(errors[k - 1].stretch / errors[k].stretch);
    std::cout << "observed rates: u_top " << rate_u << ", pressure " << rate_p << ", stretch "
              << rate_l << "\n";
    EXPECT_GE(rate_u, 1.9);
    EXPECT_GE(rate_p, k + 1 < errors.size() ? 1.8 : 1.9);
    EXPECT_GE(rate_l, k + 1 < errors.size() ? 1.8 : 1.9);
  }
  EXPECT_LT(errors.back().u_top, 1e-5);
  EXPECT_LT(errors.back().pressure, 5e-5);
  EXPECT_LT(errors.back().stretch, 6e-5);
}

namespace {

constexpr Real kStrain = 0.1; ///< ramp compression of the relaxation test
constexpr Real kT0 = 1000.0;  ///< ramp time [s]
/// The drained surface compacts far more than 10 % during the ramp: a neo-Hookean solid keeps its
/// stiffness there (SVK softens below a stretch of 1/sqrt(3)).
const std::string kRelaxationSolid = "neo-hookean";

/// Drained confined stress of the neo-Hookean solid with nu = 0: sigma_zz = mu (lambda^2 - 1) /
/// lambda, mu = E/2.
Real sigma_neo_hookean(Real lambda) {
  return kE / 2 * (lambda * lambda - 1.0) / lambda;
}

/// Confined ramp relaxation: bottom fixed and impermeable, the free-draining top moved down by
/// kStrain h over kT0 and held. Returns the total stress on the top (reaction per unit area) at
/// t = kT0 (the peak), 1.5 kT0 and 2 kT0.
std::vector<Real> relaxation_stresses(int n, Real dt, material::MixtureProperties props) {
  test::MixtureModel m = confined_column(n, std::move(props));
  m.fix("box.zmin", m.f.u, 2);
  m.impermeable("box.zmin", 2);
  m.fix("box.zmax", m.f.u, 2, -kStrain * kH,
        dofs::LoadCurve({{0.0, 0.0}, {kT0, 1.0}}, dofs::Interpolation::Linear));
  m.build();
  std::vector<Real> stresses;
  for (Real t : {kT0, 1.5 * kT0, 2 * kT0}) {
    EXPECT_TRUE(m.run(t, dt, dt).success);
    Real force = 0.0;
    for (Index node : m.mesh.node_set("box.zmax"))
      force += m.problem->full_residual()[m.dofs.dof(m.f.u, node, 2)];
    stresses.push_back(force);
    Real J_min = 1.0;
    for (Index c = 0; c < m.mesh.num_cells(); ++c)
      J_min = std::min(J_min, m.mixture->output(c, m.problem->state()).chem.V / (kH / n));
    std::cout << "  n = " << n << ", t = " << t << ": stress " << force << " MPa, smallest J "
              << J_min << "\n";
  }
  return stresses;
}

Real max_difference(const std::vector<Real>& a, const std::vector<Real>& b) {
  Real d = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
    d = std::max(d, std::abs(a[i] - b[i]));
  return d;
}

/// Rates log2(d_k / d_k+1) of the successive differences d_k of the solutions `s` (maximum over
/// the samples, relative to `scale`).
std::vector<Real> observed_rates(const std::vector<std::vector<Real>>& s, Real scale,
                                 const std::string& what) {
  std::vector<Real> d, rates;
  for (std::size_t k = 1; k < s.size(); ++k)
    d.push_back(max_difference(s[k - 1], s[k]) / scale);
  std::cout << what << ": relative differences";
  for (Real x : d)
    std::cout << " " << x;
  std::cout << "; observed rates";
  for (std::size_t k = 1; k < d.size(); ++k) {
    rates.push_back(std::log2(d[k - 1] / d[k]));
    std::cout << " " << rates.back();
  }
  std::cout << "\n";
  return rates;
}

} // namespace

/// (b) Ramp relaxation to 10 % compression with Holmes-Mow permeability (at the peak the drained
/// surface cell is compacted to J = 0.71 on 40 cells, where kappa = 0.12 k0). Under joint
/// refinement (5, 10, 20, 40 cells, dt halved each time) the differences between successive
/// solutions fall at a rate between the orders of the time (backward Euler, 1) and space (Q1/P0, 2)
/// discretisations; refining dt alone on one mesh they fall at the first order of backward Euler.
TEST(Permeability, HolmesMowRelaxationConvergesUnderRefinement) {
  const material::MixtureProperties props = tissue(kM, kAlpha, false, kRelaxationSolid);
  std::vector<std::vector<Real>> joint, in_time;
  for (auto [n, dt] : {std::pair{5, 10.0}, {10, 5.0}, {20, 2.5}, {40, 1.25}})
    joint.push_back(relaxation_stresses(n, dt, props));
  const Real scale = std::abs(joint.back()[0]); // the peak stress
  for (Real rate : observed_rates(joint, scale, "h and dt halved")) {
    EXPECT_GE(rate, 0.9);
    EXPECT_LE(rate, 2.1);
  }
  EXPECT_LT(max_difference(joint[2], joint[3]) / scale, 5e-3);
  for (Real dt : {20.0, 10.0, 5.0, 2.5})
    in_time.push_back(relaxation_stresses(10, dt, props));
  for (Real rate : observed_rates(in_time, scale, "dt halved, 10 cells")) {
    EXPECT_GE(rate, 0.9);
    EXPECT_LE(rate, 1.1);
  }
  // the relaxation is slower than with a constant permeability (compaction closes the pores)
  const std::vector<Real> constant =
      relaxation_stresses(20, 2.5, tissue(0.0, 0.0, true, kRelaxationSolid));
  EXPECT_LT(joint[2][0], 1.5 * constant[0]); // a peak compressive stress 1.5 times larger
}

/// Equilibrium of the relaxation: the drained stress of the solid at the stretch 1 - strain
/// (closed form), to the solver tolerance, whatever the permeability law.
TEST(Permeability, HolmesMowRelaxationReachesTheDrainedStress) {
  test::MixtureModel m = confined_column(10, tissue(kM, kAlpha, false, kRelaxationSolid));
  m.fix("box.zmin", m.f.u, 2);
  m.impermeable("box.zmin", 2);
  m.fix("box.zmax", m.f.u, 2, -kStrain * kH,
        dofs::LoadCurve({{0.0, 0.0}, {kT0, 1.0}}, dofs::Interpolation::Linear));
  m.build();
  ASSERT_TRUE(m.run(1e8, 10.0, 1e7, {kT0}).success);
  Real force = 0.0;
  for (Index node : m.mesh.node_set("box.zmax"))
    force += m.problem->full_residual()[m.dofs.dof(m.f.u, node, 2)];
  EXPECT_NEAR(force, sigma_neo_hookean(1.0 - kStrain),
              1e-8 * std::abs(sigma_neo_hookean(1.0 - kStrain)));
}

/// (c) Holmes-Mow with M = alpha = 0 is the constant permeability: the same relaxation history
/// to round-off (the law is evaluated, its zero derivative enters the tangent).
TEST(Permeability, HolmesMowWithoutStrainDependenceEqualsConstantPermeability) {
  const std::vector<Real> hm =
      relaxation_stresses(10, 5.0, tissue(0.0, 0.0, false, kRelaxationSolid));
  const std::vector<Real> constant =
      relaxation_stresses(10, 5.0, tissue(0.0, 0.0, true, kRelaxationSolid));
  for (std::size_t i = 0; i < hm.size(); ++i)
    EXPECT_NEAR(hm[i], constant[i], 1e-13 * std::abs(constant[0])) << "sample " << i;
  std::cout << "largest difference " << max_difference(hm, constant) << " MPa\n";
}
