// SPDX-License-Identifier: MIT
#include "trifem/analysis/explicit_step.hpp"

#include "trifem/core/error.hpp"
#include "trifem/core/interrupt.hpp"
#include "trifem/core/log.hpp"
#include "trifem/core/timer.hpp"
#include "trifem/model/conditions.hpp"
#include "trifem/model/rigid_bodies.hpp"
#include "trifem/parallel/communicator.hpp"

#include <algorithm>
#include <cmath>
#include <set>

namespace trifem::analysis {
namespace {

namespace ed = explicit_dynamics;

/// More VTU files than this from `output.interval = 0` get a warning.
constexpr double kManyFiles = 1000.0;

/// A scalar array from a per-cell vector.
io::DataArray cell_array(std::string name, const Vector& v) {
  return {std::move(name), 1, std::vector<double>(v.data(), v.data() + v.size())};
}

/// The multiplier's pressure per cell: −Λ (Ψ = J − 1, σ = Λ I) or −Λ/J̄ (Ψ = ln J, τ = Λ I).
Vector multiplier_pressure(const ed::ExplicitSolver& s) {
  const Vector& lambda = s.multiplier();
  if (s.settings().constraint == ed::Constraint::JMinusOne)
    return -lambda;
  const Vector J = s.fields().volume_change.array() + 1.0;
  return -lambda.cwiseQuotient(J);
}

/// Refuses a step that, once the stable step is known, needs more than io::kMaxSteps steps (the
/// reader checks this only for a requested time.dt).
void check_step_count(const io::CaseSpec& part, const ed::TimeStepInfo& t, Real start) {
  const double steps = (part.time.end_time - start) / t.used;
  if (steps <= io::kMaxSteps)
    return;
  throw InputError(fmt::format(
      "time.end_time = {:.6g} s: with the {} of {:.6g} s the run needs {:.3g} steps, more than "
      "the {:.0e} allowed (shorten time.end_time; a coarser mesh allows longer steps)",
      part.time.end_time, t.reduced || t.requested <= 0.0 ? "stability estimate" : "time.dt",
      t.used, steps, io::kMaxSteps));
}

ed::ExplicitSettings settings_of(const io::CaseSpec& part) {
  ed::ExplicitSettings s;
  static_cast<io::ExplicitSpec&>(s) = part.explicit_dynamics;
  s.time_step = part.time.dt;
  return s;
}

} // namespace

/// The integrator's additions to the results: its columns, its reactions (in the model's DOFs),
/// its arrays.
class ExplicitStep::Results final : public StepResults {
public:
  Results(const ed::ExplicitView& view, const ed::ExplicitSolver& solver, const model::Model& model)
      : view_(view), solver_(solver), residual_(Vector::Zero(model.dofs.num_dofs())) {}

  /// The state after `report` (the model's state is set by the caller), with the velocity if
  /// a VTU state follows. Collective on several processes: the values every process writes
  /// (rank 0 its history row, each its piece) are evaluated here.
  void update(const ed::StepReport& report, bool volume) {
    report_ = report;
    view_.scatter(solver_.reaction_force(), residual_);
    energies_ = solver_.energies();
    if (volume)
      velocity_ = solver_.velocity();
  }
  std::vector<std::string> columns() const override {
    return {"halvings",           "constraint_residual", "max|Jbar-1|",
            "max_gauss|J-1|",     "kinetic [mJ]",        "strain [mJ]",
            "external_work [mJ]", "damping_work [mJ]",   "total_energy [mJ]"};
  }
  void append_values(std::vector<double>& row) const override {
    const ed::Energies& e = energies_;
    row.insert(row.end(), {static_cast<double>(report_.halvings), report_.constraint_residual,
                           solver_.max_volume_change(), solver_.max_gauss_volume_change(),
                           e.kinetic, e.strain, e.external_work, e.damping_work, e.total()});
  }
  const Vector& full_residual() const override { return residual_; }
  /// The velocity beside the model's point arrays; the multiplier, its pressure and J̄ − 1
  /// instead of the model's cell arrays (whose stresses leave out the multiplier's pressure).
  void add_arrays(std::vector<io::DataArray>& point,
                  std::vector<io::DataArray>& cell) const override {
    const Vector& v = velocity_;
    point.push_back({"velocity [mm/s]", 3, std::vector<double>(v.data(), v.data() + v.size())});
    cell = {cell_array("multiplier [MPa]", solver_.multiplier()),
            cell_array("pressure [MPa]", multiplier_pressure(solver_)),
            cell_array("Jbar-1", solver_.fields().volume_change)};
  }

private:
  const ed::ExplicitView& view_;
  const ed::ExplicitSolver& solver_;
  ed::StepReport report_;
  ed::Energies energies_;
  Vector residual_, velocity_;
};

namespace {

/// A time an explicit step must land on.
struct StepTarget {
  Real time = 0.0;     ///< [s]
  bool output = false; ///< an output time (VTU file); otherwise a point of a load curve
};

/// The VTU output interval of an explicit step from `start` [s]: output.interval if given (0:
/// every step), otherwise (end_time − start) / io::kDefaultOutputCount (about 100 files, the
/// steps landing on them).
Real explicit_output_interval(const io::CaseSpec& spec, Real start) {
  return spec.output.interval_given ? spec.output.interval
                                    : (spec.time.end_time - start) / io::kDefaultOutputCount;
}

/// The times the step from `start` must land on, ascending, each > start: the multiples of the
/// output interval (counted from 0 if output.interval is given, from `start` otherwise),
/// output.times and time.end_time (the last) as output times, and the points of the load curves
/// in between (as the quasi-static must points).
std::vector<StepTarget> explicit_step_targets(const io::CaseSpec& spec, Real start) {
  const Real end = spec.time.end_time, interval = explicit_output_interval(spec, start);
  const Real origin = spec.output.interval_given ? 0.0 : start; // of the periodic output times
  std::vector<StepTarget> targets;
  if (interval > 0.0)
    for (long k = 1; origin + static_cast<Real>(k) * interval < end; ++k)
      targets.push_back({origin + static_cast<Real>(k) * interval, true});
  for (const Real t : spec.output.times)
    targets.push_back({t, true});
  for (const auto& [name, curve] : spec.curves) // a repeating curve's in every period
    for (const Real time : model::make_curve(spec, name).breakpoints(start, end))
      targets.push_back({time, false});
  const Real eps = 1e-12 * end;
  std::erase_if(targets,
                [&](const StepTarget& t) { return t.time <= start + eps || t.time >= end - eps; });
  targets.push_back({end, true});
  std::sort(targets.begin(), targets.end(),
            [](const StepTarget& a, const StepTarget& b) { return a.time < b.time; });
  std::vector<StepTarget> merged; // near-equal times once, an output time if any of them is
  for (const StepTarget& t : targets) {
    if (!merged.empty() && t.time - merged.back().time <= eps)
      merged.back().output = merged.back().output || t.output;
    else
      merged.push_back(t);
  }
  return merged;
}

} // namespace

io::CaseSpec explicit_part(const io::CaseSpec& spec, std::optional<std::size_t> k) {
  io::CaseSpec part = spec;
  if (k) {
    part.time = io::TimeSpec{};
    part.time.end_time = spec.steps.at(*k).time.end_time;
    part.time.dt = spec.steps.at(*k).time.dt;
  }
  return part;
}

void check_explicit_model(const model::Model& model) {
  ed::ExplicitView::check_cells(model);
  for (const model::Probe& p : model.probes)
    TRIFEM_CHECK(p.quantity->name == "displacement" || p.quantity->name == "position",
                 "output.probe '{}': dynamic-explicit analyses probe only 'displacement' and "
                 "'position' (not '{}')",
                 p.name, p.quantity->name);
}

ExplicitStep::ExplicitStep(const io::CaseSpec& part, model::Model& model, Real start,
                           const Vector& velocity)
    : part_(part), model_(model), start_(start),
      view_(std::make_unique<ed::ExplicitView>(model, model::rigid_shell_masses(part, model))),
      balance_(*view_) {
  check_explicit_model(model);
  const Vector& x = model.problem->state();
  ed::InitialState initial{view_->gather(x),
                           velocity.size() > 0 ? view_->gather(velocity) : Vector(),
                           model.problem->time()};
  for (std::size_t b = 0; b < view_->bodies().size(); ++b)
    initial.bodies.push_back(view_->motion(b, x, velocity));
  solver_ = std::make_unique<ed::ExplicitSolver>(*view_, settings_of(part), initial);
  check_step_count(part, solver_->time_step_info(), start);
  results_ = std::make_unique<Results>(*view_, *solver_, model);
}

ExplicitStep::~ExplicitStep() = default;

void ExplicitStep::log_settings() const {
  std::set<std::string> logged;
  for (const model::CellMaterial& m : model_.materials)
    if (m.rigid() && logged.insert(m.name).second)
      log::info("  rigid body {}: density {:.4g} t/mm^3", m.name, m.density);
    else if (logged.insert(m.name).second)
      log::info("  material {}: {}, density {:.4g} t/mm^3, shear modulus {:.4g} MPa", m.name,
                m.solid->type(), m.density, m.solid->shear_modulus());
  const ed::ExplicitSettings& s = solver_->settings();
  log::info("  dynamic-explicit: reading {}, constraint {}, {}penalty {:.4g} MPa, damping {:.4g} "
            "1/s, safety factor {:.3g}",
            s.reading == ed::Reading::A ? "A" : "B",
            s.constraint == ed::Constraint::LogJ ? "lnJ" : "J-1",
            s.multiplier ? "" : "no multiplier, ", s.penalty, s.damping, s.safety());
  const ed::TimeStepInfo& t = solver_->time_step_info();
  if (t.reduced)
    log::warn("  time.dt = {:.6g} s is above the stability estimate: reduced to {:.6g} s",
              t.requested, t.used);
  const double steps = std::ceil((part_.time.end_time - start_) / t.used);
  log::info("  time step: {:.6g} s ({}), about {:.0f} steps to t = {:.6g} s", t.used,
            t.requested > 0.0 && !t.reduced ? "time.dt" : "stability estimate", steps,
            part_.time.end_time);
  if (part_.output.vtu && explicit_output_interval(part_, start_) <= 0.0 && steps > kManyFiles)
    log::warn("  output.interval = 0 writes a VTU file every step: about {:.0f} files (set "
              "output.interval)",
              steps);
}

namespace {
/// The values of state() before the integrator's: the halvings and the energy balance's scale,
/// largest error and flag.
constexpr std::size_t kStepScalars = 4;
} // namespace

std::vector<double> ExplicitStep::state() const {
  const std::array<Real, 3> balance = balance_.state();
  std::vector<double> s = {static_cast<double>(halvings_), balance[0], balance[1], balance[2]};
  const std::vector<double> integrator = solver_->state();
  s.insert(s.end(), integrator.begin(), integrator.end());
  return s;
}

std::size_t ExplicitStep::state_size(const model::Model& model) {
  return kStepScalars + ed::ExplicitSolver::state_size(3 * model.mesh.num_nodes(),
                                                       model.mesh.num_cells(),
                                                       ed::ExplicitView::count_bodies(model));
}

void ExplicitStep::restore(const std::vector<double>& state) {
  TRIFEM_CHECK(state.size() == state_size(model_),
               "the dynamic-explicit step's state has {} values, this model's needs {}",
               state.size(), state_size(model_));
  TRIFEM_CHECK(state[0] >= 0.0 && state[0] == std::floor(state[0]),
               "the dynamic-explicit step's state is invalid ({} halvings)", state[0]);
  solver_->restore(view_->gather(model_.problem->state()),
                   std::vector<double>(state.begin() + kStepScalars, state.end()));
  halvings_ = static_cast<long>(state[0]);
  balance_.restore({state[1], state[2], state[3]});
}

void ExplicitStep::write(OutputWriter& output, const ed::StepReport& report, bool volume) {
  ScopedTimer timer(output_seconds_);
  Vector x = model_.problem->state();
  view_->scatter_state(solver_->displacement(), solver_->body_motions(), solver_->time(), x);
  model_.problem->set_state(x);
  model_.problem->set_time(solver_->time());
  results_->update(report, volume);
  output.write(solver_->time(), static_cast<int>(solver_->step_count()), report.dt,
               report.iterations, volume);
}

void ExplicitStep::advance(OutputWriter& output, solver::RunReport& run,
                           const RestartWriter& restart) {
  const bool every_step = explicit_output_interval(part_, start_) <= 0.0;
  // history rows: every step, or the first step at or after each multiple of history_interval
  const Real rows = part_.output.history_interval;
  const auto next_row_after = [&](Real t) {
    return start_ + (std::floor((t - start_) / rows * (1.0 + 1e-12)) + 1.0) * rows;
  };
  Real next_row = rows > 0.0 ? next_row_after(solver_->time()) : 0.0;
  for (const StepTarget& target : explicit_step_targets(part_, start_)) {
    const Real eps = 1e-12 * std::max(target.time, solver_->time_step_info().used);
    while (solver_->time() < target.time - eps) {
      if (parallel::any(interrupt::requested())) { // a signal to one process stops them all
        run.interrupted = true;
        run.failure = fmt::format("interrupted at t = {:.6g} s", solver_->time());
        return;
      }
      const ed::StepReport r = solver_->step(target.time);
      halvings_ += r.halvings;
      if (!r.ok()) {
        log::info("run stopped: {} ({})", r.message, ed::to_string(r.status));
        run.failure = r.message;
        return;
      }
      ++run.steps;
      run.iterations += r.iterations;
      run.end_time = solver_->time();
      const bool reached = solver_->time() >= target.time - eps;
      const bool volume = every_step || (reached && target.output);
      if (rows > 0.0 && !volume && !reached && solver_->time() < next_row - eps)
        continue; // no history row at this step
      if (rows > 0.0)
        next_row = next_row_after(solver_->time());
      write(output, r, volume);
      if (volume && restart) { // the run from this file and this one factorize anew alike
        restart({solver_->time(), solver_->time_step(), static_cast<int>(solver_->step_count()),
                 velocity(), state()});
        solver_->refactorize();
      }
      log::debug("step {:6d}  t = {:<12.6g} dt = {:<10.4g} iterations {:2d}  constraint {:.1e}",
                 solver_->step_count(), solver_->time(), r.dt, r.iterations, r.constraint_residual);
    }
    if (!target.output)
      continue;
    const ed::Energies e = solver_->energies();
    log::info("t = {:<10.6g} step {:6d}  kinetic {:.4g}  strain {:.4g}  external {:.4g}  total "
              "{:.3g} mJ",
              solver_->time(), solver_->step_count(), e.kinetic, e.strain, e.external_work,
              e.total());
    if (balance_.record(e))
      log::warn("t = {:.6g} s: the energy balance is off by {:.3g} % of the largest energy "
                "(kinetic + strain - external work + damping = {:.4g} mJ). The step is probably "
                "above the stability limit: lower explicit.safety_factor, leave out time.dt or "
                "use explicit.stable_step = \"element-bound\" (docs/input.md)",
                solver_->time(), 100.0 * balance_.last_error(), e.total());
  }
  run.success = true;
}

solver::RunReport ExplicitStep::run(OutputWriter& output, const std::string& history,
                                    bool initial_volume, const RestartWriter& restart) {
  const auto start = WallClock::now();
  solver::RunReport run;
  run.end_time = solver_->time();
  log::info("  initial strain energy {:.6g} mJ", solver_->initial_energy());
  try {
    output.use_history(history, results_.get());
    write(output, ed::StepReport{}, initial_volume);
    advance(output, run, restart);
  } catch (const OutputError& e) { // solved, but the results cannot be written
    run.success = false;
    run.failure = fmt::format("the results at t = {:.6g} could not be written: {}", solver_->time(),
                              e.what());
  }
  if (history != "history.csv") // back to the run's history (a step of a quasi-static case)
    output.use_history("history.csv", nullptr);
  run.cutbacks = halvings_;
  if (balance_.exceeded())
    log::warn("the energy balance error reached {:.3g} % of the largest energy: check the "
              "results ({}, total_energy [mJ])",
              100.0 * balance_.max_error(), history);
  wall_seconds_ = seconds_since(start);
  return run;
}

Vector ExplicitStep::velocity() const {
  Vector v = Vector::Zero(model_.dofs.num_dofs());
  view_->scatter(solver_->velocity(), v);
  const std::vector<ed::BodyVelocity> bodies = solver_->body_velocities();
  for (std::size_t b = 0; b < bodies.size(); ++b)
    view_->scatter_body_velocity(b, solver_->body_motions()[b], bodies[b].pivot, bodies[b].omega,
                                 v);
  return v;
}

long ExplicitStep::steps() const {
  return solver_->step_count();
}

nlohmann::json ExplicitStep::summary() const {
  const ed::SolverTimings& w = solver_->timings();
  const ed::Energies e = solver_->energies();
  const ed::TimeStepInfo& t = solver_->time_step_info();
  nlohmann::json j;
  j["end_time_s"] = solver_->time();
  j["steps"] = solver_->step_count();
  j["multiplier_solves"] = solver_->total_iterations();
  j["halvings"] = halvings_;
  j["factorizations"] = w.factorizations;
  j["time_step_s"] = {
      {"omega_iso_per_s", t.omega}, {"critical", t.critical}, {"estimate", t.stable},
      {"requested", t.requested},   {"used", t.used},         {"reduced", t.reduced}};
  j["energies_mJ"] = {
      {"kinetic", e.kinetic},           {"strain", e.strain}, {"external_work", e.external_work},
      {"damping_work", e.damping_work}, {"total", e.total()}, {"initial", e.initial}};
  j["energy_balance"] = {{"max_relative_error", balance_.max_error()},
                         {"threshold", ed::EnergyBalance::kThreshold},
                         {"exceeded", balance_.exceeded()}};
  j["max_abs_Jbar_minus_1"] = solver_->max_volume_change();
  j["wall_time_s"] = {{"total", wall_seconds_},   {"forces", w.forces},       {"lambda", w.lambda},
                      {"assemble", w.assemble},   {"factorize", w.factorize}, {"solve", w.solve},
                      {"output", output_seconds_}};
  return j;
}

} // namespace trifem::analysis
