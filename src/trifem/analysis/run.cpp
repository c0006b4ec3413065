// SPDX-License-Identifier: MIT
#include "trifem/analysis/run.hpp"

#include "trifem/analysis/explicit_step.hpp"
#include "trifem/analysis/output_writer.hpp"
#include "trifem/analysis/run_files.hpp"
#include "trifem/contact/contact_term.hpp"
#include "trifem/core/error.hpp"
#include "trifem/core/interrupt.hpp"
#include "trifem/core/log.hpp"
#include "trifem/core/printable.hpp"
#include "trifem/linalg/auto_solver.hpp"
#include "trifem/linalg/linear_solver.hpp"
#include "trifem/mesh/mesh.hpp"
#include "trifem/model/conditions.hpp"
#include "trifem/model/model.hpp"
#include "trifem/parallel/communicator.hpp"

#include <chrono>
#include <cmath>
#include <csignal>
#include <fmt/ranges.h>
#include <fstream>
#include <iostream>
#include <list>
#include <map>
#include <new>
#include <nlohmann/json.hpp>
#include <numeric>
#include <omp.h>
#include <optional>
#include <set>

namespace trifem::analysis {
namespace {

using Clock = std::chrono::steady_clock;

/// Derived scales of mixture models: osmotic pressure scale, Donnan state, consolidation time.
void log_mixture_scales(const model::Model& model) {
  const material::Electrochemistry& c = model.chem;
  const Real L = model.length_scale;
  log::info("  consolidation time L^2/(H kappa) = {:.4g} s (L = model size)",
            L * L / (model.modulus_scale * model.permeability_scale));
  if (!model.fields.j_plus.valid())
    return;
  log::info("  RT = {:.6g} mJ/mmol, RT c* = {:.6g} MPa (bath c* = {:.4g} mmol/mm^3)", c.RT(),
            c.RT() * c.c_ref, c.c_ref);
  std::set<const material::MixtureProperties*> seen;
  for (const model::CellMaterial& m : model.materials) {
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

/// "12 hex8 cells", "100 tet10 cells", "8 hex8 + 6 penta6 cells".
std::string cell_counts(const mesh::Mesh& mesh) {
  std::map<mesh::CellType, Index> count;
  for (Index c = 0; c < mesh.num_cells(); ++c)
    ++count[mesh.cell_type(c)];
  if (count.empty())
    return "0 cells";
  std::vector<std::string> parts;
  for (const auto& [type, n] : count)
    parts.push_back(fmt::format("{} {}", n, mesh::name(type)));
  return fmt::format("{} cells", fmt::join(parts, " + "));
}

void log_model(const io::CaseSpec& spec, const model::Model& model) {
  log::info("trifem {}  case {}", TRIFEM_VERSION, spec.file.string());
  if (!spec.title.empty())
    log::info("  {}", spec.title);
  log::info("  mesh: {} nodes, {}; {} equations, {} prescribed DOFs; {} threads{}",
            model.mesh.num_nodes(), cell_counts(model.mesh),
            model.problem->dof_map().num_equations(), model.problem->dof_map().num_constrained(),
            omp_get_max_threads(),
            parallel::active() ? fmt::format(" on each of {} processes", parallel::size()) : "");
  log::info("  scales: length {:.4g} mm, modulus {:.4g} MPa", model.length_scale,
            model.modulus_scale);
  if (model.mixture)
    log_mixture_scales(model);
}

/// summary.json of a quasi-static run.
nlohmann::json summary(const io::CaseSpec& spec, const model::Model& model,
                       const solver::RunReport& run, const solver::PhaseTimes& phases,
                       double output_s, double wall_s, const MassBalance* balance) {
  nlohmann::json j = summary_header(spec, run_status(run), run.failure);
  if (parallel::active()) { // collective: every process makes the summary
    const std::vector<Real> each = parallel::gather(peak_memory_mb());
    j["processes"] = parallel::size();
    j["peak_memory_mb_of_each_process"] = each;
    j["peak_memory_mb_total"] = std::accumulate(each.begin(), each.end(), 0.0);
  }
  j["end_time_s"] = run.end_time;
  j["steps"] = run.steps;
  j["newton_iterations"] = run.iterations;
  j["linear_iterations"] = run.linear_iterations;
  j["cutbacks"] = run.cutbacks;
  j["failed_attempts"] = run.failed_attempts;
  j["roundoff_floor_steps"] = run.roundoff_floor_steps;
  j["mesh"] = {{"nodes", model.mesh.num_nodes()}, {"cells", model.mesh.num_cells()}};
  j["dofs"] = {{"equations", model.problem->dof_map().num_equations()},
               {"prescribed", model.problem->dof_map().num_constrained()}};
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
  return j;
}

/// "  37 % done, about 2 min 10 s left" once a run has taken more than 10 s (the time left is
/// extrapolated from the simulated time reached so far), "" before.
std::string progress(Real time, Real end_time, Clock::duration elapsed) {
  const double seconds = std::chrono::duration<double>(elapsed).count();
  const double done = end_time > 0.0 ? time / end_time : 1.0;
  if (seconds < 10.0 || done <= 0.0)
    return "";
  const long left = std::lround(seconds * (1.0 - done) / done);
  const std::string eta = left >= 3600 ? fmt::format("{} h {} min", left / 3600, left % 3600 / 60)
                          : left >= 60 ? fmt::format("{} min {} s", left / 60, left % 60)
                                       : fmt::format("{} s", left);
  return fmt::format("  {:3.0f} % done, about {} left", 100.0 * done, eta);
}

/// Says once that Newton reached the round-off floor, with the mesh grading that causes it.
void note_roundoff_floor(const model::Model& model, const solver::StepInfo& info, bool& noted) {
  if (!info.newton->at_roundoff_floor || noted)
    return;
  noted = true;
  const mesh::EdgeRange edges = mesh::edge_length_range(model.mesh);
  log::warn("  step {}: Newton reached the round-off floor (the residual stalls at {:.2e} of its "
            "reference while the increments are at the round-off of the unknowns) and the step "
            "was accepted: the state is as converged as double precision allows. The cell edges "
            "range from {:.3g} to {:.3g} mm (ratio {:.3g}); strong grading raises this floor. "
            "Later steps at the floor are counted in summary.json (roundoff_floor_steps).",
            info.step, info.newton->final_residual, edges.min, edges.max, edges.max / edges.min);
}

/// Runs `f`, prefixing an InputError with the case file, like the reader's messages.
template <class F>
decltype(auto) with_case_file(const io::CaseSpec& spec, F&& f) {
  try {
    return f();
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: {}", spec.file.string(), e.what()));
  }
}

/// build_model with errors prefixed by the case file.
std::unique_ptr<model::Model> build_model_for(const io::CaseSpec& spec) {
  return with_case_file(spec, [&] { return model::build_model(spec); });
}

/// The linear solver of the case; InputErrors (unknown or unused PETSc options) prefixed with
/// the case file.
std::unique_ptr<linalg::LinearSolver> linear_solver_for(const io::CaseSpec& spec) {
  try {
    return linalg::make_linear_solver(spec.solver.linear_solver);
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: {}", spec.file.string(), e.what()));
  }
}

/// The sparse direct solver, and for "auto" the backend it takes for this many equations.
void log_linear_solver(const LinearSolverChoice& solver, Index equations) {
  const char* name = to_string(solver.kind);
  const std::string reusing =
      fmt::format("mumps reusing {}-precision factorizations", to_string(solver.precision));
  if (parallel::active())
    log::info("  linear solver: MUMPS on the distributed matrix ({} processes; the case names "
              "'{}')",
              parallel::size(), name);
  else if (solver.kind == LinearSolverKind::mumps && solver.reuse_factorization)
    log::info("  linear solver: {}", reusing);
  else if (solver.kind != LinearSolverKind::automatic)
    log::info("  linear solver: {}", name);
  else
    log::info("  linear solver: auto, {} for {} equations (sparselu below {}, unless its "
              "factors fill up)",
              equations < linalg::kAutoSparseLuLimit ? "sparselu" : reusing, equations,
              linalg::kAutoSparseLuLimit);
}

/// The processes that own the nodes of `nodes` (model::node_owner), ascending, as
/// "processes [0, 2]"; "no process" if none has a displacement equation (a rigid body's nodes).
std::string owners_of(const model::Model& model, const std::vector<Index>& nodes) {
  std::set<int> found;
  for (Index node : nodes)
    if (const int owner = model::node_owner(model, node); owner >= 0)
      found.insert(owner);
  if (found.empty())
    return "no process (their displacements are prescribed or follow a rigid body)";
  return fmt::format("processes [{}]", fmt::join(found, ", "));
}

/// On several processes: the equations of each, and where the sides of each contact pair live.
void log_partition(const model::Model& model) {
  if (!parallel::active())
    return;
  std::vector<Index> count(parallel::size(), 0);
  for (int owner : model.problem->equation_owners())
    ++count[owner];
  log::info("  processes: {}, equations of each: {}", parallel::size(), fmt::join(count, ", "));
  for (std::size_t k = 0; k < model.contacts.size(); ++k)
    log::info("  contact {}: slave nodes on {}, master nodes on {}", k + 1,
              owners_of(model, model.contacts[k]->slave().nodes()),
              owners_of(model, model.contacts[k]->master().nodes()));
}

/// Writes the summary, the final report and the error line; returns the exit code.
int finish_run(const io::CaseSpec& spec, const std::filesystem::path& output_dir,
               const nlohmann::json& summary_json, const solver::RunReport& run) {
  if (!parallel::is_root()) // rank 0 writes and reports for all
    return run.success ? kSuccess : run.interrupted ? interrupted_exit_code() : kAnalysisFailed;
  try {
    write_final_summary(output_dir / "summary.json", summary_json);
  } catch (const OutputError& e) {
    std::cerr << "error: " << spec.file.string() << ": " << printable(e.what()) << '\n';
    return kAnalysisFailed;
  }
  if (run.interrupted) {
    std::cerr << "error: " << spec.file.string() << ": " << printable(run.failure)
              << " (results up to the last accepted step are kept)\n";
    return interrupted_exit_code();
  }
  if (!run.success) {
    std::cerr << "error: " << spec.file.string() << ": " << printable(run.failure) << '\n';
    return kAnalysisFailed;
  }
  return kSuccess;
}

/// Copies the log to `output_dir`/run.log from now on (rank 0); the reason if it cannot be
/// opened, the same on every process.
std::string open_run_log(const std::filesystem::path& output_dir) {
  try {
    parallel::agree_on_output([&] {
      if (parallel::is_root())
        log::add_file((output_dir / "run.log").string());
    });
    return {};
  } catch (const OutputError& e) {
    return e.what();
  }
}

/// The state at t = 0 (or at the restart time) with its reactions; the reason if it cannot be
/// written.
std::string write_initial_state(OutputWriter& output, const std::optional<Resume>& resume) {
  try {
    output.write(resume ? resume->time : 0.0, resume ? resume->steps : 0, 0.0, 0, true);
    return {};
  } catch (const OutputError& e) {
    return fmt::format("the initial state could not be written: {}", e.what());
  }
}

/// Reads the restart file into the model; InputError (naming the file) if it does not fit the
/// case or holds the end of the run (read_restart).
Resume resume_from(const std::filesystem::path& file, const io::CaseSpec& spec, model::Model& model,
                   StepState& steps) {
  const Resume resume = read_restart(file, spec, model, steps);
  log::info("continuing from {} at t = {} s (after {} steps)", file.string(), resume.time,
            resume.steps);
  return resume;
}

/// After a run that stopped early: the last accepted state as a VTU file, if it is not one yet.
void write_last_state(model::Model& model, OutputWriter& output, const solver::RunReport& run) {
  solver::Linearization lin; // the reactions of the last accepted state, not the failed attempt
  if (model.problem->linearize(lin, false) != solver::SolveStatus::Converged)
    return;
  try {
    output.write_last_state(run.end_time);
  } catch (const OutputError& e) {
    log::warn("  the last accepted state could not be written: {}", e.what());
  }
}

} // namespace

std::string run_status(const solver::RunReport& run) {
  return run.success ? "completed" : run.interrupted ? "interrupted" : "failed";
}

int interrupted_exit_code() {
  return 128 + (interrupt::signal_number() > 0 ? interrupt::signal_number() : SIGINT);
}

namespace {

/// Step settings from the time keys `t`, over (start, t.end_time].
solver::StepSettings settings_over(const io::CaseSpec& spec, const io::TimeSpec& t, Real start) {
  solver::StepSettings s;
  s.start_time = start;
  s.end_time = t.end_time;
  s.dt = t.dt;
  s.dt_min = t.dt_min > 0 ? t.dt_min : t.dt * 1e-6;
  s.dt_max = t.dt_max > 0 ? t.dt_max : t.dt;
  s.growth = t.growth;
  s.cutback = t.cutback;
  s.target_iterations = t.target_iterations;
  const auto inside = [&](Real time) { return time > start && time < t.end_time; };
  for (Real time : spec.output.times)
    if (inside(time))
      s.must_points.push_back(time);
  if (spec.output.interval > 0)
    for (Real time = spec.output.interval; time < t.end_time; time += spec.output.interval)
      if (inside(time))
        s.must_points.push_back(time);
  for (const auto& [name, curve] : spec.curves) // a repeating curve's in every period
    for (Real time : model::make_curve(spec, name).breakpoints(start, t.end_time))
      if (inside(time))
        s.must_points.push_back(time);
  return s;
}

/// The pseudo-time step of a steady-state step: 1e4 times the slowest transport time of the
/// model (drainage L^2/(H kappa), ion diffusion L^2/d), so that each backward-Euler pseudo-step
/// leaves at most about 4e-5 of the transient while the friction of the fluxes stays well above
/// the round-off of the potentials (docs/theory/triphasic.md, steady-state steps).
Real steady_pseudo_step(const model::Model& model) {
  const Real L2 = model.length_scale * model.length_scale;
  Real slowest = L2 / (model.modulus_scale * model.permeability_scale);
  for (const model::CellMaterial& m : model.materials)
    if (m.mixture && m.mixture->charged)
      slowest = std::max(slowest, L2 / std::min(m.mixture->d_plus, m.mixture->d_minus));
  return 1e4 * slowest;
}

/// Adds the totals of `part` (a later step) to `run`.
void accumulate(solver::RunReport& run, const solver::RunReport& part) {
  run.success = part.success;
  run.steps += part.steps;
  run.iterations += part.iterations;
  run.linear_iterations += part.linear_iterations;
  run.cutbacks += part.cutbacks;
  run.failed_attempts += part.failed_attempts;
  run.roundoff_floor_steps += part.roundoff_floor_steps;
  run.end_time = part.end_time;
  run.failure = part.failure;
  run.interrupted = part.interrupted;
}

} // namespace

solver::StepSettings step_settings(const io::CaseSpec& spec) {
  return settings_over(spec, spec.time, 0.0);
}

solver::StepSettings step_settings(const io::CaseSpec& spec, std::size_t k) {
  const Real start = k == 0 ? 0.0 : spec.steps.at(k - 1).time.end_time;
  return settings_over(spec, spec.steps.at(k).time, start);
}

solver::RunReport run_steps(const io::CaseSpec& spec, model::Model& model, StepState& steps,
                            solver::NewtonSolver& newton, const solver::StepObserver& observer,
                            const std::function<void(const solver::StepController&)>& on_start,
                            const Resume* resume, const ExplicitRunner& run_explicit) {
  const Real tol = 1e-10 * std::max(1.0, spec.time.end_time);
  const int before = resume ? resume->steps : 0; // steps of the run before the restart
  solver::RunReport run;
  run.success = true;
  const auto run_over = [&](solver::StepSettings settings) {
    if (resume && resume->time > settings.start_time + tol) { // continue inside this step
      settings.start_time = resume->time;
      settings.dt = std::max(resume->dt, settings.dt_min);
    }
    solver::StepController controller(settings);
    on_start(controller);
    const int offset = before + run.steps;
    accumulate(run, solver::run_time_loop(*model.problem, newton, controller,
                                          [&](const solver::StepInfo& info) {
                                            solver::StepInfo whole = info;
                                            whole.step += offset;
                                            observer(whole);
                                          }));
  };
  // of the last dynamic step's end (or the rigid bodies' initial velocity)
  Vector velocity = resume ? resume->velocity : model.initial_velocity;
  const auto explicit_step = [&](std::optional<std::size_t> k) {
    TRIFEM_VERIFY(run_explicit, "a dynamic-explicit step without its integrator");
    accumulate(run, run_explicit(k, before + run.steps, velocity));
  };
  if (model.steps.empty()) {
    if (spec.is_explicit()) {
      explicit_step(std::nullopt);
      return run;
    }
    if (spec.analysis.type == io::AnalysisType::Dynamic)
      model.problem->set_dynamic(true, !resume, velocity);
    run_over(step_settings(spec));
    return run;
  }
  // the model may have further steps (a mixed case's dynamic-explicit one): those of spec run
  for (std::size_t k = 0; k < spec.steps.size() && run.success; ++k) {
    if (resume && model.steps[k].end_time <= resume->time + tol)
      continue; // done before the restart
    if (static_cast<int>(k) != steps.active)
      activate_step(model, k, steps);
    const model::ModelStep& step = model.steps[k];
    const bool is_explicit = spec.steps[k].is_explicit();
    if (!is_explicit && !spec.steps[k].is_dynamic())
      velocity = Vector(); // a quasi-static step ends at rest
    if (model.problem->inertia()) {
      // a run continued from a restart file holds the motion of the step it was written in
      const bool moving = resume && (resume->time > step.start_time + tol ||
                                     (k > 0 && spec.steps[k - 1].is_dynamic()));
      model.problem->set_dynamic(spec.steps[k].is_dynamic(), !moving, velocity);
    }
    log::info("analysis step {} '{}'{}: t = {:.6g} to {:.6g} s, {} prescribed DOFs", k + 1,
              step.name,
              is_explicit                  ? " (dynamic-explicit)"
              : spec.steps[k].is_dynamic() ? " (dynamic)"
                                           : "",
              step.start_time, step.end_time, model.problem->dof_map().num_constrained());
    if (is_explicit) {
      explicit_step(k);
      continue;
    }
    solver::StepSettings settings = step_settings(spec, k);
    if (spec.steps[k].steady) {
      settings.steady_dt = steady_pseudo_step(model);
      log::info("  steady state: each time is reached by backward-Euler pseudo-steps of {:.3g} s",
                settings.steady_dt);
    }
    run_over(settings);
    velocity = model.problem->velocity();
  }
  return run;
}

solver::NewtonSettings newton_settings(const io::SolverSpec& s) {
  solver::NewtonSettings n;
  n.max_iterations = s.max_iterations;
  n.residual_tolerance = s.residual_tolerance;
  n.increment_tolerance = s.increment_tolerance;
  n.line_search = s.line_search;
  return n;
}

namespace {

/// Builds the dynamic-explicit step `k` of `spec` (nullopt: the whole case) on `model` at its
/// current state and time `start`; InputErrors prefixed with the case file (and the step).
std::unique_ptr<ExplicitStep> explicit_step(const io::CaseSpec& spec, const io::CaseSpec& part,
                                            std::optional<std::size_t> k, model::Model& model,
                                            Real start, const Vector& velocity = {}) {
  try {
    return std::make_unique<ExplicitStep>(part, model, start, velocity);
  } catch (const InputError& e) {
    if (!k)
      throw InputError(fmt::format("{}: {}", spec.file.string(), e.what()));
    throw InputError(fmt::format("{} (dynamic-explicit, t = {:.6g} s): {}", spec.steps[*k].key,
                                 start, e.what()));
  }
}

/// The dynamic-explicit steps of a run and what summary.json says of them.
class ExplicitSteps {
public:
  /// A dynamic-explicit case builds its step (and estimates its time step) at once: an invalid
  /// case then creates no output.
  ExplicitSteps(const io::CaseSpec& spec, model::Model& model) : spec_(spec), model_(model) {
    if (spec.has_explicit_step())
      with_case_file(spec, [&] { check_explicit_model(model); });
    if (spec.is_explicit()) {
      parts_.push_back(explicit_part(spec, std::nullopt));
      whole_ = explicit_step(spec, parts_.back(), std::nullopt, model, 0.0, model.initial_velocity);
    }
  }
  void log_settings() const {
    if (whole_)
      whole_->log_settings();
  }
  /// Continues the whole case's step from `resume` (read from `file` into the model);
  /// InputError naming the file if its integrator state does not fit. A run continued inside
  /// one of several steps restores it when the step begins.
  void continue_from(const Resume& resume, const std::filesystem::path& file) {
    resume_ = &resume;
    resume_file_ = file.string();
    if (whole_)
      restore(*whole_);
  }
  /// Writes a restart file at every output time of the steps that run.
  void write_restarts(RestartWriter writer) { restart_ = std::move(writer); }

  /// Runs step k (nullopt: the whole case) into `output` after `steps_before` steps of the
  /// run, starting with `velocity` (empty: at rest), which becomes that of the last accepted
  /// state.
  solver::RunReport run(std::optional<std::size_t> k, OutputWriter& output, int steps_before,
                        Vector& velocity) {
    std::unique_ptr<ExplicitStep> step = std::move(whole_);
    const Real start = model_.problem->time();
    if (k) {
      parts_.push_back(explicit_part(spec_, k));
      const Real step_start = model_.steps[*k].start_time;
      const bool resumed = resume_ && resume_->time > step_start;
      log::info("  starting {}", resumed               ? "from the restart file"
                                 : velocity.size() > 0 ? "with the velocity of the previous step"
                                                       : "at rest");
      try {
        step =
            explicit_step(spec_, parts_.back(), k, model_, resumed ? step_start : start, velocity);
        if (resumed)
          restore(*step);
      } catch (const InputError& e) {
        solver::RunReport failed;
        failed.end_time = start;
        failed.failure = e.what();
        return failed;
      }
      step->log_settings();
    }
    resume_ = nullptr;
    const std::string history = k ? fmt::format("history_step{}.csv", *k + 1) : "history.csv";
    const int before = steps_before - static_cast<int>(step->steps()); // the run's, at its start
    RestartWriter restart;
    if (restart_)
      restart = [&](Resume r) {
        r.steps += before;
        restart_(r);
      };
    solver::RunReport report = step->run(output, history, !k, restart);
    velocity = step->velocity();
    failed_ = !report.success;
    nlohmann::json entries = step->summary();
    ran_.push_back(std::move(step)); // a dynamic-explicit case's history stays in use
    if (k)
      entries.update(
          {{"step", spec_.steps[*k].name}, {"start_time_s", start}, {"history", history}});
    summaries_.push_back(std::move(entries));
    histories_[k.value_or(0)] = history;
    return report;
  }
  /// True if the last step that ran was an explicit one that stopped early.
  bool failed() const { return failed_; }
  /// Adds the entries of the explicit steps that ran to summary.json.
  void add_to(nlohmann::json& summary) const {
    if (summaries_.empty())
      return;
    if (spec_.is_explicit()) { // the entries of Newton's method do not apply
      for (const char* key : {"newton_iterations", "linear_iterations", "cutbacks",
                              "failed_attempts", "roundoff_floor_steps"})
        summary.erase(key);
      summary["analysis"] = "dynamic-explicit";
      summary.update(summaries_.front());
      return;
    }
    summary["analysis"] = "quasi-static, dynamic-explicit";
    summary["dynamic_explicit"] = summaries_.back();
    nlohmann::json steps = nlohmann::json::array();
    Real start = 0.0;
    for (std::size_t k = 0; k < spec_.steps.size(); ++k) {
      const io::StepSpec& step = spec_.steps[k];
      const auto history = histories_.find(k);
      steps.push_back({{"name", step.name},
                       {"analysis", step.is_explicit() ? "dynamic-explicit" : "quasi-static"},
                       {"start_time_s", start},
                       {"end_time_s", step.time.end_time},
                       {"history", history != histories_.end() ? history->second : "history.csv"}});
      start = step.time.end_time;
    }
    summary["analysis_steps"] = steps;
  }

private:
  void restore(ExplicitStep& step) const {
    try {
      step.restore(resume_->integrator);
    } catch (const InputError& e) {
      throw InputError(fmt::format("{}: {}", resume_file_, e.what()));
    }
  }

  const io::CaseSpec& spec_;
  model::Model& model_;
  const Resume* resume_ = nullptr; ///< the run continues from it (until its step begins)
  std::string resume_file_;
  RestartWriter restart_;
  std::list<io::CaseSpec> parts_; ///< what each step sees (its steps refer to them)
  std::unique_ptr<ExplicitStep> whole_;
  std::vector<std::unique_ptr<ExplicitStep>> ran_;
  std::vector<nlohmann::json> summaries_;
  std::map<std::size_t, std::string> histories_;
  bool failed_ = false;
};

/// Runs a case on its model: every analysis step, results in `output_dir`.
int run_model(const io::CaseSpec& spec, const std::filesystem::path& output_dir,
              const RunOptions& options) {
  const auto start = Clock::now();
  std::unique_ptr<model::Model> model = build_model_for(spec);
  ExplicitSteps explicit_steps(spec, *model);
  std::optional<Resume> resume;
  StepState steps;
  if (!options.restart_file.empty()) {
    resume = resume_from(options.restart_file, spec, *model, steps);
    explicit_steps.continue_from(*resume, options.restart_file);
  } else {
    steps = start_steps(*model);
  }
  const bool write_restarts = options.write_restart || spec.output.restart;
  std::unique_ptr<linalg::LinearSolver> linear_solver = linear_solver_for(spec);
  parallel::agree_on_output([&] { // rank 0 writes every file of a parallel run
    if (parallel::is_root())
      start_output_directory(output_dir, spec);
  });
  OutputWriter output(*model, spec.output, output_dir, spec.time.end_time);
  const std::string log_failure = open_run_log(output_dir);
  log_model(spec, *model);
  explicit_steps.log_settings();
  log_partition(*model);

  solver::NewtonSolver newton(newton_settings(spec.solver), std::move(linear_solver));
  if (!spec.is_explicit())
    log_linear_solver(spec.solver.linear_solver, model->problem->num_equations());
  const solver::StepController* controller = nullptr; // of the current analysis step
  solver::RunReport run;
  solver::Linearization initial;
  if (!log_failure.empty()) {
    run.failure = log_failure;
  } else if (model->problem->linearize(initial, false) != solver::SolveStatus::Converged) {
    run.failure = "the initial state (t = 0) inverts an element (J <= 0; prescribed values "
                  "without a load curve apply from t = 0) or a material law cannot be evaluated "
                  "there";
  } else if (!initial.residual.allFinite()) {
    run.failure = "the forces of the initial state (t = 0) are not finite: a material parameter "
                  "or a load is beyond what the laws can evaluate";
  } else if (std::string why = spec.is_explicit() ? "" : write_initial_state(output, resume);
             !why.empty()) { // the explicit analysis writes its own initial state
    run.failure = why;
  } else {
    bool noted = false;
    const auto save_restart = [&](const Resume& state) { // at an output time
      parallel::agree_on_output([&] {
        if (parallel::is_root())
          write_restart(output_dir / fmt::format("restart_{:04d}.bin", output.last_state_index()),
                        spec, *model, steps, state);
      });
    };
    if (write_restarts)
      explicit_steps.write_restarts(save_restart);
    auto observer = [&](const solver::StepInfo& info) {
      if (output.balance())
        output.balance()->record_step(info.transport_dt);
      const int linear = info.newton->linear_iterations;
      log::info("step {:4d}  t = {:<10.5g} dt = {:<9.3g} iterations {:2d}  residual {:.2e}{}{}",
                info.step, info.time, info.dt, info.newton->iterations, info.newton->final_residual,
                linear > 0 ? fmt::format("  linear iterations {}", linear) : "",
                progress(info.time, spec.time.end_time, Clock::now() - start));
      note_roundoff_floor(*model, info, noted);
      const bool volume = output.is_output_time(info.time) || controller->finished();
      output.write(info.time, info.step, info.dt, info.newton->iterations, volume);
      if (volume && write_restarts)
        save_restart(
            {controller->time(), controller->dt(), info.step, model->problem->velocity(), {}});
    };
    run = run_steps(
        spec, *model, steps, newton, observer,
        [&](const solver::StepController& c) { controller = &c; }, resume ? &*resume : nullptr,
        [&](std::optional<std::size_t> k, int steps_before, Vector& velocity) {
          return explicit_steps.run(k, output, steps_before, velocity);
        });
    if (!run.success && !explicit_steps.failed()) // (an explicit step writes its own)
      write_last_state(*model, output, run);
  }
  const double wall = std::chrono::duration<double>(Clock::now() - start).count();
  nlohmann::json summary_json =
      summary(spec, *model, run, newton.times(), output.seconds(), wall, output.balance());
  explicit_steps.add_to(summary_json);
  log::info("{}: {} steps, {} {} iterations, {} {}, {:.2f} s (assembly {:.2f}, "
            "factorization {:.2f}, solve {:.2f}, output {:.2f})",
            run.success       ? "completed"
            : run.interrupted ? "INTERRUPTED"
                              : "FAILED",
            run.steps, run.iterations, spec.is_explicit() ? "multiplier" : "Newton", run.cutbacks,
            spec.is_explicit() ? "halvings" : "cutbacks", wall, newton.times().assembly,
            newton.times().factorization, newton.times().solve, output.seconds());
  log::info("results: {} ({} VTU files), {}, {}", output.pvd_file().string(), output.vtu_count(),
            output.history_file().string(), (output_dir / "summary.json").string());
  if (const auto surfaces = output.surfaces_pvd_file(); !surfaces.empty())
    log::info("surface meshes (rigid bodies given by their surface): {}", surfaces.string());
  return finish_run(spec, output_dir, summary_json, run);
}

} // namespace

int run_case(const io::CaseSpec& spec, const std::filesystem::path& output_dir,
             const RunOptions& options) {
  try {
    return run_model(spec, output_dir, options);
  } catch (const std::bad_alloc&) { // reported by the caller; the summary must not say running
    abandon_summary("out of memory: the model is too large for the memory available");
    throw;
  } catch (const InputError& e) {
    abandon_summary(e.what());
    throw;
  } catch (const std::exception& e) {
    abandon_summary(fmt::format("internal error: {}", e.what()));
    throw;
  }
}

int check_case(const io::CaseSpec& spec) {
  std::unique_ptr<model::Model> model = build_model_for(spec);
  start_steps(*model); // the equations of the first step
  log_model(spec, *model);
  const ExplicitSteps explicit_steps(spec, *model); // the stable step of an explicit analysis
  explicit_steps.log_settings();
  if (!spec.is_explicit())
    linear_solver_for(spec); // unknown or unused PETSc options
  log::info("check passed: the case is valid");
  return kSuccess;
}

} // namespace trifem::analysis
