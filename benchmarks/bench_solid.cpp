// SPDX-License-Identifier: MIT
// Benchmarks of the solid core: hex8 kernel, global assembly, UMFPACK, one Newton solve.
#include "trifem/assembly/fe_problem.hpp"
#include "trifem/linalg/linear_solver.hpp"
#include "trifem/material/registry.hpp"
#include "trifem/mesh/box.hpp"
#include "trifem/physics/solid_kernel.hpp"
#include "trifem/physics/solid_term.hpp"
#include "trifem/solver/newton.hpp"

#include <benchmark/benchmark.h>
#include <omp.h>

#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

using namespace trifem;

namespace {

/// Relative stretch of the box in z used for deformed states and the Newton solve.
constexpr Real kStretch = 0.05;

/// The law `type` with the registry's example (cartilage) parameters.
std::shared_ptr<const material::ElasticLaw> make_law(const std::string& type) {
  return material::create_law(type, material::find_law(type, "bench").example, "bench");
}

// ---------------------------------------------------------------------------------------------
// Element kernel
// ---------------------------------------------------------------------------------------------

/// A unit cube with every node moved by up to +-0.075 (deterministic), and a displacement field
/// of amplitude 0.05 on it: a generic, admissible deformed state.
struct DistortedElement {
  fe::HexGeometry geo;
  fe::HexCoords u;

  DistortedElement() {
    std::mt19937 rng(20240611u);
    std::uniform_real_distribution<Real> unit(-1.0, 1.0);
    const Real corners[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    fe::HexCoords X;
    for (int a = 0; a < 8; ++a)
      for (int k = 0; k < 3; ++k) {
        X(a, k) = corners[a][k] + 0.075 * unit(rng);
        u(a, k) = 0.05 * unit(rng);
      }
    geo = fe::hex8_geometry(X).value();
  }
};

/// solid_hex8 on one element; `tangent` selects residual + tangent or residual only.
void bm_hex8_kernel(benchmark::State& state, const std::string& type, bool tangent) {
  const auto law = make_law(type);
  const DistortedElement element;
  physics::HexVector f;
  physics::HexMatrix K;
  for (auto _ : state) {
    const bool ok = physics::solid_hex8(element.geo, element.u, *law, f, tangent ? &K : nullptr);
    benchmark::DoNotOptimize(ok);
    benchmark::DoNotOptimize(f.data());
    benchmark::DoNotOptimize(K.data());
    benchmark::ClobberMemory();
  }
  if (!physics::solid_hex8(element.geo, element.u, *law, f, nullptr))
    state.SkipWithError("the benchmark state is inadmissible (J <= 0)");
  state.SetItemsProcessed(state.iterations()); // one element per iteration -> elements/s
}

// ---------------------------------------------------------------------------------------------
// Box models
// ---------------------------------------------------------------------------------------------

/// A unit box of n^3 hex8 cells, neo-Hookean, bottom (z = 0) fixed; optionally u_z of the top
/// ramped to kStretch over t in [0, 1]. Never moved once built (terms refer to its members).
struct BoxModel {
  mesh::Mesh mesh;
  dofs::DofMap map;
  dofs::FieldId u;
  std::vector<dofs::DirichletCondition> conditions;
  std::shared_ptr<const material::ElasticLaw> law;

  BoxModel(int n, bool stretch_top) {
    mesh::BoxSpec spec;
    spec.divisions = {n, n, n};
    mesh = mesh::make_box(spec);
    law = make_law("neo-hookean");
    u = map.add_field("displacement", FieldRole::displacement, mesh.num_nodes(), 3);
    dofs::DirichletCondition bottom;
    for (Index node : mesh.node_set("box.zmin"))
      for (int k = 0; k < 3; ++k)
        bottom.dofs.push_back(map.dof(u, node, k));
    conditions.push_back(std::move(bottom));
    if (stretch_top) {
      dofs::DirichletCondition top{
          {}, kStretch, dofs::LoadCurve({{0.0, 0.0}, {1.0, 1.0}}, dofs::Interpolation::Linear)};
      for (Index node : mesh.node_set("box.zmax"))
        top.dofs.push_back(map.dof(u, node, 2));
      conditions.push_back(std::move(top));
    }
    dofs::constrain_all(conditions, map);
    map.finalize();
  }
  BoxModel(const BoxModel&) = delete;
  BoxModel& operator=(const BoxModel&) = delete;

  std::unique_ptr<physics::SolidTerm> make_solid_term() const {
    std::vector<Index> cells(mesh.num_cells());
    for (Index c = 0; c < mesh.num_cells(); ++c)
      cells[c] = c;
    std::vector<std::shared_ptr<const material::ElasticLaw>> laws(cells.size(), law);
    return std::make_unique<physics::SolidTerm>(mesh, map, u, std::move(cells), std::move(laws));
  }

  /// A smooth deformed state: 5 % stretch in z, lateral contraction and a small shear, zero at
  /// the fixed bottom.
  Vector deformed_state() const {
    Vector x(map.num_dofs());
    for (Index node = 0; node < mesh.num_nodes(); ++node) {
      const Vec3& X = mesh.node(node);
      x[map.dof(u, node, 0)] = X.z() * (-0.015 * (X.x() - 0.5) + 0.01 * X.y());
      x[map.dof(u, node, 1)] = -0.015 * X.z() * (X.y() - 0.5);
      x[map.dof(u, node, 2)] = kStretch * X.z();
    }
    return x;
  }
};

/// Everything assembly needs for a box of n^3 cells, built once per n and reused by every run.
struct AssemblyFixture {
  BoxModel model;
  std::unique_ptr<physics::SolidTerm> solid;
  std::unique_ptr<assembly::Assembler> assembler;
  assembly::AssembledSystem system;
  Vector x;
  Index colours = 0;

  explicit AssemblyFixture(int n) : model(n, false) {
    solid = model.make_solid_term();
    colours = static_cast<Index>(
        assembly::colour_elements(assembly::collect_stencils(*solid), model.map.num_dofs()).size());
    assembler = std::make_unique<assembly::Assembler>(
        model.map, std::vector<const physics::Term*>{solid.get()});
    system = assembler->make_system();
    x = model.deformed_state();
  }

  bool assemble() {
    const physics::EvalState state{x, x, 0.0, 0.0};
    return assembler->assemble(state, system, true);
  }

  static AssemblyFixture& get(int n) {
    static std::map<int, std::unique_ptr<AssemblyFixture>> cache;
    auto& slot = cache[n];
    if (!slot)
      slot = std::make_unique<AssemblyFixture>(n);
    return *slot;
  }
};

void set_size_counters(benchmark::State& state, const AssemblyFixture& fx) {
  state.counters["elements"] = static_cast<double>(fx.model.mesh.num_cells());
  state.counters["equations"] = static_cast<double>(fx.model.map.num_equations());
  state.counters["nnz_Kff"] = static_cast<double>(fx.system.Kff.nonZeros());
  state.counters["colours"] = static_cast<double>(fx.colours);
}

// ---------------------------------------------------------------------------------------------
// Assembly
// ---------------------------------------------------------------------------------------------

/// Residual + both Jacobian blocks of the n^3 box (Assembler::assemble), OMP_NUM_THREADS threads.
void bm_assemble_system(benchmark::State& state) {
  AssemblyFixture& fx = AssemblyFixture::get(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    const bool ok = fx.assemble();
    benchmark::DoNotOptimize(ok);
    benchmark::DoNotOptimize(fx.system.Kff.valuePtr());
    benchmark::ClobberMemory();
  }
  if (!fx.assemble())
    state.SkipWithError("the benchmark state is inadmissible (J <= 0)");
  state.SetItemsProcessed(state.iterations() * fx.model.mesh.num_cells());
  state.counters["threads"] = omp_get_max_threads();
  set_size_counters(state, fx);
}

// ---------------------------------------------------------------------------------------------
// Linear solver
// ---------------------------------------------------------------------------------------------

/// UMFPACK numeric factorization of K_ff (symbolic analysis done once, outside the loop).
void bm_factorize(benchmark::State& state) {
  AssemblyFixture& fx = AssemblyFixture::get(static_cast<int>(state.range(0)));
  if (!fx.assemble()) {
    state.SkipWithError("the benchmark state is inadmissible (J <= 0)");
    return;
  }
  auto lu = linalg::make_linear_solver({LinearSolverKind::umfpack});
  lu->analyze_pattern(fx.system.Kff);
  bool ok = true;
  for (auto _ : state) {
    ok = lu->factorize(fx.system.Kff) && ok;
    benchmark::ClobberMemory();
  }
  if (!ok)
    state.SkipWithError("UMFPACK factorization failed");
  state.counters["threads"] = omp_get_max_threads();
  set_size_counters(state, fx);
}

/// Forward/back substitution with an existing UMFPACK factorization of K_ff.
void bm_solve(benchmark::State& state) {
  AssemblyFixture& fx = AssemblyFixture::get(static_cast<int>(state.range(0)));
  if (!fx.assemble()) {
    state.SkipWithError("the benchmark state is inadmissible (J <= 0)");
    return;
  }
  auto lu = linalg::make_linear_solver({LinearSolverKind::umfpack});
  lu->analyze_pattern(fx.system.Kff);
  if (!lu->factorize(fx.system.Kff)) {
    state.SkipWithError("UMFPACK factorization failed");
    return;
  }
  const Vector b = Vector::Ones(fx.model.map.num_equations());
  Vector dx(b.size());
  bool ok = true;
  for (auto _ : state) {
    ok = lu->solve(b, dx) && ok;
    benchmark::DoNotOptimize(dx.data());
    benchmark::ClobberMemory();
  }
  if (!ok)
    state.SkipWithError("UMFPACK solve failed");
  state.counters["threads"] = omp_get_max_threads();
  set_size_counters(state, fx);
}

// ---------------------------------------------------------------------------------------------
// Newton
// ---------------------------------------------------------------------------------------------

/// One full Newton solve (default settings, UMFPACK) of the n^3 box from rest to a 5 % stretch
/// prescribed on the top in one step. The symbolic analysis is reused across solves, as in a
/// time loop; a warm-up solve outside the loop does it once.
void bm_newton_step(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  BoxModel model(n, true);
  std::vector<std::unique_ptr<physics::Term>> terms;
  terms.push_back(model.make_solid_term());
  const Real L = std::sqrt(3.0); // bounding-box diagonal of the unit box
  std::vector<solver::FieldScale> scales = {
      {"displacement", model.law->p_wave_modulus() * L * L, L}};
  assembly::FeProblem problem(model.map, model.conditions, std::move(terms), std::move(scales));
  solver::NewtonSolver newton(solver::NewtonSettings{},
                              linalg::make_linear_solver({LinearSolverKind::umfpack}));
  const Vector rest = Vector::Zero(model.map.num_dofs());

  auto solve_once = [&] {
    problem.set_state(rest);
    problem.begin_step(1.0, 1.0);
    return newton.solve(problem);
  };
  solver::NewtonReport report = solve_once(); // warm-up: symbolic analysis
  if (report.status != solver::SolveStatus::Converged) {
    state.SkipWithError(("Newton failed: " + report.failure_reason).c_str());
    return;
  }
  const solver::PhaseTimes before = newton.times();
  for (auto _ : state) {
    state.PauseTiming();
    problem.set_state(rest);
    problem.begin_step(1.0, 1.0);
    state.ResumeTiming();
    report = newton.solve(problem);
  }
  if (report.status != solver::SolveStatus::Converged)
    state.SkipWithError(("Newton failed: " + report.failure_reason).c_str());
  const solver::PhaseTimes& after = newton.times();
  const auto per_solve_ms = [&](double total) {
    return benchmark::Counter(1e3 * total, benchmark::Counter::kAvgIterations);
  };
  state.counters["newton_iterations"] = report.iterations;
  state.counters["assembly_ms"] = per_solve_ms(after.assembly - before.assembly);
  state.counters["factorize_ms"] = per_solve_ms(after.factorization - before.factorization);
  state.counters["solve_ms"] = per_solve_ms(after.solve - before.solve);
  state.counters["threads"] = omp_get_max_threads();
  state.counters["equations"] = static_cast<double>(model.map.num_equations());
}

} // namespace

int main(int argc, char** argv) {
  for (const auto& law : material::registered_laws()) {
    benchmark::RegisterBenchmark(("BM_Hex8Kernel/" + law.type).c_str(), bm_hex8_kernel, law.type,
                                 true);
    benchmark::RegisterBenchmark(("BM_Hex8Residual/" + law.type).c_str(), bm_hex8_kernel, law.type,
                                 false);
  }
  benchmark::RegisterBenchmark("BM_AssembleSystem", bm_assemble_system)
      ->Arg(10)
      ->Arg(20)
      ->Arg(30)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
  benchmark::RegisterBenchmark("BM_Factorize", bm_factorize)
      ->Arg(10)
      ->Arg(20)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
  benchmark::RegisterBenchmark("BM_Solve", bm_solve)
      ->Arg(10)
      ->Arg(20)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
  benchmark::RegisterBenchmark("BM_NewtonStep", bm_newton_step)
      ->Arg(10)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();

  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv))
    return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
