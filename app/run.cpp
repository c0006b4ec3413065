// SPDX-License-Identifier: MIT
#include "run.hpp"

#include "explicit_run.hpp"
#include "model.hpp"
#include "output.hpp"
#include "trifem/core/error.hpp"
#include "trifem/core/log.hpp"
#include "trifem/linalg/auto_solver.hpp"
#include "trifem/linalg/linear_solver.hpp"

#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <omp.h>
#include <set>

namespace trifem::app {
namespace {

using Clock = std::chrono::steady_clock;

/// Derived scales of mixture models: osmotic pressure scale, Donnan state, consolidation time.
void log_mixture_scales(const Model& model) {
  const material::Electrochemistry& c = model.chem;
  const Real L = model.length_scale;
  log::info("  consolidation time L^2/(H kappa) = {:.4g} s (L = model size)",
            L * L / (model.modulus_scale * model.permeability_scale));
  if (!model.fields.j_plus.valid())
    return;
  log::info("  RT = {:.6g} mJ/mmol, RT c* = {:.6g} MPa (bath c* = {:.4g} mmol/mm^3)", c.RT(),
            c.RT() * c.c_ref, c.c_ref);
  std::set<const material::MixtureProperties*> seen;
  for (const CellMaterial& m : model.materials) {
    if (!m.mixture || !m.mixture->charged || !seen.insert(m.mixture.get()).second)
      continue;
    const Real cF = m.mixture->fixed_charge;
    const Real K = c.gamma_bath * c.gamma_bath / (m.mixture->gamma_plus * m.mixture->gamma_minus);
    const Real cp = 0.5 * (cF + std::sqrt(cF * cF + 4 * K * c.c_ref * c.c_ref));
    const Real Pi = c.RT() * (m.mixture->osmotic * (2 * cp - cF) - 2 * c.osmotic_bath * c.c_ref);
    const Real psi =
        -c.RT() * std::log(m.mixture->gamma_plus * cp / (c.gamma_bath * c.c_ref)) / c.faraday;
    log::info("  Donnan state at the reference (cF0 = {:.4g} mEq/mm^3): Pi0 = {:.6g} MPa, "
              "psi0 = {:.4g} mV, c+ = {:.6g}, c- = {:.6g} mmol/mm^3",
              cF, Pi, psi, cp, cp - cF);
  }
}

void log_model(const io::CaseSpec& spec, const Model& model) {
  log::info("trifem {}  case {}", TRIFEM_VERSION, spec.file.string());
  if (!spec.title.empty())
    log::info("  {}", spec.title);
  log::info("  mesh: {} nodes, {} hex8 cells; {} equations, {} prescribed DOFs; {} threads",
            model.mesh.num_nodes(), model.mesh.num_cells(), model.dofs.num_equations(),
            model.dofs.num_constrained(), omp_get_max_threads());
  log::info("  scales: length {:.4g} mm, modulus {:.4g} MPa", model.length_scale,
            model.modulus_scale);
  if (model.mixture)
    log_mixture_scales(model);
}

void write_summary(const std::filesystem::path& file, const io::CaseSpec& spec, const Model& model,
                   const solver::RunReport& run, const solver::PhaseTimes& phases, double output_s,
                   double wall_s, const MassBalance* balance) {
  nlohmann::json j;
  j["trifem_version"] = TRIFEM_VERSION;
  j["case"] = spec.file.string();
  j["status"] = run.success ? "completed" : "failed";
  j["failure"] = run.failure;
  j["end_time_s"] = run.end_time;
  j["steps"] = run.steps;
  j["newton_iterations"] = run.iterations;
  j["cutbacks"] = run.cutbacks;
  j["failed_attempts"] = run.failed_attempts;
  j["mesh"] = {{"nodes", model.mesh.num_nodes()}, {"cells", model.mesh.num_cells()}};
  j["dofs"] = {{"equations", model.dofs.num_equations()},
               {"prescribed", model.dofs.num_constrained()}};
  j["threads"] = omp_get_max_threads();
  j["wall_time_s"] = {{"total", wall_s},
                      {"assembly", phases.assembly},
                      {"factorization", phases.factorization},
                      {"solve", phases.solve},
                      {"output", output_s}};
  if (balance) {
    // largest over the steps of |change of the total + dt x boundary outflow| / total, for the
    // model and (if it has several) for each body
    const auto errors = [&](const BalanceRegion& r) {
      nlohmann::json e = {{"water", r.worst[0]}};
      if (balance->has_ions()) {
        e["cation"] = r.worst[1];
        e["anion"] = r.worst[2];
      }
      return e;
    };
    j["mass_balance_max_relative_error"] = errors(balance->regions().front());
    for (std::size_t i = 1; i < balance->regions().size(); ++i)
      j["mass_balance_max_relative_error_by_body"][balance->regions()[i].name] =
          errors(balance->regions()[i]);
  }
  std::ofstream out(file);
  out << j.dump(2) << '\n';
}

/// build_model with errors prefixed by the case file, like the reader's.
std::unique_ptr<Model> build_model_for(const io::CaseSpec& spec) {
  try {
    return build_model(spec);
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: {}", spec.file.string(), e.what()));
  }
}

/// The sparse direct solver, and for "auto" the backend it takes for this many equations.
void log_linear_solver(const std::string& name, Index equations) {
  if (name != "auto")
    log::info("  linear solver: {}", name);
  else
    log::info("  linear solver: auto, {} for {} equations (sparselu below {})",
              equations < linalg::kAutoSparseLuLimit ? "sparselu" : "umfpack", equations,
              linalg::kAutoSparseLuLimit);
}

} // namespace

solver::StepSettings step_settings(const io::CaseSpec& spec) {
  const io::TimeSpec& t = spec.time;
  solver::StepSettings s;
  s.end_time = t.end_time;
  s.dt = t.dt;
  s.dt_min = t.dt_min > 0 ? t.dt_min : t.dt * 1e-6;
  s.dt_max = t.dt_max > 0 ? t.dt_max : t.dt;
  s.growth = t.growth;
  s.cutback = t.cutback;
  s.target_iterations = t.target_iterations;
  s.must_points = spec.output.times;
  if (spec.output.interval > 0)
    for (Real time = spec.output.interval; time < t.end_time; time += spec.output.interval)
      s.must_points.push_back(time);
  for (const auto& [name, curve] : spec.curves)
    for (const auto& p : curve.points)
      if (p.first > 0 && p.first < t.end_time)
        s.must_points.push_back(p.first);
  return s;
}

solver::NewtonSettings newton_settings(const io::SolverSpec& s) {
  solver::NewtonSettings n;
  n.max_iterations = s.max_iterations;
  n.residual_tolerance = s.residual_tolerance;
  n.increment_tolerance = s.increment_tolerance;
  n.line_search = s.line_search;
  return n;
}

int run_case(const io::CaseSpec& spec, const std::filesystem::path& output_dir) {
  if (spec.is_explicit())
    return run_explicit_case(spec, output_dir);
  const auto start = Clock::now();
  std::unique_ptr<Model> model = build_model_for(spec);
  OutputWriter output(*model, spec.output, output_dir);
  log::add_file((output_dir / "run.log").string());
  log_model(spec, *model);

  solver::NewtonSolver newton(newton_settings(spec.solver),
                              linalg::make_linear_solver(spec.solver.linear_solver));
  log_linear_solver(spec.solver.linear_solver, model->problem->num_equations());
  solver::StepController controller(step_settings(spec));
  solver::Linearization initial;
  if (model->problem->linearize(initial, false) != solver::SolveStatus::Converged) {
    std::cerr << "error: " << spec.file.string()
              << ": the initial state (t = 0) inverts an element (J <= 0); prescribed values "
                 "without a load curve apply from t = 0\n";
    return kAnalysisFailed;
  }
  output.write(0.0, 0, 0.0, 0, true); // the initial state, with its reactions

  auto observer = [&](const solver::StepInfo& info) {
    if (output.balance())
      output.balance()->record_step(info.dt);
    log::info("step {:4d}  t = {:<10.5g} dt = {:<9.3g} iterations {:2d}  residual {:.2e}",
              info.step, info.time, info.dt, info.newton->iterations, info.newton->final_residual);
    output.write(info.time, info.step, info.dt, info.newton->iterations,
                 output.is_output_time(info.time) || controller.finished());
  };
  const solver::RunReport run =
      solver::run_time_loop(*model->problem, newton, controller, observer);
  const double wall = std::chrono::duration<double>(Clock::now() - start).count();
  write_summary(output_dir / "summary.json", spec, *model, run, newton.times(), output.seconds(),
                wall, output.balance());
  log::info("{}: {} steps, {} Newton iterations, {} cutbacks, {:.2f} s (assembly {:.2f}, "
            "factorization {:.2f}, solve {:.2f}, output {:.2f})",
            run.success ? "completed" : "FAILED", run.steps, run.iterations, run.cutbacks, wall,
            newton.times().assembly, newton.times().factorization, newton.times().solve,
            output.seconds());
  log::info("results: {} ({} VTU files), {}, {}", output.pvd_file().string(), output.vtu_count(),
            output.history_file().string(), (output_dir / "summary.json").string());
  if (!run.success) {
    std::cerr << "error: " << spec.file.string() << ": " << run.failure << '\n';
    return kAnalysisFailed;
  }
  return kSuccess;
}

int check_case(const io::CaseSpec& spec) {
  if (spec.is_explicit())
    return check_explicit_case(spec);
  std::unique_ptr<Model> model = build_model_for(spec);
  log_model(spec, *model);
  log::info("check passed: the case is valid");
  return kSuccess;
}

} // namespace trifem::app
