// SPDX-License-Identifier: MIT
// Benchmarks of the explicit multiplier scheme (issue 5) on a 47³ = 103 823-cell hex8 cube:
// the cell loops, the multiplier system (CHOLMOD) and whole steps of reading B, split into
// force evaluation and Λ solve. Threads: run with OMP_NUM_THREADS=1 and 2 (and the same
// OPENBLAS_NUM_THREADS); see docs/performance.md, section "Explicit dynamics".
#include "fixtures.hpp"

#include "trifem/explicit/explicit_solver.hpp"
#include "trifem/explicit/lambda_system.hpp"
#include "trifem/mesh/box.hpp"

#include <benchmark/benchmark.h>
#include <omp.h>

#include <memory>

using namespace trifem;
using namespace trifem::explicit_dynamics;

namespace {

constexpr int kN = 47;          ///< cells per edge: 47³ = 103 823 cells, 110 592 nodes
constexpr Real kTimeStep = 0.5; ///< below 0.8 · 2/ω_iso ≈ 0.65 for unit cells, μ = ρ = 1
constexpr Real kPenalty = 1e4;  ///< α = 1e4 μ

/// The unit-cell cube, bottom clamped, follower pressure 0.05 μ on the top (applied at t = 0).
const ExplicitView& model() {
  static const test::TestModel m = [] {
    mesh::BoxSpec box;
    box.name = "cube";
    box.size = Vec3(kN, kN, kN);
    box.divisions = {kN, kN, kN};
    test::ExplicitTestCase c(mesh::make_box(box), test::deviatoric_material(1.0, 1.0));
    c.fix("cube.zmin", {0, 1, 2}).pressure("cube.zmax", 0.05, test::step_curve());
    return test::TestModel(c);
  }();
  return m;
}

/// A smooth admissible deformed state (a few per cent of stretch and shear).
const Vector& deformed_state() {
  static const Vector U = [] {
    const ExplicitView& m = model();
    Vector u(m.num_dofs());
    for (Index a = 0; a < m.mesh().num_nodes(); ++a) {
      const Vec3 X = m.mesh().node(a) / kN;
      u.segment<3>(3 * a) = kN * 0.03 * Vec3(X[0] * X[2], -0.5 * X[1] * X[2], X[2] * X[2] - X[0]);
    }
    return u;
  }();
  return U;
}

void set_counters(benchmark::State& state, Real cells_per_iteration) {
  state.counters["cells/s"] =
      benchmark::Counter(cells_per_iteration, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["threads"] = omp_get_max_threads();
}

/// One cell loop: Q_V, H and Ψ (what reading B evaluates once per step), or Ψ only (what each
/// Λ iteration evaluates).
void BM_CellLoop(benchmark::State& state) {
  const bool full = state.range(0) == 1;
  const CellRequest request{full, full, true, false};
  CellFields fields;
  evaluate_cells(model(), Constraint::JMinusOne, deformed_state(), request, fields); // warm-up
  for (auto _ : state) {
    const CellStatus s =
        evaluate_cells(model(), Constraint::JMinusOne, deformed_state(), request, fields);
    benchmark::DoNotOptimize(s);
    benchmark::DoNotOptimize(fields.psi.data());
  }
  state.SetLabel(full ? "Q_V + H + Psi" : "Psi only");
  set_counters(state, model().num_cells());
}
BENCHMARK(BM_CellLoop)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime();

/// The multiplier system: assembly + numeric factorization (symbolic analysis outside), and
/// one solve with it.
struct LambdaFixture {
  CellFields fields;
  LambdaSystem system{model()};
  Vector diagonal = model().volumes() / kPenalty;
  LambdaFixture() { evaluate_cells(model(), Constraint::JMinusOne, deformed_state(), {}, fields); }
  bool factorize() {
    return system.factorize(fields.gradient, model().inverse_mass(), kTimeStep * kTimeStep,
                            diagonal);
  }
};

LambdaFixture& lambda_fixture() {
  static LambdaFixture f;
  return f;
}

void BM_LambdaFactorize(benchmark::State& state) {
  LambdaFixture& f = lambda_fixture();
  for (auto _ : state)
    benchmark::DoNotOptimize(f.factorize());
  set_counters(state, model().num_cells());
}
BENCHMARK(BM_LambdaFactorize)->Unit(benchmark::kSecond)->Iterations(2)->UseRealTime();

void BM_LambdaSolve(benchmark::State& state) {
  LambdaFixture& f = lambda_fixture();
  f.factorize();
  const Vector b = f.fields.psi;
  Vector x;
  for (auto _ : state) {
    f.system.solve(b, x);
    benchmark::DoNotOptimize(x.data());
  }
  set_counters(state, model().num_cells());
}
BENCHMARK(BM_LambdaSolve)->Unit(benchmark::kMillisecond)->UseRealTime();

/// Whole steps of reading B under the suddenly applied pressure, with the multiplier matrix
/// refactorized every step (arg 1) or reused for up to 20 steps (arg 20). Counters: seconds
/// per step in the cell loops ("forces") and in the multiplier system ("lambda"),
/// multiplier iterations per step.
void BM_Step(benchmark::State& state) {
  ExplicitSettings s;
  s.penalty = kPenalty;
  s.stable_step = StableStepMethod::None;
  s.time_step = kTimeStep;
  s.factorization_age = static_cast<int>(state.range(0));
  ExplicitSolver solver(model(), s);
  solver.step(1e30); // first step (half-step start) outside the timing
  const SolverTimings t0 = solver.timings();
  const long it0 = solver.total_iterations(), steps0 = solver.step_count();
  for (auto _ : state) {
    const StepReport r = solver.step(1e30);
    if (!r.ok())
      state.SkipWithError(r.message.c_str());
  }
  const double steps = static_cast<double>(solver.step_count() - steps0);
  state.counters["forces s/step"] = (solver.timings().forces - t0.forces) / steps;
  state.counters["lambda s/step"] = (solver.timings().lambda - t0.lambda) / steps;
  state.counters["factorizations/step"] =
      static_cast<double>(solver.timings().factorizations - t0.factorizations) / steps;
  state.counters["iterations/step"] = static_cast<double>(solver.total_iterations() - it0) / steps;
  state.counters["element-steps/s"] =
      benchmark::Counter(model().num_cells(), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["threads"] = omp_get_max_threads();
}
BENCHMARK(BM_Step)->Arg(1)->Iterations(3)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK(BM_Step)->Arg(20)->Iterations(20)->Unit(benchmark::kSecond)->UseRealTime();

} // namespace

BENCHMARK_MAIN();
