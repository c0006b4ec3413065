// SPDX-License-Identifier: MIT
// Benchmarks of the triphasic mixture: hex8 kernel (98/49 DOFs) and the paper's confined column.
#include "trifem/assembly/fe_problem.hpp"
#include "trifem/linalg/linear_solver.hpp"
#include "trifem/material/mixture.hpp"
#include "trifem/material/registry.hpp"
#include "trifem/mesh/box.hpp"
#include "trifem/physics/mixture_kernel.hpp"
#include "trifem/physics/mixture_term.hpp"
#include "trifem/solver/newton.hpp"
#include "trifem/solver/time_loop.hpp"

#include <benchmark/benchmark.h>
#include <omp.h>

#include <chrono>
#include <fstream>
#include <memory>
#include <random>
#include <string>
#include <vector>

using namespace trifem;

namespace {

/// The paper's section 4.1 tissue: SVK solid E = 0.3 MPa, nu = 0, phi_s0 = 0.25,
/// kappa = 1.07e-3 mm^4/(N s); triphasic adds cF0 = 2e-4 mEq/mm^3, d+- = 5e-4 / 8e-4 mm^2/s.
material::MixtureProperties paper_tissue(bool charged) {
  auto solid = material::create_law("saint-venant-kirchhoff", {{"E", 0.3}, {"nu", 0.0}}, "bench");
  material::ParameterValues values = {{"phi_s0", 0.25}, {"permeability", 1.07e-3}};
  if (charged) {
    values["fixed_charge"] = 2e-4;
    values["d_plus"] = 5e-4;
    values["d_minus"] = 8e-4;
  }
  return material::make_mixture(charged, std::move(solid), values, "bench");
}

// ---------------------------------------------------------------------------------------------
// Element kernel
// ---------------------------------------------------------------------------------------------

/// One distorted unit hex (nodes moved by up to +-0.075) at a deformed, non-equilibrium state:
/// displacements up to 0.08 mm, fluxes of typical size, p and eta off the Donnan values, a
/// volume change since the last step and ion moles off equilibrium. Deterministic.
struct MixtureElement {
  fe::HexGeometry geo;
  physics::MixtureUnknowns x;
  physics::MixtureHistory history;
  material::MixtureProperties mat;
  material::Electrochemistry chem;
  physics::MixtureStep step;
  physics::MixtureLayout layout;

  explicit MixtureElement(bool ions) : mat(paper_tissue(ions)), layout{ions} {
    std::mt19937 rng(20240612u);
    std::uniform_real_distribution<Real> unit(-1.0, 1.0);
    const Real corners[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    fe::HexCoords X;
    for (int a = 0; a < 8; ++a)
      for (int k = 0; k < 3; ++k) {
        X(a, k) = corners[a][k] + 0.075 * unit(rng);
        x.u(a, k) = 0.08 * unit(rng);
        x.w(a, k) = 2e-5 * unit(rng);
        x.jp(a, k) = ions ? 3e-9 * unit(rng) : 0.0;
        x.jm(a, k) = ions ? 2e-9 * unit(rng) : 0.0;
      }
    x.p = 0.12;
    x.eta = ions ? -1500.0 : 0.0;
    geo = fe::hex8_geometry(X).value();
    Real V0 = 0.0;
    for (Real dV : geo.dV)
      V0 += dV;
    const Real Vw = 0.75 * V0;
    history.V0 = V0;
    history.V_old = 0.97 * V0;
    if (ions) {
      history.N_fixed = history.N_fixed_old = 2e-4 * Vw;
      history.N_plus = 2.9e-4 * Vw;
      history.N_minus = 0.85e-4 * Vw;
    }
    step = {0.7, 0.0, &chem};
  }

  bool evaluate(physics::LocalVector& r, physics::LocalMatrix* K) const {
    return physics::mixture_hex8(geo, x, history, mat, step, layout, r, K);
  }
};

/// mixture_hex8 on one element; `tangent` selects residual + tangent or residual only.
void bm_mixture_kernel(benchmark::State& state, bool ions, bool tangent) {
  const MixtureElement element(ions);
  physics::LocalVector r;
  physics::LocalMatrix K;
  for (auto _ : state) {
    const bool ok = element.evaluate(r, tangent ? &K : nullptr);
    benchmark::DoNotOptimize(ok);
    benchmark::DoNotOptimize(r.data());
    benchmark::DoNotOptimize(K.data());
    benchmark::ClobberMemory();
  }
  if (!element.evaluate(r, nullptr))
    state.SkipWithError("the benchmark state is inadmissible");
  state.SetItemsProcessed(state.iterations()); // one element per iteration -> elements/s
  state.counters["dofs"] = element.layout.size();
}

// ---------------------------------------------------------------------------------------------
// Confined compression column (paper section 4.1) as a 3-D block
// ---------------------------------------------------------------------------------------------

/// Platen displacement [mm], ramp time [s], step size [s] and number of steps of the run.
constexpr Real kPlaten = -0.05, kRamp = 50.0, kStep = 2.5;
constexpr int kSteps = 5;

/// A 1 x 1 x 1 mm triphasic block of n x n x 4n hex8 cells: bottom fixed and impermeable,
/// lateral faces confined (normal u = 0) and impermeable, top = porous platen in the bath with
/// u_z ramped to kPlaten over kRamp. Initial state: Donnan equilibrium at the reference (IC-1).
/// Never moved once built (the terms and the problem refer to its members).
struct ColumnModel {
  mesh::Mesh mesh;
  dofs::DofMap map;
  physics::MixtureFields f;
  material::Electrochemistry chem;
  std::shared_ptr<const material::MixtureProperties> props;
  std::vector<dofs::DirichletCondition> conditions;
  std::unique_ptr<assembly::FeProblem> problem;

  explicit ColumnModel(int n) {
    mesh::BoxSpec spec;
    spec.divisions = {n, n, 4 * n};
    mesh = mesh::make_box(spec);
    props = std::make_shared<material::MixtureProperties>(paper_tissue(true));
    f.u = map.add_field("displacement", FieldRole::displacement, mesh.num_nodes(), 3);
    f.w = map.add_field("fluid_flux", FieldRole::flux, mesh.num_nodes(), 3);
    f.j_plus = map.add_field("cation_flux", FieldRole::flux, mesh.num_nodes(), 3);
    f.j_minus = map.add_field("anion_flux", FieldRole::flux, mesh.num_nodes(), 3);
    f.p = map.add_field("pressure", FieldRole::potential, mesh.num_cells(), 1);
    f.eta = map.add_field("potential", FieldRole::potential, mesh.num_cells(), 1);

    for (const char* face : {"box.xmin", "box.xmax"})
      confine(face, 0);
    for (const char* face : {"box.ymin", "box.ymax"})
      confine(face, 1);
    for (int k = 0; k < 2; ++k)
      fix("box.zmin", f.u, k);
    confine("box.zmin", 2);
    fix("box.zmax", f.u, 2, kPlaten,
        dofs::LoadCurve({{0.0, 0.0}, {kRamp, 1.0}}, dofs::Interpolation::Linear));
    dofs::constrain_all(conditions, map);
    map.finalize();

    std::vector<Index> cells(mesh.num_cells());
    for (Index c = 0; c < mesh.num_cells(); ++c)
      cells[c] = c;
    std::vector<std::shared_ptr<const material::MixtureProperties>> cell_props(cells.size(), props);
    auto term = std::make_unique<physics::MixtureTerm>(mesh, map, f, std::move(cells),
                                                       std::move(cell_props), chem);
    physics::MixtureTerm* mixture = term.get();
    std::vector<std::unique_ptr<physics::Term>> terms;
    terms.push_back(std::move(term));
    problem = std::make_unique<assembly::FeProblem>(map, conditions, std::move(terms), scales());
    Vector x = problem->state();
    mixture->initialize(physics::InitialState::Donnan, 0.0, x);
    problem->set_state(x);
  }
  ColumnModel(const ColumnModel&) = delete;
  ColumnModel& operator=(const ColumnModel&) = delete;

  /// Fixes component k of `field` on a node set to value * curve(t).
  void fix(const std::string& set, dofs::FieldId field, int k, Real value = 0.0,
           dofs::LoadCurve curve = dofs::LoadCurve::constant()) {
    dofs::DirichletCondition c{{}, value, std::move(curve)};
    for (Index node : mesh.node_set(set))
      c.dofs.push_back(map.dof(field, node, k));
    conditions.push_back(std::move(c));
  }

  /// Zero normal displacement and zero normal water and ion fluxes on a face with normal axis k.
  void confine(const std::string& set, int k) {
    for (dofs::FieldId field : {f.u, f.w, f.j_plus, f.j_minus})
      fix(set, field, k);
  }

  /// Characteristic sizes: length L, modulus M, flux M kappa / L; residuals = M L^3 / size.
  std::vector<solver::FieldScale> scales() const {
    const Real L = 1.0, M = props->solid->p_wave_modulus();
    const Real flux = M * props->permeability / L, energy = M * L * L * L;
    std::vector<solver::FieldScale> s(map.num_fields());
    const auto set = [&](dofs::FieldId id, Real size) {
      s[id.index] = {map.field(id).name, energy / size, size};
    };
    set(f.u, L);
    set(f.w, flux);
    set(f.j_plus, flux);
    set(f.j_minus, flux);
    set(f.p, M);
    set(f.eta, M);
    return s;
  }

  /// `steps` fixed steps of kStep from the current time (no growth, as in the paper's step
  /// sequence).
  solver::RunReport run(solver::NewtonSolver& newton, int steps = kSteps) {
    solver::StepSettings s;
    s.start_time = problem->time();
    s.end_time = s.start_time + steps * kStep;
    s.dt = s.dt_max = kStep;
    s.dt_min = 1e-4 * kStep;
    solver::StepController controller(s);
    return solver::run_time_loop(*problem, newton, controller, [](const solver::StepInfo&) {});
  }
};

/// A field of /proc/self/status in MB (VmHWM: peak resident set size, VmRSS: current).
double proc_status_mb(const std::string& key) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind(key + ":", 0) == 0)
      return std::stod(line.substr(key.size() + 1)) / 1024.0; // the value is in kB
  return 0.0;
}

/// Resets VmHWM to the current RSS (Linux >= 4.0); false if the kernel refused.
bool reset_peak_rss() {
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5";
  clear.flush();
  return static_cast<bool>(clear);
}

/// One iteration: a fresh model (built with the timer paused) solved for kSteps steps. The
/// Newton solver, and so UMFPACK's symbolic analysis, is reused across iterations as in a time
/// loop; a one-step warm-up outside the loop does the analysis. Outside the loop too, one
/// symbolic analysis (analyze_ms) and one assembly with Jacobian (linearize_ms, the second of
/// two calls) are timed on their own.
void bm_confined_compression(benchmark::State& state) {
  using Clock = std::chrono::steady_clock;
  const int n = static_cast<int>(state.range(0));
  const bool peak_reset = reset_peak_rss();
  const double rss_before = proc_status_mb("VmRSS");

  auto model = std::make_unique<ColumnModel>(n);
  const Index equations = model->map.num_equations();
  const Index cells = model->mesh.num_cells();
  const auto ms_since = [](Clock::time_point start) {
    return 1e3 * std::chrono::duration<double>(Clock::now() - start).count();
  };
  double analyze_ms = 0.0, linearize_ms = 0.0;
  Index nnz = 0;
  {
    solver::Linearization lin;
    model->problem->begin_step(kStep, kStep);
    for (int call = 0; call < 2; ++call) {
      const auto start = Clock::now();
      if (model->problem->linearize(lin, true) != solver::SolveStatus::Converged) {
        state.SkipWithError("the initial state cannot be evaluated");
        return;
      }
      linearize_ms = ms_since(start);
    }
    nnz = lin.jacobian.nonZeros();
    auto lu = linalg::make_linear_solver({LinearSolverKind::umfpack});
    const auto start = Clock::now();
    lu->analyze_pattern(lin.jacobian);
    analyze_ms = ms_since(start);
    model->problem->reject_step();
  }
  solver::NewtonSolver newton(solver::NewtonSettings{},
                              linalg::make_linear_solver({LinearSolverKind::umfpack}));
  solver::RunReport report = model->run(newton, 1); // warm-up: symbolic analysis
  if (!report.success) {
    state.SkipWithError(("the warm-up run failed: " + report.failure).c_str());
    return;
  }

  const solver::PhaseTimes before = newton.times();
  double run_seconds = 0.0;
  long iterations = 0;
  for (auto _ : state) {
    state.PauseTiming();
    model.reset();
    model = std::make_unique<ColumnModel>(n);
    state.ResumeTiming();
    const auto start = Clock::now();
    report = model->run(newton);
    run_seconds += std::chrono::duration<double>(Clock::now() - start).count();
    iterations += report.iterations;
    if (!report.success) {
      state.SkipWithError(("the run failed: " + report.failure).c_str());
      return;
    }
  }
  const solver::PhaseTimes& after = newton.times();
  const double runs = static_cast<double>(state.iterations());
  const double per_run = iterations / runs;
  const auto ms_per_run = [&](double total) { return 1e3 * total / runs; };

  state.counters["cells"] = static_cast<double>(cells);
  state.counters["equations"] = static_cast<double>(equations);
  state.counters["nnz_Kff"] = static_cast<double>(nnz);
  state.counters["threads"] = omp_get_max_threads();
  // not "iterations": that key would overwrite the benchmark's own count in the JSON output
  state.counters["newton_iterations"] = per_run; // per run of kSteps steps
  state.counters["ms_per_iter"] = 1e3 * run_seconds / iterations;
  state.counters["assembly_ms"] = ms_per_run(after.assembly - before.assembly);
  state.counters["factorize_ms"] = ms_per_run(after.factorization - before.factorization);
  state.counters["solve_ms"] = ms_per_run(after.solve - before.solve);
  state.counters["analyze_ms"] = analyze_ms;
  state.counters["linearize_ms"] = linearize_ms;
  state.counters["rss_before_MB"] = rss_before;
  state.counters["peak_MB"] = proc_status_mb("VmHWM");
  if (!peak_reset)
    state.SetLabel("VmHWM not reset: peak of the whole process so far");
}

} // namespace

int main(int argc, char** argv) {
  for (const bool ions : {true, false}) {
    const std::string type = ions ? "triphasic" : "biphasic";
    benchmark::RegisterBenchmark(("BM_MixtureKernel/" + type).c_str(), bm_mixture_kernel, ions,
                                 true);
    benchmark::RegisterBenchmark(("BM_MixtureResidual/" + type).c_str(), bm_mixture_kernel, ions,
                                 false);
  }
  benchmark::RegisterBenchmark("BM_ConfinedCompression", bm_confined_compression)
      ->Arg(2)
      ->Arg(4)
      ->Arg(6)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();

  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv))
    return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
