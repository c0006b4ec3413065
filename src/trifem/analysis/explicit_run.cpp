// SPDX-License-Identifier: MIT
#include "trifem/analysis/explicit_run.hpp"

#include "trifem/analysis/explicit_case.hpp"
#include "trifem/analysis/explicit_output.hpp"
#include "trifem/analysis/output_writer.hpp"
#include "trifem/analysis/run.hpp"
#include "trifem/analysis/run_files.hpp"
#include "trifem/core/error.hpp"
#include "trifem/core/interrupt.hpp"
#include "trifem/core/log.hpp"
#include "trifem/core/printable.hpp"
#include "trifem/explicit/energy_balance.hpp"
#include "trifem/model/steps.hpp"

#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <omp.h>

namespace trifem::analysis {
namespace {

namespace ed = explicit_dynamics;
using Clock = std::chrono::steady_clock;

/// More VTU files than this from `output.interval = 0` get a warning.
constexpr double kManyFiles = 1000.0;

/// Runs `f`, prefixing an InputError with the case file (like the reader's messages).
template <class F>
decltype(auto) for_case(const io::CaseSpec& spec, F&& f) {
  try {
    return f();
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: {}", spec.file.string(), e.what()));
  }
}

/// The explicit case of a dynamic-explicit case file, on the model built from it; InputErrors
/// prefixed with the case file.
ExplicitCase build_explicit_case(const io::CaseSpec& spec) {
  return for_case(spec, [&] {
    const std::unique_ptr<model::Model> shared = model::build_model(spec);
    ExplicitCase c = explicit_case(spec, shared->mesh);
    build_explicit_model(c, *shared);
    return c;
  });
}

/// Counters of a run.
struct RunStats {
  explicit RunStats(const ed::ExplicitModel& model) : balance(model) {}
  long halvings = 0;          ///< step halvings over the run
  bool interrupted = false;   ///< stopped on request (Ctrl-C)
  std::string output_failure; ///< a result file could not be written
  ed::StepReport failure;     ///< the fatal report (ok() if the run completed)
  double wall_seconds = 0.0;  ///< whole run
  ed::EnergyBalance balance;  ///< energy balance at the output times

  bool completed() const { return failure.ok() && !interrupted && output_failure.empty(); }
  std::string status() const {
    return completed() ? "completed" : interrupted ? "interrupted" : "failed";
  }
  /// Why the run stopped early ("" if it completed).
  std::string message() const {
    if (interrupted)
      return "interrupted";
    return output_failure.empty() ? failure.message : output_failure;
  }
};

/// Warns (once) when the energy balance error first exceeds its threshold.
void check_energy_balance(const ed::Energies& e, Real time, ed::EnergyBalance& balance) {
  if (balance.record(e))
    log::warn("t = {:.6g} s: the energy balance is off by {:.3g} % of the largest energy "
              "(kinetic + strain - external work + damping = {:.4g} mJ). The step is probably "
              "above the stability limit: lower explicit.safety_factor, leave out time.dt or use "
              "explicit.stable_step = \"element-bound\" (docs/input.md)",
              time, 100.0 * balance.last_error(), e.total());
}

/// "A" or "B".
const char* reading_name(const ed::ExplicitSettings& s) {
  return s.reading == ed::Reading::A ? "A" : "B";
}

/// Number of fixed DOFs of the model.
long fixed_dofs(const ed::ExplicitModel& m) {
  long fixed = 0;
  for (const char f : m.fixed())
    fixed += f;
  return fixed;
}

/// The case, mesh, materials and scheme options, at the head of the log.
void log_model(const io::CaseSpec& spec, const ExplicitCase& c) {
  const ed::ExplicitModel& m = *c.model;
  const ed::ExplicitSettings& s = c.settings;
  const long fixed = fixed_dofs(m);
  log::info("trifem {}  case {}", TRIFEM_VERSION, spec.file.string());
  if (!spec.title.empty())
    log::info("  {}", spec.title);
  log::info("  mesh: {} nodes, {} hex8 cells; {} DOFs, {} fixed; {} threads", m.mesh().num_nodes(),
            m.num_cells(), m.num_dofs(), fixed, omp_get_max_threads());
  for (std::size_t i = 0; i < c.material_names.size(); ++i)
    log::info("  material {}: {}, density {:.4g} t/mm^3, shear modulus {:.4g} MPa",
              c.material_names[i], m.materials()[i].law->type(), m.materials()[i].density,
              m.materials()[i].law->shear_modulus());
  log::info("  dynamic-explicit: reading {}, constraint {}, {}penalty {:.4g} MPa, damping {:.4g} "
            "1/s, safety factor {:.3g}",
            reading_name(s), s.constraint == ed::Constraint::LogJ ? "lnJ" : "J-1",
            s.multiplier ? "" : "no multiplier, ", s.penalty, s.damping, s.safety());
}

/// The step chosen by the solver (and why), with warnings for a reduced time.dt and for very many
/// VTU files.
void log_time_step(const ed::ExplicitSolver& solver, const io::CaseSpec& spec, Real start = 0.0) {
  const ed::TimeStepInfo& t = solver.time_step_info();
  if (t.reduced)
    log::warn("  time.dt = {:.6g} s is above the stability estimate: reduced to {:.6g} s",
              t.requested, t.used);
  const double files = std::ceil((spec.time.end_time - start) / t.used);
  log::info("  time step: {:.6g} s ({}), about {:.0f} steps to t = {:.6g} s", t.used,
            t.requested > 0.0 && !t.reduced ? "time.dt" : "stability estimate", files,
            spec.time.end_time);
  if (spec.output.vtu && explicit_output_interval(spec, start) <= 0.0 && files > kManyFiles)
    log::warn("  output.interval = 0 writes a VTU file every step: about {:.0f} files (set "
              "output.interval)",
              files);
}

/// Refuses a run whose steps, once the stable step is known, exceed io::kMaxSteps (the reader
/// checks this only for a requested time.dt).
void check_step_count(const io::CaseSpec& spec, const ed::TimeStepInfo& t, Real start) {
  const double steps = (spec.time.end_time - start) / t.used;
  if (steps <= io::kMaxSteps)
    return;
  throw InputError(fmt::format(
      "time.end_time = {:.6g} s: with the {} of {:.6g} s the run needs {:.3g} steps, more than "
      "the {:.0e} allowed (shorten time.end_time; a coarser mesh allows longer steps)",
      spec.time.end_time, t.reduced || t.requested <= 0.0 ? "stability estimate" : "time.dt",
      t.used, steps, io::kMaxSteps));
}

/// The solver (it estimates the stable step); InputErrors prefixed with the case file.
std::unique_ptr<ed::ExplicitSolver> make_solver(const io::CaseSpec& spec, const ExplicitCase& c,
                                                const ed::InitialState& initial = {}) {
  return for_case(spec, [&] {
    auto solver = std::make_unique<ed::ExplicitSolver>(*c.model, c.settings, initial);
    check_step_count(spec, solver->time_step_info(), initial.time);
    return solver;
  });
}

/// Steps to every target time in turn; VTU files at the output times (every step if
/// output.interval = 0 is given), a history row after every step. Stops at the first fatal report.
void advance(const io::CaseSpec& spec, ed::ExplicitSolver& solver, ExplicitOutput& output,
             RunStats& stats, Real start = 0.0) {
  const bool every_step = explicit_output_interval(spec, start) <= 0.0;
  for (const StepTarget& target : explicit_step_targets(spec, start)) {
    const Real eps = 1e-12 * std::max(target.time, solver.time_step_info().used);
    while (solver.time() < target.time - eps) {
      if (interrupt::requested()) {
        stats.interrupted = true;
        return;
      }
      const ed::StepReport r = solver.step(target.time);
      stats.halvings += r.halvings;
      if (!r.ok()) {
        stats.failure = r;
        return;
      }
      const bool reached = solver.time() >= target.time - eps;
      output.write_step(solver, r, every_step || (reached && target.output));
      log::debug("step {:6d}  t = {:<12.6g} dt = {:<10.4g} iterations {:2d}  constraint {:.1e}",
                 solver.step_count(), solver.time(), r.dt, r.iterations, r.constraint_residual);
    }
    if (!target.output)
      continue;
    const ed::Energies e = solver.energies();
    log::info("t = {:<10.6g} step {:6d}  kinetic {:.4g}  strain {:.4g}  external {:.4g}  total "
              "{:.3g} mJ",
              solver.time(), solver.step_count(), e.kinetic, e.strain, e.external_work, e.total());
    check_energy_balance(e, solver.time(), stats.balance);
  }
}

/// summary.json "time_step_s".
nlohmann::json time_step_json(const ed::TimeStepInfo& t) {
  return {{"omega_iso_per_s", t.omega}, {"critical", t.critical}, {"estimate", t.stable},
          {"requested", t.requested},   {"used", t.used},         {"reduced", t.reduced}};
}

/// The entries of summary.json that describe the explicit steps: counts, time step, final
/// energies, the energy balance and the largest volume change.
nlohmann::json explicit_entries(const ed::ExplicitSolver& solver, const RunStats& stats) {
  const ed::SolverTimings& w = solver.timings();
  const ed::Energies e = solver.energies();
  nlohmann::json j;
  j["end_time_s"] = solver.time();
  j["steps"] = solver.step_count();
  j["multiplier_solves"] = solver.total_iterations();
  j["halvings"] = stats.halvings;
  j["factorizations"] = w.factorizations;
  j["time_step_s"] = time_step_json(solver.time_step_info());
  j["energies_mJ"] = {
      {"kinetic", e.kinetic},           {"strain", e.strain}, {"external_work", e.external_work},
      {"damping_work", e.damping_work}, {"total", e.total()}, {"initial", e.initial}};
  j["energy_balance"] = {{"max_relative_error", stats.balance.max_error()},
                         {"threshold", ed::EnergyBalance::kThreshold},
                         {"exceeded", stats.balance.exceeded()}};
  j["max_abs_Jbar_minus_1"] = solver.max_volume_change();
  return j;
}

/// summary.json: status, counts, time step, final energies, sizes and wall times.
nlohmann::json summary(const io::CaseSpec& spec, const ExplicitCase& c,
                       const ed::ExplicitSolver& solver, const RunStats& stats,
                       double output_seconds) {
  const ed::SolverTimings& w = solver.timings();
  nlohmann::json j = summary_header(spec, stats.status(), stats.message());
  j["analysis"] = "dynamic-explicit";
  j.update(explicit_entries(solver, stats));
  j["mesh"] = {{"nodes", c.model->mesh().num_nodes()}, {"cells", c.model->num_cells()}};
  j["dofs"] = {{"total", c.model->num_dofs()}, {"fixed", fixed_dofs(*c.model)}};
  j["threads"] = omp_get_max_threads();
  j["wall_time_s"] = {{"total", stats.wall_seconds}, {"forces", w.forces},
                      {"lambda", w.lambda},          {"assemble", w.assemble},
                      {"factorize", w.factorize},    {"solve", w.solve},
                      {"output", output_seconds}};
  return j;
}

/// The displacement of `model` as U0 of its explicit model (DOF 3 a + k).
Vector displacement_of(const model::Model& model) {
  const Vector& x = model.problem->state();
  Vector U(3 * model.mesh.num_nodes());
  for (Index n = 0; n < model.mesh.num_nodes(); ++n)
    for (int k = 0; k < 3; ++k)
      U[3 * n + k] = x[model.dofs.dof(model.fields.u, n, k)];
  return U;
}

/// summary.json "analysis_steps": name, analysis, time span and history file of every step.
nlohmann::json analysis_steps_json(const io::CaseSpec& spec, const std::string& explicit_history) {
  nlohmann::json steps = nlohmann::json::array();
  Real start = 0.0;
  for (const io::StepSpec& step : spec.steps) {
    steps.push_back({{"name", step.name},
                     {"analysis", step.is_explicit() ? "dynamic-explicit" : "quasi-static"},
                     {"start_time_s", start},
                     {"end_time_s", step.time.end_time},
                     {"history", step.is_explicit() ? explicit_history : "history.csv"}});
    start = step.time.end_time;
  }
  return steps;
}

/// A mixed case split in its quasi-static steps and its dynamic-explicit last step.
struct MixedCase {
  explicit MixedCase(const io::CaseSpec& spec)
      : whole(spec), quasi_static(quasi_static_part(spec)), dynamic(explicit_step_part(spec)),
        history(fmt::format("history_step{}.csv", spec.steps.size())) {}
  const io::CaseSpec& whole;
  io::CaseSpec quasi_static; ///< the steps before the explicit one
  io::CaseSpec dynamic;      ///< the explicit step as a dynamic-explicit case
  std::string history;       ///< history file of the explicit step
  const io::StepSpec& step() const { return whole.steps.back(); }
  Real start() const { return quasi_static.time.end_time; }
};

/// Runs `f`, prefixing an InputError with the case file and the explicit step.
template <class F>
decltype(auto) for_step(const MixedCase& mixed, F&& f) {
  try {
    return f();
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: {} (dynamic-explicit): {}", mixed.whole.file.string(),
                                 mixed.step().key, e.what()));
  }
}

/// The explicit step of a mixed run on the model `qs` of its quasi-static steps, from their final
/// state: U0 its displacement, at rest, t0 its end time; results continue `qs_output`.
FollowUpReport run_explicit_step(const MixedCase& mixed, ExplicitCase& c, model::Model& qs,
                                 OutputWriter& qs_output) {
  const auto start = Clock::now();
  const io::StepSpec& step = mixed.step();
  FollowUpReport report;
  report.end_time = mixed.start();
  std::unique_ptr<ed::ExplicitSolver> solver;
  try {
    model::activate_step(qs, mixed.whole.steps.size() - 1);
    build_explicit_model(c, qs);
    log::info("analysis step {} '{}' (dynamic-explicit): t = {:.6g} to {:.6g} s, from the "
              "quasi-static state at rest, {} fixed DOFs",
              mixed.whole.steps.size(), step.name, mixed.start(), step.time.end_time,
              fixed_dofs(*c.model));
    const ed::InitialState initial{displacement_of(qs), {}, mixed.start()};
    solver = std::make_unique<ed::ExplicitSolver>(*c.model, c.settings, initial);
    check_step_count(mixed.dynamic, solver->time_step_info(), mixed.start());
  } catch (const InputError& e) {
    report.success = false;
    report.failure =
        fmt::format("{} (dynamic-explicit, t = {:.6g} s): {}", step.key, mixed.start(), e.what());
    return report;
  }
  log_time_step(*solver, mixed.dynamic, mixed.start());
  log::info("  initial strain energy {:.6g} mJ", solver->initial_energy());
  RunStats stats(*c.model);
  const ExplicitContinuation continuation{&qs_output.pvd(), qs_output.state_count(), mixed.history};
  double output_seconds = 0.0;
  try {
    ExplicitOutput output(c, mixed.dynamic.output, qs_output.directory(), &continuation);
    output.write_initial(*solver);
    advance(mixed.dynamic, *solver, output, stats, mixed.start());
    output_seconds = output.seconds();
    log::info("{} '{}': {} steps, {} multiplier solves, {} halvings; {} VTU files, {}",
              stats.completed() ? "completed" : "STOPPED", step.name, solver->step_count(),
              solver->total_iterations(), stats.halvings, output.vtu_count(),
              output.history_file().string());
  } catch (const OutputError& e) {
    stats.output_failure =
        fmt::format("the results at t = {:.6g} could not be written: {}", solver->time(), e.what());
  }
  if (stats.balance.exceeded())
    log::warn("the energy balance error reached {:.3g} % of the largest energy: check the "
              "results ({}, total_energy [mJ])",
              100.0 * stats.balance.max_error(), mixed.history);
  if (!stats.failure.ok())
    log::info("run stopped: {} ({})", stats.failure.message, ed::to_string(stats.failure.status));
  stats.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  report.success = stats.completed();
  report.interrupted = stats.interrupted;
  report.failure = stats.message();
  report.end_time = solver->time();
  nlohmann::json part = explicit_entries(*solver, stats);
  part["step"] = step.name;
  part["start_time_s"] = mixed.start();
  part["history"] = mixed.history;
  const ed::SolverTimings& w = solver->timings();
  part["wall_time_s"] = {{"total", stats.wall_seconds},
                         {"forces", w.forces},
                         {"lambda", w.lambda},
                         {"output", output_seconds}};
  report.summary["analysis"] = "quasi-static, dynamic-explicit";
  report.summary["analysis_steps"] = analysis_steps_json(mixed.whole, mixed.history);
  report.summary["dynamic_explicit"] = std::move(part);
  return report;
}

} // namespace

int run_mixed_case(const io::CaseSpec& spec, const std::filesystem::path& output_dir) {
  const MixedCase mixed(spec);
  std::unique_ptr<model::Model> model = for_case(spec, [&] { return model::build_model(spec); });
  // validated before anything runs: an invalid step creates no output
  ExplicitCase c = for_step(mixed, [&] { return explicit_case(mixed.dynamic, model->mesh); });
  const FollowUp follow_up = [&](model::Model& qs, OutputWriter& output) {
    return run_explicit_step(mixed, c, qs, output);
  };
  return run_quasi_static_case(mixed.quasi_static, output_dir, {}, follow_up, std::move(model));
}

void check_explicit_step(const io::CaseSpec& spec, const model::Model& model) {
  const MixedCase mixed(spec);
  // its model and stable step follow from the quasi-static state, at the run
  for_step(mixed, [&] { return explicit_case(mixed.dynamic, model.mesh); });
}

int run_explicit_case(const io::CaseSpec& spec, const std::filesystem::path& output_dir) {
  const auto start = Clock::now();
  const ExplicitCase c = build_explicit_case(spec);
  // before the output directory: an invalid case creates no output
  const std::unique_ptr<ed::ExplicitSolver> solver = make_solver(spec, c);
  start_output_directory(output_dir, spec);
  ExplicitOutput output(c, spec.output, output_dir);
  RunStats stats(*c.model);
  try {
    log::add_file((output_dir / "run.log").string());
  } catch (const OutputError& e) {
    stats.output_failure = e.what();
  }
  log_model(spec, c);
  log_time_step(*solver, spec);
  output.write_initial(*solver);

  try {
    if (stats.output_failure.empty())
      advance(spec, *solver, output, stats);
  } catch (const OutputError& e) { // solved, but the results cannot be written
    stats.output_failure =
        fmt::format("the results at t = {:.6g} could not be written: {}", solver->time(), e.what());
  }
  stats.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  const nlohmann::json summary_json = summary(spec, c, *solver, stats, output.seconds());
  const ed::SolverTimings& w = solver->timings();
  log::info("{}: {} steps, {} multiplier solves, {} halvings, {:.2f} s (forces {:.2f}, "
            "multiplier {:.2f}, output {:.2f})",
            stats.completed()   ? "completed"
            : stats.interrupted ? "INTERRUPTED"
                                : "FAILED",
            solver->step_count(), solver->total_iterations(), stats.halvings, stats.wall_seconds,
            w.forces, w.lambda, output.seconds());
  log::info("results: {} ({} VTU files), {}, {}", output.pvd_file().string(), output.vtu_count(),
            output.history_file().string(), (output_dir / "summary.json").string());
  if (stats.balance.exceeded())
    log::warn("the energy balance error reached {:.3g} % of the largest energy: check the "
              "results (history.csv, total_energy [mJ])",
              100.0 * stats.balance.max_error());
  try {
    write_final_summary(output_dir / "summary.json", summary_json);
  } catch (const OutputError& e) {
    std::cerr << "error: " << spec.file.string() << ": " << printable(e.what()) << '\n';
    return kAnalysisFailed;
  }
  if (stats.interrupted) {
    std::cerr << "error: " << spec.file.string() << ": interrupted at t = " << solver->time()
              << " (results up to the last step are kept)\n";
    return interrupted_exit_code();
  }
  if (!stats.completed()) {
    if (!stats.failure.ok())
      log::info("run stopped: {} ({})", stats.failure.message, ed::to_string(stats.failure.status));
    std::cerr << "error: " << spec.file.string() << ": " << printable(stats.message()) << '\n';
    return kAnalysisFailed;
  }
  return kSuccess;
}

int check_explicit_case(const io::CaseSpec& spec) {
  const ExplicitCase c = build_explicit_case(spec);
  log_model(spec, c);
  const std::unique_ptr<ed::ExplicitSolver> solver = make_solver(spec, c);
  log_time_step(*solver, spec);
  log::info("check passed: the case is valid");
  return kSuccess;
}

} // namespace trifem::analysis
