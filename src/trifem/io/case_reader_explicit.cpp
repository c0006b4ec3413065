// SPDX-License-Identifier: MIT
// Case reader, part 4: the analysis type ([analysis] type, read before every other section) and
// what a dynamic-explicit analysis reads differently: [time] (dt optional), the [explicit] table
// and the sections and keys it does not support.
#include "trifem/io/toml_table.hpp"

#include <limits>

namespace trifem::io::detail {
namespace {

constexpr std::string_view kExplicit = "dynamic-explicit analyses";

/// Most multiplier iterations per step, and most halvings of one step (2^-100 of the step).
constexpr int kMaxMultiplierIterations = 10000;
constexpr int kMaxHalvings = 100;

/// [time] keys that only the adaptive quasi-static step control reads.
constexpr std::string_view kQuasiStaticTimeKeys[] = {"dt_min", "dt_max", "target_iterations",
                                                     "growth", "cutback"};

/// Throws "<path>: not supported in dynamic-explicit analyses (<why>)" at `where`.
[[noreturn]] void unsupported(const toml::node* where, std::string_view path,
                              std::string_view why) {
  fail(where, path, fmt::format("not supported in {} ({})", kExplicit, why));
}

/// Rejects every entry of the array of tables `key` of `parent`, naming the first.
void reject_tables(const Table& parent, std::string_view key, std::string_view why) {
  const std::vector<Table> tables = parent.tables(key);
  if (!tables.empty())
    unsupported(tables.front().where(), tables.front().path(), why);
}

/// [[boundary.*]] entries an explicit analysis cannot apply.
void check_explicit_boundary(const Table& boundary) {
  reject_tables(boundary, "impermeable", "no fluid or ion fields");
  reject_tables(boundary, "bath", "no fluid or ion fields");
  for (const Table& t : boundary.tables("fixed"))
    if (const toml::node* n = t.find("field")) {
      const std::string field = convert(*n, t.path("field"), Tag<std::string>{});
      if (field != "displacement")
        fail(n, fmt::format("{} = '{}'", t.path("field"), field),
             fmt::format("{} have only the displacement field", kExplicit));
    }
}

/// ExplicitSpec::penalty: a number > 0 or inf (the exact constraint).
Real read_penalty(const Table& t, Real fallback) {
  const toml::node* n = t.find("penalty");
  const auto* f = n ? n->as_floating_point() : nullptr;
  if (f && f->get() == std::numeric_limits<Real>::infinity())
    return f->get();
  return t.number("penalty", {.range = Range::positive(),
                              .fallback = fallback,
                              .unit = "MPa",
                              .hint = "or inf for the exact constraint"});
}

/// The numeric keys of [explicit] (penalty, damping, safety, counts, tolerances).
void read_explicit_numbers(const Table& t, ExplicitSpec& e) {
  e.penalty = read_penalty(t, e.penalty);
  e.damping =
      t.number("damping", {.range = Range::non_negative(), .fallback = e.damping, .unit = "1/s"});
  if (t.find("safety_factor"))
    e.safety_factor = t.number("safety_factor", {.range = {0.0, 1.0, true, false}});
  e.stable_step_interval = t.integer("stable_step_interval", 0, e.stable_step_interval);
  e.max_iterations = t.integer("max_iterations", 1, e.max_iterations, kMaxMultiplierIterations);
  e.max_halvings = t.integer("max_halvings", 0, e.max_halvings, kMaxHalvings);
  e.factorization_age = t.integer("factorization_age", 1, e.factorization_age);
  e.displacement_tolerance =
      t.number("displacement_tolerance",
               {.range = Range::open(0.0, 1.0), .fallback = e.displacement_tolerance});
  e.constraint_tolerance = t.number(
      "constraint_tolerance", {.range = Range::open(0.0, 1.0), .fallback = e.constraint_tolerance});
}

/// The named choices and the flag of [explicit].
void read_explicit_choices(const Table& t, ExplicitSpec& e) {
  static const Options<ExplicitReading> readings = {{"A", ExplicitReading::A},
                                                    {"B", ExplicitReading::B}};
  static const Options<VolumeConstraint> constraints = {{"J-1", VolumeConstraint::JMinusOne},
                                                        {"lnJ", VolumeConstraint::LogJ}};
  static const Options<StableStepEstimate> estimates = {
      {"power-iteration", StableStepEstimate::PowerIteration},
      {"element-bound", StableStepEstimate::ElementBound},
      {"none", StableStepEstimate::None}};
  e.reading = t.choice("reading", readings, std::optional(e.reading), "reading");
  e.constraint = t.choice("constraint", constraints, std::optional(e.constraint), "constraint");
  e.multiplier = t.get<bool>("multiplier").value_or(e.multiplier);
  e.stable_step =
      t.choice("stable_step", estimates, std::optional(e.stable_step), "stable step estimate");
}

} // namespace

void read_analysis_type(const Table& root, CaseSpec& spec) {
  const auto t = root.table("analysis");
  if (!t)
    return;
  static const Options<AnalysisType> types = {{"quasi-static", AnalysisType::QuasiStatic},
                                              {"dynamic", AnalysisType::Dynamic},
                                              {"dynamic-explicit", AnalysisType::DynamicExplicit}};
  spec.analysis.type = t->choice("type", types, std::optional(spec.analysis.type), "analysis type");
}

void check_analysis_sections(const Table& root, const CaseSpec& spec) {
  if (!spec.is_explicit()) {
    if (const auto t = root.table("explicit"); t && !declares_explicit_step(root))
      fail(t->where(), t->path(),
           "only applies to dynamic-explicit analyses (set [analysis] type = "
           "\"dynamic-explicit\", or analysis = \"dynamic-explicit\" in a [[step]])");
    return;
  }
  if (const auto boundary = root.table("boundary"))
    check_explicit_boundary(*boundary);
  reject_tables(root, "contact", "contact needs the implicit solver");
  reject_tables(root, "connector", "connectors join rigid bodies, which need the implicit solver");
  reject_tables(root, "constraint", "constraints need the implicit solver (Lagrange multipliers)");
  if (const auto solver = root.table("solver"))
    fail(solver->where(), solver->path(),
         fmt::format("applies to quasi-static analyses only (the Newton solver); {} take their "
                     "options from [explicit]",
                     kExplicit));
}

void read_explicit_time(const Table& root, CaseSpec& spec) {
  const auto t = root.table("time");
  if (!t)
    fail(nullptr, "time", "missing required table [time] (with at least end_time)");
  for (const std::string_view key : kQuasiStaticTimeKeys)
    if (const toml::node* n = t->find(key))
      fail(n, t->path(key),
           fmt::format("applies to quasi-static analyses only; {} step with dt or the stability "
                       "estimate (see [explicit])",
                       kExplicit));
  t->allow({"end_time", "dt"});
  TimeSpec& s = spec.time;
  s.end_time = t->number("end_time", {.range = Range::positive(), .unit = "s"});
  s.dt = t->number("dt", {.range = {0.0, s.end_time, true, false},
                          .fallback = 0.0,
                          .unit = "s",
                          .hint = "at most time.end_time; omit it to use the stability estimate"});
}

void read_explicit(const Table& root, CaseSpec& spec) {
  const auto t = root.table("explicit");
  if (!t)
    return; // with another analysis type, check_analysis_sections has rejected it
  t->allow({"reading", "constraint", "multiplier", "penalty", "damping", "safety_factor",
            "stable_step", "stable_step_interval", "max_iterations", "max_halvings",
            "factorization_age", "displacement_tolerance", "constraint_tolerance"});
  ExplicitSpec& e = spec.explicit_dynamics; // holds the defaults until overwritten
  read_explicit_choices(*t, e);
  read_explicit_numbers(*t, e);
  // (a dynamic-explicit [[step]] checks its own dt)
  if (spec.is_explicit() && e.stable_step == StableStepEstimate::None && spec.time.dt <= 0.0)
    fail(t->find("stable_step"), fmt::format("{} = 'none'", t->path("stable_step")),
         "needs time.dt (the step is not estimated)");
}

} // namespace trifem::io::detail
