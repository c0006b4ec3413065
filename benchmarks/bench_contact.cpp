// SPDX-License-Identifier: MIT
// Benchmarks of contact per Newton iteration versus the number of slave nodes: search and
// projections alone, ContactTerm::prepare (search, projections of slave and master nodes,
// active set, stencils), the loop over all contact elements with residual and tangent, and the
// contact assembly into the sparse system. Two thin stacked blocks with non-matching interface
// meshes; see docs/performance.md, section "Contact search and assembly". Run with
// OMP_NUM_THREADS=1.
#include "trifem/assembly/fe_problem.hpp"
#include "trifem/contact/contact_term.hpp"
#include "trifem/contact/projection.hpp"
#include "trifem/mesh/box.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

using namespace trifem;

namespace {

constexpr Real kModulus = 1.0;      ///< E: sets c_N = E / h_s and the multiplier level
constexpr Real kCompression = 0.01; ///< vertical compressive strain of both blocks
constexpr Real kPoisson = 0.3;      ///< lateral expansion = kPoisson * kCompression
constexpr Real kBending = 0.02;     ///< amplitude of a smooth sin·sin bending of both blocks
constexpr Real kPenetration = 0.05; ///< interface penetration, in slave facet sizes h_s
constexpr Real kOffsetX = 0.3;      ///< tangential offset of the upper block, in h_s
constexpr Real kOffsetY = 0.2;
constexpr Real kPressure = 0.01; ///< contact pressure at the edges of the interface, in E

/// Master facets per side for n_s slave facets per side: 3/4 as many (non-matching).
int master_divisions(int n_s) {
  return std::max(1, (3 * n_s) / 4);
}

/// A unit-square block of n × n × 1 hex8 cells, one cell thick, with its bottom at z0.
mesh::Mesh make_layer(const std::string& name, int n, Real z0) {
  mesh::BoxSpec spec;
  spec.name = name;
  spec.origin = Vec3(0, 0, z0);
  spec.size = Vec3(1, 1, 1.0 / n);
  spec.divisions = {n, n, 1};
  return mesh::make_box(spec);
}

/// The two blocks: "lower" (n_s × n_s facets on its top, the slave surface lower.zmax) and
/// "upper" (3/4 n_s facets per side, master surface upper.zmin) touching in the reference
/// configuration at z = h_s.
mesh::Mesh two_layers(int n_s) {
  mesh::Mesh mesh = make_layer("lower", n_s, 0.0);
  mesh.append(make_layer("upper", master_divisions(n_s), 1.0 / n_s));
  return mesh;
}

/// Displacement of a node of either block: a uniform compression with lateral expansion, a
/// smooth bending evaluated at the current in-plane position (so both interface surfaces bend
/// alike), and for the upper block a rigid tangential offset and a penetration into the lower
/// one.
Vec3 displacement(const Vec3& X, bool upper, Real h_s) {
  Vec3 u(kPoisson * kCompression * (X.x() - 0.5), kPoisson * kCompression * (X.y() - 0.5),
         -kCompression * X.z());
  if (upper)
    u += Vec3(kOffsetX * h_s, kOffsetY * h_s, -kPenetration * h_s);
  const Real x = X.x() + u.x(), y = X.y() + u.y();
  u.z() += kBending * std::sin(std::numbers::pi * x) * std::sin(std::numbers::pi * y);
  return u;
}

/// Contact pressure at slave node X: kPressure * E, raised by up to 50 % towards the centre. Not
/// uniform, so that the derivatives through the master-node projections (Σ_k ∂M_k/∂ζ λ_k) do not
/// vanish as they would for equal multipliers.
Real pressure(const Vec3& X) {
  return kPressure * kModulus *
         (1 + 0.5 * std::sin(std::numbers::pi * X.x()) * std::sin(std::numbers::pi * X.y()));
}

/// Everything one size needs: mesh, DOFs (bottom of the lower block fixed), the contact term
/// (frictionless, both-surface integration) and a deformed, compressive state. prepare() has
/// been called once at that state. Never moved once built.
struct ContactFixture {
  int n_s;
  mesh::Mesh mesh;
  dofs::DofMap map;
  dofs::FieldId u, lambda;
  std::unique_ptr<contact::ContactTerm> term;
  std::unique_ptr<assembly::Assembler> assembler; ///< built on first use (assembly only)
  Vector x;

  explicit ContactFixture(int n) : n_s(n), mesh(two_layers(n)) {
    u = map.add_field("displacement", FieldRole::displacement, mesh.num_nodes(), 3);
    lambda = map.add_field("contact_pressure", FieldRole::multiplier,
                           static_cast<Index>(mesh.node_set("lower.zmax").size()), 1);
    for (Index node : mesh.node_set("lower.zmin"))
      for (int k = 0; k < 3; ++k)
        map.constrain(map.dof(u, node, k));
    map.finalize();
    contact::ContactSettings settings;
    settings.scale = kModulus * n; // c_N = E / h_s
    term = std::make_unique<contact::ContactTerm>(
        mesh, map, u, lambda, mesh.surface("upper.zmin"), mesh.surface("lower.zmax"),
        std::make_shared<contact::FrictionlessLaw>(u), settings);
    x = deformed_state();
    term->prepare(eval_state());
  }
  ContactFixture(const ContactFixture&) = delete;
  ContactFixture& operator=(const ContactFixture&) = delete;

  /// Displacements from displacement(), multipliers from pressure().
  Vector deformed_state() const {
    Vector out(map.num_dofs());
    const auto& upper = mesh.node_set("upper.all");
    for (Index node = 0; node < mesh.num_nodes(); ++node) {
      const bool is_upper = std::binary_search(upper.begin(), upper.end(), node);
      const Vec3 d = displacement(mesh.node(node), is_upper, 1.0 / n_s);
      for (int k = 0; k < 3; ++k)
        out[map.dof(u, node, k)] = d[k];
    }
    const auto& slave = term->slave().nodes();
    for (Index k = 0; k < static_cast<Index>(slave.size()); ++k)
      out[term->multiplier_dof(k, 0)] = -pressure(mesh.node(slave[k]));
    return out;
  }

  physics::EvalState eval_state() const { return {x, x, 1.0, 1.0}; }

  /// Current nodal positions X + u in the state x.
  contact::NodePositions positions() const {
    return contact::NodePositions([this](Index n) {
      return Vec3(mesh.node(n) +
                  Vec3(x[map.dof(u, n, 0)], x[map.dof(u, n, 1)], x[map.dof(u, n, 2)]));
    });
  }

  Index slave_nodes() const { return term->slave().num_nodes(); }
  Index master_nodes() const { return term->master().num_nodes(); }

  assembly::Assembler& get_assembler() {
    if (!assembler)
      assembler =
          std::make_unique<assembly::Assembler>(map, std::vector<const physics::Term*>{term.get()});
    return *assembler;
  }

  static ContactFixture& get(int n) {
    static std::map<int, std::unique_ptr<ContactFixture>> cache;
    auto& slot = cache[n];
    if (!slot)
      slot = std::make_unique<ContactFixture>(n);
    return *slot;
  }
};

/// Projected nodes (slave onto master, master onto slave) and how many of them lie inside the
/// other surface.
struct ProjectionCounts {
  Index slave_projected = 0, slave_interior = 0, master_projected = 0, master_interior = 0;
};

ProjectionCounts count_projections(const contact::ContactTerm& term) {
  ProjectionCounts c;
  for (Index k = 0; k < term.slave().num_nodes(); ++k)
    if (const auto& p = term.slave_projection(k)) {
      ++c.slave_projected;
      c.slave_interior += p->on_boundary ? 0 : 1;
    }
  for (Index i = 0; i < term.master().num_nodes(); ++i)
    if (const auto& p = term.master_projection(i)) {
      ++c.master_projected;
      c.master_interior += p->on_boundary ? 0 : 1;
    }
  return c;
}

/// Size counters, the complexity parameter N = slave nodes, slave nodes per second and the
/// time per slave node (seconds; the inverse rate).
void set_counters(benchmark::State& state, const ContactFixture& fx) {
  const auto slave = static_cast<double>(fx.slave_nodes());
  state.SetComplexityN(fx.slave_nodes());
  state.SetItemsProcessed(state.iterations() * fx.slave_nodes());
  state.counters["slave_nodes"] = slave;
  state.counters["master_nodes"] = static_cast<double>(fx.master_nodes());
  state.counters["active"] = static_cast<double>(fx.term->active_set().num_active());
  state.counters["elements"] = static_cast<double>(fx.term->num_elements());
  state.counters["t_per_slave_node"] = benchmark::Counter(
      slave, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// ---------------------------------------------------------------------------------------------
// Search
// ---------------------------------------------------------------------------------------------

/// The search part of prepare() on its own, through the public API: bucket grids of both
/// surfaces and the closest-point projections of all slave and all master nodes.
Index search_and_project(const ContactFixture& fx) {
  const contact::ContactTerm& term = *fx.term;
  const contact::NodePositions pos = fx.positions();
  contact::ProjectionOptions options;
  options.xi_tolerance = term.settings().xi_tolerance;
  options.search_distance = term.settings().search_distance;
  const contact::BucketSearch on_master(term.master(), pos, options.search_distance);
  const contact::BucketSearch on_slave(term.slave(), pos, options.search_distance);
  const auto s =
      contact::project_nodes(term.slave().nodes(), term.master(), pos, on_master, options);
  const auto m =
      contact::project_nodes(term.master().nodes(), term.slave(), pos, on_slave, options);
  return static_cast<Index>(s.size() + m.size());
}

/// Mean number of candidate facets the bucket grid returns per slave node (broad phase quality).
double mean_candidates(const ContactFixture& fx) {
  const contact::ContactTerm& term = *fx.term;
  const contact::NodePositions pos = fx.positions();
  const contact::BucketSearch on_master(term.master(), pos, term.settings().search_distance);
  std::vector<Index> candidates;
  std::size_t total = 0;
  for (Index node : term.slave().nodes()) {
    on_master.candidates(pos(node), candidates);
    total += candidates.size();
  }
  return static_cast<double>(total) / static_cast<double>(term.slave().num_nodes());
}

/// Bucket grids + projections of slave and master nodes (no active set, no stencils).
void bm_contact_search(benchmark::State& state) {
  ContactFixture& fx = ContactFixture::get(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    const Index n = search_and_project(fx);
    benchmark::DoNotOptimize(n);
    benchmark::ClobberMemory();
  }
  set_counters(state, fx);
  state.counters["candidates_per_node"] = mean_candidates(fx);
}

/// ContactTerm::prepare: search, projections, active-set update and stencil rebuild, as at the
/// start of every Newton iteration. commit() before each call starts a new step, so every call
/// applies the primal-dual rule (it costs O(1)).
void bm_contact_prepare(benchmark::State& state) {
  ContactFixture& fx = ContactFixture::get(static_cast<int>(state.range(0)));
  const physics::EvalState es = fx.eval_state();
  bool changed = false;
  for (auto _ : state) {
    fx.term->commit(es);
    changed = fx.term->prepare(es) || changed;
    benchmark::ClobberMemory();
  }
  if (changed)
    state.SkipWithError("the stencils changed at a fixed state");
  set_counters(state, fx);
  const ProjectionCounts c = count_projections(*fx.term);
  state.counters["slave_interior"] = static_cast<double>(c.slave_interior);
  state.counters["master_projected"] = static_cast<double>(c.master_projected);
  state.counters["master_interior"] = static_cast<double>(c.master_interior);
}

// ---------------------------------------------------------------------------------------------
// Element loop and assembly
// ---------------------------------------------------------------------------------------------

/// Entries of all element matrices, Σ_e n_e² (n_e: stencil size), per slave node: the dense
/// work of forming, zeroing and scattering the element tangents.
double local_entries_per_slave_node(const contact::ContactTerm& term) {
  std::vector<Index> dofs;
  double total = 0;
  for (Index e = 0; e < term.num_elements(); ++e) {
    term.element_dofs(e, dofs);
    total += static_cast<double>(dofs.size() * dofs.size());
  }
  return total / static_cast<double>(term.slave().num_nodes());
}

/// Residual and tangent of every contact element (slave facets, master facets, slave nodes)
/// into one reused LocalVector/LocalMatrix, single thread: the element work of one assembly.
void bm_contact_elements(benchmark::State& state) {
  ContactFixture& fx = ContactFixture::get(static_cast<int>(state.range(0)));
  const physics::EvalState es = fx.eval_state();
  const contact::ContactTerm& term = *fx.term;
  physics::LocalVector r;
  physics::LocalMatrix K;
  bool ok = true;
  for (auto _ : state) {
    for (Index e = 0; e < term.num_elements(); ++e) {
      ok = term.evaluate(e, es, r, &K) && ok;
      benchmark::DoNotOptimize(K.data());
    }
    benchmark::ClobberMemory();
  }
  if (!ok)
    state.SkipWithError("a contact element reported an inadmissible state");
  set_counters(state, fx);
  state.counters["K_entries_per_slave_node"] = local_entries_per_slave_node(term);
}

/// Stored entries of A that are exactly zero after an assembly (pattern entries no element
/// writes to).
Index zero_entries(const SparseMatrix& A) {
  Index n = 0;
  for (Index k = 0; k < A.nonZeros(); ++k)
    n += A.valuePtr()[k] == 0.0 ? 1 : 0;
  return n;
}

/// Assembler::assemble of the contact term alone into its sparse pattern (residual, K_ff, K_fc,
/// zeroing included; the pattern is built once, outside the loop). OMP_NUM_THREADS threads.
void bm_contact_assembly(benchmark::State& state) {
  ContactFixture& fx = ContactFixture::get(static_cast<int>(state.range(0)));
  assembly::Assembler& assembler = fx.get_assembler();
  assembly::AssembledSystem system = assembler.make_system();
  const physics::EvalState es = fx.eval_state();
  bool ok = true;
  for (auto _ : state) {
    ok = assembler.assemble(es, system, true) && ok;
    benchmark::DoNotOptimize(system.Kff.valuePtr());
    benchmark::ClobberMemory();
  }
  if (!ok)
    state.SkipWithError("a contact element reported an inadmissible state");
  set_counters(state, fx);
  state.counters["nnz_Kff"] = static_cast<double>(system.Kff.nonZeros());
  state.counters["Kff_zeros"] = static_cast<double>(zero_entries(system.Kff));
  state.counters["colours"] = static_cast<double>(
      assembly::colour_elements(assembly::collect_stencils(*fx.term), fx.map.num_dofs()).size());
}

/// Slave facets per side: 8 ... 255, i.e. 81 ... 65 536 slave nodes.
void slave_sizes(benchmark::internal::Benchmark* b) {
  for (int n : {8, 16, 32, 64, 128, 255})
    b->Arg(n);
  b->Unit(benchmark::kMicrosecond)->UseRealTime()->Complexity(benchmark::oN);
}

} // namespace

BENCHMARK(bm_contact_search)->Name("BM_ContactSearch")->Apply(slave_sizes);
BENCHMARK(bm_contact_prepare)->Name("BM_ContactPrepare")->Apply(slave_sizes);
BENCHMARK(bm_contact_elements)->Name("BM_ContactElements")->Apply(slave_sizes);
BENCHMARK(bm_contact_assembly)->Name("BM_ContactAssembly")->Apply(slave_sizes);

BENCHMARK_MAIN();
