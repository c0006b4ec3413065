// SPDX-License-Identifier: MIT
// Cook's membrane of a nearly incompressible neo-Hookean solid under a suddenly applied shear
// load (README.md): the explicit multiplier scheme (Q1–P0) against the pure-displacement Q1
// version with the same bulk modulus, which locks. Writes history.csv (mixed), history_q1.csv
// and plot.gp into the output folder and, with --plot, runs gnuplot on it.
#include "fixtures.hpp"
#include "generated_meshes.hpp"

#include "solver_history.hpp"
#include "trifem/core/log.hpp"

#include <CLI/CLI.hpp>

#include <cstdlib>
#include <filesystem>

using namespace trifem;
using namespace trifem::explicit_dynamics;
using namespace trifem::test;

namespace {

/// Case parameters (units mm, s, MPa, t/mm³).
struct Case {
  Real mu = 1.0;            ///< shear modulus [MPa]
  Real rho = 1.0e-9;        ///< density [t/mm³]
  Real shear = 0.05;        ///< traction on the loaded edge, applied at t = 0 [MPa]
  Real alpha_over_mu = 1e3; ///< penalty α = bulk modulus κ of the Q1 run, / μ
  int divisions = 8;        ///< cells along each side (one through the thickness)
  Real t_end = 0.016;       ///< about two periods of the first bending mode [s]
  std::string reading = "B";
  bool q1 = true;
  std::filesystem::path out = "results/cooks_membrane";
  bool plot = false;
};

/// `mixed`: W = μ/2 (I1 − 3) − μ ln J plus the multiplier; otherwise the compressible
/// neo-Hookean with κ = α (ν = (3κ − 2μ)/(2(3κ + μ))) and no multiplier.
test::TestModel build_model(const Case& c, bool mixed) {
  test::CookSpec cook;
  cook.nx = cook.ny = c.divisions;
  const io::MaterialSpec material =
      mixed ? test::deviatoric_material(c.mu, c.rho)
            : test::compressible_material(c.mu, c.alpha_over_mu * c.mu, c.rho);
  test::ExplicitTestCase model(test::make_cook_membrane(cook), material);
  // Clamped edge; u_z = 0 everywhere (plane strain).
  model.fix("cook.xmin", {0, 1}).fix("cook.all", {2});
  model.traction("cook.xmax", Vec3(0.0, c.shear, 0.0), test::step_curve());
  return test::TestModel(model);
}

/// Runs one formulation and writes its history; returns true if the run completed.
bool run_one(const Case& c, bool mixed, const std::filesystem::path& file) {
  const test::TestModel model = build_model(c, mixed);
  ExplicitSettings settings;
  settings.reading = c.reading == "A" ? Reading::A : Reading::B;
  settings.multiplier = mixed;
  settings.penalty = c.alpha_over_mu * c.mu;
  ExplicitSolver solver(model, settings);
  HistoryWriter history(file, {{"tip_uy [mm]", [](const ExplicitSolver& sv) {
                                  return mean_displacement(sv, "cook.xmax", 1);
                                }}});
  history.record_initial(solver);
  // Write every step until t_end; the Q1 run takes ~sqrt(α/μ) times more steps.
  const StepReport last = solver.run(
      c.t_end, [&](const ExplicitSolver& sv, const StepReport& r) { history.record(sv, r); });
  log::info("{}: {} cells, dt = {:.4g} s, {} steps, {} multiplier solves, mean iterations "
            "{:.2f}; cell loops {:.3f} s, multiplier system {:.3f} s; final tip u_y = {:.4f} mm",
            mixed ? "mixed Q1-P0" : "pure-displacement Q1", model.num_cells(), solver.time_step(),
            solver.step_count(), solver.total_iterations(),
            static_cast<double>(solver.total_iterations()) /
                static_cast<double>(std::max(1L, solver.step_count())),
            solver.timings().forces, solver.timings().lambda,
            mean_displacement(solver, "cook.xmax", 1));
  return last.ok();
}

int run(const Case& c) {
  std::filesystem::create_directories(c.out);
  bool ok = run_one(c, true, c.out / "history.csv");
  if (c.q1)
    ok = run_one(c, false, c.out / "history_q1.csv") && ok;
  std::filesystem::copy_file(TRIFEM_EXAMPLE_DIR "/plot.gp", c.out / "plot.gp",
                             std::filesystem::copy_options::overwrite_existing);
  if (c.plot) {
    const std::string cmd = "cd '" + c.out.string() + "' && gnuplot plot.gp";
    if (std::system(cmd.c_str()) != 0)
      log::warn("gnuplot failed (is it installed?); run `gnuplot plot.gp` in {}", c.out.string());
  }
  return ok ? 0 : 1;
}

} // namespace

int main(int argc, char** argv) {
  Case c;
  CLI::App cli{"Cook's membrane under a sudden shear load (explicit multiplier scheme vs Q1)"};
  cli.add_option("-o,--output", c.out, "output folder")->capture_default_str();
  cli.add_option("-n,--divisions", c.divisions, "cells along each side")
      ->capture_default_str()
      ->check(CLI::Range(1, 256));
  cli.add_option("--reading", c.reading, "A (forces iterated) or B (central difference)")
      ->capture_default_str()
      ->check(CLI::IsMember({"A", "B"}));
  cli.add_option("--alpha", c.alpha_over_mu, "penalty alpha / mu (= kappa / mu of Q1)")
      ->capture_default_str();
  cli.add_option("--t-end", c.t_end, "simulated time [s]")->capture_default_str();
  cli.add_flag("!--no-q1", c.q1, "skip the pure-displacement Q1 comparison run");
  cli.add_flag("--plot", c.plot, "run gnuplot on plot.gp after the run");
  CLI11_PARSE(cli, argc, argv);
  try {
    return run(c);
  } catch (const std::exception& e) {
    log::error("{}", e.what());
    return 2;
  }
}
