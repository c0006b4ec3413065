// SPDX-License-Identifier: MIT
// FEBio test problems run from their unchanged .feb files (tests/data/feb, README.md there for
// their sources) and compared with independent answers: closed forms of homogeneous uniaxial
// states for the solids, the confined-compression ramp-relaxation series for a biphasic column.
#include "exact_solutions.hpp"
#include "feb_run.hpp"
#include "trifem/analysis/case_file.hpp"
#include "trifem/analysis/run.hpp"
#include "trifem/feb/feb_reader.hpp"
#include "trifem/io/case_writer.hpp"
#include "trifem/linalg/linear_solver.hpp"
#include "trifem/model/model.hpp"
#include "trifem/model/rigid_bodies.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

using namespace trifem;

namespace {

const std::filesystem::path kData = TRIFEM_FEB_DATA_DIR;

using test::FebRun;

FebRun run(io::CaseSpec spec, const std::function<void(const model::Model&, Real)>& observer = {}) {
  return test::run_feb_case(std::move(spec), observer);
}

/// Sum of the residual (reaction) at one displacement component of a node set.
Real reaction(const model::Model& m, const std::string& set, int component) {
  Real sum = 0.0;
  for (Index n : m.mesh.node_set(set))
    sum += m.problem->full_residual()[m.dofs.dof(m.fields.u, n, component)];
  return sum;
}

Real displacement(const model::Model& m, Index node, int component) {
  return m.problem->state()[m.dofs.dof(m.fields.u, node, component)];
}

/// Principal Cauchy stresses of a homogeneous state with stretches (a, a, c).
using StressLaw = std::function<std::array<Real, 2>(Real a, Real c)>;

/// The lateral stretch a of uniaxial stress along z at axial stretch c (sigma_xx = 0), by
/// Newton's method with a difference quotient (the laws are smooth).
Real lateral_stretch(const StressLaw& law, Real c) {
  Real a = 1.0;
  for (int i = 0; i < 100; ++i) {
    const Real f = law(a, c)[0], h = 1e-7;
    const Real df = (law(a + h, c)[0] - law(a - h, c)[0]) / (2.0 * h);
    const Real step = f / df;
    a -= step;
    if (std::abs(step) < 1e-14)
      break;
  }
  return a;
}

/// Compressible neo-Hookean (W = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2):
/// sigma_i = [mu (l_i^2 - 1) + lambda ln J] / J.
StressLaw neo_hookean(Real E, Real nu) {
  const Real mu = E / (2.0 * (1.0 + nu)), lambda = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  return [=](Real a, Real c) {
    const Real J = a * a * c;
    return std::array<Real, 2>{(mu * (a * a - 1.0) + lambda * std::log(J)) / J,
                               (mu * (c * c - 1.0) + lambda * std::log(J)) / J};
  };
}

/// Uncoupled laws: Kirchhoff stress tau_i = dev(t~)_i + k ln J with t~_i = t~(l~_i, I1~) the
/// isochoric principal Kirchhoff stress of the deviatoric stretches l~ = J^(-1/3) l.
StressLaw uncoupled(std::function<Real(Real, Real)> isochoric_tau, Real k) {
  return [=](Real a, Real c) {
    const Real J = a * a * c, s = std::cbrt(J);
    const Real I1 = (2.0 * a * a + c * c) / (s * s);
    const Real ta = isochoric_tau(a / s, I1), tc = isochoric_tau(c / s, I1);
    const Real mean = (2.0 * ta + tc) / 3.0;
    return std::array<Real, 2>{(ta - mean + k * std::log(J)) / J,
                               (tc - mean + k * std::log(J)) / J};
  };
}

/// Mooney-Rivlin: t~_i = 2 c1 l~_i^2 + 2 c2 l~_i^2 (I1~ - l~_i^2).
StressLaw mooney_rivlin(Real c1, Real c2, Real k) {
  return uncoupled(
      [=](Real l, Real I1) { return 2.0 * c1 * l * l + 2.0 * c2 * l * l * (I1 - l * l); }, k);
}

/// Ogden: t~_i = sum_p c_p/m_p l~_i^m_p.
StressLaw ogden(std::vector<std::pair<Real, Real>> terms, Real k) {
  return uncoupled(
      [=](Real l, Real) {
        Real t = 0.0;
        for (const auto& [c, m] : terms)
          t += c / m * std::pow(l, m);
        return t;
      },
      k);
}

std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

} // namespace

// The 2x2x2-point hex8 reproduces a homogeneous state exactly: the single-element problems
// match their closed forms to the Newton tolerance.

TEST(FebVerification, NeoHookeanUniaxialStretch) {
  const auto law = neo_hookean(1.0, 0.3);
  std::map<long, Real> force; // time in 1/100 s -> reaction
  const FebRun r = run(
      analysis::read_case_file(kData / "uniaxial_neo_hookean.feb"),
      [&](const model::Model& m, Real t) { force[std::lround(t * 100)] = reaction(m, "Top", 2); });
  ASSERT_TRUE(r.report.success);
  ASSERT_EQ(force.size(), 10u);
  for (const auto& [t, f] : force) {
    const Real c = 1.0 + 0.2 * t / 100.0, a = lateral_stretch(law, c);
    EXPECT_NEAR(f, law(a, c)[1] * a * a, 1e-8) << "t = " << t / 100.0;
  }
  const Real a = lateral_stretch(law, 1.2);
  const Index corner = 6; // FEBio node 7 at (1, 1, 1)
  EXPECT_NEAR(displacement(*r.model, corner, 0), a - 1.0, 1e-9);
  EXPECT_NEAR(displacement(*r.model, corner, 2), 0.2, 1e-12);
}

// Two blocks on non-matching meshes (2x2 below, 3x3 above) in frictionless sliding-elastic
// contact, the stack compressed 10 % under uniaxial stress: the state is homogeneous, so the
// contact patch test holds through the .feb reader (FEBio's primary surface is the slave).
TEST(FebVerification, StackedBlocksInContactStayInUniaxialStress) {
  const auto law = neo_hookean(1.0, 0.3);
  std::map<long, std::pair<Real, Real>> force; // time in 1/100 s -> (top reaction, contact)
  const FebRun r = run(analysis::read_case_file(kData / "stacked_blocks_contact.feb"),
                       [&](const model::Model& m, Real t) {
                         const Real contact = m.contacts.at(0)->slave_force(m.problem->state()).z();
                         force[std::lround(t * 100)] = {reaction(m, "Top", 2), contact};
                       });
  ASSERT_TRUE(r.report.success) << r.report.failure;
  ASSERT_EQ(force.size(), 5u);
  for (const auto& [t, f] : force) {
    const Real c = 1.0 - 0.1 * t / 100.0, a = lateral_stretch(law, c);
    EXPECT_NEAR(f.first, law(a, c)[1] * a * a, 1e-8) << "t = " << t / 100.0;
    EXPECT_NEAR(f.second, -f.first, 1e-8) << "t = " << t / 100.0; // pushes the upper block up
  }
  const Real a = lateral_stretch(law, 0.9);
  const Index corner = 49; // FEBio node 132 at (1, 1, 1), the last of the 50 nodes
  EXPECT_NEAR(displacement(*r.model, corner, 0), a - 1.0, 1e-9);
  EXPECT_NEAR(displacement(*r.model, corner, 2), -0.1, 1e-12);
}

// The confined biphasic column split at mid-height into two parts joined by sliding-biphasic
// contact: the closed interface holds the fluid pressure and the normal flux continuous, so the
// split column is the whole column (same file, one part) to round-off (first 150 s).
TEST(FebVerification, SplitBiphasicColumnEqualsTheWholeColumn) {
  const auto top_reactions = [](const std::string& name) {
    std::string text = read_file(kData / name);
    const std::string steps = "<time_steps>400</time_steps>";
    EXPECT_NE(text.find(steps), std::string::npos);
    text.replace(text.find(steps), steps.size(), "<time_steps>60</time_steps>");
    std::map<long, Real> force; // time in 1/10 s -> top reaction
    const FebRun r = run(feb::parse_feb(text, kData / name), [&](const model::Model& m, Real t) {
      force[std::lround(t * 10)] = reaction(m, "Top", 2);
    });
    EXPECT_TRUE(r.report.success) << r.report.failure;
    EXPECT_EQ(r.model->contacts.size(), name == "confined_biphasic_split.feb" ? 1u : 0u);
    return force;
  };
  const std::map<long, Real> whole = top_reactions("confined_biphasic_ramp.feb");
  const std::map<long, Real> split = top_reactions("confined_biphasic_split.feb");
  ASSERT_EQ(whole.size(), 60u);
  ASSERT_EQ(split.size(), whole.size());
  Real peak = 0.0, worst = 0.0;
  for (const auto& [t, f] : whole) {
    peak = std::max(peak, std::abs(f));
    worst = std::max(worst, std::abs(split.at(t) - f));
  }
  EXPECT_GT(peak, 0.1); // -0.35 N at the end of the ramp
  EXPECT_LT(worst, 1e-8 * peak);
  std::cout << "split - whole column: largest difference " << worst / peak << " of the peak\n";
}

TEST(FebVerification, MooneyRivlinFollowerPressure) {
  const Real p = 0.1;
  const auto law = mooney_rivlin(0.2, 0.05, 20.0);
  // Uniaxial stress sigma_zz = -p: solve for the axial stretch c by bisection on sigma_zz(c).
  Real lo = 0.5, hi = 1.0;
  for (int i = 0; i < 200; ++i) {
    const Real c = 0.5 * (lo + hi);
    (law(lateral_stretch(law, c), c)[1] > -p ? hi : lo) = c;
  }
  const Real c = 0.5 * (lo + hi), a = lateral_stretch(law, c);
  std::vector<Real> times;
  const FebRun r = run(analysis::read_case_file(kData / "uniaxial_mooney_rivlin_pressure.feb"),
                       [&](const model::Model&, Real t) { times.push_back(t); });
  ASSERT_TRUE(r.report.success);
  EXPECT_TRUE(std::any_of(times.begin(), times.end(), [](Real t) {
    return std::abs(t - 0.35) < 1e-9;
  })) << "the must point of the dtmax curve";
  const Index corner = 6;
  EXPECT_NEAR(displacement(*r.model, corner, 2), c - 1.0, 1e-8);
  EXPECT_NEAR(displacement(*r.model, corner, 0), a - 1.0, 1e-8);
  EXPECT_LT(c, 0.94); // a real compression (about 6.6 %), not a trivial state
}

// The same file with <linear>1</linear>: FEBio's dead pressure, along the reference normal per
// reference area: the nominal stress P_zz = sigma_zz a^2 = -p.
TEST(FebVerification, MooneyRivlinLinearPressureIsADeadLoad) {
  const Real p = 0.1;
  const auto law = mooney_rivlin(0.2, 0.05, 20.0);
  Real lo = 0.5, hi = 1.0;
  for (int i = 0; i < 200; ++i) {
    const Real c = 0.5 * (lo + hi);
    const Real a = lateral_stretch(law, c);
    (law(a, c)[1] * a * a > -p ? hi : lo) = c;
  }
  const Real c = 0.5 * (lo + hi), a = lateral_stretch(law, c);
  const std::filesystem::path file = kData / "uniaxial_mooney_rivlin_pressure.feb";
  std::string text = read_file(file);
  const std::string follower = "<linear>0</linear>";
  text.replace(text.find(follower), follower.size(), "<linear>1</linear>");
  const io::CaseSpec spec = feb::parse_feb(text, file);
  ASSERT_EQ(spec.pressures.size(), 1u);
  EXPECT_FALSE(spec.pressures[0].follower);
  const FebRun r = run(spec);
  ASSERT_TRUE(r.report.success) << r.report.failure;
  const Index corner = 6;
  EXPECT_NEAR(displacement(*r.model, corner, 2), c - 1.0, 1e-8);
  EXPECT_NEAR(displacement(*r.model, corner, 0), a - 1.0, 1e-8);
  EXPECT_LT(c, 0.94);
}

// The same block under a traction of 0.1 MPa pulling the top face (<surface_load
// type="traction">, the pressure load of the file replaced in memory). With <linear>1</linear>
// FEBio integrates it over the reference surface (a dead load): the nominal stress P_zz =
// sigma_zz a^2 = 0.1. By default (linear = 0) over the current surface: sigma_zz = 0.1.
TEST(FebVerification, MooneyRivlinTractionPerReferenceAndPerCurrentArea) {
  const Real t = 0.1;
  const auto law = mooney_rivlin(0.2, 0.05, 20.0);
  for (const bool linear : {true, false}) {
    const auto stress = [&](Real c) { // the stress the traction sets: nominal or Cauchy
      const Real a = lateral_stretch(law, c);
      return law(a, c)[1] * (linear ? a * a : 1.0);
    };
    Real lo = 1.0, hi = 1.5;
    for (int i = 0; i < 200; ++i) {
      const Real c = 0.5 * (lo + hi);
      (stress(c) > t ? hi : lo) = c;
    }
    const Real c = 0.5 * (lo + hi), a = lateral_stretch(law, c);
    const std::filesystem::path file = kData / "uniaxial_mooney_rivlin_pressure.feb";
    std::string text = read_file(file);
    const std::string from = text.substr(
        text.find("<surface_load"), text.find("</surface_load>") + 15 - text.find("<surface_load"));
    text.replace(text.find(from), from.size(),
                 std::string("<surface_load name=\"Pull\" surface=\"Top\" type=\"traction\">\n"
                             "<scale lc=\"1\">0.2</scale>\n<traction>0,0,0.5</traction>\n") +
                     (linear ? "<linear>1</linear>\n" : "") + "</surface_load>");
    const io::CaseSpec spec = feb::parse_feb(text, file);
    ASSERT_EQ(spec.tractions.size(), 1u);
    EXPECT_TRUE(spec.pressures.empty());
    EXPECT_EQ(spec.tractions[0].curve, "ramp");
    EXPECT_DOUBLE_EQ(spec.tractions[0].value.z(), 0.1); // scale x traction
    EXPECT_EQ(spec.tractions[0].per_current_area, !linear);
    const FebRun r = run(spec);
    ASSERT_TRUE(r.report.success) << r.report.failure;
    const Index corner = 6;
    EXPECT_NEAR(displacement(*r.model, corner, 2), c - 1.0, 1e-8) << "linear " << linear;
    EXPECT_NEAR(displacement(*r.model, corner, 0), a - 1.0, 1e-8) << "linear " << linear;
    EXPECT_GT(c, 1.05); // a real stretch, not a trivial state
  }
}

// The same block under FEBio's surface force (<surface_load type="force">): 0.2 x (0, 0, 0.5) N
// spread over the top's reference area of 1 mm^2 is the dead traction of 0.1 MPa (linear = 1
// above): P_zz = 0.1.
TEST(FebVerification, MooneyRivlinSurfaceForceIsTheDeadTractionForceOverArea) {
  const auto law = mooney_rivlin(0.2, 0.05, 20.0);
  const auto nominal = [&](Real c) {
    const Real a = lateral_stretch(law, c);
    return law(a, c)[1] * a * a;
  };
  Real lo = 1.0, hi = 1.5;
  for (int i = 0; i < 200; ++i) {
    const Real c = 0.5 * (lo + hi);
    (nominal(c) > 0.1 ? hi : lo) = c;
  }
  const Real c = 0.5 * (lo + hi);
  const std::filesystem::path file = kData / "uniaxial_mooney_rivlin_pressure.feb";
  std::string text = read_file(file);
  const std::string from = text.substr(
      text.find("<surface_load"), text.find("</surface_load>") + 15 - text.find("<surface_load"));
  text.replace(text.find(from), from.size(),
               "<surface_load name=\"Pull\" surface=\"Top\" type=\"force\">\n"
               "<scale lc=\"1\">0.2</scale>\n<force>0,0,0.5</force>\n"
               "<shell_bottom>0</shell_bottom>\n</surface_load>");
  const io::CaseSpec spec = feb::parse_feb(text, file);
  ASSERT_EQ(spec.tractions.size(), 1u);
  EXPECT_TRUE(spec.tractions[0].total_force);
  EXPECT_FALSE(spec.tractions[0].per_current_area);
  EXPECT_DOUBLE_EQ(spec.tractions[0].value.z(), 0.1); // scale x force [N]
  const FebRun r = run(spec);
  ASSERT_TRUE(r.report.success) << r.report.failure;
  EXPECT_NEAR(displacement(*r.model, 6, 2), c - 1.0, 1e-8);
  EXPECT_GT(c, 1.05);
}

TEST(FebVerification, OgdenTwoSteps) {
  const auto law = ogden({{0.4, 4.0}, {0.2, -2.0}}, 30.0);
  std::map<long, Real> force;
  const FebRun r = run(
      analysis::read_case_file(kData / "ogden_two_steps.feb"),
      [&](const model::Model& m, Real t) { force[std::lround(t * 100)] = reaction(m, "top", 2); });
  ASSERT_TRUE(r.report.success);
  for (const auto& [t, c] : {std::pair{100L, 1.3}, {200L, 1.1}, {150L, 1.2}}) {
    const Real a = lateral_stretch(law, c);
    EXPECT_NEAR(force.at(t), law(a, c)[1] * a * a, 1e-8) << "t = " << t / 100.0;
  }
}

// The ramp-relaxation problem of FEBio's test suite (bp04), as a .feb file written for trifem:
// a biphasic column of 10 elements, 1 x 1 x 1, confined
// laterally, impermeable except at the top (FEBio's natural condition, here written out as
// impermeable surfaces), compressed 0.1 in 100 s and held to 1000 s. Reference: the linear
// ramp-relaxation series of Mow et al. (1980) (exact_solutions.hpp), H_A = 1, kappa = 1e-3,
// tau = h^2/(H_A kappa) = 1000 s; at 10 % strain the neo-Hookean solid is nonlinear, so the
// equilibrium is compared with its exact finite-strain value and the history with the series at
// a 1000 times smaller strain (the same file with the load curve scaled).

namespace {

/// The top reaction history of the column with the load curve's end value replaced by `end`.
std::map<long, Real> ramp_history(const std::string& end) {
  std::string text = read_file(kData / "confined_biphasic_ramp.feb");
  const std::string point = "<pt>100,-0.1</pt>";
  text.replace(text.find(point), point.size(), "<pt>100," + end + "</pt>");
  std::map<long, Real> history; // t [s] -> top reaction [N]
  const FebRun r = run(
      feb::parse_feb(text, kData / "confined_biphasic_ramp.feb"),
      [&](const model::Model& m, Real t) { history[std::lround(t * 10)] = reaction(m, "Top", 2); });
  EXPECT_TRUE(r.report.success);
  return history;
}

const exact::ConfinedLayer kColumn{1.0, 1.0, 1e-3};

} // namespace

TEST(FebVerification, ConfinedRampEquilibriumAtFiniteStrain) {
  const std::map<long, Real> h = ramp_history("-0.1");
  ASSERT_EQ(h.size(), 400u);
  // Neo-Hookean, nu = 0 (lambda = 0, mu = 0.5), confined stretch 0.9: sigma = mu (l - 1/l).
  const Real equilibrium = 0.5 * (0.9 - 1.0 / 0.9);
  // What remains of the relaxation at t = 1000 s in linear theory (relative).
  const Real remaining = exact::ramp_relaxation_stress(kColumn, 0.1, 100.0, 1000.0) / -0.1 - 1.0;
  EXPECT_NEAR(h.at(10000), equilibrium * (1.0 + remaining), 2e-3 * std::abs(equilibrium));
  const Real peak = h.at(1000);
  const Real linear_peak = exact::ramp_relaxation_stress(kColumn, 0.1, 100.0, 100.0);
  EXPECT_LT(peak, 0.0);
  EXPECT_NEAR(peak / linear_peak, 1.0, 0.15); // finite strain: a moderately larger peak
  std::cout << "[ ramp     ] peak " << peak << " (linear theory " << linear_peak
            << "), t = 1000 s: " << h.at(10000) << " (equilibrium " << equilibrium << ")\n";
}

TEST(FebVerification, ConfinedRampSmallStrainMatchesTheSeries) {
  const Real eps = 1e-4;
  const std::map<long, Real> h = ramp_history("-0.0001");
  const Real peak = exact::ramp_relaxation_stress(kColumn, eps, 100.0, 100.0);
  Real worst = 0.0;
  for (const auto& [t10, f] : h) {
    const Real t = t10 / 10.0;
    const Real reference = exact::ramp_relaxation_stress(kColumn, eps, 100.0, t);
    worst = std::max(worst, std::abs(f - reference) / std::abs(peak));
  }
  std::cout << "[ ramp     ] small strain: largest difference " << worst << " of the peak " << peak
            << "\n";
  EXPECT_LT(worst, 0.03);
}

// A triphasic column (FEBio's multiphasic module: Na and Cl solutes, FEBio units with amounts in
// nmol, effective fluid pressure and concentrations prescribed at the top, initial conditions)
// swells as its fixed charge rises to -200 mM, then is compressed 0.1 from the swollen state.
// Both equilibria are homogeneous: the swollen stretch and the final top reaction match the
// closed forms of the Donnan swelling equilibrium (neo-Hookean, nu = 0, confined).
TEST(FebVerification, TriphasicColumnSwellsThenCompressesToTheDonnanEquilibria) {
  const Real T = 293.0, E = 0.3;
  const exact::ChargedMedium medium{2e-4, 0.2, 1.5e-4, 8.314 * T, 96.485};
  const exact::SwellingState swollen = exact::swelling_equilibrium(
      exact::SolidLaw::NeoHookean, exact::Deformation::Confined, E, 0.0, medium);
  const Real compressed = swollen.stretch - 0.1;
  const exact::ColumnEquilibrium loaded =
      exact::confined_column_equilibrium(compressed, E, 0.0, medium, exact::SolidLaw::NeoHookean);
  std::map<long, std::pair<Real, Real>> state; // time [s] -> (top uz, top reaction)
  const FebRun r = run(analysis::read_case_file(kData / "triphasic_swelling_column.feb"),
                       [&](const model::Model& m, Real t) {
                         state[std::lround(t)] = {displacement(m, 40, 2), reaction(m, "Top", 2)};
                       });
  ASSERT_TRUE(r.report.success) << r.report.failure;
  EXPECT_NEAR(r.spec.electrochemistry.bath_concentration, 1.5e-4, 1e-18);
  EXPECT_NEAR(r.spec.materials.at("Cartilage").parameters.at("fixed_charge"), 1e-6, 1e-20);
  ASSERT_TRUE(state.contains(100000) && state.contains(200000));
  // the swelling stretch (about 1.3) to 1e-7 of the swelling; the column is 1 mm high
  EXPECT_NEAR(state.at(100000).first, swollen.stretch - 1.0, 1e-7 * (swollen.stretch - 1.0));
  EXPECT_NEAR(state.at(100000).second, 0.0, 1e-9); // the top is free while it swells
  EXPECT_NEAR(state.at(200000).first, compressed - 1.0, 1e-12);
  // total stress sigma_zz = sigma_e - Pi on the unit area, to 1e-6 of the osmotic pressure
  EXPECT_NEAR(state.at(200000).second, loaded.total_stress, 1e-6 * loaded.donnan.pressure);
}

// The same column with FEBio's tr01 protocol: the swelling is a STEADY-STATE step of 10 steps
// over 1 s (the fixed charge ramped 0 -> -200 mM over it), the compression a TRANSIENT step
// from t = 1 s. At t = 1 s the column is at the closed-form swelling equilibrium.
TEST(FebVerification, SteadyStateSwellingStepReachesTheDonnanEquilibrium) {
  const Real E = 0.3;
  const exact::ChargedMedium medium{2e-4, 0.2, 1.5e-4, 8.314 * 293.0, 96.485};
  const exact::SwellingState swollen = exact::swelling_equilibrium(
      exact::SolidLaw::NeoHookean, exact::Deformation::Confined, E, 0.0, medium);
  std::string text = read_file(kData / "triphasic_swelling_column.feb");
  const auto replace = [&](const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
  };
  replace("<analysis>TRANSIENT</analysis>\n        <time_steps>100000</time_steps>\n        "
          "<step_size>1</step_size>",
          "<analysis>STEADY-STATE</analysis>\n        <time_steps>10</time_steps>\n        "
          "<step_size>0.1</step_size>");
  replace("<pt>1000,-200</pt>", "<pt>1,-200</pt>");
  replace("<pt>100000,0</pt>\n        <pt>100100,-0.1</pt>",
          "<pt>1,0</pt>\n        <pt>101,-0.1</pt>");
  std::map<Real, Real> top; // time [s] -> top uz
  const FebRun r = run(feb::parse_feb(text, kData / "steady.feb"),
                       [&](const model::Model& m, Real t) { top[t] = displacement(m, 40, 2); });
  ASSERT_TRUE(r.report.success) << r.report.failure;
  ASSERT_TRUE(r.spec.steps.at(0).steady);
  EXPECT_FALSE(r.spec.steps.at(1).steady);
  ASSERT_TRUE(top.contains(1.0));
  EXPECT_NEAR(top.at(1.0), swollen.stretch - 1.0, 1e-9 * swollen.stretch);
  // every step of the ramp ends at the equilibrium of its charge, 2e-4 t mmol/mm^3
  int ramp_steps = 0;
  for (const auto& [t, uz] : top) {
    if (t >= 1.0)
      continue;
    const exact::ChargedMedium partial{2e-4 * t, 0.2, 1.5e-4, 8.314 * 293.0, 96.485};
    const Real stretch = exact::swelling_equilibrium(exact::SolidLaw::NeoHookean,
                                                     exact::Deformation::Confined, E, 0.0, partial)
                             .stretch;
    EXPECT_NEAR(uz, stretch - 1.0, 1e-9 * stretch) << "t = " << t << " s";
    ++ramp_steps;
  }
  EXPECT_GE(ramp_steps, 3);
}

namespace {

/// A clamped neo-Hookean hex under a hex of a "rigid body" material (sharing its top nodes)
/// turned by 0.3 rad about z (rigid_rotation Rw); its center of mass held (rigid_fixed).
const char* kRigidLid = R"(<?xml version="1.0"?>
<febio_spec version="4.0">
  <Module type="solid"/>
  <Control><analysis>STATIC</analysis><time_steps>2</time_steps><step_size>0.5</step_size></Control>
  <Material>
    <material id="1" name="tissue" type="neo-Hookean"><E>1</E><v>0.3</v></material>
    <material id="2" name="bone" type="rigid body"><density>1</density></material>
  </Material>
  <Mesh>
    <Nodes name="all">
      <node id="1">0,0,0</node><node id="2">1,0,0</node><node id="3">1,1,0</node><node id="4">0,1,0</node>
      <node id="5">0,0,1</node><node id="6">1,0,1</node><node id="7">1,1,1</node><node id="8">0,1,1</node>
      <node id="9">0,0,1.5</node><node id="10">1,0,1.5</node><node id="11">1,1,1.5</node><node id="12">0,1,1.5</node>
    </Nodes>
    <Elements type="hex8" name="Soft"><elem id="1">1,2,3,4,5,6,7,8</elem></Elements>
    <Elements type="hex8" name="Bone"><elem id="2">5,6,7,8,9,10,11,12</elem></Elements>
    <NodeSet name="bottom">1, 2, 3, 4</NodeSet>
  </Mesh>
  <MeshDomains><SolidDomain name="Soft" mat="tissue"/><SolidDomain name="Bone" mat="bone"/></MeshDomains>
  <Boundary>
    <bc name="fix" node_set="bottom" type="zero displacement"><x_dof>1</x_dof><y_dof>1</y_dof><z_dof>1</z_dof></bc>
  </Boundary>
  <Rigid>
    <rigid_bc type="rigid_fixed"><rb>bone</rb><Rx_dof>1</Rx_dof><Ry_dof>1</Ry_dof><Rz_dof>1</Rz_dof><Ru_dof>1</Ru_dof><Rv_dof>1</Rv_dof></rigid_bc>
    <rigid_bc type="rigid_rotation"><rb>bone</rb><dof>Rw</dof><value lc="1">0.3</value><relative>0</relative></rigid_bc>
  </Rigid>
  <LoadData>
    <load_controller id="1" type="loadcurve"><interpolate>LINEAR</interpolate>
      <points><pt>0,0</pt><pt>1,1</pt></points></load_controller>
  </LoadData>
</febio_spec>
)";

} // namespace

TEST(FebRigid, ABodyOfElementsTurnsRigidlyAboutItsCenterOfMassAndTheBaseHoldsItsMoment) {
  FebRun run = test::run_feb_case(feb::parse_feb(kRigidLid, "rigid_lid.feb"));
  ASSERT_TRUE(run.report.success) << run.report.failure;
  const model::Model& m = *run.model;
  ASSERT_EQ(m.rigid_bodies.size(), 1u);
  const dofs::RigidBodyDofs& body = m.problem->rigid_map().bodies().at(0);
  EXPECT_LT((body.centre - Vec3(0.5, 0.5, 1.25)).norm(), 1e-15); // the element's centroid
  const Vector& x = m.problem->state();
  const auto position = [&](Index n) {
    Vec3 p = m.mesh.node(n);
    for (int k = 0; k < 3; ++k)
      p[k] += x[m.dofs.dof(m.fields.u, n, k)];
    return p;
  };
  const Real c = std::cos(0.3), s = std::sin(0.3);
  Mat3 R;
  R << c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0;
  Real error = 0.0;
  for (Index n = 4; n < 12; ++n) // the rigid element's nodes (ids 5-12)
    error =
        std::max(error, (position(n) - (body.centre + R * (m.mesh.node(n) - body.centre))).norm());
  EXPECT_LT(error, 1e-14);
  // the moment the body applies to the tissue is held by the clamped base
  const Vec3 moment = model::rigid_body_moment(m, m.rigid_bodies[0]);
  const Vector& r = m.problem->full_residual();
  Real base = 0.0;
  for (Index n = 0; n < 4; ++n)
    base += position(n).x() * r[m.dofs.dof(m.fields.u, n, 1)] -
            position(n).y() * r[m.dofs.dof(m.fields.u, n, 0)];
  EXPECT_GT(moment.z(), 0.01);
  EXPECT_NEAR(base, -moment.z(), 1e-10 * moment.z());
}

namespace {

/// A neo-Hookean hex on a frictionless base, pressed 0.1 mm through sliding contact by a rigid
/// plate made only of a quad4 shell (its own nodes on the hex's top, facing down).
const char* kShellPlate = R"(<?xml version="1.0"?>
<febio_spec version="4.0">
  <Module type="solid"/>
  <Control><analysis>STATIC</analysis><time_steps>2</time_steps><step_size>0.5</step_size></Control>
  <Material>
    <material id="1" name="tissue" type="neo-Hookean"><E>1</E><v>0.3</v></material>
    <material id="2" name="plate" type="rigid body"><density>1</density><center_of_mass>0.5,0.5,1</center_of_mass></material>
  </Material>
  <Mesh>
    <Nodes name="all">
      <node id="1">0,0,0</node><node id="2">1,0,0</node><node id="3">1,1,0</node><node id="4">0,1,0</node>
      <node id="5">0,0,1</node><node id="6">1,0,1</node><node id="7">1,1,1</node><node id="8">0,1,1</node>
      <node id="9">-0.5,-0.5,1</node><node id="10">1.5,-0.5,1</node><node id="11">1.5,1.5,1</node><node id="12">-0.5,1.5,1</node>
    </Nodes>
    <Elements type="hex8" name="Soft"><elem id="1">1,2,3,4,5,6,7,8</elem></Elements>
    <Elements type="quad4" name="Plate"><elem id="2">9,12,11,10</elem></Elements>
    <NodeSet name="bottom">1, 2, 3, 4</NodeSet>
    <NodeSet name="corner">1</NodeSet>
    <NodeSet name="edge">2</NodeSet>
    <Surface name="top"><quad4 id="1">5,6,7,8</quad4></Surface>
    <Surface name="plate_face"><quad4 id="1">9,12,11,10</quad4></Surface>
    <SurfacePair name="press"><primary>top</primary><secondary>plate_face</secondary></SurfacePair>
  </Mesh>
  <MeshDomains><SolidDomain name="Soft" mat="tissue"/><ShellDomain name="Plate" mat="plate"><shell_thickness>0.01</shell_thickness></ShellDomain></MeshDomains>
  <Boundary>
    <bc name="base" node_set="bottom" type="zero displacement"><x_dof>0</x_dof><y_dof>0</y_dof><z_dof>1</z_dof></bc>
    <bc name="corner" node_set="corner" type="zero displacement"><x_dof>1</x_dof><y_dof>1</y_dof><z_dof>0</z_dof></bc>
    <bc name="edge" node_set="edge" type="zero displacement"><x_dof>0</x_dof><y_dof>1</y_dof><z_dof>0</z_dof></bc>
  </Boundary>
  <Rigid>
    <rigid_bc type="rigid_fixed"><rb>plate</rb><Rx_dof>1</Rx_dof><Ry_dof>1</Ry_dof><Ru_dof>1</Ru_dof><Rv_dof>1</Rv_dof><Rw_dof>1</Rw_dof></rigid_bc>
    <rigid_bc type="rigid_displacement"><rb>plate</rb><dof>z</dof><value lc="1">-0.1</value><relative>0</relative></rigid_bc>
  </Rigid>
  <Contact>
    <contact type="sliding-elastic" name="press" surface_pair="press"><laugon>0</laugon><fric_coeff>0</fric_coeff></contact>
  </Contact>
  <LoadData>
    <load_controller id="1" type="loadcurve"><interpolate>LINEAR</interpolate>
      <points><pt>0,0</pt><pt>1,1</pt></points></load_controller>
  </LoadData>
</febio_spec>
)";

} // namespace

class FebRigidShell : public testing::TestWithParam<bool> {};

TEST_P(FebRigidShell, ARigidPlateMadeOfAShellPressesTheTopOfAHexByItsDisplacement) {
  std::string text = kShellPlate;
  if (GetParam()) { // the plate as two triangles
    for (
        const auto& [quad, triangles] :
        {std::pair<std::string, std::string>{
             R"(<Elements type="quad4" name="Plate"><elem id="2">9,12,11,10</elem></Elements>)",
             R"(<Elements type="tri3" name="Plate"><elem id="2">9,12,11</elem><elem id="3">9,11,10</elem></Elements>)"},
         {R"(<Surface name="plate_face"><quad4 id="1">9,12,11,10</quad4></Surface>)",
          R"(<Surface name="plate_face"><tri3 id="1">9,12,11</tri3><tri3 id="2">9,11,10</tri3></Surface>)"}}) {
      ASSERT_NE(text.find(quad), std::string::npos) << quad;
      text.replace(text.find(quad), quad.size(), triangles);
    }
  }
  FebRun run = test::run_feb_case(feb::parse_feb(text, "shell_plate.feb"));
  ASSERT_TRUE(run.report.success) << run.report.failure;
  const model::Model& m = *run.model;
  ASSERT_EQ(m.rigid_bodies.size(), 1u);
  EXPECT_GE(m.rigid_bodies[0].rotating, 0); // a shell body rotates (its rotations held here)
  EXPECT_FALSE(m.mesh.surface("Plate").facets[0].bounds_cell());
  const Vector& x = m.problem->state();
  for (Index n = 4; n < 8; ++n) // the hex's top follows the plate
    EXPECT_NEAR(x[m.dofs.dof(m.fields.u, n, 2)], -0.1, 1e-12) << "node " << n;
  for (Index n = 8; n < 12; ++n) // the plate translated rigidly
    EXPECT_NEAR(x[m.dofs.dof(m.fields.u, n, 2)], -0.1, 1e-15) << "node " << n;
}

// A file with one <step> holding the <Rigid> and <Contact> sections runs as the same file with
// them at the top level (FEBio applies a step's conditions during the step, here the whole run).
TEST(FebRigid, TheSectionsOfTheOnlyStepActOverTheWholeRun) {
  std::string text = kShellPlate;
  const auto cut = [&](const std::string& open, const std::string& close) {
    const auto from = text.find(open);
    const auto to = text.find(close, from) + close.size();
    std::string part = text.substr(from, to - from);
    text.erase(from, to - from);
    return part;
  };
  const std::string rigid = cut("  <Rigid>", "</Rigid>\n");
  const std::string contact = cut("  <Contact>", "</Contact>\n");
  text.insert(text.find("  <LoadData>"),
              "  <Step><step id=\"1\" name=\"press\">\n" + rigid + contact + "  </step></Step>\n");
  const auto top_z = [](const std::string& feb) {
    FebRun run = test::run_feb_case(feb::parse_feb(feb, "shell_plate.feb"));
    EXPECT_TRUE(run.report.success) << run.report.failure;
    const model::Model& m = *run.model;
    return m.problem->state()[m.dofs.dof(m.fields.u, 4, 2)];
  };
  const Real in_step = top_z(text);
  EXPECT_NEAR(in_step, -0.1, 1e-12);
  EXPECT_EQ(in_step, top_z(kShellPlate));
}

INSTANTIATE_TEST_SUITE_P(Facets, FebRigidShell, testing::Values(false, true),
                         [](const auto& info) { return info.param ? "Triangles" : "Quads"; });

namespace {

/// A plate of two quad4 shells (area 8, centroid (1.5, 0.5, 1)) forming a rigid body of
/// density 2, held fixed under gravity along z. `domain` is its <ShellDomain> element,
/// `mesh_data` the content of a <MeshData> section (none if empty).
std::string held_plate(const std::string& domain, const std::string& mesh_data = "") {
  const std::string data =
      mesh_data.empty() ? std::string() : "\n  <MeshData>" + mesh_data + "</MeshData>";
  return R"(<?xml version="1.0"?>
<febio_spec version="4.0">
  <Module type="solid"/>
  <Control><analysis>STATIC</analysis><time_steps>1</time_steps><step_size>1</step_size></Control>
  <Material>
    <material id="1" name="plate" type="rigid body"><density>2</density></material>
  </Material>
  <Mesh>
    <Nodes name="all">
      <node id="1">-0.5,-0.5,1</node><node id="2">1.5,-0.5,1</node><node id="3">1.5,1.5,1</node><node id="4">-0.5,1.5,1</node>
      <node id="5">3.5,-0.5,1</node><node id="6">3.5,1.5,1</node>
    </Nodes>
    <Elements type="quad4" name="Plate"><elem id="1">1,2,3,4</elem><elem id="2">2,5,6,3</elem></Elements>
  </Mesh>
  <MeshDomains>)" +
         domain + "</MeshDomains>" + data + R"(
  <Rigid>
    <rigid_bc type="rigid_fixed"><rb>plate</rb><Rx_dof>1</Rx_dof><Ry_dof>1</Ry_dof><Rz_dof>1</Rz_dof><Ru_dof>1</Ru_dof><Rv_dof>1</Rv_dof><Rw_dof>1</Rw_dof></rigid_bc>
  </Rigid>
  <Loads><body_load type="const"><z>9.81</z></body_load></Loads>
</febio_spec>
)";
}

/// A plate whose shell thickness comes from a <MeshData> section of content `data`.
std::string plate_with_mesh_data(const std::string& data) {
  return held_plate(R"(<ShellDomain name="Plate" mat="plate"/>)", data);
}

} // namespace

// A model of the rigid plate alone, held, under gravity (FEBio's body force b = 9.81 along z
// is the load −ρ b): its shells of thickness 0.01 and density 2 weigh W = ρ t A g, which the
// hold carries at the centroid of the plate (no moment). The body's force in history.csv is the
// residual at its unknowns, R = f_int − f_ext = +W along z.
TEST(FebRigidShell, AHeldShellBodyCarriesTheWeightOfItsShells) {
  const std::string text = held_plate(
      R"(<ShellDomain name="Plate" mat="plate"><shell_thickness>0.01</shell_thickness></ShellDomain>)");
  FebRun run = test::run_feb_case(feb::parse_feb(text, "shell_weight.feb"));
  ASSERT_TRUE(run.report.success) << run.report.failure;
  ASSERT_EQ(run.spec.rigid_bodies.size(), 1u);
  EXPECT_EQ(run.spec.rigid_bodies[0].shell_thickness, 0.01);
  EXPECT_EQ(run.spec.rigid_bodies[0].density, 2.0);
  const model::Model& m = *run.model;
  const model::RigidBody& b = m.rigid_bodies.at(0);
  EXPECT_LE((m.problem->rigid_map().bodies()[b.rotating].centre - Vec3(1.5, 0.5, 1)).norm(),
            1e-15); // the centroid of the shells
  const Real weight = 2.0 * 0.01 * 8.0 * 9.81;
  const Vec3 force = model::rigid_body_force(m, b, 1.0), moment = model::rigid_body_moment(m, b);
  EXPECT_LE((force - Vec3(0, 0, weight)).norm(), 1e-12 * weight) << force.transpose();
  EXPECT_LE(moment.norm(), 1e-12 * weight) << moment.transpose();
}

// FEBio Studio writes the thickness of shells as element data (<MeshData>): the plate then
// weighs what it weighs with the thickness on its domain.
TEST(FebRigidShell, AShellThicknessFromMeshDataGivesTheBodyItsWeight) {
  const std::string text = plate_with_mesh_data(
      R"(<ElementData type="shell thickness" elem_set="Plate"><e lid="1">0.01,0.01,0.01,0.01</e><e lid="2">0.01,0.01,0.01,0.01</e></ElementData>)");
  FebRun run = test::run_feb_case(feb::parse_feb(text, "shell_weight.feb"));
  ASSERT_TRUE(run.report.success) << run.report.failure;
  ASSERT_EQ(run.spec.rigid_bodies.size(), 1u);
  EXPECT_EQ(run.spec.rigid_bodies[0].shell_thickness, 0.01);
  const model::Model& m = *run.model;
  const Real weight = 2.0 * 0.01 * 8.0 * 9.81;
  const Vec3 force = model::rigid_body_force(m, m.rigid_bodies.at(0), 1.0);
  EXPECT_LE((force - Vec3(0, 0, weight)).norm(), 1e-12 * weight) << force.transpose();
}

TEST(FebRigidShell, MeshDataTrifemCannotUseIsRefusedNamingIt) {
  const std::pair<std::string, std::string> cases[] = {
      {R"(<ElementData type="shell thickness" elem_set="Plate"><e lid="1">0.01,0.01,0.01,0.01</e><e lid="2">0.02,0.02,0.02,0.02</e></ElementData>)",
       "varies from 0.01 to 0.02"},
      {R"(<ElementData type="shell thickness" elem_set="Plate"><e lid="1">-1,-1,-1,-1</e></ElementData>)",
       "must not be negative"},
      {R"(<ElementData type="shell thickness" elem_set="Other"><e lid="1">1,1,1,1</e></ElementData>)",
       "no quad4 or tri3 part is named 'Other'"},
      {R"(<ElementData type="mat_axis" elem_set="Plate"><e lid="1"><a>1,0,0</a><d>0,1,0</d></e></ElementData>)",
       "element data of type 'mat_axis' is not supported"},
      {R"(<SurfaceData name="inlet" data_type="scalar" surface="Plate"><face lid="1">1</face></SurfaceData>)",
       "<SurfaceData> is not supported"}};
  for (const auto& [data, message] : cases) {
    try {
      (void)feb::parse_feb(plate_with_mesh_data(data), "shell_data.feb");
      ADD_FAILURE() << "accepted: " << data;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("shell_data.feb:"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  }
}

// FEBio ignores the fixed and prescribed displacements of the nodes a rigid body carries: the
// lid with every node's z also "fixed" turns as it did.
TEST(FebRigid, ConditionsOnTheNodesOfARigidBodyAreIgnoredAsFebioDoes) {
  std::string text = kRigidLid;
  const std::string set = R"(<NodeSet name="bottom">1, 2, 3, 4</NodeSet>)";
  const std::string bc = R"(<bc name="fix" node_set="bottom")";
  ASSERT_NE(text.find(set), std::string::npos);
  ASSERT_NE(text.find(bc), std::string::npos);
  text.replace(text.find(set), set.size(),
               set + R"(<NodeSet name="every">1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12</NodeSet>)");
  text.replace(
      text.find(bc), bc.size(),
      R"(<bc name="every_z" node_set="every" type="zero displacement"><x_dof>0</x_dof><y_dof>0</y_dof><z_dof>1</z_dof></bc>)" +
          bc);
  FebRun plain = test::run_feb_case(feb::parse_feb(kRigidLid, "rigid_lid.feb"));
  FebRun fixed = test::run_feb_case(feb::parse_feb(text, "rigid_lid_fixed.feb"));
  ASSERT_TRUE(plain.report.success) << plain.report.failure;
  ASSERT_TRUE(fixed.report.success) << fixed.report.failure;
  const Vector& a = plain.model->problem->state();
  const Vector& b = fixed.model->problem->state();
  ASSERT_EQ(a.size(), b.size());
  EXPECT_GT(a.lpNorm<Eigen::Infinity>(), 0.1); // the lid turned
  EXPECT_LT((a - b).lpNorm<Eigen::Infinity>(), 1e-14);
}

// A body attached by two node sets (bc type "rigid" twice) carries the union of them.
TEST(FebRigid, ABodyAttachedByTwoNodeSetsCarriesBoth) {
  const char* text = R"(<?xml version="1.0"?>
<febio_spec version="4.0">
  <Module type="solid"/>
  <Control><analysis>STATIC</analysis><time_steps>2</time_steps><step_size>0.5</step_size></Control>
  <Material>
    <material id="1" name="tissue" type="neo-Hookean"><E>1</E><v>0.3</v></material>
    <material id="2" name="plate" type="rigid body"><density>1</density></material>
  </Material>
  <Mesh>
    <Nodes name="all">
      <node id="1">0,0,0</node><node id="2">1,0,0</node><node id="3">1,1,0</node><node id="4">0,1,0</node>
      <node id="5">0,0,1</node><node id="6">1,0,1</node><node id="7">1,1,1</node><node id="8">0,1,1</node>
    </Nodes>
    <Elements type="hex8" name="Soft"><elem id="1">1,2,3,4,5,6,7,8</elem></Elements>
    <NodeSet name="bottom">1, 2, 3, 4</NodeSet>
    <NodeSet name="front">5, 6</NodeSet>
    <NodeSet name="back">7, 8</NodeSet>
  </Mesh>
  <MeshDomains><SolidDomain name="Soft" mat="tissue"/></MeshDomains>
  <Boundary>
    <bc name="fix" node_set="bottom" type="zero displacement"><x_dof>1</x_dof><y_dof>1</y_dof><z_dof>1</z_dof></bc>
    <bc name="a" node_set="front" type="rigid"><rb>plate</rb></bc>
    <bc name="b" node_set="back" type="rigid"><rb>plate</rb></bc>
  </Boundary>
  <Rigid>
    <rigid_bc type="rigid_fixed"><rb>plate</rb><Rx_dof>1</Rx_dof><Ry_dof>1</Ry_dof><Ru_dof>1</Ru_dof><Rv_dof>1</Rv_dof><Rw_dof>1</Rw_dof></rigid_bc>
    <rigid_bc type="rigid_displacement"><rb>plate</rb><dof>z</dof><value lc="1">0.2</value><relative>0</relative></rigid_bc>
  </Rigid>
  <LoadData>
    <load_controller id="1" type="loadcurve"><interpolate>LINEAR</interpolate>
      <points><pt>0,0</pt><pt>1,1</pt></points></load_controller>
  </LoadData>
</febio_spec>
)";
  FebRun run = test::run_feb_case(feb::parse_feb(text, "two_sets.feb"));
  ASSERT_TRUE(run.report.success) << run.report.failure;
  const model::Model& m = *run.model;
  const Vector& x = m.problem->state();
  for (Index n = 4; n < 8; ++n)
    EXPECT_NEAR(x[m.dofs.dof(m.fields.u, n, 2)], 0.2, 1e-14) << "node " << n;
}

// A boundary condition on "@elem_set:<part>" acts on the nodes of the part's elements.
TEST(FebRigid, AnElementSetReferenceNamesTheNodesOfItsElements) {
  std::string text = kShellPlate;
  const std::string base = R"(<bc name="base" node_set="bottom")";
  ASSERT_NE(text.find(base), std::string::npos);
  text.replace(text.find(base), base.size(), R"(<bc name="base" node_set="@elem_set:Soft")");
  const io::CaseSpec spec = feb::parse_feb(text, "elem_set.feb");
  const mesh::Mesh& mesh = spec.meshes.at(0).mesh;
  ASSERT_TRUE(std::any_of(spec.fixed.begin(), spec.fixed.end(),
                          [](const io::FixedSpec& f) { return f.set == "Soft"; }));
  EXPECT_EQ(mesh.node_set("Soft"), (std::vector<Index>{0, 1, 2, 3, 4, 5, 6, 7}));
  std::string missing = text;
  missing.replace(missing.find("@elem_set:Soft"), 14, "@elem_set:Hard");
  try {
    feb::parse_feb(missing, "elem_set.feb");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("element set 'Hard' is not defined"), std::string::npos)
        << e.what();
  }
}

TEST(FebRigid, AHingeToAGroundBodyTurnsTheBodyAsItsPrescribedRotationDid) {
  // the same lid turned by a rigid revolute joint about z through its center of mass, to a
  // "Ground" body of no elements held in all six components; the joint carries the moment
  std::string text = kRigidLid;
  const auto replace = [&](const std::string& from, const std::string& to) {
    text.replace(text.find(from), from.size(), to);
  };
  replace(R"(<material id="2" name="bone" type="rigid body"><density>1</density></material>)",
          R"(<material id="2" name="bone" type="rigid body"><density>1</density></material>
    <material id="3" name="Ground" type="rigid body"><density>1</density></material>)");
  const std::size_t from = text.find("<Rigid>"), to = text.find("</Rigid>");
  text.replace(from, to - from, R"(<Rigid>
    <rigid_bc type="rigid_fixed"><rb>Ground</rb><Rx_dof>1</Rx_dof><Ry_dof>1</Ry_dof><Rz_dof>1</Rz_dof><Ru_dof>1</Ru_dof><Rv_dof>1</Rv_dof><Rw_dof>1</Rw_dof></rigid_bc>
    <rigid_connector name="hinge" type="rigid revolute joint">
      <body_a>Ground</body_a><body_b>bone</body_b><laugon>1</laugon><tolerance>0</tolerance>
      <gaptol>0.0001</gaptol><angtol>0.0001</angtol><force_penalty>1000</force_penalty>
      <moment_penalty>1000</moment_penalty><force_damping>0</force_damping><moment_damping>0</moment_damping>
      <joint_origin>0.5,0.5,1.25</joint_origin><rotation_axis>0,0,1</rotation_axis>
      <transverse_axis>1,0,0</transverse_axis><minaug>0</minaug><maxaug>10</maxaug>
      <prescribed_rotation>1</prescribed_rotation><rotation lc="1">0.3</rotation><moment>0</moment>
      <auto_penalty>0</auto_penalty>
    </rigid_connector>
  )");
  const io::CaseSpec spec = feb::parse_feb(text, "hinge.feb");
  ASSERT_EQ(spec.connectors.size(), 1u);
  EXPECT_EQ(spec.connectors[0].body_a, "ground"); // a body of nothing, held: space
  EXPECT_EQ(spec.connectors[0].rotation.drive, io::RigidDrive::Displacement);
  FebRun run = test::run_feb_case(spec);
  ASSERT_TRUE(run.report.success) << run.report.failure;
  const model::Model& m = *run.model;
  const FebRun reference = test::run_feb_case(feb::parse_feb(kRigidLid, "rigid_lid.feb"));
  ASSERT_TRUE(reference.report.success) << reference.report.failure;
  const Vector &x = m.problem->state(), &x_ref = reference.model->problem->state();
  for (Index n = 0; n < m.mesh.num_nodes(); ++n)
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(x[m.dofs.dof(m.fields.u, n, k)], x_ref[m.dofs.dof(m.fields.u, n, k)], 1e-12) << n;
  const Vec3 moment = model::rigid_body_moment(m, m.rigid_bodies[0]);
  EXPECT_GT(moment.z(), 0.01);
  EXPECT_LT((m.connectors->committed_wrenches()[0].moment - moment).norm(), 1e-10 * moment.z());
}

// <nodal_load type="nodal_force"> run: the four top nodes of a cube pushed up by 0.1 N each
// (ramped by its load controller to t = 1) hand 0.4 N to the fixed base.
TEST(FebNodalLoad, TheBaseCarriesTheForcesOfTheTopNodes) {
  const std::string text = R"(<?xml version="1.0"?>
<febio_spec version="4.0">
  <Module type="solid"/>
  <Control><analysis>STATIC</analysis><time_steps>2</time_steps><step_size>0.5</step_size></Control>
  <Material>
    <material id="1" name="m" type="neo-Hookean"><E>1</E><v>0.3</v></material>
  </Material>
  <Mesh>
    <Nodes name="all">
      <node id="1">0,0,0</node><node id="2">1,0,0</node><node id="3">1,1,0</node><node id="4">0,1,0</node>
      <node id="5">0,0,1</node><node id="6">1,0,1</node><node id="7">1,1,1</node><node id="8">0,1,1</node>
    </Nodes>
    <Elements type="hex8" name="P"><elem id="1">1,2,3,4,5,6,7,8</elem></Elements>
    <NodeSet name="bottom">1, 2, 3, 4</NodeSet>
    <NodeSet name="top">5, 6, 7, 8</NodeSet>
  </Mesh>
  <MeshDomains><SolidDomain name="P" mat="m"/></MeshDomains>
  <Boundary>
    <bc name="fix" node_set="bottom" type="zero displacement"><x_dof>1</x_dof><y_dof>1</y_dof><z_dof>1</z_dof></bc>
  </Boundary>
  <Loads>
    <nodal_load name="F" node_set="top" type="nodal_force"><relative>0</relative><value lc="1">0,0,0.1</value></nodal_load>
  </Loads>
  <LoadData>
    <load_controller id="1" name="LC1" type="loadcurve"><interpolate>LINEAR</interpolate>
      <points><point>0,0</point><point>1,1</point></points></load_controller>
  </LoadData>
</febio_spec>
)";
  FebRun run = test::run_feb_case(feb::parse_feb(text, "nodal_force.feb"));
  ASSERT_TRUE(run.report.success) << run.report.failure;
  const model::Model& m = *run.model;
  Real base = 0.0, top = 0.0;
  for (Index n : m.mesh.node_set("bottom"))
    base += m.problem->full_residual()[m.dofs.dof(m.fields.u, n, 2)];
  for (Index n : m.mesh.node_set("top"))
    top += m.problem->state()[m.dofs.dof(m.fields.u, n, 2)];
  EXPECT_NEAR(base, -0.4, 1e-12);
  EXPECT_GT(top, 0.0); // pulled up
}

// The laws added for FEBio's test problems, through the two-step uniaxial cube of
// ogden_two_steps.feb with its material replaced: the reactions at 30 % and 10 % stretch and the
// lateral stretches against each law's closed form.

namespace {

/// ogden_two_steps.feb with its material element replaced by `material` (named "Ogden").
io::CaseSpec two_step_cube(const std::string& material) {
  std::string text = read_file(kData / "ogden_two_steps.feb");
  const auto from = text.find("<material id=\"1\"");
  const auto to = text.find("</material>", from) + std::string("</material>").size();
  text.replace(from, to - from, material);
  return feb::parse_feb(text, "two_step_cube.feb");
}

/// Trans iso Mooney-Rivlin (c2 = 0) with its fibre along the pull: the isochoric Kirchhoff
/// stress along it adds the fibre's F(l~) = c3 (exp(c4 (l~ - 1)) - 1) (below lam_max) or
/// c5 l~ + c6 to the Mooney-Rivlin part; across it, Mooney-Rivlin alone.
StressLaw trans_iso_mooney_rivlin(Real c1, Real c3, Real c4, Real c5, Real lam_max, Real k) {
  const Real c6 = c3 * (std::exp(c4 * (lam_max - 1.0)) - 1.0) - c5 * lam_max;
  return [=](Real a, Real c) {
    const Real J = a * a * c, s = std::cbrt(J), la = a / s, lc = c / s;
    const Real fibre = lc <= 1.0      ? 0.0
                       : lc < lam_max ? c3 * (std::exp(c4 * (lc - 1.0)) - 1.0)
                                      : c5 * lc + c6;
    const Real ta = 2.0 * c1 * la * la, tc = 2.0 * c1 * lc * lc + fibre;
    const Real mean = (2.0 * ta + tc) / 3.0;
    return std::array<Real, 2>{(ta - mean + k * std::log(J)) / J,
                               (tc - mean + k * std::log(J)) / J};
  };
}

/// The top reaction after every step of the run of `spec`.
std::vector<Real> top_reactions(const io::CaseSpec& spec) {
  std::vector<Real> out;
  const FebRun r =
      run(spec, [&](const model::Model& m, Real) { out.push_back(reaction(m, "top", 2)); });
  EXPECT_TRUE(r.report.success) << r.report.failure;
  return out;
}

/// The top reactions at t = 1 (stretch 1.3) and t = 2 (1.1) against `law`.
void expect_two_step_reactions(const io::CaseSpec& spec, const StressLaw& law) {
  std::map<long, Real> force;
  const FebRun r = run(spec, [&](const model::Model& m, Real t) {
    force[std::lround(t * 100)] = reaction(m, "top", 2);
  });
  ASSERT_TRUE(r.report.success) << r.report.failure;
  for (const auto& [t, c] : {std::pair{100L, 1.3}, {200L, 1.1}}) {
    const Real a = lateral_stretch(law, c);
    EXPECT_NEAR(force.at(t), law(a, c)[1] * a * a, 1e-8) << "t = " << t / 100.0;
  }
}

} // namespace

// Ogden unconstrained: sigma_i = sum_p c_p/m_p (l_i^m_p - 1)/J + cp (J - 1).
TEST(FebVerification, OgdenUnconstrainedTwoSteps) {
  const io::CaseSpec spec =
      two_step_cube(R"(<material id="1" name="Ogden" type="Ogden unconstrained">
      <density>1</density><cp>1</cp><c1>0.658</c1><c2>0</c2><c3>0</c3><c4>0</c4><c5>0</c5><c6>0</c6>
      <m1>6.83</m1><m2>1</m2><m3>1</m3><m4>1</m4><m5>1</m5><m6>1</m6></material>)");
  EXPECT_EQ(spec.materials.at("Ogden").type, "ogden-unconstrained");
  expect_two_step_reactions(spec, [](Real a, Real c) {
    const Real J = a * a * c, cp = 1.0, c1 = 0.658, m1 = 6.83;
    const auto s = [&](Real l) { return c1 / m1 * (std::pow(l, m1) - 1.0) / J + cp * (J - 1.0); };
    return std::array<Real, 2>{s(a), s(c)};
  });
}

// Yeoh: t~_i = 2 W'(I1~ - 3) l~_i^2 with W' = c1 + 2 c2 x + 3 c3 x^2 (FEBio's ma61 parameters).
TEST(FebVerification, YeohTwoSteps) {
  const io::CaseSpec spec = two_step_cube(R"(<material id="1" name="Ogden" type="Yeoh">
      <k>1000</k><pressure_model>default</pressure_model><c1>0.57382</c1><c2>-0.074744</c2>
      <c3>0.011321</c3><c4>0</c4><c5>0</c5><c6>0</c6></material>)");
  EXPECT_EQ(spec.materials.at("Ogden").type, "yeoh");
  expect_two_step_reactions(spec, uncoupled(
                                      [](Real l, Real I1) {
                                        const Real x = I1 - 3.0;
                                        const Real dW =
                                            0.57382 - 2.0 * 0.074744 * x + 3.0 * 0.011321 * x * x;
                                        return 2.0 * dW * l * l;
                                      },
                                      1000.0));
}

// Orthotropic elastic with its e1 along z (mat_axis a = z, d = x: e2 = x, e3 = y): the uniaxial
// stress S_zz = E1 E_zz with E_zz = (c^2 - 1)/2 gives the nominal stress P_zz = c S_zz, and the
// lateral strains E_xx = -v12 E_zz (along e2), E_yy = -v31 E1/E3 E_zz (along e3).
TEST(FebVerification, OrthotropicElasticAlongItsMaterialAxisTwoSteps) {
  const Real E1 = 2.0, E3 = 3.0, v12 = 0.3, v31 = 0.1;
  const io::CaseSpec spec =
      two_step_cube(R"(<material id="1" name="Ogden" type="orthotropic elastic">
      <E1>2</E1><E2>1</E2><E3>3</E3><G12>3</G12><G23>2</G23><G31>1</G31>
      <v12>0.3</v12><v23>0.2</v23><v31>0.1</v31>
      <mat_axis type="vector"><a>0,0,1</a><d>1,0,0</d></mat_axis></material>)");
  const io::MaterialSpec& m = spec.materials.at("Ogden");
  EXPECT_EQ(m.type, "orthotropic-elastic");
  ASSERT_TRUE(m.axes.has_value());
  EXPECT_EQ(m.axes->a, Vec3(0, 0, 1));
  EXPECT_EQ(m.axes->d, Vec3(1, 0, 0));
  std::map<long, std::array<Real, 3>> state; // force, u_x and u_y of node (1, 1, 1)
  const FebRun r = run(spec, [&](const model::Model& model, Real t) {
    state[std::lround(t * 100)] = {reaction(model, "top", 2), displacement(model, 6, 0),
                                   displacement(model, 6, 1)};
  });
  ASSERT_TRUE(r.report.success) << r.report.failure;
  for (const auto& [t, c] : {std::pair{100L, 1.3}, {200L, 1.1}}) {
    const Real Ezz = 0.5 * (c * c - 1.0);
    const Real ax = std::sqrt(1.0 - 2.0 * v12 * Ezz),
               ay = std::sqrt(1.0 - 2.0 * v31 * E1 / E3 * Ezz);
    const auto& [force, ux, uy] = state.at(t);
    EXPECT_NEAR(force, c * E1 * Ezz, 1e-8) << "t = " << t / 100.0;
    EXPECT_NEAR(ux, ax - 1.0, 1e-8) << "t = " << t / 100.0;
    EXPECT_NEAR(uy, ay - 1.0, 1e-8) << "t = " << t / 100.0;
  }
}

TEST(FebVerification, AMatAxisOtherThanAVectorIsRefusedNamingIt) {
  try {
    (void)two_step_cube(R"(<material id="1" name="Ogden" type="orthotropic elastic">
      <E1>2</E1><E2>1</E2><E3>3</E3><G12>3</G12><G23>2</G23><G31>1</G31>
      <v12>0.3</v12><v23>0.2</v23><v31>0.1</v31>
      <mat_axis type="local">0,0,0</mat_axis></material>)");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("two_step_cube.feb:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("mat_axis of type 'local' is not supported"),
              std::string::npos)
        << e.what();
  }
}

// Veronda-Westmann: t~_i = 2 l~_i^2 [W1 + W2 (I1~ - l~_i^2)], W1 = c1 c2 exp(c2 (I1~ - 3)),
// W2 = -c1 c2 / 2.
TEST(FebVerification, VerondaWestmannTwoSteps) {
  const Real c1 = 0.2, c2 = 1.5;
  const io::CaseSpec spec = two_step_cube(R"(<material id="1" name="Ogden" type="Veronda-Westmann">
      <c1>0.2</c1><c2>1.5</c2><k>20</k></material>)");
  EXPECT_EQ(spec.materials.at("Ogden").type, "veronda-westmann");
  expect_two_step_reactions(spec, uncoupled(
                                      [=](Real l, Real I1) {
                                        const Real W1 = c1 * c2 * std::exp(c2 * (I1 - 3.0));
                                        const Real W2 = -0.5 * c1 * c2;
                                        return 2.0 * l * l * (W1 + W2 * (I1 - l * l));
                                      },
                                      20.0));
}

// Arruda-Boyce as FEBio writes it, W = mu sum_i a_i (I1~^i - 3^i)/N^(i-1) with a = (1/2, 1/10,
// 11/350, 19/1750, 519/134750): t~_i = 2 l~_i^2 W1, W1 = mu sum_i i a_i (I1~/N)^(i-1) (FEBio's
// FEArrudaBoyce stress), through trifem's Yeoh law of the expanded polynomial.
TEST(FebVerification, ArrudaBoyceTwoSteps) {
  const Real mu = 1.0, N = 2.5;
  const io::CaseSpec spec = two_step_cube(R"(<material id="1" name="Ogden" type="Arruda-Boyce">
      <density>1</density><k>100</k><pressure_model>default</pressure_model><mu>1</mu><N>2.5</N>
      </material>)");
  EXPECT_EQ(spec.materials.at("Ogden").type, "yeoh");
  expect_two_step_reactions(
      spec, uncoupled(
                [=](Real l, Real I1) {
                  const Real a[] = {0.5, 0.1, 11.0 / 350.0, 19.0 / 1750.0, 519.0 / 134750.0};
                  Real W1 = 0.0;
                  for (int i = 1; i <= 5; ++i)
                    W1 += i * a[i - 1] * std::pow(I1 / N, i - 1);
                  return 2.0 * l * l * mu * W1;
                },
                100.0));
}

// Trans iso Mooney-Rivlin with its fibre along the pull (z): the isochoric Kirchhoff stress
// along z adds the fibre's F(l~) = c3 (exp(c4 (l~ - 1)) - 1) (below lam_max) or c5 l~ + c6 to
// the Mooney-Rivlin part; across it, Mooney-Rivlin alone.
TEST(FebVerification, TransIsoMooneyRivlinAlongItsFibreTwoSteps) {
  const Real c1 = 0.5, c3 = 0.2, c4 = 3.0, c5 = 4.0, lam_max = 1.2, k = 30.0;
  const io::CaseSpec spec =
      two_step_cube(R"(<material id="1" name="Ogden" type="trans iso Mooney-Rivlin">
      <density>1</density><k>30</k><pressure_model>default</pressure_model><c1>0.5</c1><c2>0</c2>
      <c3>0.2</c3><c4>3</c4><c5>4</c5><lam_max>1.2</lam_max>
      <fiber type="vector"><vector>0,0,1</vector></fiber></material>)");
  const io::MaterialSpec& m = spec.materials.at("Ogden");
  EXPECT_EQ(m.type, "solid-mixture");
  ASSERT_EQ(m.constituents.size(), 2u);
  EXPECT_EQ(m.constituents[1].type, "fibre-exp-linear");
  expect_two_step_reactions(spec, trans_iso_mooney_rivlin(c1, c3, c4, c5, lam_max, k));
}

// FEBio's uncoupled solid mixture of Mooney-Rivlin and an uncoupled fiber-exp-linear is trans
// iso Mooney-Rivlin (the test above), its bulk modulus the sum of the mixture's k (20) and its
// constituents' (10; FEBio sums them).
TEST(FebVerification, UncoupledSolidMixtureIsTransIsoMooneyRivlinWithTheSummedBulkModulus) {
  const Real c1 = 0.5, c3 = 0.2, c4 = 3.0, c5 = 4.0, lam_max = 1.2, k = 30.0;
  const io::CaseSpec spec =
      two_step_cube(R"(<material id="1" name="Ogden" type="uncoupled solid mixture">
      <density>1</density><k>20</k><pressure_model>default</pressure_model>
      <solid type="Mooney-Rivlin"><density>1</density><k>10</k><c1>0.5</c1><c2>0</c2></solid>
      <solid type="uncoupled fiber-exp-linear"><k>0</k><c3>0.2</c3><c4>3</c4><c5>4</c5>
        <lambda>1.2</lambda><fiber type="vector"><vector>0,0,1</vector></fiber></solid>
      </material>)");
  const io::MaterialSpec& m = spec.materials.at("Ogden");
  EXPECT_EQ(m.type, "solid-mixture");
  ASSERT_EQ(m.constituents.size(), 2u);
  EXPECT_EQ(m.constituents[0].parameters.at("k"), k);
  EXPECT_EQ(m.constituents[1].type, "fibre-exp-linear");
  expect_two_step_reactions(spec, trans_iso_mooney_rivlin(c1, c3, c4, c5, lam_max, k));
}

// FEBio's solid mixture of neo-Hookean and the coupled fiber-exp-linear, its fibre given by
// angles (theta = 0, phi = 0: along z, the pull): sigma_i = mu/J (l_i^2 - 1) + lambda ln J / J
// plus, along the fibre, F(c)/J of the whole stretch c, F = c3 (exp(c4 (c - 1)) - 1) below
// lambda and c5 c + c6 above.
TEST(FebVerification, SolidMixtureOfNeoHookeanAndACoupledFibreTwoSteps) {
  const Real E = 1.0, v = 0.3, c3 = 0.02, c4 = 10.0, c5 = 2.0, lam_max = 1.2;
  const io::CaseSpec spec = two_step_cube(R"(<material id="1" name="Ogden" type="solid mixture">
      <density>1</density>
      <solid type="neo-Hookean"><density>1</density><E>1</E><v>0.3</v></solid>
      <solid type="fiber-exp-linear"><density>1</density><c3>0.02</c3><c4>10</c4><c5>2</c5>
        <lambda>1.2</lambda><fiber type="angles"><theta>0</theta><phi>0</phi></fiber></solid>
      </material>)");
  const io::MaterialSpec& m = spec.materials.at("Ogden");
  ASSERT_EQ(m.constituents.size(), 2u);
  EXPECT_EQ(m.constituents[1].type, "fibre-exp-linear-coupled");
  const Real mu = E / (2.0 * (1.0 + v)), lambda = E * v / ((1.0 + v) * (1.0 - 2.0 * v));
  const Real c6 = c3 * (std::exp(c4 * (lam_max - 1.0)) - 1.0) - c5 * lam_max;
  expect_two_step_reactions(spec, [=](Real a, Real c) {
    const Real J = a * a * c;
    const auto neo = [&](Real l) { return (mu * (l * l - 1.0) + lambda * std::log(J)) / J; };
    const Real fibre = c <= 1.0      ? 0.0
                       : c < lam_max ? c3 * (std::exp(c4 * (c - 1.0)) - 1.0)
                                     : c5 * c + c6;
    return std::array<Real, 2>{neo(a), neo(c) + fibre / J};
  });
}

// A fiber-exp-pow constituent with its fibre by angles (theta = phi = 90 degrees: along y);
// its toe stretch and fibre modulus only at FEBio's defaults; nested mixtures refused.
TEST(FebVerification, SolidMixtureFibresByAnglesAndWhatIsRefused) {
  const auto cube = [](const std::string& fibre) {
    return two_step_cube(R"(<material id="1" name="Ogden" type="solid mixture">
      <solid type="neo-Hookean"><E>1</E><v>0.3</v></solid>)" +
                         fibre + "</material>");
  };
  const io::CaseSpec spec = cube(R"(<solid type="fiber-exp-pow"><alpha>1</alpha><beta>2</beta>
      <ksi>5</ksi><mu>0</mu><lam0>1</lam0><fiber type="angles"><theta>90</theta><phi>90</phi>
      </fiber></solid>)");
  const material::LawSpec& fibre = spec.materials.at("Ogden").constituents.at(1);
  EXPECT_EQ(fibre.type, "fibre-exp-pow");
  EXPECT_LE((material::vector_value(fibre.parameters, "fibre") - Vec3::UnitY()).norm(), 1e-15);
  const std::pair<std::string, std::string> refused[] = {
      {R"(<solid type="fiber-exp-pow"><alpha>1</alpha><beta>2</beta><ksi>5</ksi><lam0>1.1</lam0>
         <fiber type="vector"><vector>1,0,0</vector></fiber></solid>)",
       "lam0 = 1 only"},
      {R"(<solid type="solid mixture"><solid type="neo-Hookean"><E>1</E><v>0.3</v></solid></solid>)",
       "a solid mixture inside a solid mixture is not supported"},
      {R"(<solid type="fiber-exp-pow"><alpha>1</alpha><beta>2</beta><ksi>5</ksi></solid>)",
       "the fibre direction <fiber> is required"}};
  for (const auto& [text, message] : refused) {
    try {
      (void)cube(text);
      ADD_FAILURE() << "accepted: " << text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("two_step_cube.feb:"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  }
}

// FEBio's EFD neo-Hookean is neo-Hookean plus the ellipsoidal fibre distribution: the same cube
// as a solid mixture of the two gives the same reactions to the bit, and the fibres stiffen it.
TEST(FebVerification, EfdNeoHookeanIsTheSolidMixtureOfItsTwoParts) {
  const io::CaseSpec efd = two_step_cube(R"(<material id="1" name="Ogden" type="EFD neo-Hookean">
      <density>1</density><E>1</E><v>0.3</v><beta>2.5,3,3</beta><ksi>3,2,2</ksi></material>)");
  const io::MaterialSpec& m = efd.materials.at("Ogden");
  EXPECT_EQ(m.type, "solid-mixture");
  ASSERT_EQ(m.constituents.size(), 2u);
  EXPECT_EQ(m.constituents[1].type, "ellipsoidal-fibre-distribution");
  EXPECT_EQ(material::vector_value(m.constituents[1].parameters, "ksi"), Vec3(3.0, 2.0, 2.0));
  const io::CaseSpec mixture = two_step_cube(R"(<material id="1" name="Ogden" type="solid mixture">
      <solid type="neo-Hookean"><E>1</E><v>0.3</v></solid>
      <solid type="ellipsoidal fiber distribution"><beta>2.5,3,3</beta><ksi>3,2,2</ksi></solid>
      </material>)");
  const io::CaseSpec matrix = two_step_cube(
      R"(<material id="1" name="Ogden" type="neo-Hookean"><E>1</E><v>0.3</v></material>)");
  const std::vector<Real> with_fibres = top_reactions(efd);
  EXPECT_EQ(with_fibres, top_reactions(mixture));
  const std::vector<Real> without = top_reactions(matrix);
  ASSERT_EQ(with_fibres.size(), without.size());
  ASSERT_FALSE(with_fibres.empty());
  EXPECT_GT(with_fibres.front(), 1.5 * without.front()) << "pulled 30 %: the fibres carry load";
}

// FEBio's EFD Mooney-Rivlin is the uncoupled solid mixture of Mooney-Rivlin and the uncoupled
// ellipsoidal fibre distribution: the same reactions to the bit; the fibres stiffen the cube.
TEST(FebVerification, EfdMooneyRivlinIsTheUncoupledMixtureOfItsTwoParts) {
  const io::CaseSpec efd = two_step_cube(R"(<material id="1" name="Ogden" type="EFD Mooney-Rivlin">
      <k>30</k><pressure_model>default</pressure_model><c1>0.5</c1><c2>0.1</c2>
      <beta>2.5,3,3</beta><ksi>3,2,2</ksi></material>)");
  const io::MaterialSpec& m = efd.materials.at("Ogden");
  ASSERT_EQ(m.constituents.size(), 2u);
  EXPECT_EQ(m.constituents[0].type, "mooney-rivlin");
  EXPECT_EQ(m.constituents[1].type, "ellipsoidal-fibre-distribution-uncoupled");
  const io::CaseSpec mixture = two_step_cube(
      R"(<material id="1" name="Ogden" type="uncoupled solid mixture">
      <k>20</k><solid type="Mooney-Rivlin"><k>10</k><c1>0.5</c1><c2>0.1</c2></solid>
      <solid type="EFD uncoupled"><beta>2.5,3,3</beta><ksi>3,2,2</ksi></solid></material>)");
  const io::CaseSpec matrix = two_step_cube(R"(<material id="1" name="Ogden" type="Mooney-Rivlin">
      <k>30</k><c1>0.5</c1><c2>0.1</c2></material>)");
  const std::vector<Real> with_fibres = top_reactions(efd);
  EXPECT_EQ(with_fibres, top_reactions(mixture));
  const std::vector<Real> without = top_reactions(matrix);
  ASSERT_FALSE(with_fibres.empty());
  EXPECT_GT(with_fibres.front(), 1.5 * without.front());
}

// FEBio's local fibre (<fiber type="local"><local>1,7</local></fiber>: from each element's node 1
// to its node 7) on the unit cube is the diagonal (1, 1, 1): the same reactions as that constant
// vector (to round-off: the local one goes through the material's rotated axes); a local fibre
// cannot be written to a TOML case (its per-cell data).
TEST(FebVerification, ALocalFibreIsTheDirectionBetweenTheElementsNodes) {
  const auto cube = [](const std::string& fibre) {
    return two_step_cube(R"(<material id="1" name="Ogden" type="trans iso Mooney-Rivlin">
      <k>30</k><c1>0.5</c1><c2>0</c2><c3>0.2</c3><c4>3</c4><c5>4</c5><lam_max>1.2</lam_max>)" +
                         fibre + "</material>");
  };
  const io::CaseSpec local = cube(R"(<fiber type="local"><local>1,7</local></fiber>)");
  ASSERT_TRUE(local.materials.at("Ogden").axes.has_value());
  EXPECT_EQ(local.materials.at("Ogden").axes->kind, material::AxesKind::Mesh);
  const std::vector<Real> reactions = top_reactions(local);
  ASSERT_FALSE(reactions.empty());
  const std::vector<Real> diagonal =
      top_reactions(cube(R"(<fiber type="vector"><vector>1,1,1</vector></fiber>)"));
  const std::vector<Real> along_z =
      top_reactions(cube(R"(<fiber type="vector"><vector>0,0,1</vector></fiber>)"));
  ASSERT_EQ(diagonal.size(), reactions.size());
  ASSERT_EQ(along_z.size(), reactions.size());
  for (std::size_t i = 0; i < reactions.size(); ++i) {
    EXPECT_NEAR(reactions[i], diagonal[i], 1e-12 * std::abs(diagonal[i])) << i;
    EXPECT_GT(std::abs(reactions[i] - along_z[i]), 1e-3 * std::abs(along_z[i])) << i;
  }
  try {
    (void)io::write_case(local, std::filesystem::temp_directory_path() / "trifem_local.toml");
    ADD_FAILURE() << "written";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("local fibres"), std::string::npos) << e.what();
  }
}

TEST(FebVerification, TransIsoFibresOtherThanAConstantVectorAndActiveContractionAreRefused) {
  const std::pair<std::string, std::string> cases[] = {
      {R"(<fiber type="map">1,7</fiber>)", "fiber of type 'map' is not supported"},
      {R"(<fiber type="vector"><vector>1,0,0</vector></fiber><active_contraction><Tmax>1</Tmax></active_contraction>)",
       "an active contraction is not supported"},
      {"", "the fibre direction <fiber> is required"}};
  for (const auto& [fiber, message] : cases) {
    try {
      (void)two_step_cube(R"(<material id="1" name="Ogden" type="trans iso Mooney-Rivlin">
      <k>30</k><c1>0.5</c1><c2>0</c2><c3>0.2</c3><c4>3</c4><c5>4</c5><lam_max>1.2</lam_max>)" +
                          fiber + "</material>");
      ADD_FAILURE() << "accepted: " << fiber;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("two_step_cube.feb:"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  }
}
