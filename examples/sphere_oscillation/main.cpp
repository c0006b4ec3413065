// SPDX-License-Identifier: MIT
// Radial oscillation of a thick nearly incompressible neo-Hookean sphere under a step internal
// pressure (README.md): explicit multiplier scheme on an octant, compared with the exact
// one-degree-of-freedom ODE of docs/theory/reference-solutions.md §R8.4. Writes history.csv,
// reference.csv and plot.gp into the output folder and, with --plot, runs gnuplot on it.
#include "exact_sphere.hpp"
#include "fixtures.hpp"
#include "generated_meshes.hpp"

#include "solver_history.hpp"
#include "trifem/core/log.hpp"

#include <CLI/CLI.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>

using namespace trifem;
using namespace trifem::explicit_dynamics;
using namespace trifem::test;

namespace {

/// Case parameters (units mm, s, MPa, t/mm³): a rubber-like sphere A = 10 mm, B = 20 mm.
struct Case {
  Real inner = 10.0, outer = 20.0;
  Real mu = 0.4;        ///< shear modulus [MPa]
  Real rho = 1.1e-9;    ///< density [t/mm³]
  Real pressure = 0.12; ///< step pressure on the cavity, 0.3 μ [MPa]
  int divisions = 6;    ///< cells per patch edge and through the thickness
  Real periods = 5.0;   ///< simulated time in periods of the exact ODE
  std::string reading = "B";
  Real alpha_over_mu = 1e4;
  std::filesystem::path out = "results/sphere_oscillation";
  bool plot = false;
};

test::TestModel build_model(const Case& c) {
  test::ShellOctantSpec shell;
  shell.inner = c.inner;
  shell.outer = c.outer;
  shell.divisions = shell.layers = c.divisions;
  // W = μ/2 (I1 − 3) − μ ln J (ν = 0); the bulk response is the multiplier's.
  test::ExplicitTestCase model(test::make_shell_octant(shell),
                               test::deviatoric_material(c.mu, c.rho));
  model.fix("shell.x0", {0}).fix("shell.y0", {1}).fix("shell.z0", {2});
  model.pressure("shell.inner", c.pressure, test::step_curve());
  return test::TestModel(model);
}

/// The exact ODE history from rest; returns the first period.
Real write_reference(const Case& c, Real t_end, const std::filesystem::path& file) {
  const test::sphere::Sphere s{c.inner, c.outer, c.mu, c.rho};
  const Real h = 1e-4 * c.inner / std::sqrt(c.mu / c.rho);
  const auto ode = test::sphere::integrate_radial(
      s, [&](Real) { return c.pressure; }, t_end, h);
  std::ofstream out(file);
  out << "time [s],inner_radius_exact [mm]\n";
  Real period = 0.0;
  for (std::size_t i = 0; i < ode.size(); ++i) {
    if (i % 20 == 0)
      out << ode[i].t << "," << ode[i].a << "\n";
    if (period == 0.0 && i > 0 && ode[i - 1].v < 0.0 && ode[i].v >= 0.0)
      period = ode[i].t;
  }
  return period;
}

/// Copies plot.gp next to the results and, if asked, runs gnuplot there.
void plot(const Case& c) {
  std::filesystem::copy_file(TRIFEM_EXAMPLE_DIR "/plot.gp", c.out / "plot.gp",
                             std::filesystem::copy_options::overwrite_existing);
  if (!c.plot)
    return;
  const std::string cmd = "cd '" + c.out.string() + "' && gnuplot plot.gp";
  if (std::system(cmd.c_str()) != 0)
    log::warn("gnuplot failed (is it installed?); run `gnuplot plot.gp` in {}", c.out.string());
}

/// The radius probes of history.csv.
std::vector<Probe> probes() {
  return {{"inner_radius [mm]",
           [](const ExplicitSolver& sv) { return mean_radius(sv, "shell.inner"); }},
          {"outer_radius [mm]",
           [](const ExplicitSolver& sv) { return mean_radius(sv, "shell.outer"); }},
          {"max_lambda [MPa]",
           [](const ExplicitSolver& sv) { return sv.multiplier().cwiseAbs().maxCoeff(); }}};
}

int run(const Case& c) {
  std::filesystem::create_directories(c.out);
  const test::sphere::Sphere s{c.inner, c.outer, c.mu, c.rho};
  // Period of the exact ODE (a long first pass), then the reference over the simulated time.
  const Real period =
      write_reference(c, 10.0 * c.inner / std::sqrt(c.mu / c.rho), c.out / "reference.csv");
  const Real t_end = c.periods * period;
  write_reference(c, t_end, c.out / "reference.csv");
  log::info("exact: static inner radius {:.6f} mm, period {:.6g} s", s.static_radius(c.pressure),
            period);

  const test::TestModel model = build_model(c);
  ExplicitSettings settings;
  settings.reading = c.reading == "A" ? Reading::A : Reading::B;
  settings.penalty = c.alpha_over_mu * c.mu;
  ExplicitSolver solver(model, settings);
  log::info("mesh: {} cells, {} nodes; dt = {:.6g} s ({:.0f} steps per period)", model.num_cells(),
            model.mesh().num_nodes(), solver.time_step(), period / solver.time_step());
  HistoryWriter history(c.out / "history.csv", probes());
  history.record_initial(solver);
  const StepReport last = solver.run(
      t_end, [&](const ExplicitSolver& sv, const StepReport& r) { history.record(sv, r); });
  log::info("{} steps, {} multiplier solves; time in cell loops {:.3f} s, in the multiplier "
            "system {:.3f} s",
            solver.step_count(), solver.total_iterations(), solver.timings().forces,
            solver.timings().lambda);
  plot(c);
  return last.ok() ? 0 : 1;
}

} // namespace

int main(int argc, char** argv) {
  Case c;
  CLI::App cli{"Radial oscillation of a thick incompressible sphere (explicit multiplier scheme)"};
  cli.add_option("-o,--output", c.out, "output folder")->capture_default_str();
  cli.add_option("-n,--divisions", c.divisions, "cells per patch edge and radially")
      ->capture_default_str()
      ->check(CLI::Range(1, 64));
  cli.add_option("--reading", c.reading, "A (forces iterated) or B (central difference)")
      ->capture_default_str()
      ->check(CLI::IsMember({"A", "B"}));
  cli.add_option("--alpha", c.alpha_over_mu, "penalty alpha / mu")->capture_default_str();
  cli.add_option("--periods", c.periods, "simulated time in periods")->capture_default_str();
  cli.add_flag("--plot", c.plot, "run gnuplot on plot.gp after the run");
  CLI11_PARSE(cli, argc, argv);
  try {
    return run(c);
  } catch (const std::exception& e) {
    log::error("{}", e.what());
    return 2;
  }
}
